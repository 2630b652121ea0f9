"""The installed package's version, read when first asked for."""

from __future__ import annotations

from functools import cache

__all__ = ["package_version"]


@cache
def package_version() -> str:
    """The version of the installed distribution, ``"0+unknown"`` from a bare source tree.

    Read from the installed metadata on the first call: :mod:`importlib.metadata` and its
    scan of the installed distributions cost more than a one-revolution run's contact
    solve, so nothing reads it at import time.
    """
    from importlib import metadata

    try:
        return metadata.version("jointwear")
    except metadata.PackageNotFoundError:  # running from a source tree
        return "0+unknown"
