"""The machinery behind every exercise checker: reports that teach.

A checker runs the student's function on a list of cases and compares each
answer with the library's. A pass is one line. A failure names the first
failing case, its inputs, what was expected and what was given, and where
they first differ (the first wrong value, or the first missing and extra
pixel); it shows a picture of the difference when the checker can draw one;
and it ends with a hint written for that exercise.

Before the hint, the failure is compared with the handouts' own mistakes,
which the library reproduces (:class:`Mistake`): when the student's answer
is what one of them gives, the report names it, says what the code must
have done, and the picture is that mistake's.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import AbstractContextManager, contextmanager
from dataclasses import dataclass
from typing import Any

import numpy as np

from course import limits
from course._validate import as_float_array, require_finite

__all__ = [
    "CallBudget",
    "CheckFailed",
    "CheckResult",
    "Mistake",
    "call_budget",
    "close",
    "first_difference",
    "pixel_difference",
    "run_cases",
    "same_pixels",
]

Case = Mapping[str, Any]


@dataclass(frozen=True)
class Mistake:
    """One of the handouts' known mistakes, as a checker recognises it.

    ``answer(**case)`` is what code with this mistake returns for a case,
    computed by the library's reproduction of the mistake; ``explanation``
    tells the student what their code must have done ("your curve runs
    backwards: you wrote t P[i] + (1 - t) P[i+1]"). ``matches(answer,
    given)`` decides whether the student's answer is the mistake's; by
    default, the checker's own comparison.
    """

    name: str
    explanation: str
    answer: Callable[..., Any]
    matches: Callable[[Any, Any], bool] | None = None


@dataclass(frozen=True)
class CheckResult:
    """The outcome of checking one exercise; truthy when it passed.

    ``picture`` is a PNG of the difference (or None); ``mistake`` the name of
    the known mistake recognised (or None). In a notebook the report shows
    as text, then the picture. A grader (nbgrader's test cells) calls
    :meth:`assert_passed`, which raises on a failure with the same report.
    """

    exercise: str
    passed: bool
    cases_run: int
    message: str
    picture: bytes | None = None
    mistake: str | None = None

    def __bool__(self) -> bool:
        return self.passed

    def assert_passed(self) -> CheckResult:
        """Return this result if it passed; otherwise raise :class:`CheckFailed` with the report.

        Examples
        --------
        >>> CheckResult("f", True, 2, "all 2 cases pass").assert_passed()
        PASS f: all 2 cases pass
        >>> CheckResult("f", False, 1, "case 1 is wrong").assert_passed()
        Traceback (most recent call last):
        ...
        course.check.base.CheckFailed: FAIL f: case 1 is wrong
        """
        if not self.passed:
            raise CheckFailed(str(self))
        return self

    def __str__(self) -> str:
        mark = "PASS" if self.passed else "FAIL"
        return f"{mark} {self.exercise}: {self.message}"

    __repr__ = __str__

    def _ipython_display_(self) -> None:
        from IPython.display import display

        display({"text/plain": str(self)}, raw=True)
        if self.picture is not None:
            display({"image/png": self.picture}, raw=True)


class CheckFailed(AssertionError):
    """A failed check, raised for graders: its message is the checker's whole report."""


class CallBudget(Exception):
    """Raised inside the student's code when it calls what the exercise forbids, or too often.

    ``mistake`` names the known mistake this stands for, if any.
    """

    def __init__(self, message: str, mistake: str | None = None) -> None:
        super().__init__(message)
        self.mistake = mistake


def _show(value: Any) -> str:
    if isinstance(value, np.ndarray):
        return np.array2string(value, precision=6, separator=", ", threshold=40)
    return repr(value)


def close(atol: float = 1e-9, rtol: float = 1e-9) -> Callable[[Any, Any], bool]:
    """A comparison: same shape and equal within the tolerances."""

    def compare(expected: Any, given: Any) -> bool:
        expected, given = np.asarray(expected, dtype=float), np.asarray(given, dtype=float)
        return expected.shape == given.shape and bool(
            np.allclose(given, expected, atol=atol, rtol=rtol)
        )

    return compare


def same_pixels(expected: Any, given: Any) -> bool:
    """A comparison of pixel sets: the same (x, y) pixels, in any order, repeats ignored."""
    return _pixel_set(expected, "expected") == _pixel_set(given, "given")


def _pixel_set(pixels: Any, name: str) -> set[tuple[int, int]]:
    array = as_float_array(pixels, name)
    if array.size % 2:
        raise ValueError(f"{name} must hold (x, y) pairs; got {array.size} numbers")
    require_finite(array, name)
    if array.size > limits.MAX_SAMPLES:
        raise ValueError(
            f"{name} must hold at most {limits.MAX_SAMPLES} pixels; got {array.size // 2}"
        )
    return {(int(x), int(y)) for x, y in array.reshape(-1, 2)}


def first_difference(expected: Any, given: Any, atol: float = 1e-9, rtol: float = 1e-9) -> str:
    """Where two answers first differ, in words: the first wrong value and its index.

    Examples
    --------
    >>> first_difference([1.0, 2.0, 3.0], [1.0, 2.5, 3.0])
    'first wrong value: [1] expected 2, given 2.5'
    >>> first_difference([[1.0, 2.0]], [1.0, 2.0])
    'expected shape (1, 2), given shape (2,)'
    """
    try:
        expected, given = np.asarray(expected, dtype=float), np.asarray(given, dtype=float)
    except (TypeError, ValueError):
        return f"given a {type(given).__name__}, not numbers"
    if expected.shape != given.shape:
        return f"expected shape {expected.shape}, given shape {given.shape}"
    if expected.ndim == 0:
        return ""  # one value: the lines above say it all
    wrong = ~np.isclose(given, expected, atol=atol, rtol=rtol)
    if not wrong.any():
        return "the values agree within the tolerance"
    index = tuple(int(i) for i in np.argwhere(wrong)[0])
    where = "[" + ", ".join(map(str, index)) + "]"
    return f"first wrong value: {where} expected {expected[index]:.6g}, given {given[index]:.6g}"


def pixel_difference(expected: Any, given: Any) -> str:
    """Missing and extra pixels, in words, each with its first pixel in reading order.

    Examples
    --------
    >>> pixel_difference([[0, 0], [1, 0], [2, 1]], [[0, 0], [1, 1], [2, 1]])
    '1 pixel missing, first (1, 0); 1 extra, first (1, 1)'
    """
    want, have = _pixel_set(expected, "expected"), _pixel_set(given, "given")

    def reading_order(pixel: tuple[int, int]) -> tuple[int, int]:
        return pixel[1], pixel[0]

    parts = []
    missing, extra = sorted(want - have, key=reading_order), sorted(have - want, key=reading_order)
    if missing:
        plural = "pixel" if len(missing) == 1 else "pixels"
        parts.append(f"{len(missing)} {plural} missing, first {missing[0]}")
    if extra:
        parts.append(f"{len(extra)} extra, first {extra[0]}")
    return "; ".join(parts) or "the same pixels"


@contextmanager
def call_budget(
    max_calls: int | None = None,
    forbidden: Mapping[Any, str] | None = None,
    too_many: Mistake | None = None,
) -> Iterator[None]:
    """Stop the student's code after ``max_calls`` Python calls, or at a forbidden call.

    Every Python function call counts (the student's own, their helpers',
    a comprehension's), so a recursion that recomputes the same values is
    stopped however it is written. ``forbidden`` maps functions
    (``math.comb``, a library function) to the message the report gives when
    one is called. A profile hook sees every call, C functions included,
    however the student imported them. With ``too_many``, running out of
    calls is reported as that known mistake.
    """
    forbidden = dict(forbidden or {})
    forbidden_codes = {getattr(f, "__code__", None): text for f, text in forbidden.items()}
    forbidden_codes.pop(None, None)
    calls = 0

    def watch(frame: Any, event: str, argument: Any) -> None:
        nonlocal calls
        if event == "c_call":
            for function, text in forbidden.items():
                if argument is function:
                    raise CallBudget(text)
        elif event == "call":
            if frame.f_code in forbidden_codes:
                raise CallBudget(forbidden_codes[frame.f_code])
            calls += 1
            if max_calls is not None and calls > max_calls:
                message = f"more than {max_calls:,} Python function calls"
                if too_many is None:
                    raise CallBudget(message)
                raise CallBudget(
                    f"{message}\nThis is a known mistake, {too_many.name}: {too_many.explanation}",
                    too_many.name,
                )

    previous = sys.getprofile()
    sys.setprofile(watch)
    try:
        yield
    finally:
        sys.setprofile(previous)


def run_cases(
    exercise: str,
    student: Callable[..., Any],
    cases: Iterable[Case],
    reference: Callable[..., Any],
    compare: Callable[[Any, Any], bool],
    convert: Callable[[Any], Any] = lambda value: value,
    *,
    hint: str,
    mistakes: Sequence[Mistake] = (),
    difference: Callable[[Any, Any], str] = first_difference,
    picture: Callable[[Case, Any, Any], bytes | None] | None = None,
    watch: Callable[[], AbstractContextManager[Any]] | None = None,
    explain: Callable[[Case, Any, Any], str] | None = None,
    show: Callable[[Any], str] | None = None,
) -> CheckResult:
    """Call ``student(**case)`` and ``reference(**case)`` for every case.

    ``convert`` turns the student's answer into the reference's form (for
    example a tuple into an array) before ``compare(expected, given)``.
    Stops at the first wrong answer, or at the first exception the student's
    code raises, and reports that case: its inputs, both answers,
    ``difference(expected, given)``, the mistake of ``mistakes`` whose
    answer the student's matches (by ``compare``), ``picture(case, expected,
    given)`` and ``hint``. ``watch()``, if given, makes a context manager
    the student's code runs under, each case anew (:func:`call_budget`).
    ``explain(case, expected, given)``, if given, adds a line about the
    first difference that needs the case's inputs (what was carried into
    the first wrong pixel, say). ``show(answer)``, if given, writes an
    answer for the report in the exercise's own terms.
    """
    if not callable(student):
        raise TypeError(f"{exercise}: expected a function to check; got {type(student).__name__}")
    count = 0
    for count, case in enumerate(cases, start=1):
        inputs = ", ".join(f"{name}={_show(value)}" for name, value in case.items())
        expected = reference(**case)
        try:
            if watch is None:
                given = convert(student(**{k: _copy(v) for k, v in case.items()}))
            else:
                with watch():
                    given = convert(student(**{k: _copy(v) for k, v in case.items()}))
        except CallBudget as stopped:
            reason, *known = str(stopped).split("\n", 1)
            lines = [f"case {count} was stopped: {reason}", f"  inputs: {inputs}", *known]
            return CheckResult(
                exercise,
                False,
                count,
                "\n".join([*lines, f"Hint: {hint}"]),
                mistake=stopped.mistake,
            )
        except Exception as error:  # the student's bug, reported, not raised
            return CheckResult(
                exercise,
                False,
                count,
                f"case {count} raised {type(error).__name__}: {error}\n  inputs: {inputs}\n"
                f"Hint: {hint}",
            )
        try:
            same = compare(expected, given)
        except (TypeError, ValueError):
            same = False
        if same:
            continue
        lines = [
            f"case {count} is wrong",
            f"  inputs: {inputs}",
            f"  expected: {(show or _show)(expected)}",
            f"  given:    {(show or _show)(given)}",
        ]
        where = difference(expected, given)
        if where:
            lines.append(f"  {where}")
        if explain is not None:
            lines.append(f"  {explain(case, expected, given)}")
        known = _recognise(mistakes, case, given, compare)
        if known is not None:
            lines.append(f"This is a known mistake, {known.name}: {known.explanation}")
        lines.append(f"Hint: {hint}")
        drawn = picture(case, expected, given) if picture is not None else None
        return CheckResult(
            exercise,
            False,
            count,
            "\n".join(lines),
            picture=drawn,
            mistake=None if known is None else known.name,
        )
    return CheckResult(exercise, True, count, f"all {count} cases pass")


def _recognise(
    mistakes: Sequence[Mistake], case: Case, given: Any, compare: Callable[[Any, Any], bool]
) -> Mistake | None:
    """The first mistake whose answer for ``case`` is the student's."""
    for mistake in mistakes:
        try:
            if (mistake.matches or compare)(mistake.answer(**case), given):
                return mistake
        except (TypeError, ValueError, IndexError):
            continue
    return None


def _copy(value: Any) -> Any:
    """Students get copies, so a function that mutates its input cannot corrupt the next case."""
    return value.copy() if isinstance(value, np.ndarray) else value
