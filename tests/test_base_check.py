"""course.check.base: reports that name the difference, recognise mistakes and show pictures."""

import sys

import pytest

from course.check.base import (
    CallBudget,
    CheckResult,
    Mistake,
    call_budget,
    close,
    run_cases,
    same_pixels,
)

CASES = [{"x": 1.0}, {"x": 2.0}, {"x": 3.0}]


def run(student, **options):
    options.setdefault("hint", "double it")
    return run_cases("double", student, CASES, lambda x: 2 * x, close(), **options)


def test_a_pass_is_one_line_and_a_failure_ends_with_the_hint():
    assert str(run(lambda x: 2 * x)) == "PASS double: all 3 cases pass"
    failed = run(lambda x: 2 * x if x < 3 else x + 2)
    assert str(failed).splitlines() == [
        "FAIL double: case 3 is wrong",
        "  inputs: x=3.0",
        "  expected: 6.0",
        "  given:    5.0",
        "Hint: double it",
    ]
    assert failed.cases_run == 3 and not failed


def test_a_known_mistake_is_named_only_when_the_answer_is_its_answer():
    squared = Mistake("squared", "you multiplied x by itself", lambda x: x * x)
    result = run(lambda x: x * x, mistakes=[squared])
    assert result.mistake == "squared" and "known mistake, squared: you multiplied" in str(result)
    other = run(lambda x: x + 5, mistakes=[squared])
    assert other.mistake is None and "known mistake" not in str(other)


def test_a_mistake_may_match_by_its_own_rule():
    rounded = Mistake("rounded", "r", lambda x: 2 * x, matches=lambda want, got: round(got) == want)
    result = run(lambda x: 2 * x + 0.25, mistakes=[rounded])
    assert result.mistake == "rounded"


def test_the_picture_is_drawn_for_the_failing_case_only():
    drawn = []

    def picture(case, expected, given):
        drawn.append((case["x"], expected, given))
        return b"png"

    assert run(lambda x: 2 * x, picture=picture).picture is None
    result = run(lambda x: 3 * x, picture=picture)
    assert result.picture == b"png" and drawn == [(1.0, 2.0, 3.0)]


def test_in_a_notebook_the_report_shows_as_text_then_picture(monkeypatch):
    shown = []
    monkeypatch.setattr("IPython.get_ipython", lambda: object())
    monkeypatch.setattr(
        "IPython.display.display",
        lambda data, raw, metadata=None: shown.append((data, metadata) if metadata else data),
    )
    CheckResult("x", False, 1, "case 1 is wrong", picture=b"\x89PNG")._ipython_display_()
    assert shown == [{"text/plain": "FAIL x: case 1 is wrong"}, {"image/png": b"\x89PNG"}]
    shown.clear()
    CheckResult("x", True, 3, "all 3 cases pass")._ipython_display_()
    assert shown == [{"text/plain": "PASS x: all 3 cases pass"}]
    shown.clear()
    CheckResult("x", False, 1, "case 1 is wrong", mistake="drawn backwards").graded()
    outcome = {"exercise": "x", "passed": False, "mistake": "drawn backwards"}
    outcome["report"] = "FAIL x: case 1 is wrong"
    # A check cell's outcome rides in the text's metadata, for the class's mistakes report.
    assert shown == [({"text/plain": "FAIL x: case 1 is wrong"}, {"course": {"check": outcome}})]


def test_the_budget_stops_runaway_recursion_and_forbidden_calls_then_steps_aside():
    def forever(n):
        return 1 if n == 0 else forever(n - 1) + forever(n - 1)

    before = sys.getprofile()
    with pytest.raises(CallBudget, match="more than 100 Python function calls"):
        with call_budget(max_calls=100):
            forever(20)
    assert sys.getprofile() is before
    with pytest.raises(CallBudget, match="no sorted here"):
        with call_budget(forbidden={sorted: "no sorted here"}):
            sorted([2, 1])
    assert sys.getprofile() is before


def test_the_budget_reports_its_mistake_and_the_case():
    slow = Mistake("slow", "it recomputes", lambda x: None)

    def watch():
        return call_budget(max_calls=50, too_many=slow)

    def student(x):
        return 2 * x if x < 3 else sum(abs(i) for i in range(1000)) * 0 + 2 * x

    result = run(student, watch=watch)
    assert result.mistake == "slow"
    lines = str(result).splitlines()
    assert lines[:3] == [
        "FAIL double: case 3 was stopped: more than 50 Python function calls",
        "  inputs: x=3.0",
        "This is a known mistake, slow: it recomputes",
    ]


def test_pixel_sets_compare_in_any_order_without_repeats():
    assert same_pixels([[1, 2], [3, 4]], [[3, 4], [1, 2], [1, 2]])
    assert not same_pixels([[1, 2]], [[2, 1]])


def test_assert_passed_raises_the_whole_report_for_a_grader_and_returns_a_pass():
    failed = CheckResult("blur", False, 2, "case 2 is wrong\n  expected: 1, given: 2")
    with pytest.raises(AssertionError, match="FAIL blur: case 2 is wrong\n  expected: 1, given: 2"):
        failed.assert_passed()
    passed = CheckResult("blur", True, 3, "all 3 cases pass")
    assert passed.assert_passed() is passed


# --- Bounded, positional, input-keeping runs (issue 20) ---------------------------------

import math  # noqa: E402
import tracemalloc  # noqa: E402

import numpy as np  # noqa: E402

from course.check import base, sandbox  # noqa: E402
from course.check.base import AnswerError, Hints, hint, register_hints  # noqa: E402

SMALL = {"seconds": 0.2, "memory": 32 * 2**20}


def bounded(student, **options):
    options.setdefault("hint", "double it")
    options = {**SMALL, **options}
    return run_cases("double", student, CASES, lambda x: 2 * x, close(), **options)


def spin(x):
    while True:
        pass


def never_one(x):
    t = 0.0
    while t != 1.0:
        t += 0.001
    return 2 * x


def growing_list(x):
    kept = []
    while True:
        kept.append([x] * 10_000)


def growing_arrays(x):
    kept = []
    while True:
        kept.append(np.zeros((512, 512)))


def catches_exceptions(x):
    while True:
        try:
            while True:
                pass
        except Exception:
            pass


@pytest.mark.parametrize("student", [spin, never_one, catches_exceptions])
def test_a_loop_that_never_ends_is_stopped_and_reported_with_its_case(student):
    before = sys.getprofile()
    result = bounded(student)
    lines = str(result).splitlines()
    assert lines[:2] == [
        "FAIL double: case 1 was stopped: the loop did not stop within 0.2 s",
        "  inputs: x=1.0",
    ]
    assert sys.getprofile() is before and not tracemalloc.is_tracing()


@pytest.mark.parametrize("student", [growing_list, growing_arrays])
def test_memory_that_keeps_growing_is_stopped_or_the_loop_is(student):
    result = bounded(student, seconds=5.0)
    assert not result
    assert "memory kept growing (past 32 MiB)" in str(result)
    assert not tracemalloc.is_tracing()


def test_the_budget_composes_with_call_budget():
    def watch():
        return call_budget(max_calls=50)

    def recursing(x):
        return recursing(x)

    result = bounded(recursing, watch=watch)
    assert "case 1 was stopped: more than 50 Python function calls" in str(result)


def test_the_students_globals_survive_a_stopped_case():
    state = {"calls": 0}

    def counting(x):
        state["calls"] += 1
        while True:
            pass

    assert not bounded(counting)
    assert state == {"calls": 1}
    assert bounded(lambda x: 2 * x)


def test_the_function_is_called_by_position_and_any_names_pass():
    cases = [{"control_points": 1.0, "t": 2.0}, {"control_points": 3.0, "t": 4.0}]

    def run2(student):
        return run_cases(
            "f", student, cases, lambda control_points, t: control_points - t, close(), hint="h"
        )

    assert run2(lambda p, u: p - u)
    assert run2(lambda px, py, extra=0: px - py)
    wrong = run2(lambda p: p)
    assert str(wrong).splitlines()[0] == (
        "FAIL f: your function cannot be called as the handout does: expected 2 parameters, "
        "(control_points, t); your function takes 1, (p)"
    )
    assert wrong.cases_run == 0


def test_a_changed_input_fails_naming_the_argument_and_element_even_when_the_value_is_right():
    cases = [{"image": np.array([[1.0, 2.0], [3.0, 4.0]]), "k": 2}]

    def doubled_in_place(image, k):
        image *= k
        return image

    result = run_cases(
        "scale",
        doubled_in_place,
        cases,
        lambda image, k: image * k,
        close(),
        hint="h",
        on_change="keep a copy",
    )
    lines = str(result).splitlines()
    assert lines[0] == "FAIL scale: case 1 changed its input image: element [0, 0] was 1, is now 2"
    assert "  keep a copy" in lines
    assert cases[0]["image"][0, 0] == 1.0  # the checker's own input is untouched

    def paints(image, k):
        image[0, 0] = 9.0
        return k

    allowed = run_cases(
        "paint", paints, cases, lambda image, k: k, close(), hint="h", writable=("image",)
    )
    assert allowed


def test_none_and_stubs_are_told_apart():
    def forgot(x):
        2 * x

    def stub(x):
        """Double x."""
        ...

    assert str(bounded(forgot)).splitlines()[0] == (
        "FAIL double: case 1 returned None: did you forget the return statement?"
    )
    assert str(bounded(stub)).splitlines() == [
        "FAIL double: not written yet: your function returns nothing",
        "Start here: double it",
    ]

    def raises(x):
        raise NotImplementedError("your code here")

    assert str(bounded(raises)).splitlines()[0] == (
        "FAIL double: not written yet: your function raised NotImplementedError: your code here"
    )

    def says_nothing(x):
        raise NotImplementedError

    assert str(bounded(says_nothing)).splitlines()[0] == (
        "FAIL double: not written yet: your function raised NotImplementedError"
    )


def test_odd_answers_get_a_clear_report_never_a_library_traceback():
    complex_answer = bounded(lambda x: 2 * x + 1j)
    assert "your answer holds complex numbers" in str(complex_answer)
    nan_answer = bounded(lambda x: np.array([np.nan]))
    assert "your answer holds nan at [0]" in str(nan_answer)
    float32 = bounded(lambda x: np.float32(2 * x + 1e-6))
    assert "your answer is float32" in str(float32) and "allows 1e-09" in str(float32)
    assert bounded(lambda x: [2 * x][0])


def test_a_list_or_tuple_with_the_right_values_passes():
    cases = [{"x": 1.0}]
    assert run_cases(
        "pair", lambda x: [x, 2 * x], cases, lambda x: np.array([x, 2 * x]), close(), hint="h"
    )
    assert run_cases(
        "pair", lambda x: (x, 2 * x), cases, lambda x: np.array([x, 2 * x]), close(), hint="h"
    )


def test_an_exception_shows_the_students_line_and_the_checkers_own_errors_say_so():
    def divides(x):
        zero = 0
        return x / zero

    text = str(bounded(divides))
    # the line as Python (and Jupyter, in a cell) numbers it: the return is two below the def
    line = divides.__code__.co_firstlineno + 2
    with pytest.raises(ZeroDivisionError) as python_says:  # its words vary across versions
        divides(1.0)
    assert f"case 1 raised ZeroDivisionError: {python_says.value}\n" in text
    assert f"at line {line} of divides: return x / zero" in text

    def unreadable(value):
        raise AnswerError("a point is two numbers")

    assert "your answer cannot be read: a point is two numbers" in str(
        bounded(lambda x: 2 * x, convert=unreadable)
    )

    def strict(value):
        return np.asarray(value, dtype=float)

    ragged = str(bounded(lambda x: [[1.0], [1.0, 2.0]], convert=strict))
    assert "the checker raised this while reading your answer" in ragged


def test_cases_must_be_mappings():
    with pytest.raises(TypeError, match="case \\[0\\] is int"):
        run_cases("f", abs, [1], abs, close(), hint="h")
    with pytest.raises(TypeError, match="got int"):
        run_cases("f", abs, 1, abs, close(), hint="h")


def test_the_librarys_own_answer_is_refused_when_called_or_named():
    def library_double(x):
        return 2 * x

    forbidden = {library_double: "you called the library's double"}
    assert str(bounded(library_double, forbidden=forbidden)).splitlines()[0] == (
        "FAIL double: you called the library's double"
    )
    assert "library's double" in str(bounded(lambda x: library_double(x), forbidden=forbidden))
    refused = {math.comb: "math.comb was called"}
    cases = [{"m": 5, "n": 2}]

    def through_map(m, n):
        return next(map(math.comb, [m], [n]))

    def reference(m, n):
        return math.comb(m, n)

    result = run_cases(
        "comb", through_map, cases, reference, lambda a, b: a == b, hint="h", forbidden=refused
    )
    assert str(result).splitlines()[0] == "FAIL comb: math.comb was called"

    def own(m, n):
        comb = 10  # a local of the same name is not math.comb
        return comb

    assert run_cases(
        "comb", own, cases, reference, lambda a, b: a == b, hint="h", forbidden=refused
    )


def test_hints_come_in_steps_and_the_recipe_only_on_request(monkeypatch):
    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    steps = register_hints(
        "tripling", Hints("look at x", "three of them", "return 3 * x"), "triple"
    )
    first = run_cases("tripling", lambda x: x, CASES, lambda x: 3 * x, close(), hint=steps)
    assert str(first).splitlines()[-2:] == ["Hint: look at x", '(More: check.hint("tripling").)']
    second = run_cases("tripling", lambda x: x, CASES, lambda x: 3 * x, close(), hint=steps)
    assert "Hint: look at x three of them" in str(second)
    assert "return 3 * x" not in str(first) + str(second)
    assert str(hint("triple")) == "Hint for tripling: look at x three of them"
    assert str(hint("Triple", recipe=True)) == "Hint for tripling: return 3 * x"
    with pytest.raises(ValueError, match="exercise must be one of"):
        hint("no such exercise")


def test_a_pass_carries_the_pass_picture_made_from_the_students_answers():
    seen = []

    def draw(results):
        seen.extend(given for _, _, given in results)
        return b"png"

    result = run(lambda x: 2 * x, pass_picture=draw)
    assert result.picture == b"png" and seen == [2.0, 4.0, 6.0]


def test_a_huge_wrong_answer_is_refused_quickly_by_size_not_read_pixel_by_pixel():
    cases = [{"n": 3}]
    result = run_cases(
        "pixels",
        lambda n: np.zeros((2**21, 2)),
        cases,
        lambda n: np.array([[0, 0]]),
        same_pixels,
        base.pixel_rows,
        hint="h",
    )
    assert "far more than any case needs" in str(result)


def test_student_line_skips_frames_inside_the_course():
    def calls_library(x):
        return sandbox.arity_problem(None, ("x",)) + 1

    with pytest.raises(TypeError) as caught:
        calls_library(1)
    line = calls_library.__code__.co_firstlineno + 1
    assert sandbox.student_line(caught.value).startswith(f"line {line} of calls_library: return")


def test_the_second_step_of_a_hint_starts_a_sentence_with_a_capital(monkeypatch):
    # Lessons 06-08 read "... the comparison itself. each input pixel ...".
    from course.lessons.l06_dithering import check as dithering

    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    wrong = lambda gray: np.zeros((3 * gray.shape[0], 3 * gray.shape[1]))  # noqa: E731
    dithering.dithering_ordered(wrong)
    second = str(dithering.dithering_ordered(wrong))
    assert "the comparison itself. Each input pixel becomes a 3 x 3 cell" in second
    assert "the comparison itself. Each input pixel" in str(hint("dithering_ordered"))
    steps = Hints("look at t.", "t must reach 1; x = 2 is wrong.", "recipe")
    register_hints("t_steps", steps)
    assert str(hint("t_steps")).endswith("look at t. t must reach 1; x = 2 is wrong.")
    for more, start in (("offset = (x, y) puts", "offset ="), ("a pixel is in", "A pixel")):
        register_hints("steps", Hints("look.", more, "recipe"))
        assert str(hint("steps")) == f"Hint for steps: look. {start}{more[len(start) :]}"


def test_hints_and_a_pass_in_chinese_and_english_after(monkeypatch):
    import course
    from course.lessons.l06_dithering import check as dithering  # noqa: F401 (registers the hints asked for)

    monkeypatch.setattr(base, "_FAILURES", base.Counter())
    course.use_language("zh-CN")
    try:
        text = str(hint("dithering_ordered"))
        passed = str(run(lambda x: 2 * x))
        wrong = str(run(lambda x: [x]))
    finally:
        course.use_language("en")
    # Chinese steps join without a space after the full stop.
    assert text.startswith("dithering_ordered 的提示：看看输出的大小")
    assert "以及比较本身。每个输入像素变成一个 3 × 3 的单元" in text
    assert passed == "double 通过：3 个用例全部正确"
    assert "第 1 个用例结果错误" in wrong and "  期望的形状是 ()，你的结果是 (1,)" in wrong
    assert str(run(lambda x: 2 * x)) == "PASS double: all 3 cases pass"


def test_a_colour_image_is_shown_by_shape_dtype_and_range_not_in_full():
    from course.check.shown import show_value

    image = np.linspace(0.0, 1.0, 8 * 10 * 3).reshape(8, 10, 3)
    assert show_value(image) == "an array of shape (8, 10, 3), dtype float64, values 0 to 1"
    small = np.zeros((2, 2, 3))  # 12 numbers: still shown in full
    assert show_value(small).startswith("[[[0., 0., 0.]")


def test_a_large_wrong_array_shows_a_small_window_around_its_first_wrong_value():
    from course.check.comparisons import first_difference

    expected = np.zeros((6, 7, 3))
    given = expected.copy()
    given[0, 6, 1] = 0.5
    text = first_difference(expected, given)
    assert text.startswith("first wrong value: [0, 6, 1] expected 0, given 0.5")
    assert "rows 0-1 and columns 5-6" in text
    # 2 rows x 2 columns x 3 channels each side: 12 numbers, not 126.
    given_line = text.splitlines()[-1]
    assert given_line.count(",") == 11 and "0.5" in given_line


# --- Tricks and accidents: the in-notebook checker holds (issue 33) ---------------------

import time  # noqa: E402
import warnings  # noqa: E402

from course.check.base import CheckFailed  # noqa: E402


def _timed(check):
    started = time.monotonic()
    result = check()
    return result, time.monotonic() - started


def _no_traceback(result):
    assert isinstance(result, CheckResult) and not result
    assert "Traceback" not in str(result) and 'File "' not in str(result)


def test_an_endless_iterator_of_pixels_fails_saying_so_within_the_budget():
    def endless(n):
        def pixels():
            while True:
                yield (0, 0)

        return pixels()

    result, took = _timed(
        lambda: run_cases(
            "pixels",
            endless,
            [{"n": 3}],
            lambda n: np.array([[0, 0]]),
            same_pixels,
            base.pixel_rows,
            hint="h",
            **SMALL,
        )
    )
    _no_traceback(result)
    assert str(result).splitlines()[:2] == [
        "FAIL pixels: case 1: your answer cannot be read: your generator gave more than "
        "1,048,576 pixels and did not end: return a list (or an array) of the pixels, not an "
        "endless iterator",
        "  inputs: n=3",
    ]
    assert took < 5

    def endless_pixel(n):
        return [iter(int, 1)]  # one "pixel" that never ends

    result = run_cases(
        "pixels",
        endless_pixel,
        [{"n": 3}],
        lambda n: np.array([[0, 0]]),
        same_pixels,
        base.pixel_rows,
        hint="h",
        **SMALL,
    )
    _no_traceback(result)
    assert "each pixel must be a pair (x, y)" in str(result)


def test_an_endless_iterator_for_numbers_is_shown_not_listed():
    result, took = _timed(lambda: bounded(lambda x: iter(int, 1)))
    _no_traceback(result)
    lines = str(result).splitlines()
    assert lines[0] == "FAIL double: case 1 is wrong"
    assert lines[3].startswith("  given:    <callable_iterator object at ")
    assert lines[4] == "  given a callable_iterator, not numbers"
    assert took < 5


class _LyingDtypeArray(np.ndarray):
    @property
    def dtype(self):
        raise RuntimeError("no dtype here")


class _LyingDtype:
    @property
    def dtype(self):
        raise RuntimeError("no dtype here")

    def __len__(self):
        raise RuntimeError("no length either")


def test_an_answer_whose_dtype_raises_fails_without_a_traceback():
    array = bounded(lambda x: np.array(2 * x).view(_LyingDtypeArray))
    assert array  # numpy's own record of the dtype is read, not the property: 2x is right
    wrong = bounded(lambda x: np.array(3 * x).view(_LyingDtypeArray))
    _no_traceback(wrong)
    assert str(wrong).splitlines()[3] == "  given:    3."
    lying = bounded(lambda x: _LyingDtype())
    _no_traceback(lying)
    assert "given a _LyingDtype, not numbers" in str(lying)

    def strict(value):
        return np.asarray(value.dtype)

    converted = bounded(lambda x: _LyingDtype(), convert=strict)
    _no_traceback(converted)
    assert str(converted).splitlines()[:2] == [
        "FAIL double: case 1: your answer, a _LyingDtype, cannot be read as the exercise's "
        "answer (RuntimeError: no dtype here)",
        "  (the checker raised this while reading your answer; your function ran without an error)",
    ]


class _EndlessNumber:
    def __array__(self, dtype=None, copy=None):
        while True:
            pass


class _EndlessMessage(Exception):
    def __str__(self):
        while True:
            pass


def test_reading_an_answer_and_an_error_stays_within_the_budget():
    result, took = _timed(lambda: bounded(lambda x: _EndlessNumber()))
    _no_traceback(result)
    assert str(result).splitlines()[:2] == [
        "FAIL double: case 1: reading your answer was stopped: the loop did not stop within 0.2 s",
        "  inputs: x=1.0",
    ]

    def raises(x):
        raise _EndlessMessage

    message, took_too = _timed(lambda: bounded(raises))
    _no_traceback(message)
    assert str(message).splitlines()[0] == "FAIL double: case 1 raised _EndlessMessage: "
    assert took < 5 and took_too < 5


def test_a_base_exception_from_the_students_code_is_a_failure_not_a_traceback():
    def exits(x):
        raise SystemExit(3)

    result = bounded(exits)
    _no_traceback(result)
    assert str(result).splitlines()[0] == "FAIL double: case 1 raised SystemExit: 3"


def test_a_right_answer_that_warns_passes_and_shows_the_warning_once_as_text(capfd):
    def with_infinity(x):
        m = np.array([0.0, x])
        return np.where(m > 0, 9 / m, np.inf)[1] * x * x / 4.5

    with warnings.catch_warnings(record=True) as printed:
        warnings.simplefilter("default")
        first = bounded(with_infinity)
        again = bounded(with_infinity)
        with_infinity(1.0)  # in the student's own cell after: not shown again either
    line = with_infinity.__code__.co_firstlineno + 2
    assert str(first).splitlines() == [
        "PASS double: all 3 cases pass",
        "  your code warned (this is not counted): RuntimeWarning: divide by zero encountered "
        f"in divide (line {line} of test_base_check.py)",
    ]
    assert first.passed and str(again) == "PASS double: all 3 cases pass"
    assert printed == [] and capfd.readouterr().err == ""


def test_a_warning_shown_in_the_students_cell_is_not_shown_again_by_the_check(capfd):
    def with_infinity(x):
        m = np.array([0.0, x])
        return np.where(m > 0, 9 / m, np.inf)[1] * x * x / 4.5

    with warnings.catch_warnings(record=True) as printed:
        warnings.simplefilter("default")
        with_infinity(1.0)  # the student's cell: shown once, there
        result = bounded(with_infinity)
        wrong = bounded(lambda x: with_infinity(x) + 1)
    assert len(printed) == 1
    assert str(result) == "PASS double: all 3 cases pass"
    assert "warned" not in str(wrong)


def test_numpy_patched_by_an_earlier_cell_does_not_pass_a_wrong_answer():
    from course.lessons.l03_lines_and_triangles import check as lines_and_triangles

    saved = np.allclose, np.array_equal, np.asarray
    seen = []

    def sees_their_patch(x):
        seen.append(np.allclose(0.0, 1.0))
        return 3 * x

    try:
        np.allclose = lambda *args, **kwargs: True
        np.array_equal = lambda *args, **kwargs: True
        wrong = bounded(sees_their_patch)
        pixels = run_cases(
            "pixels",
            lambda n: [(1, 1)],
            [{"n": 3}],
            lambda n: np.array([[0, 0]]),
            same_pixels,
            base.pixel_rows,
            hint="h",
        )
        triangle = lines_and_triangles.draw_triangle_filled(lambda p0, p1, p2: [(0, 0)])
        still = (np.allclose(0.0, 1.0), np.array_equal([0], [1]))
        np.asarray = lambda *args, **kwargs: saved[2]([0.0])  # every answer the same
        as_one = bounded(lambda x: 3 * x)
    finally:
        np.allclose, np.array_equal, np.asarray = saved
    assert str(wrong).splitlines()[0] == "FAIL double: case 1 is wrong"
    assert seen == [True]  # the student's own code sees what their cell did
    assert str(pixels).splitlines()[0] == "FAIL pixels: case 1 is wrong"
    assert not triangle and "is wrong" in str(triangle).splitlines()[0]
    assert still == (True, True)  # and their patch is theirs again after the check
    assert str(as_one).splitlines()[0] == "FAIL double: case 1 is wrong"


def test_an_int_that_equals_everything_does_not_pass_comb():
    from course.lessons.l02_bernstein import check as bernstein

    class Agreeable(int):
        def __eq__(self, other):
            return True

        __hash__ = int.__hash__

    result = bernstein.comb(lambda m, n: Agreeable(0))
    _no_traceback(result)
    assert str(result).splitlines()[:4] == [
        "FAIL comb: case 1 is wrong",
        "  inputs: m=0, n=0",
        "  expected: 1",
        "  given:    0",
    ]


def test_clearing_the_checkers_cases_from_a_frame_walk_does_not_pass():
    def clears_cases(x):
        frame = sys._getframe(1)
        while frame is not None:
            try:
                frame.f_locals["cases"].clear()
            except Exception:
                pass
            frame = frame.f_back
        return 2 * x if x == 1.0 else 0.0  # right on the first case only

    result = bounded(clears_cases)
    assert str(result).splitlines()[:2] == ["FAIL double: case 2 is wrong", "  inputs: x=2.0"]


def test_a_check_whose_cases_all_vanished_fails():
    result = run_cases("double", lambda: 2.0, [], lambda: 2.0, close(), hint="h")
    assert not result and str(result).splitlines()[0] == (
        "FAIL double: no case ran: a check needs at least one case"
    )


def test_a_result_class_patched_by_an_earlier_cell_is_put_back():
    saved = CheckResult.assert_passed, CheckResult.__bool__
    try:
        CheckResult.assert_passed = lambda self: self
        CheckResult.__bool__ = lambda self: True
        failed = bounded(lambda x: 3 * x)
        with pytest.raises(CheckFailed, match="FAIL double: case 1 is wrong"):
            failed.assert_passed()
        assert not failed
    finally:
        CheckResult.assert_passed, CheckResult.__bool__ = saved


def test_switching_off_the_watch_for_forbidden_calls_fails_the_case():
    refused = {math.comb: "math.comb was called"}

    def hidden(m, n):
        sys.setprofile(None)
        return getattr(math, "co" + "mb")(m, n)

    def hidden_later(m, n):
        list(map(sys.setprofile, [None]))  # from C: the hook does not see this call
        return getattr(math, "co" + "mb")(m, n)

    for student in (hidden, hidden_later):
        result = run_cases(
            "comb",
            student,
            [{"m": 5, "n": 2}],
            math.comb,
            lambda a, b: a == b,
            hint="h",
            forbidden=refused,
        )
        assert str(result).splitlines()[0] == (
            "FAIL comb: case 1 was stopped: your code switched off the checker's watch "
            "(sys.setprofile): leave it on, and write the exercise's answer yourself"
        )
    assert sys.getprofile() is None


def test_a_budget_inside_another_keeps_the_outer_one_watching():
    with pytest.raises(CallBudget, match="no sorted here"):
        with call_budget(forbidden={sorted: "no sorted here"}):
            with call_budget(max_calls=1000):
                sorted([2, 1])
    assert sys.getprofile() is None


class _Agreeable(int):
    def __eq__(self, other):
        return True

    __hash__ = int.__hash__


def _endless(*arguments):
    return iter(int, 1)


def _lying(*arguments):
    return _LyingDtype()


def _never_read(*arguments):
    return _EndlessNumber()


def _exits(*arguments):
    raise SystemExit(0)


def _agreeable(*arguments):
    return _Agreeable(0)


def _zeros_with_numpy_patched(*arguments):
    np.allclose = np.array_equal = lambda *args, **kwargs: True  # an earlier cell's slip
    return [[0.0, 0.0]]


ACCIDENTS = [_endless, _lying, _never_read, _exits, _agreeable, _zeros_with_numpy_patched]


def _every_checker():
    from course.classroom.exercise_list import course_exercises

    return [e for lesson in course_exercises().values() for e in lesson]


@pytest.mark.parametrize("accident", ACCIDENTS, ids=lambda f: f.__name__.strip("_"))
def test_no_checker_passes_an_accident_or_shows_a_traceback(accident, monkeypatch):
    from course.check import budget

    monkeypatch.setattr(budget, "TIME_BUDGET", 0.2)
    saved = np.allclose, np.array_equal
    failed = {}
    try:
        for declared in _every_checker():
            np.allclose, np.array_equal = saved
            started = time.monotonic()
            result = declared.checker(accident)
            failed[declared.name] = (result.passed, "Traceback" in str(result))
            assert time.monotonic() - started < 10, declared.name
    finally:
        np.allclose, np.array_equal = saved
    assert len(failed) >= 15
    assert all(outcome == (False, False) for outcome in failed.values()), failed
