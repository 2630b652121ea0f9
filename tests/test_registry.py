"""Named registries: entries named by ``"module:attribute"`` are imported when first used."""

from __future__ import annotations

import subprocess
import sys

import pytest

from jointwear.errors import ConfigError
from jointwear.registry import Registry


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
