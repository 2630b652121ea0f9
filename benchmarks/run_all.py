"""Run every benchmark script in this folder, one after the other, in fresh interpreters.

Usage (from the repository root)::

    python benchmarks/run_all.py [--quick]

Each ``bench_*.py`` prints its own Markdown table on stdout; this runner passes
``--quick`` on and pins BLAS/OpenMP to one thread (the targets are for one core).
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def main() -> int:
    extra = [arg for arg in sys.argv[1:] if arg == "--quick"]
    threads = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")
    env = {**os.environ, **dict.fromkeys(threads, "1")}
    status = 0
    for script in sorted(HERE.glob("bench_*.py")):
        print(f"\n## {script.name}\n", flush=True)
        done = subprocess.run([sys.executable, str(script), *extra], env=env, cwd=HERE.parent)
        status = status or done.returncode
    return status


if __name__ == "__main__":
    raise SystemExit(main())
