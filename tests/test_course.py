"""The package as a whole: layers, imports and one vocabulary for the handout's forms.

``design.md``'s three layers: the algorithms (the topic packages ``course/<topic>/``
and the few shared modules at ``course/``'s root), the shared teaching machinery
(``course/widgets``, ``course/check``), and the lessons and classroom (the
chapters ``course/lessons/lNN_topic/``, ``course/classroom``, ``python -m course``). The
imports are read from the source (ast), at module level and inside
functions alike, so a deferred import cannot hide an upward dependency.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import json
import re
import sys
from pathlib import Path

import numpy as np
import pytest

import course
from course import filters, raster
from course.antialias import splats
from course.classroom.source import source_of
from course.curves import bezier
from course.halftone import dither
from course.poisson import solvers
from course.raster import triangles
from course.sampling import resample

PACKAGE = Path(course.__file__).resolve().parent
LAYERS = {"algorithms": 0, "shared teaching machinery": 1, "lessons and classroom": 2}


def module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {module_name(path): path for path in sorted(PACKAGE.rglob("*.py"))}


def layer(module: str) -> str:
    parts = module.split(".")
    if len(parts) == 1:
        return "algorithms"  # the package's __init__: a docstring and the version
    if parts[1] in ("widgets", "check"):
        return "shared teaching machinery"
    if parts[1] in ("classroom", "lessons", "__main__"):
        return "lessons and classroom"
    return "algorithms"


def course_imports(module: str) -> set[str]:
    """The course modules ``module`` imports, anywhere in its source."""
    tree = ast.parse(MODULES[module].read_text(encoding="utf-8"))
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            # "from course import dither" imports the module course.halftone.dither.
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
    assert {"course.curves.bezier", "course.raster", "course._validate"} <= set(
        by_layer["algorithms"]
    )
    assert {"course.widgets.base", "course.check.base"} <= set(
        by_layer["shared teaching machinery"]
    )
    assert {
        "course.classroom.registry",
        "course.lessons.l01_de_casteljau.lesson",
        "course.lessons.l01_de_casteljau.check",
        "course.lessons.l01_de_casteljau.apps",
    } <= set(by_layer["lessons and classroom"])


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
    assert layer("course.lessons.l03_lines_and_triangles.apps") == "lessons and classroom"
    assert LAYERS[layer("course.widgets.base")] > LAYERS[layer("course.raster")]
    assert LAYERS[layer("course.classroom.pictures")] > LAYERS[layer("course.raster")]
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert "course.widgets.base" in GRAPH["course.lessons.l03_lines_and_triangles.apps"]
    assert (
        "course.halftone.dither" in GRAPH["course.lessons.l06_dithering.lesson"]
    )  # "from course import dither"


# --- one vocabulary: the handout's form is method="loop" ----------------------

ALGORITHMS = sorted(m for m in MODULES if layer(m) == "algorithms" and m != "course")


def methods_tuples() -> dict[str, tuple[str, ...]]:
    """Every ``<FUNCTION>_METHODS`` tuple of the algorithm modules that has a "loop" form."""
    found = {}
    for module_name in ALGORITHMS:
        module = importlib.import_module(module_name)
        for name, value in vars(module).items():
            if name.endswith("_METHODS") and isinstance(value, tuple) and "loop" in value:
                function = getattr(module, name[: -len("_METHODS")].lower(), None)
                if getattr(function, "__module__", None) == module_name:  # not a re-export
                    found[f"{module_name}.{function.__name__}"] = value
    return found


FORMS = methods_tuples()


def dyadic(shape, seed=0, levels=256):
    """Values k / levels: sums and averages of them are exact in floating point."""
    return np.random.default_rng(seed).integers(0, levels + 1, shape) / levels


def run_sweeps(sweeps, count):
    return np.stack([next(sweeps).copy() for _ in range(count)])


def _poisson_arrays():
    values = dyadic((2, 7, 9), seed=4)
    region = np.zeros((7, 9), bool)
    region[1:-1, 1:-1] = True
    region[3, 2] = False
    return values, region, dyadic((2, 7, 9), seed=5) / 16


SPLAT_SAMPLES = np.random.default_rng(3).uniform(-5, 40, size=(300, 2))
# Each function with a loop form, called on the same inputs with a given method;
# the tolerance is 0 where the forms add the same numbers in the same order.
FORM_CASES = {
    "course.curves.bezier.bezier_bernstein": (
        lambda method: bezier.bezier_bernstein(dyadic((8, 2)) * 700, np.arange(17) / 16, method),
        1e-12,
    ),
    "course.raster.lines.line": (
        lambda method: np.concatenate([raster.line(p0, p1, method=method) for p0, p1 in LINE_ENDS]),
        0,
    ),
    "course.raster.triangles.triangle": (
        lambda method: np.concatenate(
            [
                triangles.triangle(*vertices, rule=rule, method=method)
                for vertices in TRIANGLES
                for rule in triangles.EDGE_RULES
            ]
        ),
        0,
    ),
    "course.sampling.resample.supersample": (
        lambda method: resample.supersample(dyadic((20, 30, 3)), (7, 9), 3, method),
        1e-12,
    ),
    "course.filters.convolution.blur": (lambda method: filters.blur(dyadic((9, 11, 3)), method), 0),
    "course.filters.convolution.sobel": (
        lambda method: np.stack(
            [filters.sobel(dyadic((9, 11)), border, method) for border in BORDERS_OF_SOBEL]
        ),
        0,
    ),
    "course.halftone.dither.ordered": (
        lambda method: dither.ordered(dyadic((9, 11), 1, 9), method),
        0,
    ),
    "course.halftone.diffusion.error_diffusion": (
        lambda method: dither.error_diffusion_values(dyadic((12, 17)), method=method),
        0,
    ),
    "course.antialias.splats.splat": (
        lambda method: [splats.splat(SPLAT_SAMPLES, kind, method=method) for kind in splats.SPLATS],
        1e-12,
    ),
    "course.poisson.solvers.jacobi_sweeps": (
        lambda method: run_sweeps(solvers.jacobi_sweeps(*_poisson_arrays(), method=method), 6),
        0,
    ),
    "course.poisson.solvers.sor_sweeps": (
        lambda method: run_sweeps(
            solvers.sor_sweeps(*_poisson_arrays(), omega=1.5, method=method), 6
        ),
        1e-14,
    ),
}
LINE_ENDS = [((3, 6), (27, 17)), ((27, 17), (3, 6)), ((5, 5), (5, -4)), ((0, 0), (-7, 3))]
TRIANGLES = [((0.5, 0.25), (9.75, 3.5), (2.25, 8.0)), ((0, 0), (4, 4), (0, 4))]
BORDERS_OF_SOBEL = ("replicate", "reflect", "zero")


def test_every_function_with_a_loop_form_is_proven_equal_to_its_other_forms():
    assert sorted(FORMS) == sorted(FORM_CASES)
    assert len(FORMS) >= 10


@pytest.mark.parametrize("function", sorted(FORM_CASES))
def test_the_loop_form_equals_the_default_on_the_same_inputs(function):
    call, tolerance = FORM_CASES[function]
    default = call(inspect.signature(resolve(function)).parameters["method"].default)
    for method in FORMS[function]:
        for got, expected in zip(as_list(call(method)), as_list(default), strict=True):
            if tolerance:
                np.testing.assert_allclose(got, expected, rtol=tolerance, atol=tolerance)
            else:
                np.testing.assert_array_equal(got, expected)


def resolve(dotted: str):
    module, name = dotted.rsplit(".", 1)
    return getattr(importlib.import_module(module), name)


def as_list(result):
    """A result as a flat list of arrays (splats give (pixels, weights) per kind)."""
    if isinstance(result, list):
        return [array for pair in result for array in pair]
    return [result]


@pytest.mark.parametrize("function", sorted(FORMS))
def test_each_form_lives_in_its_module_under_the_convention_name(function):
    """``f(..., method=m)`` runs ``_f_m``: where ``source_of`` and a newcomer find a form."""
    module_name, name = function.rsplit(".", 1)
    module = importlib.import_module(module_name)
    for method in FORMS[function]:
        assert callable(getattr(module, f"_{name}_{method}", None)), f"_{name}_{method}"
        assert source_of(resolve(function), method).startswith(f"def _{name}_{method}(")
    # The handout's form is "loop"; the others are named for their technique.
    assert not {"fast", "naive", "scanline", "vectorised"} & set(FORMS[function])


# --- public names only across modules, and in the notebooks ---------------------

NOTEBOOKS = sorted((PACKAGE.parent / "notebooks").glob("*.ipynb"))


def private_imports(tree: ast.AST) -> list[str]:
    """Names imported with a leading underscore (``from x import _y``), and dunder reaches.

    gettext's ``_`` from course.i18n is public: the name every extractor looks for.
    """
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            found += [
                alias.name
                for alias in node.names
                if alias.name.startswith("_")
                and not (node.module == "course.i18n" and alias.name == "_")
            ]
        if isinstance(node, ast.Attribute) and node.attr == "__globals__":
            found.append("__globals__")
    return found


@pytest.mark.parametrize("module", sorted(MODULES))
def test_no_module_imports_another_module_s_private_names(module):
    tree = ast.parse(MODULES[module].read_text(encoding="utf-8"))
    assert not private_imports(tree), f"{module} imports {private_imports(tree)}"


def notebook_code(path: Path) -> ast.AST:
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    lines = [
        line
        for cell in cells
        if cell["cell_type"] == "code"
        for line in "".join(cell["source"]).splitlines()
        if not line.lstrip().startswith(("%", "!"))  # IPython magics
    ]
    return ast.parse("\n".join(lines))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda path: path.stem)
def test_notebooks_use_public_names_only(path):
    tree = notebook_code(path)
    private = private_imports(tree)
    for node in ast.walk(tree):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            modules = [alias.name for alias in node.names] if isinstance(node, ast.Import) else []
            modules.append(getattr(node, "module", None) or "")
            private += [name for name in modules if any(p.startswith("_") for p in name.split("."))]
        if isinstance(node, ast.Attribute) and node.attr.startswith("_"):
            if not (node.attr.startswith("__") and node.attr.endswith("__")):
                private.append(node.attr)
    assert not private, f"{path.name} reaches private names: {private}"


def test_the_private_name_checks_can_fail():
    tree = ast.parse("from course.curves.bezier import _pascal_row\nf.__globals__['x']")
    assert private_imports(tree) == ["_pascal_row", "__globals__"]


def test_test_files_are_named_for_what_they_test():
    """``test_<module>.py``, and a lesson's ``test_<topic>_{check,apps,figures}.py``.

    A chapter ``course/lessons/lNN_<topic>/`` is tested by ``test_<topic>_check.py``,
    ``test_<topic>_apps.py`` and ``test_<topic>_figures.py``; the shared machinery by
    ``test_<module>_check.py`` (``course/check/``) and ``test_<module>_widgets.py``
    (``course/widgets/``). Six test the whole package: ``test_course.py`` (its layout),
    ``test_fuzz.py`` (every public callable, given bad input), ``test_figure_bounds.py``
    (every figure's size bounds), ``test_mutants.py`` (every exercise's checker against the
    slips of its answer), ``test_install.py`` (make, the locks, the README's commands) and
    ``test_hub.py`` (docs/hub.md's server steps, on a real hub).
    """
    whole = {"course", "fuzz", "figure_bounds", "mutants", "install", "hub"}
    stems = {name.rsplit(".", 1)[-1] for name in MODULES} | whole
    chapters = {
        name.split(".")[2].split("_", 1)[1]
        for name in MODULES
        if name.startswith("course.lessons.l") and name.count(".") == 2
    }
    shared = {
        "check": {name.rsplit(".", 1)[-1] for name in MODULES if name.startswith("course.check.")},
        "widgets": {
            name.rsplit(".", 1)[-1] for name in MODULES if name.startswith("course.widgets.")
        },
    }
    named = [path.stem[len("test_") :] for path in Path(__file__).parent.glob("test_*.py")]

    def names_a_module(name: str) -> bool:
        topic, _, kind = name.rpartition("_")
        return (
            name in stems
            or (kind in ("check", "apps", "figures") and topic in chapters)
            or topic in shared.get(kind, ())
        )

    stray = [name for name in named if not names_a_module(name)]
    assert not stray, f"tests named for no module: {stray}"
    assert chapters >= {"de_casteljau", "poisson"}


def test_each_chapter_says_what_its_modules_hold():
    """A teacher opening ``course/lessons/lNN_topic/`` reads there what each file teaches."""
    chapters = sorted((PACKAGE / "lessons").glob("l[0-9][0-9]_*/__init__.py"))
    assert chapters
    for init in chapters:
        listed = set(re.findall(r":mod:`\.(\w+)`", ast.get_docstring(ast.parse(init.read_text()))))
        present = {path.stem for path in init.parent.glob("*.py")} - {"__init__"}
        assert listed == present, f"{init.parent.name}: its docstring lists {sorted(listed)}"
        assert {"lesson", "check", "apps", "figures"} <= present, init.parent.name


def test_at_most_eight_modules_at_the_root_and_none_past_500_lines():
    """Topics are packages; a module past 500 lines holds two concepts."""
    root = sorted(path.name for path in PACKAGE.glob("*.py")) + sorted(
        path.parent.name for path in PACKAGE.glob("_*/__init__.py")
    )
    assert len(root) <= 8, root
    long = {
        name: lines
        for name, path in MODULES.items()
        if (lines := len(path.read_text(encoding="utf-8").splitlines())) > 500
    }
    assert not long, f"modules past 500 lines: {long}"


STANDARD_LIBRARY_ONLY = [
    f"course.classroom.{name}"
    for name in (
        "cli",
        "course_map",
        "edition",
        "edition_folder",
        "folders",
        "gallery",
        "notebooks",
        "registry",
        "release",
        "stubs",
    )
] + ["course.classroom.source", "course.classroom", "course.__main__", "course"]
# Imported by the plumbing, and standard library only at import: Babel and matplotlib are
# imported inside the functions that compile a catalog or add the CJK font.
STANDARD_LIBRARY_AT_IMPORT = ["course.i18n"]


@pytest.mark.parametrize("module", STANDARD_LIBRARY_ONLY)
def test_the_classroom_s_plumbing_needs_the_standard_library_only(module):
    tree = ast.parse(MODULES[module].read_text(encoding="utf-8"))
    imported = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            imported.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            imported.add(node.module)
    outside = {
        name
        for name in imported
        if name.split(".")[0] not in sys.stdlib_module_names
        and name not in STANDARD_LIBRARY_ONLY + STANDARD_LIBRARY_AT_IMPORT
    }
    assert not outside, f"{module} imports {sorted(outside)}"


def test_the_language_module_imports_the_standard_library_only_at_import():
    tree = ast.parse(MODULES["course.i18n"].read_text(encoding="utf-8"))
    imported = {
        alias.name if isinstance(node, ast.Import) else node.module
        for node in tree.body  # module level only
        if isinstance(node, (ast.Import, ast.ImportFrom))
        for alias in node.names
    }
    assert {name.split(".")[0] for name in imported} <= set(sys.stdlib_module_names) | {
        "__future__"
    }
