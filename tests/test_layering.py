"""The package's layers: data flows one way, private names stay in their module.

Every module under ``src/jointwear`` is parsed with :mod:`ast` (nothing is
imported), and every ``import``/``from ... import`` in it -- at the top, inside
functions (lazy) or under ``TYPE_CHECKING`` -- is checked against three rules:

(a) no private name (``_name``) is imported from another module, and a private
    module (``jointwear.x._mod``) only from inside its own package;
(b) :mod:`jointwear.paper` (the reproduction of the paper) is imported only by
    itself and by the command line;
(c) imports follow the data flow: a module imports only from its own layer or
    layers below it (:data:`LAYERS`).

There is no exception list: an import against a rule is fixed (promote the name,
move the caller or the module), never recorded.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "jointwear"

#: the layers, lowest first: a module is in the layer of the longest prefix that names it.
#: The pipeline (paper Fig. 7) is mechanism -> contact -> tribology -> geometry update ->
#: simulation; the results and plots present a simulation, the analyses run many, the
#: paper's reproduction uses all of them, and the command line sits on top.
LAYERS: tuple[tuple[str, tuple[str, ...]], ...] = (
    (
        "foundation",
        (
            "jointwear.errors",
            "jointwear.version",
            # pint's conversions of quantity texts remembered between processes
            "jointwear.quantity_memo",
            "jointwear.units",
            "jointwear.registry",
            "jointwear.tables",
            # signals as one exception (standard library only), used by io and the CLI
            "jointwear.interrupts",
            "jointwear.io",
            "jointwear.solvers",
            # numba's compile time in this process (imports numba only when asked)
            "jointwear.compile_time",
            "jointwear.state",
            # the materials library: named materials that configs refer to
            "jointwear.materials",
            # the configuration (imports no physics: the stages' names and checks are
            # lazy "module:attr" registry entries, jointwear.config.choices)
            "jointwear.config",
            # memory and time budgets checked before a run or sweep starts
            "jointwear.resources",
            # the bushing contour and the pin: the data every stage works on
            "jointwear.geometry",
        ),
    ),
    ("mechanism", ("jointwear.mechanism",)),
    # film and asperity forces of a lubricated joint: what the contact stage will share
    ("lubrication", ("jointwear.lubrication",)),
    # the exact and finite-element references are contact models (and registered as such);
    # the mechanism stage's entry from a Config hands the contact-impact force laws the
    # contact models' elastic laws
    ("contact", ("jointwear.contact", "jointwear.references", "jointwear.mechanism.stage")),
    ("tribology", ("jointwear.tribology",)),
    ("geometry update", ("jointwear.geometry.update",)),
    # the loop's schedule (cycle jumping, dynamics re-solves, life limits) and the plain
    # record the loop fills
    ("schedule", ("jointwear.coupling", "jointwear.record")),
    # a record presented: Dataset, summary, files, plots, text
    # (plots_axial: the wear maps of a result cut into slices along the pin)
    (
        "results",
        ("jointwear.results", "jointwear.plots", "jointwear.plots_axial", "jointwear.display"),
    ),
    # the one loop over revolutions returns its record presented (a WearResult); the
    # checkpoints save and resume that loop
    ("simulation", ("jointwear.simulation", "jointwear.checkpoint")),
    (
        "analyses",
        (
            "jointwear.measurement",
            "jointwear.references.compare",
            "jointwear.references.spring_fit",
            # runs the simulation against the exact references (the Validation page)
            "jointwear.references.validation",
            # a run to a folder, sweeps, life, calibration: many runs and their outputs
            "jointwear.workflows",
        ),
    ),
    ("paper", ("jointwear.paper",)),
    ("command line", ("jointwear.cli", "jointwear.__main__", "jointwear")),
)


@dataclass(frozen=True)
class Import:
    """One imported module (and, for ``from`` imports, one name) at one place."""

    importer: str
    module: str
    name: str | None
    where: str


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def is_package(module: str) -> bool:
    return (PACKAGE.parent / module.replace(".", "/") / "__init__.py").exists()


def is_module(module: str) -> bool:
    return (PACKAGE.parent / f"{module.replace('.', '/')}.py").exists()


def imports() -> list[Import]:
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        importer = module_name(path)
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            where = f"{path.relative_to(PACKAGE.parent)}:{getattr(node, 'lineno', 0)}"
            if isinstance(node, ast.Import):
                found += [
                    Import(importer, alias.name, None, where)
                    for alias in node.names
                    if alias.name.split(".")[0] == "jointwear"
                ]
            elif isinstance(node, ast.ImportFrom) and node.level:
                raise AssertionError(f"{where}: relative import; write the absolute module")
            elif isinstance(node, ast.ImportFrom) and (node.module or "").split(".")[0] == (
                "jointwear"
            ):
                for alias in node.names:
                    submodule = f"{node.module}.{alias.name}"
                    if is_package(submodule) or is_module(submodule):
                        # ``from jointwear.contact import nlcp``: the module is imported
                        found.append(Import(importer, submodule, None, where))
                    else:
                        found.append(Import(importer, node.module, alias.name, where))
    return found


def layer(module: str) -> int:
    best, rank = -1, -1
    for index, (_, prefixes) in enumerate(LAYERS):
        for prefix in prefixes:
            if (module == prefix or module.startswith(prefix + ".")) and len(prefix) > best:
                best, rank = len(prefix), index
    assert rank >= 0, f"{module}: in no layer; add it to LAYERS"
    return rank


ALL = imports()


def test_the_parser_sees_the_imports() -> None:
    """The rules below see real imports (a parser that found none would pass them all)."""
    assert len({i.importer for i in ALL}) > 50
    assert any(
        (i.importer, i.module, i.name)
        == ("jointwear.paper.reproduce", "jointwear.paper.cases", "case_config")
        for i in ALL
    )
    # lazy imports inside functions count too
    assert any(
        i.importer == "jointwear.cli.reproduce_cmd" and i.module == "jointwear.paper.reproduce"
        for i in ALL
    )


def private_violations() -> dict[tuple[str, str], list[str]]:
    found: dict[tuple[str, str], list[str]] = {}
    for i in ALL:
        private_name = i.name is not None and i.name.startswith("_") and i.name != "__version__"
        if private_name and i.module != i.importer:
            found.setdefault((i.importer, i.module), []).append(f"{i.where}: {i.name}")
        private_parts = [p for p in i.module.split(".") if p.startswith("_") and p != "__main__"]
        if private_parts:
            owner = i.module.split("." + private_parts[0])[0]
            if not (i.importer == owner or i.importer.startswith(owner + ".")):
                found.setdefault((i.importer, i.module), []).append(f"{i.where}: {i.module}")
    return found


def test_no_private_name_is_imported_from_another_module() -> None:
    found = private_violations()
    assert not found, (
        "private names imported across modules (make them public, with a docstring and "
        f"units, or move the caller): {found}"
    )


def test_the_paper_is_imported_only_by_itself_and_the_command_line() -> None:
    def inside(module: str, package: str) -> bool:
        return module == package or module.startswith(package + ".")

    offenders = [
        f"{i.where}: {i.module}"
        for i in ALL
        if inside(i.module, "jointwear.paper")
        and not inside(i.importer, "jointwear.paper")
        and not inside(i.importer, "jointwear.cli")
    ]
    assert not offenders, offenders


def layer_violations() -> dict[tuple[str, str], list[str]]:
    found: dict[tuple[str, str], list[str]] = {}
    for i in ALL:
        if i.module == "jointwear":  # ``from jointwear import __version__``
            continue
        if layer(i.module) > layer(i.importer):
            found.setdefault((i.importer, i.module), []).append(
                f"{i.where} ({LAYERS[layer(i.importer)][0]} imports {LAYERS[layer(i.module)][0]})"
            )
    return found


def test_imports_follow_the_data_flow() -> None:
    found = layer_violations()
    assert not found, f"imports against the layer order (see LAYERS): {found}"


@pytest.mark.parametrize(
    ("importer", "module", "allowed"),
    [
        ("jointwear.contact.nlcp", "jointwear.geometry.contour", True),
        ("jointwear.mechanism.slider_crank", "jointwear.geometry.update", False),
        ("jointwear.mechanism.slider_crank", "jointwear.simulation", False),
        ("jointwear.contact.hertz", "jointwear.tribology.archard", False),
        ("jointwear.references.compare", "jointwear.plots", True),
        ("jointwear.references.fem", "jointwear.plots", False),
        ("jointwear.measurement.compare", "jointwear.paper.cases", False),
        ("jointwear.cli.reproduce_cmd", "jointwear.paper.reproduce", True),
    ],
)
def test_the_layer_order_says_what_the_architecture_says(
    importer: str, module: str, allowed: bool
) -> None:
    assert (layer(module) <= layer(importer)) == allowed
