"""Registries of named models (pvlib's pattern: a model is a name or a callable).

An entry may be named by a ``"module:attribute"`` string (:meth:`Registry.add_lazy`),
imported when it is first asked for: a package can register models of a package that
imports it without importing that package (no import cycle).
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from importlib import import_module
from typing import Generic, TypeVar

from jointwear.errors import ConfigError

__all__ = ["Registry", "suggest"]

T = TypeVar("T")


def suggest(name: str, options: Iterable[str]) -> str:
    """Return ``"; did you mean 'x'?"`` for the closest option, or a list of options."""
    options = list(options)
    close = difflib.get_close_matches(str(name), options, n=1, cutoff=0.5)
    if close:
        return f"; did you mean {close[0]!r}?"
    return f"; choose from {', '.join(repr(o) for o in options)}"


@dataclass(frozen=True)
class _Lazy:
    """An entry named by ``"module:attribute"``, imported on first use."""

    target: str

    def load(self) -> object:
        module, _, attribute = self.target.partition(":")
        return getattr(import_module(module), attribute)


class Registry(Generic[T]):
    """A name -> object mapping that fails early with a best-match suggestion.

    Parameters
    ----------
    kind : str
        What is registered (used in messages), e.g. ``"contact model"``.
    key : str
        The config key that selects an entry, e.g. ``"contact.model"``.
    """

    def __init__(self, kind: str, key: str) -> None:
        self.kind = kind
        self.key = key
        self._entries: dict[str, T] = {}

    def register(self, name: str) -> Callable[[T], T]:
        def decorator(obj: T) -> T:
            self._entries[name] = obj
            return obj

        return decorator

    def add(self, name: str, obj: T) -> None:
        self._entries[name] = obj

    def add_lazy(self, name: str, target: str) -> None:
        """Register the object ``target`` names (``"package.module:attribute"``).

        The module is imported when the entry is first asked for (:meth:`get`,
        :meth:`items`); names, membership and suggestions do not import it.
        """
        self._entries[name] = _Lazy(target)  # type: ignore[assignment]

    def __contains__(self, name: object) -> bool:
        return name in self._entries

    def __iter__(self):
        return iter(self._entries)

    def items(self):
        for name in self._entries:
            self.get(name)  # imports the lazy entries
        return self._entries.items()

    def names(self) -> list[str]:
        return list(self._entries)

    def get(self, name: str) -> T:
        try:
            entry = self._entries[name]
        except KeyError:
            raise ConfigError(
                f"{self.key}: unknown {self.kind} {name!r}{suggest(name, self._entries)}"
            ) from None
        if isinstance(entry, _Lazy):
            entry = self._entries[name] = entry.load()
        return entry
