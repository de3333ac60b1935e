"""docs/architecture.md §1: data flows one way; a lower layer never imports a higher one."""

import ast
import importlib
from pathlib import Path

import pytest

SRC = Path(__file__).parents[1] / "src" / "taut"

#: Layer of each top-level module of taut; a module may import its own layer and below.
LAYERS = {
    "errors": 0,
    "_lazy": 0,
    "_results": 0,
    "_checks": 0,
    "geometry": 0,
    "interval": 0,
    "model": 1,
    "parallel": 1,
    "kinematics": 2,
    "cables": 3,
    "motion": 2,
    "statics": 3,
    "collision": 4,
    "wrapping": 4,
    "dgp": 4,
    "planning": 4,
    "dynamics": 4,
    "workspace": 5,
    "atlas": 6,
    "calibration": 6,
    "viz": 7,
    "demo": 8,
    "cli": 9,
    "__main__": 10,
}


def _top(path: Path) -> str:
    rel = path.relative_to(SRC)
    return rel.parts[0].removesuffix(".py")


def _imports(path: Path):
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("taut."):
            yield node.module.split(".")[1]
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("taut."):
                    yield alias.name.split(".")[1]


FILES = [p for p in sorted(SRC.rglob("*.py")) if _top(p) != "__init__"]


def test_every_module_has_a_layer():
    assert {_top(p) for p in FILES} <= set(LAYERS)


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(SRC)) for p in FILES])
def test_no_upward_import(path):
    own = LAYERS[_top(path)]
    upward = sorted({m for m in _imports(path) if LAYERS[m] > own})
    assert not upward, f"{path.relative_to(SRC)} (layer {own}) imports {upward}"


def _package(path: Path) -> str | None:
    """The package a source file belongs to (``kinematics``), or None for a top-level module."""
    rel = path.relative_to(SRC)
    return rel.parts[0] if len(rel.parts) > 1 else None


def _private_module(dotted: str) -> str | None:
    """``taut.PKG`` when ``dotted`` names a private module of package PKG (``taut.PKG._x``)."""
    parts = dotted.split(".")
    if len(parts) >= 3 and parts[0] == "taut" and parts[2].startswith("_") and not parts[2].startswith("__"):
        return ".".join(parts[:2])
    return None


def _private_imports(source: str):
    """Every private module of a taut package that ``source`` imports, with the import's line:
    ``from taut.pkg._x import y``, ``import taut.pkg._x`` and ``from taut.pkg import _x``."""
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("taut"):
            if _private_module(node.module):
                yield node.lineno, node.module
                continue
            for alias in node.names:
                if _private_module(f"{node.module}.{alias.name}"):
                    yield node.lineno, f"{node.module}.{alias.name}"
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if _private_module(alias.name):
                    yield node.lineno, alias.name


PACKAGE_FILES = [p for p in FILES if _package(p) is not None]


@pytest.mark.parametrize("path", PACKAGE_FILES, ids=[str(p.relative_to(SRC)) for p in PACKAGE_FILES])
def test_modules_inside_packages_are_private(path):
    """docs/architecture.md §2.7: a package's API is its ``__all__``; its modules are private."""
    assert path.name.startswith("_"), f"{path.relative_to(SRC)}: a module inside a package is private (_name.py)"


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(SRC)) for p in FILES])
def test_no_private_module_of_another_package(path):
    own = _package(path)
    used = sorted(
        {f"{line}: {m}" for line, m in _private_imports(path.read_text()) if _private_module(m) != f"taut.{own}"}
    )
    assert not used, f"{path.relative_to(SRC)} imports private modules of other packages: {used}"


def test_private_import_is_detected():
    source = (
        "from taut.kinematics._inverse import anchors_at\n"
        "from taut.interval import _kernels as K\n"
        "import taut.geometry._rotation\n"
        "from taut.statics import distribute_tensions\n"
        "from taut.errors import TautError\n"
    )
    assert [m for _, m in _private_imports(source)] == [
        "taut.kinematics._inverse",
        "taut.interval._kernels",
        "taut.geometry._rotation",
    ]


ROOT = SRC.parents[1]
USERS = sorted([*(ROOT / "tests").rglob("*.py"), *(ROOT / "benchmarks").glob("*.py")])


def _tested_package(path: Path) -> str | None:
    """The package whose tests ``path`` holds (``tests/kinematics/…`` → ``taut.kinematics``)."""
    rel = path.relative_to(ROOT)
    return f"taut.{rel.parts[1]}" if rel.parts[0] == "tests" and len(rel.parts) > 2 else None


@pytest.mark.parametrize("path", USERS, ids=[str(p.relative_to(ROOT)) for p in USERS])
def test_tests_and_benchmarks_use_the_public_api(path):
    """Benchmarks and the tests of other packages use taut as its users do, through each
    package's ``__all__``; a package's own tests may reach its private modules (kernels)."""
    own = _tested_package(path)
    used = sorted({f"{line}: {m}" for line, m in _private_imports(path.read_text()) if _private_module(m) != own})
    assert not used, f"{path.relative_to(ROOT)} imports private modules of taut: {used}"


PACKAGES = sorted({_package(p) for p in PACKAGE_FILES} - {None})


@pytest.mark.parametrize("package", PACKAGES)
def test_every_exported_name_exists(package):
    """Each name of a package's ``__all__`` resolves (the lazy re-exports point at real names)."""
    module = importlib.import_module(f"taut.{package}")
    missing = [name for name in module.__all__ if not hasattr(module, name)]
    assert not missing, f"taut.{package}.__all__ names what it does not define: {missing}"


def _module_of(path: Path) -> str:
    parts = list(path.relative_to(SRC.parent).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _type_checking_nodes(tree: ast.AST) -> set[int]:
    inside: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            inside.update(id(n) for n in ast.walk(node))
    return inside


def import_graph() -> dict[str, set[str]]:
    """Module → the taut modules it imports, at the top or inside functions (both are a
    dependency); imports under ``if TYPE_CHECKING:`` are annotations only and do not count."""
    modules = {_module_of(p): p for p in SRC.rglob("*.py")}

    def resolve(dotted: str) -> str | None:
        while dotted and dotted not in modules:
            dotted = dotted.rpartition(".")[0]
        return dotted or None

    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        tree = ast.parse(path.read_text())
        skip = _type_checking_nodes(tree)
        deps: set[str] = set()
        for node in ast.walk(tree):
            if id(node) in skip:
                continue
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("taut"):
                for alias in node.names:
                    target = resolve(f"{node.module}.{alias.name}")
                    deps.add(target) if target else None
            elif isinstance(node, ast.Import):
                deps.update(t for a in node.names if a.name.startswith("taut") and (t := resolve(a.name)))
        deps.discard(name)
        graph[name] = deps
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_no_import_cycles():
    assert cycles(import_graph()) == []


def test_cycles_are_detected():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": set()}
    assert cycles(graph) == [["a", "b", "c"]]


#: What a viz module may import at run time (§1, the row of viz): the robot and the geometry
#: of a pose, and layer 0's argument checks.  The results it draws come in as arguments;
#: their classes are named in annotations only, imported under ``if TYPE_CHECKING:``.  So
#: viz cannot run a solver.
VIZ_RUNTIME = {"_lazy", "_checks", "errors", "geometry", "model", "kinematics", "viz"}


def _is_type_checking(test: ast.expr) -> bool:
    return ast.unparse(test) in ("TYPE_CHECKING", "typing.TYPE_CHECKING")


def _runtime_imports(source: str):
    """``(line, taut module, names)`` of every import of taut in ``source`` that runs:
    module level and inside functions, not the body of ``if TYPE_CHECKING:``."""
    found = []

    def visit(node: ast.AST) -> None:
        if isinstance(node, ast.If) and _is_type_checking(node.test):
            for child in node.orelse:
                visit(child)
            return
        if isinstance(node, ast.ImportFrom) and node.module and node.module.split(".")[0] == "taut":
            found.append((node.lineno, node.module, [a.name for a in node.names]))
        elif isinstance(node, ast.Import):
            found.extend((node.lineno, a.name, []) for a in node.names if a.name.split(".")[0] == "taut")
        for child in ast.iter_child_nodes(node):
            visit(child)

    visit(ast.parse(source))
    return found


def _viz_violations(source: str) -> list[str]:
    bad = []
    for line, module, names in _runtime_imports(source):
        parts = module.split(".")
        if len(parts) == 1:  # ``from taut import __version__``: dunder names of the package only
            ok = bool(names) and all(n.startswith("__") for n in names)
        else:
            ok = parts[1] in VIZ_RUNTIME
        if not ok:
            bad.append(f"line {line}: {module} {names}")
    return bad


def test_viz_rule_is_detected():
    source = (
        "from typing import TYPE_CHECKING\n"
        "from taut.model import Robot\n"
        "from taut import __version__\n"
        "if TYPE_CHECKING:\n"
        "    from taut.dgp import DGPSolution\n"
        "else:\n"
        "    import taut.planning\n"
        "def f():\n"
        "    from taut.dgp import solve_dgp\n"
        "    from taut import example\n"
    )
    assert _viz_violations(source) == [
        "line 7: taut.planning []",
        "line 9: taut.dgp ['solve_dgp']",
        "line 10: taut ['example']",
    ]


VIZ = [p for p in FILES if _top(p) == "viz"]


@pytest.mark.parametrize("path", VIZ, ids=[str(p.relative_to(SRC)) for p in VIZ])
def test_viz_only_draws(path):
    """viz imports no solver, planner, simulation or atlas builder (§1): the demo and the
    command line compute, viz draws what they pass."""
    bad = _viz_violations(path.read_text())
    assert not bad, f"{path.relative_to(SRC)} imports at run time beyond {sorted(VIZ_RUNTIME)}: {bad}"
