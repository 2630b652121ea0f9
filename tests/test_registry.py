"""Registries: unknown names get the best match; lazy ``"module:attr"`` entries are
imported on first use and fail with one line naming the key and the entry."""

from __future__ import annotations

import math
import subprocess
import sys

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


def test_a_lazy_entry_is_imported_when_first_asked_for(tmp_path, monkeypatch) -> None:
    (tmp_path / "lazy_models_for_test.py").write_text("def model(x):\n    return 2 * x\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    registry: Registry = Registry("thing", "section.thing")
    registry.add("eager", len)
    registry.add_lazy("lazy", "lazy_models_for_test:model")
    assert registry.names() == ["eager", "lazy"]
    assert "lazy" in registry
    assert "lazy_models_for_test" not in sys.modules
    assert registry.get("lazy")(21) == 42
    assert "lazy_models_for_test" in sys.modules
    assert dict(registry.items())["lazy"] is registry.get("lazy")
    with pytest.raises(ConfigError, match="^section.thing: unknown thing 'lazzy'; did you mean"):
        registry.get("lazzy")
    monkeypatch.delitem(sys.modules, "lazy_models_for_test")


def test_the_contact_package_names_the_references_without_importing_them() -> None:
    """The references import the contact package; it must not import them back (a cycle)."""
    code = (
        "import sys\n"
        "from jointwear.contact import CONTACT_MODELS, ContactParameters\n"
        "assert not [m for m in sys.modules if m.startswith('jointwear.references')]\n"
        "p = ContactParameters(7.45e-3, 7.5e-3, 0.02, 3e-3, 2.09e11, 0.28, 5e8, 0.38)\n"
        "assert type(CONTACT_MODELS.get('persson')(p)).__name__ == 'PerssonModel'\n"
        "assert type(CONTACT_MODELS.get('fem')(p)).__name__ == 'FemModel'\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
