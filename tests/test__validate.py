"""course._validate: its errors name the parameter, in English or in Chinese, and each
public function enters it at most once per parameter.

A public function checks each argument once, at its boundary, then calls unchecked kernels
(dhermes/bezier's rule): the entries into the input checks that one valid call of each
callable of the fuzz table (tests/test_fuzz.py) outside the lessons' chapters makes are
counted, and are at most its parameters, but for the two in :data:`EXCEEDS`, each with its
reason. The bounds on a call's work (course.limits' ``require_*``), which several arguments
decide together, are not argument checks: they are counted apart, and none is made twice
for the same work.
"""

import collections
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
from course import _validate, limits


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
        limits.require_step_samples(1e-5, curves=1000)


# --- each argument is validated once ---------------------------------------------------------


def _in_validate(frame: types.FrameType | None) -> bool:
    name = frame.f_globals.get("__name__", "") if frame is not None else ""
    return name == "course._validate" or name.startswith("course._validate.")


def _work_bound(frame: types.FrameType) -> bool:
    return frame.f_globals.get("__name__") == "course.limits" and frame.f_code.co_name in (
        limits.__all__
    )


def _fingerprint(value: Any) -> Any:
    if isinstance(value, np.ndarray):
        return (value.shape, str(value.dtype), hash(value.tobytes()))
    return repr(value)


@contextlib.contextmanager
def counting_entries(work_bounds: list[tuple[Any, ...]] | None = None) -> Iterator[list[str]]:
    """Record every entry into the input checks: a call into a function of
    :mod:`course._validate` made from outside it (a validator calling another is one entry).
    With ``work_bounds``, also record there each check of a call's work
    (:mod:`course.limits`' ``require_*``) with what it was given.

    A profile function sees every call, however the caller bound the validator
    (``from course._validate import as_x`` binds it at import, out of a patch's reach).
    """
    entries: list[str] = []

    def profile(frame: types.FrameType, event: str, arg: Any) -> None:
        if event != "call":
            return
        if _in_validate(frame) and not _in_validate(frame.f_back):
            caller = frame.f_back
            where = f"{caller.f_globals.get('__name__')}.{caller.f_code.co_name}" if caller else "?"
            entries.append(f"{frame.f_code.co_name} from {where}")
        elif work_bounds is not None and _work_bound(frame):
            given = tuple(_fingerprint(value) for value in frame.f_locals.values())
            work_bounds.append((frame.f_code.co_name, *given))

    previous = sys.getprofile()
    sys.setprofile(profile)
    try:
        yield entries
    finally:
        sys.setprofile(previous)


# Functions that validate more often than they have parameters, for a reason: the most
# entries their valid call makes, and why.
EXCEEDS: dict[str, tuple[int, str]] = {
    "course.curves.bezier_handouts.step_report": (
        4,
        "checks its points as numbers, then the samples it draws within the coordinates' "
        "bound: the curve, not its control polygon, must lie in image space, or a sample far "
        "away would wrap around to a pixel",
    ),
    "course.sampling.resample.measure_shift": (
        8,
        "calls the resampler it is given, as any caller would, which checks its own arguments "
        "(supersample: 4), and checks what that resampler returns",
    ),
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


def _entries_of_valid_call(
    qualified: str, tmp_path: Path, work_bounds: list[tuple[Any, ...]] | None = None
) -> tuple[int, list[str]]:
    """The parameters of the callable and the entries of its valid call (and, into
    ``work_bounds``, the checks of its work)."""
    found = _valid_call(qualified, tmp_path)
    if found is None:
        pytest.skip("no valid input known (tests/test_fuzz.py: VALID)")
    function, arguments = found
    try:
        with contextlib.redirect_stdout(io.StringIO()), counting_entries(work_bounds) as entries:
            result = function(**arguments)
            if inspect.isgenerator(result):  # generators validate at their first step
                result = [next(result, None), next(result, None)]
    finally:
        if "matplotlib.pyplot" in sys.modules:
            sys.modules["matplotlib.pyplot"].close("all")
    return len(inspect.signature(function).parameters), entries


#: The library's public surface: everything but the lessons' chapters, which call the
#: library as any caller does (a figure that draws a curve passes it through the curve's
#: checked functions; the chapters use public names only).
LIBRARY_TARGETS = [name for name in test_fuzz.TARGETS if not name.startswith("course.lessons.")]


@pytest.mark.parametrize("qualified", LIBRARY_TARGETS)
def test_every_public_function_validates_each_argument_once(qualified, tmp_path):
    parameters, entries = _entries_of_valid_call(qualified, tmp_path)
    most, _why = EXCEEDS.get(qualified, (parameters, ""))
    assert len(entries) <= most, (
        f"{qualified} has {parameters} parameters and entered the input checks "
        f"{len(entries)} times:\n  " + "\n  ".join(entries)
    )
    if qualified in EXCEEDS:
        assert len(entries) > parameters, f"{qualified} no longer exceeds: take it off EXCEEDS"


#: Calls that do the same work twice, and so check its bound twice.
WORK_DONE_TWICE = {
    "course.antialias.curve_quality.variants": (
        "draws each variant from the curve itself: bilinear_centres and normalised_centres "
        "both evaluate the curve at the same parameters"
    ),
}


@pytest.mark.parametrize(
    "qualified",
    [
        pytest.param(name, marks=pytest.mark.xfail(strict=True, reason=WORK_DONE_TWICE[name]))
        if name in WORK_DONE_TWICE
        else name
        for name in LIBRARY_TARGETS
    ],
)
def test_no_call_checks_the_same_work_twice(qualified, tmp_path):
    """The bounds on a call's work (vertices, samples, interpolations: course.limits'
    ``require_*``) are not argument checks, so the count above leaves them out; each is
    still made once for what it is given (a path's several curves may each be checked)."""
    work_bounds: list[tuple[Any, ...]] = []
    _entries_of_valid_call(qualified, tmp_path, work_bounds)
    repeated = [check for check, times in collections.Counter(work_bounds).items() if times > 1]
    assert not repeated, f"{qualified} checks the same work again: {[r[0] for r in repeated]}"


def test_the_lists_name_callables_of_the_fuzz_table_once():
    assert set(EXCEEDS) <= set(LIBRARY_TARGETS)
    assert set(WORK_DONE_TWICE) <= set(LIBRARY_TARGETS)


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
