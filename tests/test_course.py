"""The package as a whole: its layers import one way, downwards, and without cycles.

``design.md``'s three layers: the algorithms (``course/*.py``), the apps and
checkers (``course/widgets``, ``course/check``), and the classroom
(``course/lessons``, ``course/classroom``, ``python -m course``). The
imports are read from the source (ast), at module level and inside
functions alike, so a deferred import cannot hide an upward dependency.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import course

PACKAGE = Path(course.__file__).resolve().parent
LAYERS = {"algorithms": 0, "apps and checkers": 1, "classroom": 2}


def module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {module_name(path): path for path in sorted(PACKAGE.rglob("*.py"))}


def layer(module: str) -> str:
    parts = module.split(".")
    if len(parts) == 1:
        return "algorithms"  # the package's __init__: a docstring and the version
    if parts[1] in ("widgets", "check"):
        return "apps and checkers"
    if parts[1] in ("classroom", "lessons", "__main__"):
        return "classroom"
    return "algorithms"


def course_imports(module: str) -> set[str]:
    """The course modules ``module`` imports, anywhere in its source."""
    tree = ast.parse(MODULES[module].read_text(encoding="utf-8"))
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            # "from course import dither" imports the module course.dither.
            names = [
                f"{node.module}.{alias.name}"
                if f"{node.module}.{alias.name}" in MODULES
                else node.module
                for alias in node.names
            ]
        else:
            continue
        found.update(name for name in names if name in MODULES and name != module)
    return found


GRAPH = {module: course_imports(module) for module in MODULES}


def test_the_three_layers_are_where_design_md_puts_them():
    by_layer = {name: [m for m in MODULES if layer(m) == name] for name in LAYERS}
    assert {"course.bezier", "course.raster", "course._validate"} <= set(by_layer["algorithms"])
    assert {"course.widgets.base", "course.check.base"} <= set(by_layer["apps and checkers"])
    assert {"course.classroom.registry", "course.lessons.l01_de_casteljau"} <= set(
        by_layer["classroom"]
    )


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_run_downwards_only(module):
    upward = [
        imported for imported in GRAPH[module] if LAYERS[layer(imported)] > LAYERS[layer(module)]
    ]
    assert not upward, f"{module} ({layer(module)}) imports from a layer above: {upward}"


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found = []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        for other in graph[node]:
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def test_no_module_imports_itself_through_others():
    assert cycles(GRAPH) == []


def test_the_checks_can_fail():
    """A made-up upward import and a made-up cycle are both caught."""
    assert layer("course.widgets.lines_and_triangles") == "apps and checkers"
    assert LAYERS[layer("course.classroom.pictures")] > LAYERS[layer("course.raster")]
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert "course.widgets.base" in GRAPH["course.widgets.lines_and_triangles"]
    assert "course.dither" in GRAPH["course.lessons.l06_dithering"]  # "from course import dither"
