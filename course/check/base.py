"""The machinery behind every exercise checker: reports that teach, and never hang.

A checker runs the student's function on a list of cases and compares each
answer with the library's. The function is called by position, in the
handout's order, so its parameters may have any names; a wrong number of
parameters is reported with the handout's signature before any case runs.
Each case runs under a time and a memory budget
(:mod:`course.check.sandbox`), on copies of its inputs, which are compared
with the originals afterwards: an answer that changes its input fails, even
when its value is right.

A pass is one line, with a small picture of the student's own result when
the checker can draw one. A failure names the first failing case, its
inputs, what was expected and what was given, and where they first differ;
it shows a picture of the difference when the checker can draw one; and it
ends with a hint. Before the hint, the failure is compared with the
handouts' own mistakes, which the library reproduces (:class:`Mistake`):
when the student's answer is what one of them gives, the report names it.

Hints come in steps (:class:`Hints`): the first failure of an exercise says
where to look; from the second failure on, the report says more;
``check.hint("name")`` says more at once, and only
``check.hint("name", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

import builtins
import dis
import sys
import warnings
from collections import Counter
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import AbstractContextManager, ExitStack, contextmanager
from dataclasses import dataclass
from typing import Any

import numpy as np

from course import limits
from course.check.sandbox import (
    CaseStopped,
    arity_problem,
    changed_argument,
    copies,
    is_stub,
    run_bounded,
    student_line,
)

__all__ = [
    "AnswerError",
    "CallBudget",
    "CheckFailed",
    "CheckResult",
    "Hint",
    "Hints",
    "Mistake",
    "call_budget",
    "close",
    "copies_of",
    "first_difference",
    "hint",
    "pixel_difference",
    "pixel_rows",
    "register_hints",
    "run_cases",
    "same_pixels",
]

Case = Mapping[str, Any]
#: Most numbers of a wrong answer the report reads in full; past it, only sizes are compared.
_LARGEST_ANSWER = 2**20


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


class AnswerError(ValueError):
    """A student's answer the checker cannot read, with a message in the student's terms."""


@dataclass(frozen=True)
class Hints:
    """An exercise's hints, in steps: where to look, then the idea, then the recipe.

    ``where`` comes with the first failure; ``more`` is added from the
    second failure on, and by :func:`hint`; ``recipe`` is shown only when
    asked for, ``hint(name, recipe=True)``.
    """

    where: str
    more: str
    recipe: str


@dataclass(frozen=True)
class Hint:
    """A hint asked for with :func:`hint`: shows as its text."""

    exercise: str
    text: str

    def __str__(self) -> str:
        return f"Hint for {self.exercise}: {self.text}"

    __repr__ = __str__


_HINTS: dict[str, tuple[str, Hints]] = {}
_ASK_BY: dict[str, str] = {}  # exercise -> the name a student asks check.hint() with
_FAILURES: Counter[str] = Counter()


def register_hints(exercise: str, hints: Hints, *names: str) -> Hints:
    """Make ``hints`` those of ``exercise``, found by :func:`hint` under ``names`` too."""
    if not isinstance(hints, Hints):
        raise TypeError(f"hints must be a Hints; got {type(hints).__name__}")
    for name in (exercise, *names):
        _HINTS[name.lower()] = (exercise, hints)
    _ASK_BY[exercise] = names[0] if names else exercise
    return hints


def hint(exercise: str, recipe: bool = False) -> Hint:
    """More help with an exercise, by its name or its function's: the idea, or the recipe.

    Examples
    --------
    >>> register_hints("double", Hints("look at x", "twice x", "return 2 * x"))
    Hints(where='look at x', more='twice x', recipe='return 2 * x')
    >>> hint("double")
    Hint for double: look at x twice x
    >>> hint("double", recipe=True)
    Hint for double: return 2 * x
    """
    if not isinstance(exercise, str):
        raise TypeError(f"exercise must be an exercise's name; got {type(exercise).__name__}")
    found = _HINTS.get(exercise.lower())
    if found is None:
        known = ", ".join(sorted({name for name, _ in _HINTS.values()}))
        raise ValueError(f"exercise must be one of {known}; got {exercise!r}")
    name, hints = found
    return Hint(name, hints.recipe if recipe else f"{hints.where} {hints.more}")


def _hint_line(exercise: str, hint: str | Hints) -> str:
    """The report's hint: a plain text, or the next step of an exercise's hints."""
    if isinstance(hint, str):
        return f"Hint: {hint}"
    _FAILURES[exercise] += 1
    name = _ASK_BY.get(exercise, exercise)
    if _FAILURES[exercise] == 1:
        return f'Hint: {hint.where}\n(More: check.hint("{name}").)'
    return (
        f"Hint: {hint.where} {hint.more}\n"
        f'(The recipe, if you want it: check.hint("{name}", recipe=True).)'
    )


def _show(value: Any) -> str:
    if isinstance(value, np.generic):
        return repr(value.item())
    if isinstance(value, np.ndarray):
        if value.size > 400:
            return f"an array of shape {value.shape}, dtype {value.dtype}"
        text = np.array2string(value, precision=6, separator=", ", threshold=40)
        return " ".join(text.split())
    text = repr(value)
    return text if len(text) <= 300 else text[:297] + "..."


def close(atol: float = 1e-9, rtol: float = 1e-9) -> Callable[[Any, Any], bool]:
    """A comparison: same shape and equal within the tolerances.

    The comparison carries its tolerances (``compare.atol``, ``compare.rtol``)
    for the report.

    Examples
    --------
    >>> close(atol=1e-3)([1.0, 2.0], (1.0, 2.0005))
    True
    """

    def compare(expected: Any, given: Any) -> bool:
        expected, given = np.asarray(expected, dtype=float), np.asarray(given, dtype=float)
        return expected.shape == given.shape and bool(
            np.allclose(given, expected, atol=atol, rtol=rtol)
        )

    compare.atol, compare.rtol = atol, rtol  # type: ignore[attr-defined]
    return compare


# Pixels are compared as one int64 key each, in reading order: (y, x) -> y * _WIDE + x.
_OFFSET = 2**21
_WIDE = 2**22


def pixel_rows(pixels: Any, name: str = "") -> np.ndarray:
    """A student's pixels as a (K, 2) int64 array of (x, y); :class:`AnswerError` if unreadable.

    Accepts an array, or a list of pairs; each coordinate must be a whole
    number within the course's coordinate bound.

    Examples
    --------
    >>> pixel_rows([(1, 2), (3.0, 4)])
    array([[1, 2],
           [3, 4]])
    >>> pixel_rows([(1.5, 2)])
    Traceback (most recent call last):
    ...
    course.check.base.AnswerError: a pixel is two whole numbers (x, y); pixel [0] is (1.5, 2)
    """
    name = f"{name}: " if name else ""
    if isinstance(pixels, np.ndarray):
        array = pixels
    else:
        try:
            items = list(pixels)
        except TypeError:
            raise AnswerError(
                f"{name}expected a list of (x, y) pixels; got {type(pixels).__name__}"
            ) from None
        if len(items) > _LARGEST_ANSWER:
            raise AnswerError(f"{name}{len(items):,} pixels, far more than any case needs")
        try:
            array = np.array([tuple(item) for item in items], dtype=object).reshape(-1, 2)
        except (TypeError, ValueError):
            raise AnswerError(
                f"{name}each pixel must be a pair (x, y); got {_show(items[:3])[:80]}..."
            ) from None
    if np.iscomplexobj(array):
        raise AnswerError(f"{name}pixels are real numbers; yours are complex")
    try:
        values = np.asarray(array, dtype=float)
    except (TypeError, ValueError):
        raise AnswerError(f"{name}pixels must be numbers (x, y)") from None
    if values.size % 2 or (values.ndim == 2 and values.shape[1] != 2) or values.ndim > 2:
        raise AnswerError(f"{name}pixels are (x, y) pairs, shape (K, 2); got {values.shape}")
    values = values.reshape(-1, 2)
    if len(values) > _LARGEST_ANSWER:
        raise AnswerError(f"{name}{len(values):,} pixels, far more than any case needs")
    bad = ~np.isfinite(values).all(axis=1)
    if bad.any():
        index = int(np.argmax(bad))
        raise AnswerError(f"{name}pixel [{index}] is {_pair(values[index])}, not a number")
    far = (np.abs(values) > limits.MAX_COORDINATE).any(axis=1)
    if far.any():
        index = int(np.argmax(far))
        raise AnswerError(
            f"{name}pixel [{index}] is {_pair(values[index])}, beyond any image "
            f"(+-{limits.MAX_COORDINATE:g})"
        )
    whole = (values == np.round(values)).all(axis=1)
    if not whole.all():
        index = int(np.argmin(whole))
        raise AnswerError(
            f"{name}a pixel is two whole numbers (x, y); pixel [{index}] is {_pair(values[index])}"
        )
    return values.astype(np.int64)


def _pair(values: np.ndarray) -> str:
    return "(" + ", ".join(f"{float(v):g}" for v in values) + ")"


def _keys(pixels: Any, name: str) -> np.ndarray:
    rows = pixels if isinstance(pixels, np.ndarray) and pixels.dtype == np.int64 else None
    rows = pixel_rows(pixels, name) if rows is None else rows.reshape(-1, 2)
    return np.unique((rows[:, 1] + _OFFSET) * _WIDE + (rows[:, 0] + _OFFSET))


def _pixel_of(key: int) -> tuple[int, int]:
    return int(key % _WIDE - _OFFSET), int(key // _WIDE - _OFFSET)


def same_pixels(expected: Any, given: Any) -> bool:
    """A comparison of pixel sets: the same (x, y) pixels, in any order, repeats ignored.

    Examples
    --------
    >>> same_pixels([[1, 2], [3, 4]], [[3, 4], [1, 2], [1, 2]])
    True
    """
    return bool(np.array_equal(_keys(expected, "expected"), _keys(given, "given")))


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
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
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

    Repeated pixels are named: a pixel listed twice is painted twice.

    Examples
    --------
    >>> pixel_difference([[0, 0], [1, 0], [2, 1]], [[0, 0], [1, 1], [2, 1]])
    '1 pixel missing, first (1, 0); 1 extra, first (1, 1)'
    >>> pixel_difference([[0, 0], [1, 0]], [[0, 0], [1, 0], [1, 0]])
    'the same pixels, but 1 listed more than once, first (1, 0): each pixel once'
    """
    want, have = _keys(expected, "expected"), _keys(given, "given")
    parts = []
    missing, extra = np.setdiff1d(want, have), np.setdiff1d(have, want)
    if len(missing):
        plural = "pixel" if len(missing) == 1 else "pixels"
        parts.append(f"{len(missing)} {plural} missing, first {_pixel_of(missing[0])}")
    if len(extra):
        parts.append(f"{len(extra)} extra, first {_pixel_of(extra[0])}")
    if parts:
        return "; ".join(parts)
    rows = pixel_rows(given, "given")
    keys = (rows[:, 1] + _OFFSET) * _WIDE + (rows[:, 0] + _OFFSET)
    unique, counts = np.unique(keys, return_counts=True)
    repeated = unique[counts > 1]
    if len(repeated):
        return (
            f"the same pixels, but {len(repeated)} listed more than once, first "
            f"{_pixel_of(repeated[0])}: each pixel once"
        )
    return "the same pixels"


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
    one is called. A profile hook sees every call of a Python function, and
    every call of a C function made from Python, however the student
    imported them. With ``too_many``, running out of calls is reported as
    that known mistake.
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


def _references(function: Any, forbidden: Mapping[Any, str], depth: int = 3) -> str | None:
    """The message of a forbidden callable that ``function``'s code names, or None.

    Reads the globals and attributes the code loads (``math.comb`` in
    ``map(math.comb, ...)``, a ``from scipy.special import comb``), in the
    function, its nested functions and the functions of its own module it
    calls: a call made from C (through ``map``) is invisible to the profile
    hook.
    """
    seen: set[int] = set()
    targets = {id(f): text for f, text in forbidden.items()}

    def loaded(candidate: Any) -> list[Any]:
        space = getattr(candidate, "__globals__", {})
        cells = getattr(candidate, "__closure__", None) or ()
        free = dict(zip(candidate.__code__.co_freevars, cells, strict=False))
        values, codes = [], [candidate.__code__]
        while codes:
            code = codes.pop()
            codes.extend(c for c in code.co_consts if hasattr(c, "co_code"))
            current: Any = None
            for instruction in dis.get_instructions(code):
                name = instruction.argval
                if instruction.opname in ("LOAD_GLOBAL", "LOAD_NAME"):
                    current = space.get(name, getattr(builtins, str(name), None))
                elif instruction.opname == "LOAD_DEREF" and name in free and _full(free[name]):
                    current = free[name].cell_contents
                elif instruction.opname in ("LOAD_ATTR", "LOAD_METHOD") and current is not None:
                    current = getattr(current, str(name), None) if _module_like(current) else None
                else:
                    current = None
                    continue
                if current is not None:
                    values.append(current)
        return values

    def visit(candidate: Any, level: int) -> str | None:
        code = getattr(candidate, "__code__", None)
        if code is None or id(code) in seen or level < 0:
            return None
        seen.add(id(code))
        values = loaded(candidate)
        for value in values:
            if id(value) in targets:
                return targets[id(value)]
        module = getattr(candidate, "__module__", None)
        for value in values:
            if getattr(value, "__module__", 0) == module and hasattr(value, "__code__"):
                text = visit(value, level - 1)
                if text is not None:
                    return text
        return None

    try:
        return visit(function, depth)
    except Exception:  # an unusual callable: the profile hook still watches it
        return None


def _module_like(value: Any) -> bool:
    return isinstance(value, (type(sys), type))


def _full(cell: Any) -> bool:
    try:
        cell.cell_contents  # noqa: B018
    except ValueError:
        return False
    return True


def _validated_cases(cases: Any) -> list[Case]:
    if isinstance(cases, (str, bytes, Mapping)) or not isinstance(cases, Iterable):
        raise TypeError(
            f"cases must be a list of mappings, one per case; got {type(cases).__name__}"
        )
    listed = list(cases)
    for index, case in enumerate(listed):
        if not isinstance(case, Mapping) or not all(isinstance(k, str) for k in case):
            raise TypeError(
                f"cases must be a list of mappings from parameter names to inputs; case [{index}] "
                f"is {type(case).__name__}"
            )
    return listed


def _holds_complex(value: Any) -> bool:
    if isinstance(value, complex) or np.iscomplexobj(getattr(value, "dtype", None) or 0):
        return True
    if isinstance(value, (np.ndarray, np.generic)):
        return value.dtype.kind == "c"
    if isinstance(value, (list, tuple)) and len(value) <= 64:
        return any(_holds_complex(item) for item in value)
    return False


def _non_finite(given: Any) -> str | None:
    """Where a converted answer holds NaN or inf, in words; None if nowhere."""
    if isinstance(given, (float, np.floating)):
        return None if np.isfinite(given) else f"your answer is {given}"
    if not isinstance(given, np.ndarray) or given.dtype.kind != "f":
        return None
    bad = ~np.isfinite(given)
    if not bad.any():
        return None
    index = tuple(int(i) for i in np.argwhere(bad)[0])
    where = "[" + ", ".join(map(str, index)) + "]"
    return f"your answer holds {given[index]} at {where}: every value must be a finite number"


def _narrow_float(value: Any, compare: Any) -> str | None:
    dtype = getattr(value, "dtype", None)
    if dtype is None or dtype.kind != "f" or dtype.itemsize >= 8:
        return None
    tolerance = getattr(compare, "atol", None)
    allowed = f"the check allows {tolerance:g}" if tolerance else "the check is exact"
    return (
        f"your answer is {dtype} (about {np.finfo(dtype).precision} significant digits); "
        f"{allowed}: compute in float64, Python's float"
    )


@dataclass
class _Report:
    exercise: str
    hint: str | Hints

    def fail(self, count: int, lines: list[str], hinted: bool = True, **extra: Any) -> CheckResult:
        text = "\n".join([*lines, _hint_line(self.exercise, self.hint)] if hinted else lines)
        return CheckResult(self.exercise, False, count, text, **extra)

    def start(self) -> str:
        if isinstance(self.hint, str):
            return f"Start here: {self.hint}"
        return f"Start here: {self.hint.where}"


def _quietly(function: Callable[..., Any] | None, *arguments: Any) -> Any:
    """A report's extra (a line, a picture): None rather than an error from the checker."""
    if function is None:
        return None
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return function(*arguments)
    except Exception:
        return None


def run_cases(
    exercise: str,
    student: Callable[..., Any],
    cases: Iterable[Case],
    reference: Callable[..., Any],
    compare: Callable[[Any, Any], bool],
    convert: Callable[[Any], Any] = lambda value: value,
    *,
    hint: str | Hints,
    mistakes: Sequence[Mistake] = (),
    difference: Callable[[Any, Any], str] = first_difference,
    picture: Callable[[Case, Any, Any], bytes | None] | None = None,
    watch: Callable[[], AbstractContextManager[Any]] | None = None,
    explain: Callable[[Case, Any, Any], str] | None = None,
    show: Callable[[Any], str] | None = None,
    answer: Callable[[Any, tuple[Any, ...]], Any] | None = None,
    writable: Sequence[str] = (),
    forbidden: Mapping[Any, str] | None = None,
    on_change: str = "",
    pass_picture: Callable[[list[tuple[Case, Any, Any]]], bytes | None] | None = None,
    seconds: float | None = None,
    memory: int | None = None,
) -> CheckResult:
    """Call ``student(*case.values())`` and ``reference(**case)`` for every case.

    The student's function gets deep copies of the case's inputs, by
    position, in the case's order (the handout's), under a budget of
    ``seconds`` and ``memory`` bytes (:data:`~course.check.sandbox.TIME_BUDGET`,
    :data:`~course.check.sandbox.MEMORY_BUDGET` by default). A copy it
    changed fails the case, naming the argument and the first changed
    element (plus ``on_change``), unless the argument is ``writable``.
    ``answer(returned, arguments)``, if given, makes the answer from what it
    returned and the arguments after the call (a window painted into);
    otherwise the answer is what it returned, and None is reported as a
    missing ``return``.

    ``convert`` turns the answer into the reference's form (a tuple into an
    array, say; an :class:`AnswerError` it raises is the report's words)
    before ``compare(expected, given)``. Stops at the first wrong answer, or
    at the first exception the student's code raises (naming their line),
    and reports that case: its inputs, both answers, ``difference(expected,
    given)``, ``explain(case, expected, given)``, the mistake of
    ``mistakes`` whose answer the student's matches, ``picture(case,
    expected, given)`` and the next step of ``hint``. ``watch()``, if given,
    makes a context manager the student's code runs under, each case anew
    (:func:`call_budget`); ``forbidden`` maps the library's own answers to
    the message given when the student's code calls or names one. On a pass,
    ``pass_picture`` draws the (case, expected, given) of every case.
    """
    if not callable(student):
        raise TypeError(f"{exercise}: expected a function to check; got {type(student).__name__}")
    cases = _validated_cases(cases)
    report = _Report(exercise, hint)
    parameters = tuple(cases[0]) if cases else ()
    mismatch = arity_problem(student, parameters)
    if mismatch is not None:
        return report.fail(0, [f"your function cannot be called as the handout does: {mismatch}"])
    forbidden = dict(forbidden or {})
    if forbidden:
        named = forbidden.get(student) if _hashable(student) else None
        named = named or _references(student, forbidden)
        if named is not None:
            return report.fail(0, [named])

    def guarded() -> AbstractContextManager[Any]:
        stack = ExitStack()
        if forbidden:
            stack.enter_context(call_budget(forbidden=forbidden))
        if watch is not None:
            stack.enter_context(watch())
        return stack

    results: list[tuple[Case, Any, Any]] = []
    count = 0
    for count, case in enumerate(cases, start=1):
        inputs = ", ".join(f"{name}={_show(value)}" for name, value in case.items())
        expected = reference(**case)
        arguments = copies(tuple(case.values()))
        try:
            returned = run_bounded(
                lambda arguments=arguments: student(*arguments),
                seconds=seconds,
                memory=memory,
                watch=guarded if (forbidden or watch is not None) else None,
            )
        except CaseStopped as stopped:
            return report.fail(
                count, [f"case {count} was stopped: {stopped}", f"  inputs: {inputs}"]
            )
        except CallBudget as stopped:
            reason, *known = str(stopped).split("\n", 1)
            lines = [f"case {count} was stopped: {reason}", f"  inputs: {inputs}", *known]
            return report.fail(count, lines, mistake=stopped.mistake)
        except NotImplementedError as error:
            return report.fail(
                count,
                [
                    f"not written yet: your function raised NotImplementedError: {error}",
                    report.start(),
                ],
                hinted=False,
            )
        except Exception as error:  # the student's bug, reported, not raised
            line = student_line(error)
            lines = [f"case {count} raised {type(error).__name__}: {error}"]
            if line is not None:
                lines.append(f"  at {line}")
            return report.fail(count, [*lines, f"  inputs: {inputs}"])
        names = tuple(name for name in parameters if name not in writable)
        keep = [i for i, name in enumerate(parameters) if name not in writable]
        changed = changed_argument(
            names, tuple(case[n] for n in names), tuple(arguments[i] for i in keep)
        )
        if changed is not None:
            lines = [
                f"case {count} changed its input {changed}",
                "  your function must leave its inputs as they were: work on a copy "
                "(np.array(x, dtype=float) or x.copy())",
                f"  inputs: {inputs}",
            ]
            if on_change:
                lines.append(f"  {on_change}")
            return report.fail(count, lines)
        if answer is None and returned is None:
            if is_stub(student):
                return report.fail(
                    count,
                    ["not written yet: your function returns nothing", report.start()],
                    hinted=False,
                )
            return report.fail(
                count,
                [f"case {count} returned None: did you forget `return`?", f"  inputs: {inputs}"],
            )
        raw = answer(returned, arguments) if answer is not None else returned
        if _holds_complex(raw):
            return report.fail(
                count,
                [
                    f"case {count}: your answer holds complex numbers; the answer is real",
                    f"  inputs: {inputs}",
                ],
            )
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                given = convert(raw)
        except AnswerError as unreadable:
            return report.fail(
                count,
                [f"case {count}: your answer cannot be read: {unreadable}", f"  inputs: {inputs}"],
            )
        except Exception as unreadable:
            return report.fail(
                count,
                [
                    f"case {count}: your answer, {_described(raw)}, cannot be read as the "
                    f"exercise's answer ({type(unreadable).__name__}: {unreadable})",
                    "  (the checker raised this while reading your answer; your function ran "
                    "without an error)",
                    f"  inputs: {inputs}",
                ],
            )
        bad = _non_finite(given)
        if bad is not None:
            lines = [f"case {count}: {bad}", f"  inputs: {inputs}"]
            # A mistake with its own rule may expect NaN (an empty window's mean).
            known = _recognise([m for m in mistakes if m.matches], case, given, compare)
            if known is not None:
                lines.append(f"This is a known mistake, {known.name}: {known.explanation}")
            return report.fail(count, lines, mistake=None if known is None else known.name)
        try:
            same = compare(expected, given)
        except (TypeError, ValueError):
            same = False
        if same:
            results.append((case, expected, given))
            continue
        writer = show or _show
        lines = [
            f"case {count} is wrong",
            f"  inputs: {inputs}",
            f"  expected: {_quietly(writer, expected)}",
            f"  given:    {_quietly(writer, given) or _described(raw)}",
        ]
        for extra in (_quietly(difference, expected, given), _narrow_float(raw, compare)):
            if extra:
                lines.append(f"  {extra}")
        if explain is not None:
            said = _quietly(explain, case, expected, given)
            if said:
                lines.append(f"  {said}")
        known = _recognise(mistakes, case, given, compare)
        if known is not None:
            lines.append(f"This is a known mistake, {known.name}: {known.explanation}")
        drawn = _quietly(picture, case, expected, given)
        return report.fail(
            count, lines, picture=drawn, mistake=None if known is None else known.name
        )
    drawn = _quietly(pass_picture, results)
    return CheckResult(exercise, True, count, f"all {count} cases pass", picture=drawn)


def _hashable(value: Any) -> bool:
    try:
        hash(value)
    except TypeError:
        return False
    return True


def _described(value: Any) -> str:
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape} and dtype {value.dtype}"
    if isinstance(value, (list, tuple)):
        return f"a {type(value).__name__} of {len(value)} items"
    return f"a {type(value).__name__}"


def _recognise(
    mistakes: Sequence[Mistake], case: Case, given: Any, compare: Callable[[Any, Any], bool]
) -> Mistake | None:
    """The first mistake whose answer for ``case`` is the student's."""
    for mistake in mistakes:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                if (mistake.matches or compare)(mistake.answer(**copies_of(case)), given):
                    return mistake
        except Exception:
            continue
    return None


def copies_of(case: Case) -> dict[str, Any]:
    """A case with every input deep-copied, for code that may write into it."""
    return dict(zip(case, copies(tuple(case.values())), strict=True))
