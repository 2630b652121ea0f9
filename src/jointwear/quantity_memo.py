"""Quantity texts read before: pint's SI magnitudes kept between processes.

A run reads its config's quantity texts (``"70 mm"``, ``"120 rpm"``) with pint
(:mod:`jointwear.units`). pint's import costs ~0.15 s of a run's start, ~0.3 s where
dask is installed (pint imports ``dask.base`` with itself). A text pint has converted
is remembered here with the SI magnitude pint gave, so that a process that reads only
texts read before imports no pint. The memo holds pint's answers, nothing computed
otherwise: a text not in it, and every text that is refused, goes to pint.

Besides whole texts, the memo keeps the unit of a text of one number and a unit
(``"70 mm"``: ``mm``) with pint's factor into the SI unit (:func:`recall_unit`), where
pint's answer for that text was the number times that factor, bit for bit
(:mod:`jointwear.units` checks it before it remembers one): a new number in a unit read
before (``"75 mm"``) is then converted without pint, as pint converts it (the number
times its cached factor). Units with an offset (``degC``) are not kept.

The memo is one JSON file in the user's cache folder (:func:`folder`; the environment
variable :data:`ENVIRONMENT` names another folder, an empty value turns the memo off).
It is stamped with what the answers depend on: the source of :mod:`jointwear.units`
(the package's definitions and its rules for angles and turns) and pint's installed
files; a file of another stamp is read as empty and replaced. A folder that cannot be
read or written is no error: the texts then go to pint, as without a memo.

A memo begins (no file yet, or a file of another stamp) from the package's *seed*
(:data:`SEED`): pint's factors for the units of the package's example configs and
parameter sets, as a memo of those units would hold them, made by pint itself. It is
used only where the installed pint is the one that made it (its version and its
definition files, compared byte for byte by digest) and the units module is the one it
was made for; otherwise the memo begins empty. So a fresh install's first run in these
units imports no pint (nor the ``dask.base`` that pint imports where dask is
installed). With the memo turned off (an empty :data:`ENVIRONMENT`) nothing is read
from or written to a cache folder; the seed, part of the package, is still read: a text
in a unit the seed holds needs no pint, any other text goes to pint in every process.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import tempfile
import threading
from functools import cache
from importlib.util import find_spec
from pathlib import Path

__all__ = [
    "ENVIRONMENT",
    "MAX_TEXTS",
    "SEED",
    "folder",
    "has_unit",
    "knows_unit",
    "recall",
    "recall_unit",
    "remember",
    "remember_unit",
    "seed_stamp",
    "stamp",
]

#: environment variable naming the memo's folder (empty: no memo)
ENVIRONMENT = "JOINTWEAR_CACHE_DIR"
#: most texts remembered (the oldest are dropped first)
MAX_TEXTS = 4096
#: the memo's file in :func:`folder`
FILE_NAME = "quantities.json"
#: the source whose rules the answers follow
UNITS_SOURCE = Path(__file__).with_name("units.py")
#: the seed of a new memo: pint's factors for the units of the package's own configs
#: (None: no seed)
SEED: Path | None = Path(__file__).with_name("data") / "units_seed.json"
#: pint's definition files whose content the seed's answers depend on
PINT_DEFINITIONS = ("default_en.txt", "constants_en.txt")

_lock = threading.Lock()


def folder() -> Path | None:
    """The memo's folder: :data:`ENVIRONMENT`, else the user's cache folder of jointwear."""
    chosen = os.environ.get(ENVIRONMENT)
    if chosen is not None:
        return Path(chosen) if chosen.strip() else None
    try:
        import platformdirs
    except ImportError:
        return None
    return Path(platformdirs.user_cache_path("jointwear", appauthor=False))


@cache
def _units_source() -> bytes:
    """The source of :mod:`jointwear.units` (both stamps hash it)."""
    return UNITS_SOURCE.read_bytes()


@cache
def stamp() -> str:
    """What pint's answers depend on: the units module's source and pint's installed files."""
    digest = hashlib.sha256(_units_source())
    spec = find_spec("pint")
    origin = Path(spec.origin) if spec is not None and spec.origin else None
    if origin is not None:
        for name in ("__init__.py", "default_en.txt", "constants_en.txt"):
            try:
                status = (origin.parent / name).stat()
            except OSError:
                continue
            digest.update(f"{origin.parent / name}:{status.st_size}:{status.st_mtime_ns};".encode())
    return digest.hexdigest()[:32]


def seed_stamp() -> dict[str, str]:
    """What the seed's answers depend on, by content: the units module's source, pint's
    version and pint's definition files (nothing of where they are installed)."""
    from importlib import metadata

    spec = find_spec("pint")
    if spec is None or not spec.origin:
        return {}
    try:
        version = metadata.version("pint")
        definitions = hashlib.sha256()
        for name in PINT_DEFINITIONS:
            definitions.update((Path(spec.origin).parent / name).read_bytes())
    except (OSError, metadata.PackageNotFoundError):
        return {}
    units = hashlib.sha256(_units_source()).hexdigest()[:32]
    return {"units": units, "pint": version, "definitions": definitions.hexdigest()[:32]}


def _seed_units() -> dict[str, dict]:
    """The seed's units (unit text -> {target: [factor, turn factor]}) where it was made
    by the installed pint for this units module, else none."""
    if SEED is None:
        return {}
    try:
        seed = json.loads(SEED.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    if not isinstance(seed, dict) or not isinstance(seed.get("units"), dict):
        return {}
    stamp_now = seed_stamp()
    return seed["units"] if stamp_now and seed.get("stamp") == stamp_now else {}


@cache
def _memo() -> dict[str, dict]:
    """The memo of this process: ``texts`` (text -> {target: SI magnitude}) and ``units``
    (unit text -> {target: [factor, turn factor]})."""
    where = folder()
    data = None
    if where is not None:
        try:
            data = json.loads((where / FILE_NAME).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            data = None
    # no folder (the memo turned off), no file yet, or a file of other code: the seed,
    # which is the package's data, not the user's cache, and is never written back
    if not isinstance(data, dict) or data.get("stamp") != stamp():
        data = {"units": _seed_units()}
    return {
        part: data[part] if isinstance(data.get(part), dict) else {} for part in ("texts", "units")
    }


def _texts() -> dict[str, dict[str, float]]:
    """The remembered texts of this process: text -> {target: SI magnitude}."""
    return _memo()["texts"]


def recall(text: str, target: str) -> float | None:
    """The SI magnitude pint gave ``text`` in ``target``, or None if not remembered.

    Parameters
    ----------
    text : str
        The quantity text as given, e.g. ``"70 mm"``.
    target : str
        The conversion it was read for: the SI unit and the power of the radian of a
        rate, as :mod:`jointwear.units` names it (e.g. ``"m|"``, ``"rad/s|1"``).

    Returns
    -------
    float or None
        The magnitude [SI unit of ``target``].
    """
    known = _texts().get(text)
    value = known.get(target) if isinstance(known, dict) else None
    if isinstance(value, bool) or not isinstance(value, int | float):
        return None
    return float(value) if math.isfinite(value) else None


def recall_unit(unit: str, target: str) -> tuple[float, float] | None:
    """pint's factor of ``unit`` into ``target``, and the turn factor of a rate, if kept.

    Parameters
    ----------
    unit : str
        The unit text of a quantity text of one number and a unit, e.g. ``"mm"``.
    target : str
        The conversion (see :func:`recall`).

    Returns
    -------
    tuple of float or None
        ``(factor, turns)``: the SI magnitude of a number ``x`` in ``unit`` is
        ``x * factor * turns`` [SI unit of ``target``].
    """
    known = _memo()["units"].get(unit)
    pair = known.get(target) if isinstance(known, dict) else None
    if not isinstance(pair, list) or len(pair) != 2:
        return None
    if any(isinstance(x, bool) or not isinstance(x, int | float) for x in pair):
        return None
    factor, turns = float(pair[0]), float(pair[1])
    return (factor, turns) if math.isfinite(factor) and math.isfinite(turns) else None


def has_unit(text: str) -> bool:
    """Whether pint read ``text`` before as a quantity with a unit (not a bare number).

    Parameters
    ----------
    text : str
        The quantity text as given.
    """
    known = _texts().get(text)
    return isinstance(known, dict) and bool(known)


def knows_unit(unit: str) -> bool:
    """Whether pint read ``unit`` before as the unit of a quantity text (not unitless).

    Parameters
    ----------
    unit : str
        The unit text, e.g. ``"mm"``.
    """
    known = _memo()["units"].get(unit)
    return isinstance(known, dict) and bool(known)


def remember(text: str, target: str, magnitude: float) -> None:
    """Keep pint's SI magnitude of ``text`` in ``target`` for later processes.

    Parameters
    ----------
    text : str
        The quantity text as given; it carries a unit.
    target : str
        The conversion (see :func:`recall`).
    magnitude : float
        pint's answer [SI unit of ``target``].
    """
    _keep("texts", text, target, magnitude)


def remember_unit(unit: str, target: str, factor: float, turns: float) -> None:
    """Keep pint's factor of ``unit`` into ``target`` for later processes.

    Only for a unit whose quantity texts pint converts as the number times ``factor``
    (:mod:`jointwear.units` checks it).

    Parameters
    ----------
    unit : str
        The unit text.
    target : str
        The conversion (see :func:`recall`).
    factor : float
        pint's magnitude of one ``unit`` in ``target`` [SI unit of ``target``].
    turns : float
        The factor of a rate between turns and radians (1 if none) [-].
    """
    _keep("units", unit, target, [factor, turns])


def _keep(part: str, text: str, target: str, answer: float | list[float]) -> None:
    """Add an answer to the memo and write it (no error if the folder is not writable)."""
    where = folder()
    if where is None:
        return
    with _lock:
        memo = _memo()
        entries = memo[part]
        if not isinstance(entries.get(text), dict):
            entries[text] = {}
        entries[text][target] = answer
        while len(entries) > MAX_TEXTS:
            del entries[next(iter(entries))]
        try:
            where.mkdir(parents=True, exist_ok=True)
            _write(where, {"stamp": stamp(), **memo})
        except (OSError, ValueError):
            pass


def _write(where: Path, data: dict) -> None:
    # written whole to a file beside it, then moved over it: a reader in another
    # process sees the old memo or the new one, never half of one
    handle, name = tempfile.mkstemp(dir=where, prefix=".quantities-", suffix=".json")
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as out:
            json.dump(data, out, allow_nan=False)
        os.replace(name, where / FILE_NAME)
    except BaseException:
        Path(name).unlink(missing_ok=True)
        raise
