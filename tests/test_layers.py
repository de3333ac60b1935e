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
        "from taut.kinematics._inverse import _x, anchors_at\n"
        "from taut.interval import _kernels as K\n"
        "import taut.geometry._rotation\n"
        "from taut.statics._wrench import _own\n"
        "K._y, K.add, K.__name__, taut.geometry._rotation._z\n"
    )
    assert list(_private_uses("taut.statics._wrench", source)) == [
        ("taut.kinematics._inverse", "_x"),
        ("taut.interval._kernels", "_y"),
        ("taut.geometry._rotation", "_z"),
    ]


ROOT = SRC.parents[1]
USERS = sorted([*(ROOT / "tests").rglob("*.py"), *(ROOT / "benchmarks").glob("*.py")])


@pytest.mark.parametrize("path", USERS, ids=[str(p.relative_to(ROOT)) for p in USERS])
def test_tests_and_benchmarks_use_no_private_name(path):
    """Tests and benchmarks use taut as its users do: through public names only."""
    used = sorted({f"{m}.{n}" for m, n in _private_uses("", path.read_text())})
    assert not used, f"{path.relative_to(ROOT)} uses private names of taut: {used}"
