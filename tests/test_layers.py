"""docs/architecture.md §1: data flows one way; a lower layer never imports a higher one."""

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).parents[1] / "src" / "taut"

#: Layer of each top-level module of taut; a module may import its own layer and below.
LAYERS = {
    "errors": 0,
    "lazy": 0,
    "geometry": 0,
    "interval": 0,
    "model": 1,
    "parallel": 1,
    "kinematics": 2,
    "motion": 2,
    "statics": 3,
    "collision": 4,
    "wrapping": 4,
    "dgp": 4,
    "planning": 4,
    "dynamics": 4,
    "workspace": 5,
    "atlas": 6,
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


def _is_module(dotted: str) -> bool:
    path = SRC.parent.joinpath(*dotted.split("."))
    return path.with_suffix(".py").exists() or (path / "__init__.py").exists()


def _private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def _module_name(path: Path) -> str:
    return "taut." + ".".join(path.relative_to(SRC).with_suffix("").parts)


def _private_uses(own: str, source: str):
    """``(module, name)`` for every private name of another taut module that the module
    ``own`` uses in ``source``: ``from taut.x import _name``, and ``m._name`` after
    ``import taut.x as m`` or ``from taut.pkg import x as m``."""
    tree = ast.parse(source)
    aliases = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("taut"):
            for alias in node.names:
                if _private(alias.name) and node.module != own:
                    yield node.module, alias.name
                if _is_module(f"{node.module}.{alias.name}"):
                    aliases[alias.asname or alias.name] = f"{node.module}.{alias.name}"
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("taut.") and alias.asname:
                    aliases[alias.asname] = alias.name
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and _private(node.attr):
            target = node.value
            if isinstance(target, ast.Name) and target.id in aliases and aliases[target.id] != own:
                yield aliases[target.id], node.attr
            elif isinstance(target, ast.Attribute) and ast.unparse(target).startswith("taut."):
                yield ast.unparse(target), node.attr


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(SRC)) for p in FILES])
def test_no_private_name_across_modules(path):
    used = sorted({f"{m}.{n}" for m, n in _private_uses(_module_name(path), path.read_text())})
    assert not used, f"{path.relative_to(SRC)} uses private names of other modules: {used}"


def test_private_use_is_detected():
    source = (
        "from taut.kinematics.inverse import _x, anchors_at\n"
        "from taut.interval import kernels as K\n"
        "import taut.geometry.rotation\n"
        "from taut.statics.wrench import _own\n"
        "K._y, K.add, K.__name__, taut.geometry.rotation._z\n"
    )
    assert list(_private_uses("taut.statics.wrench", source)) == [
        ("taut.kinematics.inverse", "_x"),
        ("taut.interval.kernels", "_y"),
        ("taut.geometry.rotation", "_z"),
    ]


ROOT = SRC.parents[1]
USERS = sorted([*(ROOT / "tests").rglob("*.py"), *(ROOT / "benchmarks").glob("*.py")])


@pytest.mark.parametrize("path", USERS, ids=[str(p.relative_to(ROOT)) for p in USERS])
def test_tests_and_benchmarks_use_no_private_name(path):
    """Tests and benchmarks use taut as its users do: through public names only."""
    used = sorted({f"{m}.{n}" for m, n in _private_uses("", path.read_text())})
    assert not used, f"{path.relative_to(ROOT)} uses private names of taut: {used}"


#: What a viz module may import at run time (§1, the row of viz): the robot and the geometry
#: of a pose.  The results it draws come in as arguments; their classes are named in
#: annotations only, imported under ``if TYPE_CHECKING:``.  So viz cannot run a solver.
VIZ_RUNTIME = {"errors", "geometry", "model", "kinematics", "viz"}


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
