"""Files in and out, one policy for every command.

Output is never half-written:

* :func:`atomic_path` / :func:`atomic_write` write one file through a temporary
  file next to it and a rename;
* :func:`staged_output` stages everything a command writes into a temporary
  directory and publishes it in one step: one rename of the whole directory when
  ``--out`` does not exist yet, or renames with a rollback when merging into an
  existing directory. Symbolic links and special files are never written
  through; a full disk or a read-only file system is a one-line
  :class:`~jointwear.errors.DataError` naming the path.

Input goes through :func:`check_input` / :func:`read_input`: regular files only (a
FIFO, device or directory is refused without being opened), a size limit
(:data:`MAX_INPUT_BYTES`, raised with the ``JOINTWEAR_MAX_INPUT_MB`` environment
variable) and UTF-8 with or without a byte-order mark.
"""

from __future__ import annotations

import contextlib
import errno
import json
import math
import os
import shutil
import stat
import tempfile
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import IO, Any

from jointwear.errors import ConfigError, DataError
from jointwear.interrupts import raise_pending

__all__ = [
    "MAX_INPUT_BYTES",
    "atomic_path",
    "atomic_write",
    "check_input",
    "check_out",
    "check_tree",
    "json_ready",
    "os_reason",
    "read_input",
    "read_input_bytes",
    "staged_output",
    "write_json",
]

#: default size limit of a text input file [bytes] (``JOINTWEAR_MAX_INPUT_MB`` overrides)
MAX_INPUT_BYTES = 64 * 1024 * 1024
_LIMIT_VARIABLE = "JOINTWEAR_MAX_INPUT_MB"

_REASONS = {
    errno.ENOSPC: "no space left on device",
    errno.EDQUOT: "disk quota exceeded",
    errno.EROFS: "read-only file system",
    errno.EACCES: "permission denied",
    errno.EPERM: "permission denied",
    errno.ENAMETOOLONG: "file name too long",
    errno.ENOTDIR: "a parent is not a directory",
    errno.ELOOP: "too many levels of symbolic links",
    errno.EISDIR: "is a directory",
}


def os_reason(exc: OSError) -> str:
    """A short, stable reason for an operating-system error (``no space left on device``).

    Parameters
    ----------
    exc : OSError
        The error; its ``errno`` picks the reason.
    """
    if exc.errno in _REASONS:
        return _REASONS[exc.errno]
    return (exc.strerror or str(exc) or type(exc).__name__).lower()


def _umask() -> int:
    """The process umask (read without changing it where the OS allows)."""
    with contextlib.suppress(OSError, ValueError):
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("Umask:"):
                return int(line.split()[1], 8)
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


# ---------------------------------------------------------------- input


def _limit() -> int:
    text = os.environ.get(_LIMIT_VARIABLE, "").strip()
    if not text:
        return MAX_INPUT_BYTES
    try:
        megabytes = float(text)
    except ValueError:
        raise ConfigError(f"{_LIMIT_VARIABLE}: expected a number of MiB, got {text!r}") from None
    if not megabytes > 0:
        raise ConfigError(f"{_LIMIT_VARIABLE}: must be > 0, got {text!r}")
    return int(megabytes * 1024 * 1024)


def _kind(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISFIFO(mode):
        return "a named pipe (FIFO)"
    if stat.S_ISSOCK(mode):
        return "a socket"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    return "not a regular file"


def check_input(
    path: str | Path,
    what: str = "file",
    max_bytes: int | None = 0,
    error: type[Exception] = DataError,
) -> os.stat_result:
    """Check that ``path`` is a readable regular file within the size limit, without opening it.

    Parameters
    ----------
    path : path-like
        The input file.
    what : str
        What the file is, for messages (``"config"``, ``"data file"``) [-].
    max_bytes : int or None
        Size limit [bytes]; ``0`` means :data:`MAX_INPUT_BYTES` (or the environment's
        ``JOINTWEAR_MAX_INPUT_MB``), ``None`` no limit.
    error : exception type
        Raised with a one-line message naming the file.
    """
    path = Path(path)
    try:
        info = path.stat()
    except FileNotFoundError:
        raise error(f"{path}: file not found") from None
    except OSError as exc:
        raise error(f"{path}: cannot read ({os_reason(exc)})") from None
    if not stat.S_ISREG(info.st_mode):
        raise error(f"{path}: cannot read {what}: is {_kind(info.st_mode)}, not a regular file")
    limit = _limit() if max_bytes == 0 else max_bytes
    if limit is not None and info.st_size > limit:
        raise error(
            f"{path}: {what} too large ({info.st_size / 2**20:.1f} MiB > "
            f"{limit / 2**20:.0f} MiB; raise the limit with {_LIMIT_VARIABLE}=N)"
        )
    return info


def read_input_bytes(
    path: str | Path,
    what: str = "file",
    max_bytes: int | None = 0,
    error: type[Exception] = DataError,
) -> bytes:
    """The bytes of an input file checked by :func:`check_input`."""
    check_input(path, what, max_bytes, error)
    try:
        # O_NONBLOCK: should the file be swapped for a FIFO after the check, do not hang
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(fd, "rb") as handle:
            if not stat.S_ISREG(os.fstat(handle.fileno()).st_mode):
                raise error(f"{path}: cannot read {what}: not a regular file")
            return handle.read()
    except OSError as exc:
        raise error(f"{path}: cannot read ({os_reason(exc)})") from None


def read_input(
    path: str | Path,
    what: str = "file",
    max_bytes: int | None = 0,
    error: type[Exception] = DataError,
) -> str:
    """The text of a UTF-8 input file (a byte-order mark is dropped), see :func:`check_input`.

    Parameters
    ----------
    path : path-like
        The input file.
    what : str
        What the file is, for messages [-].
    max_bytes : int or None
        Size limit [bytes] (``0``: the default limit).
    error : exception type
        Raised with a one-line message naming the file.
    """
    data = read_input_bytes(path, what, max_bytes, error)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise error(f"{path}: not a text file (cannot read the {what} as UTF-8)") from None


# ---------------------------------------------------------------- single files


@contextlib.contextmanager
def atomic_path(path: str | Path) -> Iterator[Path]:
    """Yield a temporary path next to ``path``; rename it onto ``path`` on success.

    On any exception the temporary file is removed and ``path`` is untouched.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    tmp_path = Path(tmp)
    try:
        yield tmp_path
        # mkstemp creates 0600; give the result the mode a plain open() would have
        os.chmod(tmp_path, 0o666 & ~_umask())
        os.replace(tmp_path, path)
    finally:
        with contextlib.suppress(FileNotFoundError):
            tmp_path.unlink()


@contextlib.contextmanager
def atomic_write(path: str | Path, mode: str = "w", **kwargs: Any) -> Iterator[IO[Any]]:
    """Open a temporary file for writing; it replaces ``path`` only when closed cleanly."""
    with atomic_path(path) as tmp, open(tmp, mode, **kwargs) as handle:
        yield handle
        handle.flush()
        os.fsync(handle.fileno())


def json_ready(value: Any) -> Any:
    """``value`` as plain JSON data: non-finite floats become ``None`` (``null``).

    Dicts and lists are converted recursively, tuples become lists and numpy
    scalars Python numbers; everything else is returned as it is.

    Parameters
    ----------
    value : Any
        Nested dicts, lists and tuples of numbers, strings, booleans and ``None``
        (any units: the values are not changed).
    """
    if isinstance(value, dict):
        return {key: json_ready(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [json_ready(item) for item in value]
    if hasattr(value, "item") and callable(value.item) and getattr(value, "shape", None) == ():
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def write_json(path: str | Path, data: Any) -> None:
    """Write ``data`` as indented, strict JSON, atomically.

    Non-finite floats are written as ``null`` (:func:`json_ready`): ``NaN`` and
    ``Infinity`` are not JSON, and strict readers refuse them.
    """
    text = json.dumps(json_ready(data), indent=2, sort_keys=False, allow_nan=False)
    with atomic_write(path, encoding="utf-8") as handle:
        handle.write(text + "\n")


# ---------------------------------------------------------------- output directories


def _refuse_special(target: Path, flag: str) -> os.stat_result | None:
    """``lstat`` of ``target`` (``None`` if absent); a link or special file is refused."""
    try:
        info = target.lstat()
    except FileNotFoundError:
        return None
    if stat.S_ISLNK(info.st_mode):
        raise DataError(f"{flag}: {target} is a symbolic link; refusing to write through it")
    if not (stat.S_ISREG(info.st_mode) or stat.S_ISDIR(info.st_mode)):
        raise DataError(f"{flag}: {target} is {_kind(info.st_mode)}; refusing to replace it")
    return info


def check_out(
    out: str | Path,
    flag: str = "--out",
    names: Iterable[str] = (),
    files: Iterable[str] = (),
    dirs: Iterable[str] = (),
) -> Path:
    """Check an output directory before anything is computed or written.

    Parameters
    ----------
    out : path-like
        The directory (created on publishing if absent). A symbolic link to a
        directory is followed (the link itself stays).
    flag : str
        The option, for messages.
    names : iterable of str
        Entries the command will write into ``out``: each must be absent, a regular
        file or a directory, not a symbolic link or special file.
    files : iterable of str
        Entries that are files: a directory of that name is refused.
    dirs : iterable of str
        Entries that are folders: a file of that name is refused.

    Returns
    -------
    Path
        ``out`` (resolved if it is a symbolic link).
    """
    if str(out) == "":
        raise ConfigError(f"{flag}: empty path")
    out = Path(out)
    if out.is_symlink() and out.is_dir():
        out = out.resolve()
    if out.exists() and not out.is_dir():
        raise ConfigError(f"{flag}: {out} exists and is not a directory")
    if out.is_symlink():
        raise ConfigError(f"{flag}: {out} is a dangling symbolic link")
    if out.is_dir():
        files, dirs = set(files), set(dirs)
        for name in sorted({*names, *files, *dirs}):
            info = _refuse_special(out / name, flag)
            if info is not None and name in files and stat.S_ISDIR(info.st_mode):
                raise DataError(f"{flag}: {out / name} is a directory, not a file")
            if info is not None and name in dirs and not stat.S_ISDIR(info.st_mode):
                raise DataError(f"{flag}: {out / name} is a file, not a directory")
    else:
        for parent in out.parents:  # the first existing ancestor must be a directory
            if parent.exists() or parent.is_symlink():
                if not parent.is_dir():
                    raise ConfigError(f"{flag}: {parent} is not a directory")
                break
    return out


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    else:
        path.unlink()


def _publish_into(staging: Path, out: Path, flag: str) -> None:
    """Move the entries of ``staging`` into the existing ``out``; roll back on failure."""
    items = sorted(staging.iterdir())
    for item in items:  # check every target before the first rename
        info = _refuse_special(out / item.name, flag)
        if info is not None and stat.S_ISDIR(info.st_mode) != item.is_dir():
            kind = "a directory" if stat.S_ISDIR(info.st_mode) else "a file"
            raise DataError(f"{flag}: {out / item.name} is {kind}; refusing to replace it")
    backup = Path(tempfile.mkdtemp(prefix=".backup-", dir=out))
    done: list[tuple[Path, bool]] = []
    try:
        for item in items:
            target = out / item.name
            saved = target.exists()
            if saved:
                target.rename(backup / item.name)
            done.append((target, saved))
            item.rename(target)
    except BaseException:
        for target, saved in reversed(done):
            with contextlib.suppress(OSError):
                if target.exists() or target.is_symlink():
                    _remove(target)
                if saved:
                    (backup / target.name).rename(target)
        raise
    finally:
        shutil.rmtree(backup, ignore_errors=True)


def _publish(staging: Path, out: Path, flag: str) -> None:
    if staging.parent != out:
        os.chmod(staging, 0o777 & ~_umask())
        try:
            os.rename(staging, out)  # a new --out: one atomic rename
            return
        except OSError as exc:  # created meanwhile by someone else: merge into it
            if exc.errno not in (errno.ENOTEMPTY, errno.EEXIST, errno.EISDIR):
                raise
    # an existing folder (perhaps the working directory, a mount point): keep it, move in
    _publish_into(staging, out, flag)


@contextlib.contextmanager
def staged_output(
    out: str | Path,
    flag: str = "--out",
    names: Iterable[str] = (),
    files: Iterable[str] = (),
    dirs: Iterable[str] = (),
) -> Iterator[Path]:
    """Stage a command's output and publish it into ``out`` all at once, or not at all.

    Yields a temporary directory on the same file system (next to ``out`` when it
    does not exist yet, else inside it); whatever is written there appears in ``out``
    when the block ends without an exception: a new ``out`` by one rename, an
    existing one (kept as it is, with its other files) by renames with a rollback.
    On an exception nothing in ``out`` changes and every directory this call created
    is removed again.

    Parameters
    ----------
    out : path-like
        Output directory.
    flag : str
        The option, for messages.
    names, files, dirs : iterable of str
        As in :func:`check_out`.

    Raises
    ------
    DataError
        If ``out`` cannot be written (``error: --out: DIR: no space left on device``),
        or an entry to replace is a symbolic link, a special file, or a directory
        where a file goes.
    """
    shown = check_out(out, flag, names, files, dirs)
    out = Path(os.path.abspath(shown))  # "." and ".." have no usable parent or name
    created: list[Path] = []
    for parent in reversed(out.parents):
        if not parent.exists():
            created.append(parent)
    staging: Path | None = None
    try:
        try:
            if out.is_dir():  # stage inside: same file system even if --out is a mount point
                staging = Path(tempfile.mkdtemp(prefix=".staging-", dir=out))
            else:
                out.parent.mkdir(parents=True, exist_ok=True)
                staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.staging-", dir=out.parent))
        except OSError as exc:
            raise DataError(f"{flag}: {shown}: {os_reason(exc)}") from None
        try:
            yield staging
            raise_pending()  # a signal that arrived meanwhile publishes nothing
            _publish(staging, out, flag)
        except OSError as exc:
            where = _shown(exc, staging, out, shown)
            raise DataError(f"{flag}: {where}: {os_reason(exc)}") from None
    finally:
        if staging is not None:
            shutil.rmtree(staging, ignore_errors=True)
        if not out.exists():
            for parent in reversed(created):
                with contextlib.suppress(OSError):
                    parent.rmdir()


def _shown(exc: OSError, staging: Path, out: Path, shown: Path) -> Path:
    """The path an error is about, as the user wrote it (the staging folder hidden)."""
    if not isinstance(exc.filename, str):
        return shown
    path = Path(os.path.abspath(exc.filename))
    for base in (staging, out):
        if path.is_relative_to(base) and path != base:
            return shown / path.relative_to(base)
    return shown


def check_tree(out: str | Path, names: Iterable[str], flag: str = "--out") -> None:
    """Refuse symbolic links and special files in the folders ``names`` of ``out``.

    Used for directories a command fills incrementally (a sweep's ``cases/``), so a
    link planted inside can never make it write or delete outside ``out``.

    Parameters
    ----------
    out : path-like
        The output directory.
    names : iterable of str
        Its entries the command owns (checked with everything below them).
    flag : str
        The option, for messages.
    """
    out = Path(out)
    for name in names:
        top = out / name
        if _refuse_special(top, flag) is None or not top.is_dir():
            continue
        for root, dirs, entries in os.walk(top):
            for entry in [*dirs, *entries]:
                _refuse_special(Path(root) / entry, flag)
