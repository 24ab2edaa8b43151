"""course._validate: its errors name the parameter, in English or in Chinese, and each
public function enters it at most once per parameter.

A public function checks each argument once, at its boundary, then calls unchecked kernels
(dhermes/bezier's rule): the entries into the input checks that one valid call of each
callable of the fuzz table (tests/test_fuzz.py) outside the lessons' chapters makes are
counted, and are at most its parameters, but for the few in :data:`EXCEEDS`, each with its
reason, and those still in :data:`NOT_YET`.
"""

import contextlib
import inspect
import io
import sys
import types
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import test_fuzz

import course
from course import _validate


@pytest.fixture
def in_chinese():
    course.use_language("zh-CN")
    yield
    course.use_language("en")


def test_errors_name_the_parameter_what_was_expected_and_what_was_given():
    with pytest.raises(
        ValueError, match=r"^image values must lie in \[0, 1\]; got values from 255"
    ):
        _validate.as_image(np.full((2, 2), 255.0))
    with pytest.raises(ValueError, match=r"^p must be finite; got nan at index \(1,\)$"):
        _validate.require_finite(np.array([1.0, np.nan]), "p")


def test_a_validation_error_reads_in_chinese_and_keeps_the_parameters_name(in_chinese):
    with pytest.raises(ValueError, match=r"^image 的值必须在 \[0, 1\] 内；实际取值从 255 到 255"):
        _validate.as_image(np.full((2, 2), 255.0))
    with pytest.raises(TypeError, match=r"^n 必须是整数；实际得到 float 1\.5$"):
        _validate.as_int(1.5, "n")
    with pytest.raises(ValueError, match=r"^t 的取值必须在 ±1000 以内；实际有 1e\+30$"):
        _validate.as_parameter([1e30])
    with pytest.raises(ValueError, match=r"^step 最多只能产生 1048576 个采样（1000 条曲线合计）"):
        _validate.require_step_samples(1e-5, curves=1000)


# --- each argument is validated once ---------------------------------------------------------


def _in_validate(frame: types.FrameType | None) -> bool:
    name = frame.f_globals.get("__name__", "") if frame is not None else ""
    return name == "course._validate" or name.startswith("course._validate.")


@contextlib.contextmanager
def counting_entries() -> Iterator[list[str]]:
    """Record every entry into the input checks: a call into a function of
    :mod:`course._validate` made from outside it (a validator calling another is one entry).

    A profile function sees every call, however the caller bound the validator
    (``from course._validate import as_x`` binds it at import, out of a patch's reach).
    """
    entries: list[str] = []

    def profile(frame: types.FrameType, event: str, arg: Any) -> None:
        if event == "call" and _in_validate(frame) and not _in_validate(frame.f_back):
            caller = frame.f_back
            where = f"{caller.f_globals.get('__name__')}.{caller.f_code.co_name}" if caller else "?"
            entries.append(f"{frame.f_code.co_name} from {where}")

    previous = sys.getprofile()
    sys.setprofile(profile)
    try:
        yield entries
    finally:
        sys.setprofile(previous)


# Functions that validate more often than they have parameters, for a reason: the most
# entries their valid call makes, and why.
_COST_AFTER = (
    "checks what flattening or evaluating the curve costs (course._validate's "
    "require_bounded_*), which its points and its own tolerance decide together, after its "
    "other arguments, as it always has"
)
_STEP_AFTER = (
    "checks step, then accumulate, then what step costs (course._validate's "
    "require_step_samples), as it always has: one check of step would report a step too "
    "fine before a bad accumulate"
)
_STEP_COST = (
    "checks what its step costs (require_step_samples) after the step itself, and what "
    "evaluating the curve costs (require_bounded_evaluation), which its points and step "
    "decide together"
)
_NUMBERS_SHAPE_FINITE = (
    "checks its array's numbers, then its shape, then that the values it uses are finite, "
    "as it always has: one check of numbers and finiteness would report a NaN before a "
    "wrong shape"
)
_CORNER = "and checks each of the corner's two integers by name (corner[0] (x), corner[1] (y))"
_VERTICES = (
    "checks the path's vertices as numbers, then its codes, then finite, and the curves' "
    "points within the coordinates' bound once read (flipped by height), as it always has"
)
EXCEEDS: dict[str, tuple[int, str]] = {
    "course.antialias.curve_quality.intensity_along": (4, _COST_AFTER),
    "course.antialias.curve_quality.uniformity": (4, _COST_AFTER),
    "course.antialias.curve_quality.centroid_offsets": (4, _COST_AFTER),
    "course.antialias.curve_quality.position_error": (4, _COST_AFTER),
    "course.antialias.curve_quality.render_variant": (5, _COST_AFTER),
    "course.antialias.curve_quality.variants": (
        19,
        "checks what evaluating or flattening the curve costs (require_bounded_*) in each of "
        "the variants it draws, after its own arguments",
    ),
    "course.antialias.coverage.reference": (5, _COST_AFTER),
    "course.antialias.rendering.curve_samples": (4, _STEP_COST),
    "course.antialias.rendering.stroke_polyline": (3, _COST_AFTER),
    "course.antialias.curve_quality.quality_table": (
        6,
        "checks each image of images once, and at the first image the width and the curve's "
        "two flattening costs, where the measures it reports checked them (an empty table "
        "checks neither)",
    ),
    "course.curves.bezier.sample_uniform": (4, _STEP_AFTER),
    "course.curves.drawable_paths.wang_counts": (3, _NUMBERS_SHAPE_FINITE),
    "course.curves.flattening.uniform_parameters": (3, _STEP_AFTER),
    "course.curves.paths.path_curves": (4, _VERTICES),
    "course.curves.paths.text_curves": (
        6,
        _VERTICES + ", and the offset that moves them by the margin, which can take them past it",
    ),
    "course.poisson.problem.PoissonProblem.paste": (3, _NUMBERS_SHAPE_FINITE),
    "course.poisson.problem.PoissonProblem.residual": (2, _NUMBERS_SHAPE_FINITE),
    "course.poisson.windows.planes_of": (2, _NUMBERS_SHAPE_FINITE),
    "course.poisson.windows.window_at": (5, f"{_NUMBERS_SHAPE_FINITE}, {_CORNER}"),
    "course.poisson.windows.window_in": (4, f"{_NUMBERS_SHAPE_FINITE}, {_CORNER}"),
    "course.sampling.resample.measure_shift": (
        8,
        "calls the resampler it is given, as any caller would, which checks its own arguments "
        "(supersample: 4), and checks what that resampler returns",
    ),
}

# Functions that still validate an argument again on its way down: the entries their valid
# call makes (measured), until they call kernels instead. A function here that passes fails
# the test (strict): then take it off the list.
NOT_YET: dict[str, int] = {
    # course.curves: the accuracy study and the handout loops call the public evaluators
    # (pascal_row, binomial, de_casteljau, bezier_bernstein), whose cached Pascal rows and
    # loop form the notebooks print (course.classroom.source), so their kernels cannot move
    # yet; the handouts' pixels go through course.raster's nearest_pixels and line, which
    # check their points again (course.raster has no kernel for them yet).
    "course.curves.bezier_accuracy.accuracy_by_degree": 164,
    "course.curves.bezier_accuracy.bezier_exact": 3,
    "course.curves.bezier_accuracy.bezier_power": 14,
    "course.curves.bezier_accuracy.power_coefficients": 13,
    "course.curves.bezier_accuracy.relative_errors": 7,
    "course.curves.bezier_handouts.bresenham_curve": 12,
    "course.curves.bezier_handouts.curve_pixels": 4,
    "course.curves.bezier_handouts.segments_report": 15,
    "course.curves.bezier_handouts.step_report": 6,
    "course.curves.handout_loops.loop_pixels": 17,
    "course.curves.handout_loops.yellow_check": 37,
    # course.poisson: the sweeps check their method (solvers.jacobi_sweeps) again; then it
    # exceeds as PoissonProblem.residual does (exact: numbers, shape, finite).
    "course.poisson.methods.convergence": 7,
}


def _valid_call(qualified: str, tmp_path: Path) -> tuple[Any, dict[str, Any]] | None:
    """The callable and the keyword arguments of the fuzz table's valid call, or None."""
    function = test_fuzz.CALLABLES[qualified]
    if isinstance(function, test_fuzz.Method):
        owner = qualified.rsplit(".", 1)[0]
        arguments = test_fuzz.valid_arguments(owner, function.owner, tmp_path)
        if arguments is None:
            return None
        with contextlib.redirect_stdout(io.StringIO()):
            function = getattr(function.owner(**arguments), function.name)
    arguments = test_fuzz.valid_arguments(qualified, function, tmp_path)
    return None if arguments is None else (function, arguments)


def _entries_of_valid_call(qualified: str, tmp_path: Path) -> tuple[int, list[str]]:
    """The parameters of the callable and the entries of its valid call."""
    found = _valid_call(qualified, tmp_path)
    if found is None:
        pytest.skip("no valid input known (tests/test_fuzz.py: VALID)")
    function, arguments = found
    try:
        with contextlib.redirect_stdout(io.StringIO()), counting_entries() as entries:
            result = function(**arguments)
            if inspect.isgenerator(result):  # generators validate at their first step
                result = [next(result, None), next(result, None)]
    finally:
        if "matplotlib.pyplot" in sys.modules:
            sys.modules["matplotlib.pyplot"].close("all")
    return len(inspect.signature(function).parameters), entries


def _target(qualified: str) -> Any:
    if qualified in NOT_YET:
        reason = f"validates {NOT_YET[qualified]} times (measured): an argument again"
        return pytest.param(qualified, marks=pytest.mark.xfail(strict=True, reason=reason))
    return qualified


#: The library's public surface: everything but the lessons' chapters, which call the
#: library as any caller does (a figure that draws a curve passes it through the curve's
#: checked functions; the chapters use public names only).
LIBRARY_TARGETS = [name for name in test_fuzz.TARGETS if not name.startswith("course.lessons.")]


@pytest.mark.parametrize("qualified", [_target(name) for name in LIBRARY_TARGETS])
def test_every_public_function_validates_each_argument_once(qualified, tmp_path):
    parameters, entries = _entries_of_valid_call(qualified, tmp_path)
    most, _why = EXCEEDS.get(qualified, (parameters, ""))
    assert len(entries) <= most, (
        f"{qualified} has {parameters} parameters and entered the input checks "
        f"{len(entries)} times:\n  " + "\n  ".join(entries)
    )
    if qualified in EXCEEDS:
        assert len(entries) > parameters, f"{qualified} no longer exceeds: take it off EXCEEDS"


def test_the_lists_name_callables_of_the_fuzz_table_once():
    assert set(EXCEEDS) <= set(LIBRARY_TARGETS)
    assert set(NOT_YET) <= set(LIBRARY_TARGETS)
    assert not set(EXCEEDS) & set(NOT_YET)


def checked_twice(step: Any) -> float:
    """A made-up public function that checks its one argument twice on its way down."""
    return _validate.as_unit(_validate.as_positive_float(step, "step"), "step")


def checked_once(shape: Any) -> tuple[int, int]:
    """as_shape calls as_int twice: validators calling validators are one entry."""
    return _validate.as_shape(shape)


def test_the_count_catches_a_function_that_validates_an_argument_twice():
    with counting_entries() as entries:
        checked_twice(0.5)
    assert entries == [
        f"as_positive_float from {__name__}.checked_twice",
        f"as_unit from {__name__}.checked_twice",
    ]
    with counting_entries() as entries:
        checked_once((2, 3))
    assert entries == [f"as_shape from {__name__}.checked_once"]
    with counting_entries() as entries:
        assert _validate.describe(1) == "int 1"  # the test itself counts as outside
    assert len(entries) == 1


def test_a_function_s_source_never_shows_its_input_checks():
    """course.classroom.source follows private helpers, never into the package's modules."""
    from course.classroom.source import source_of
    from course.raster import triangles

    shown = source_of(triangles.triangle)
    assert "def _checked_triangle(" in shown  # a private helper that calls validators
    assert "def as_" not in shown and "def require_" not in shown


def test_the_catalog_keeps_the_validators_messages_and_their_translations():
    """Babel's extraction skips directories whose names start with an underscore, as
    course/_validate/ does, unless told otherwise (``pybabel extract --ignore-dirs``,
    ``extract_from_dir(directory_filter=...)``): every message of the package must stay in
    course.pot, translated, or the checks would speak English in the Chinese edition."""
    from babel.messages.extract import extract_from_file
    from babel.messages.pofile import read_po

    package = Path(_validate.__file__).parent
    marked = {
        message if isinstance(message, str) else message[0]
        for path in sorted(package.glob("*.py"))
        for _, message, _, _ in extract_from_file("python", str(path))
    }
    locale = package.parent / "locale"
    with (locale / "course.pot").open("rb") as file:
        template = {m.id for m in read_po(file) if m.id}
    with (locale / "zh_CN" / "LC_MESSAGES" / "course.po").open("rb") as file:
        translated = {m.id for m in read_po(file) if m.id and m.string and not m.fuzzy}
    assert len(marked) > 40
    assert marked <= template, f"not in course.pot: {sorted(marked - template)[:3]}"
    assert marked <= translated, f"not translated: {sorted(marked - translated)[:3]}"
