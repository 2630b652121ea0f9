"""docs/bad-input.md is the rendering of this suite: it must not drift from the cases."""

from __future__ import annotations

from tests.hostile import catalogue


def test_page_is_up_to_date():
    """docs/bad-input.md equals what python -m tests.hostile.catalogue writes."""
    current = catalogue.PAGE.read_text(encoding="utf-8")
    assert current == catalogue.page(), (
        "docs/bad-input.md is out of date with tests/hostile/; "
        "regenerate it with `python -m tests.hostile.catalogue`"
    )


def test_every_case_and_area_is_on_the_page():
    """Each case id appears once on the page, under the section of its area."""
    cases, free = catalogue.collect(catalogue.modules())
    text = catalogue.render(cases, free)
    sections = text.split("\n### ")
    for case in cases:
        section = catalogue.AREAS[case.area]
        holding = [s for s in sections if f"| `{case.id}` |" in s]
        assert len(holding) == 1, case.id
        assert holding[0].startswith(section + "\n"), (case.id, section)
    assert len(cases) >= 150
    assert all(test.doc for test in free)


def test_a_duplicate_id_is_refused():
    """Two cases with one id cannot be catalogued (ids name the rows and the tests)."""
    import pytest

    from tests.hostile.harness import Bad

    twice = [Bad("same", "numbers", ["run"], ["x"]), Bad("same", "units", ["run"], ["y"])]

    class Module:
        __name__ = "tests.hostile.test_twice"
        CASES = twice

    with pytest.raises(ValueError, match="case ids used twice: same"):
        catalogue.collect([Module])  # type: ignore[list-item]
