"""Registries: unknown names get the best match; lazy ``"module:attr"`` entries are
imported on first use and fail with one line naming the key and the entry."""

from __future__ import annotations

import math

import pytest

from jointwear.errors import ConfigError
from jointwear.registry import Lazy, Registry, resolve


@pytest.fixture
def registry() -> Registry:
    models = Registry("contact model", "contact.model")
    models.add("winkler", math.sqrt)
    models.add_lazy("nlcp", "jointwear.contact.nlcp:spring_law")
    return models


def test_an_unknown_name_gets_the_best_match(registry: Registry) -> None:
    with pytest.raises(ConfigError) as info:
        registry.get("nlpc")
    assert str(info.value) == "contact.model: unknown contact model 'nlpc'; did you mean 'nlcp'?"
    with pytest.raises(ConfigError) as info:
        registry.get("xyz")
    assert str(info.value).endswith("; choose from 'winkler', 'nlcp'")


def test_a_lazy_entry_is_the_object_it_names(registry: Registry) -> None:
    from jointwear.contact import nlcp

    assert registry.names() == ["winkler", "nlcp"]
    assert "nlcp" in registry
    assert registry.get("nlcp") is nlcp.spring_law
    assert dict(registry.items()) == {"winkler": math.sqrt, "nlcp": nlcp.spring_law}


def test_a_lazy_entry_is_called_as_the_function_it_names() -> None:
    assert Lazy("math:hypot", "key")(3.0, 4.0) == 5.0
    assert resolve("os:path.join", "key")("a", "b").replace("\\", "/") == "a/b"


@pytest.mark.parametrize(
    ("target", "message"),
    [
        (
            "jointwear.contact.nlcp:spring_lw",
            "contact.model: the registry entry 'jointwear.contact.nlcp:spring_lw' names "
            "'spring_lw', which 'jointwear.contact.nlcp' does not have",
        ),
        (
            "jointwear.contact.nlpc:spring_law",
            "contact.model: the registry entry 'jointwear.contact.nlpc:spring_law' names "
            "module 'jointwear.contact.nlpc', which does not exist",
        ),
        (
            "jointwear.contact.nlcp.spring_law",
            "contact.model: the registry entry 'jointwear.contact.nlcp.spring_law' is not "
            "'module:attribute'",
        ),
    ],
)
def test_a_lazy_entry_that_points_nowhere_is_one_line(
    registry: Registry, target: str, message: str
) -> None:
    registry.add_lazy("broken", target)
    with pytest.raises(ConfigError) as info:
        registry.get("broken")
    assert str(info.value) == message


def test_a_module_that_fails_its_own_import_is_not_taken_for_a_missing_entry(
    tmp_path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "plugin_with_a_missing_dependency.py").write_text(
        "import no_such_dependency_here\n", encoding="utf-8"
    )
    monkeypatch.syspath_prepend(str(tmp_path))
    with pytest.raises(ModuleNotFoundError, match="no_such_dependency_here"):
        resolve("plugin_with_a_missing_dependency:law", "wear.law")
