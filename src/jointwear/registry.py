"""Registries of named models (pvlib's pattern: a model is a name or a callable).

An entry is an object, or a :class:`Lazy` ``"module:attr"`` string that
:mod:`importlib` imports when the entry is first used. A module that names a
function of another this way does not import it: the configuration validates the
stages' choices and takes their closed-form defaults so (:mod:`jointwear.config.choices`)
and stays below them in the layers.
"""

from __future__ import annotations

import difflib
import importlib
from collections.abc import Callable, Iterable
from typing import Any, Generic, TypeVar

from jointwear.errors import ConfigError

__all__ = ["Lazy", "Registry", "resolve", "suggest"]

T = TypeVar("T")


def suggest(name: str, options: Iterable[str]) -> str:
    """Return ``"; did you mean 'x'?"`` for the closest option, or a list of options."""
    options = list(options)
    close = difflib.get_close_matches(str(name), options, n=1, cutoff=0.5)
    if close:
        return f"; did you mean {close[0]!r}?"
    return f"; choose from {', '.join(repr(o) for o in options)}"


def resolve(target: str, key: str) -> Any:
    """The object a ``"module:attr"`` string names (``attr`` may be dotted).

    Parameters
    ----------
    target : str
        ``"jointwear.contact.nlcp:stiffness"``: a module and an attribute of it.
    key : str
        The config key the entry serves, to start the message with.

    Raises
    ------
    ConfigError
        One line naming ``key`` and ``target`` if the module cannot be found or lacks
        the attribute (an entry that points nowhere, not a physics failure).
    """
    module_name, sep, attribute = target.partition(":")
    if not sep or not module_name or not attribute:
        raise ConfigError(f"{key}: the registry entry {target!r} is not 'module:attribute'")
    try:
        found: Any = importlib.import_module(module_name)
    except ModuleNotFoundError as exc:
        if exc.name is None or not (module_name + ".").startswith(exc.name + "."):
            raise  # the module is there but one of its own imports is missing
        raise ConfigError(
            f"{key}: the registry entry {target!r} names module {module_name!r}, "
            "which does not exist"
        ) from None
    for part in attribute.split("."):
        try:
            found = getattr(found, part)
        except AttributeError:
            raise ConfigError(
                f"{key}: the registry entry {target!r} names {attribute!r}, "
                f"which {module_name!r} does not have"
            ) from None
    return found


class Lazy:
    """A registry entry named by ``"module:attr"``, imported when first used.

    Calling it calls the object it names.

    Parameters
    ----------
    target : str
        ``"module:attr"``, e.g. ``"jointwear.mechanism.four_bar.geometry:check_four_bar"``.
    key : str
        The config key the entry serves (its errors start with it).
    """

    def __init__(self, target: str, key: str) -> None:
        self.target = target
        self.key = key
        self._object: Any = None
        self._resolved = False

    def resolve(self) -> Any:
        """The object the entry names (imported on the first call, :func:`resolve`)."""
        if not self._resolved:
            self._object = resolve(self.target, self.key)
            self._resolved = True
        return self._object

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        return self.resolve()(*args, **kwargs)

    def __repr__(self) -> str:
        return f"Lazy({self.target!r})"


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
        self._entries: dict[str, T | Lazy] = {}

    def register(self, name: str) -> Callable[[T], T]:
        def decorator(obj: T) -> T:
            self._entries[name] = obj
            return obj

        return decorator

    def add(self, name: str, obj: T) -> None:
        self._entries[name] = obj

    def add_lazy(self, name: str, target: str) -> None:
        """Register the object ``"module:attr"`` names; it is imported by :meth:`get`."""
        self._entries[name] = Lazy(target, self.key)

    def __contains__(self, name: object) -> bool:
        return name in self._entries

    def __iter__(self):
        return iter(self._entries)

    def items(self):
        return {name: self.get(name) for name in self._entries}.items()

    def names(self) -> list[str]:
        return list(self._entries)

    def get(self, name: str) -> T:
        try:
            entry = self._entries[name]
        except KeyError:
            raise ConfigError(
                f"{self.key}: unknown {self.kind} {name!r}{suggest(name, self._entries)}"
            ) from None
        if isinstance(entry, Lazy):
            entry = self._entries[name] = entry.resolve()
        return entry
