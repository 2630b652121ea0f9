"""Make the package's seed of the memo of quantity texts (``jointwear/data/units_seed.json``).

Run ``python -m tests.units_seed`` from the repository root after a change of
``jointwear/units.py`` or of the pint it is made with. It reads every config of the
examples and of the paper, and the materials and lubricants libraries, in a fresh
interpreter with a memo of its own and no seed, and keeps the units that memo holds:
pint's own factors, checked
bit for bit by :mod:`jointwear.units` before they are kept. ``tests/test_quantity_memo.py``
fails while the seed is stale.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SEED = REPO / "src" / "jointwear" / "data" / "units_seed.json"
#: the configs whose units the seed holds
CONFIGS = sorted(
    [*(REPO / "examples").rglob("*.toml"), *(REPO / "src/jointwear/paper/configs").glob("*.toml")]
)

READ_ALL = """
import json, sys
from jointwear import quantity_memo
quantity_memo.SEED = None
from jointwear.config import load_config
from jointwear.materials import library
from jointwear.lubrication import lubricants
for path in json.loads(sys.argv[1]):
    load_config(path)
for material in library().values():
    material.limits()
    material.summary()
lubricants.library()
print(json.dumps(quantity_memo.seed_stamp()))
"""


def read_units() -> dict:
    """The seed as pint makes it now: ``{"stamp": ..., "units": ...}``."""
    with tempfile.TemporaryDirectory(prefix="jointwear-seed-") as memo:
        path = os.pathsep.join([str(REPO / "src"), os.environ.get("PYTHONPATH", "")])
        done = subprocess.run(
            [sys.executable, "-c", READ_ALL, json.dumps([str(p) for p in CONFIGS])],
            env={**os.environ, "PYTHONPATH": path, "JOINTWEAR_CACHE_DIR": memo},
            capture_output=True,
            text=True,
            check=True,
        )
        units = json.loads((Path(memo) / "quantities.json").read_text())["units"]
    return {"stamp": json.loads(done.stdout), "units": dict(sorted(units.items()))}


def main() -> None:
    seed = read_units()
    SEED.write_text(json.dumps(seed, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    print(f"{SEED.relative_to(REPO)}: {len(seed['units'])} units, pint {seed['stamp']['pint']}")


if __name__ == "__main__":
    main()
