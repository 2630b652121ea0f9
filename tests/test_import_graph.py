"""The package's import graph has no cycle, and its functions stay short.

Every module under ``src/jointwear`` is parsed with :mod:`ast` (nothing is
imported). An edge A -> B is any ``import`` of B in A: at the top, inside a
function (a lazy import still runs, only later) or in a class body; only imports
under ``if TYPE_CHECKING:`` are left out, because they never run. Importing
``jointwear.a.b`` also runs the package ``jointwear.a``'s ``__init__``, so that edge
counts too (the root package's ``__init__`` imports only inside ``__getattr__`` and
``run``/``models``, the public entry points, and is the one node left out as a
target of that implicit edge).

There is no exception list: a cycle is a design fault to fix, not to record.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "jointwear"

#: compiled kernels may be long: one loop the compiler sees whole
COMPILED_DECORATORS = ("njit", "jit", "vectorize", "guvectorize")

#: the longest function body a reader should have to hold in mind [lines, docstring excluded]
MAX_FUNCTION_LINES = 80


def module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


MODULES = {module_name(path): path for path in sorted(PACKAGE.rglob("*.py"))}


def type_checking_nodes(tree: ast.AST) -> set[int]:
    """ids of the nodes under ``if TYPE_CHECKING:`` (never executed)."""
    skipped: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            for statement in node.body:
                skipped.update(id(child) for child in ast.walk(statement))
    return skipped


def resolve(name: str) -> str | None:
    """The jointwear module an import of ``name`` loads (a name inside a module maps to it)."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


def imported_modules(module: str, path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
    skipped = type_checking_nodes(tree)
    targets: set[str] = set()
    for node in ast.walk(tree):
        if id(node) in skipped:
            continue
        if isinstance(node, ast.Import):
            targets.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            targets.update(f"{node.module}.{alias.name}" for alias in node.names)
    found = {resolve(t) for t in targets if t.split(".")[0] == "jointwear"}
    edges = set()
    for target in found - {None, module}:
        edges.add(target)
        parts = target.split(".")
        # the packages a submodule import runs first (the root's __init__ is lazy)
        edges.update(".".join(parts[:k]) for k in range(2, len(parts)))
    return {e for e in edges if e != module and not module.startswith(e + ".")}


GRAPH = {module: imported_modules(module, path) for module, path in MODULES.items()}


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(sorted(graph.get(root, ()))))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def test_the_graph_sees_lazy_imports_and_packages() -> None:
    """The parser finds imports inside functions and the package ``__init__`` they run."""
    assert len(GRAPH) > 50
    # `jointwear models` reads the registries inside the function
    assert "jointwear.contact" in GRAPH["jointwear"]
    assert any("jointwear.contact" in targets for name, targets in GRAPH.items() if ".cli" in name)


@pytest.mark.parametrize(
    ("graph", "expected"),
    [
        ({"a": {"b"}, "b": {"c"}, "c": set()}, []),
        ({"a": {"b"}, "b": {"c"}, "c": {"a"}}, [["a", "b", "c"]]),
        ({"a": {"b"}, "b": {"a"}, "c": {"c"}, "d": {"a"}}, [["a", "b"]]),
    ],
)
def test_the_cycle_finder_finds_cycles(graph: dict[str, set[str]], expected: list) -> None:
    assert cycles(graph) == expected


def test_the_import_graph_is_acyclic() -> None:
    found = cycles(GRAPH)
    assert not found, "import cycles (a lazy import counts; break them, do not record them): " + (
        "; ".join(" <-> ".join(c) for c in found)
    )


def body_lines(function: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    lines = function.end_lineno - function.lineno + 1
    first = function.body[0]
    docstring = isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant)
    if docstring and isinstance(first.value.value, str):
        lines -= first.end_lineno - first.lineno + 1
    return lines


def is_compiled(function: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    names = {
        ast.unparse(d.func if isinstance(d, ast.Call) else d).split(".")[-1]
        for d in function.decorator_list
    }
    return bool(names & set(COMPILED_DECORATORS))


def test_no_function_is_longer_than_a_screen() -> None:
    long = []
    for module, path in MODULES.items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            function = isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef)
            if function and not is_compiled(node) and body_lines(node) > MAX_FUNCTION_LINES:
                long.append(f"{module}.{node.name}: {body_lines(node)} lines")
    assert not long, f"functions over {MAX_FUNCTION_LINES} lines (docstring excluded): {long}"


def test_no_module_edits_the_interpreter_s_module_table() -> None:
    """Library code never edits ``sys.modules``: import costs are solved where imports happen."""
    offenders = [
        f"{module}:{node.lineno}"
        for module, path in MODULES.items()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
        if isinstance(node, ast.Subscript) and ast.unparse(node.value) == "sys.modules"
    ]
    assert not offenders, offenders
