"""DESIGN.md §1: data flows one way; a lower layer never imports a higher one."""

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).parents[1] / "src" / "taut"

#: Layer of each top-level module of taut; a module may import its own layer and below.
LAYERS = {
    "errors": 0,
    "geometry": 0,
    "interval": 0,
    "model": 1,
    "parallel": 1,
    "kinematics": 2,
    "statics": 3,
    "collision": 4,
    "wrapping": 4,
    "dgp": 4,
    "planning": 4,
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
