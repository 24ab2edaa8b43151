"""The machinery behind every exercise checker.

A checker runs the student's function on a list of cases, compares each
answer with the library's reference, and reports either a pass or the first
failing case with its inputs, the expected value and the value given.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["CheckResult", "close", "run_cases"]


@dataclass(frozen=True)
class CheckResult:
    """The outcome of checking one exercise; truthy when it passed."""

    exercise: str
    passed: bool
    cases_run: int
    message: str

    def __bool__(self) -> bool:
        return self.passed

    def __str__(self) -> str:
        mark = "PASS" if self.passed else "FAIL"
        return f"{mark} {self.exercise}: {self.message}"

    __repr__ = __str__


def _show(value: Any) -> str:
    if isinstance(value, np.ndarray):
        return np.array2string(value, precision=6, separator=", ", threshold=40)
    if isinstance(value, float):
        return f"{value:.6g}"
    return repr(value)


def close(atol: float = 1e-9, rtol: float = 1e-9) -> Callable[[Any, Any], bool]:
    """A comparison: same shape and equal within the tolerances."""

    def compare(expected: Any, given: Any) -> bool:
        expected, given = np.asarray(expected, dtype=float), np.asarray(given, dtype=float)
        return expected.shape == given.shape and bool(
            np.allclose(given, expected, atol=atol, rtol=rtol)
        )

    return compare


def run_cases(
    exercise: str,
    student: Callable[..., Any],
    cases: Iterable[Mapping[str, Any]],
    reference: Callable[..., Any],
    compare: Callable[[Any, Any], bool],
    convert: Callable[[Any], Any] = lambda value: value,
) -> CheckResult:
    """Call ``student(**case)`` and ``reference(**case)`` for every case.

    ``convert`` turns the student's answer into the reference's form (for
    example a tuple into an array) before ``compare(expected, given)``.
    Stops at the first failure, or at the first exception the student's code
    raises, and names the case.
    """
    if not callable(student):
        raise TypeError(f"{exercise}: expected a function to check; got {type(student).__name__}")
    count = 0
    for count, case in enumerate(cases, start=1):
        inputs = ", ".join(f"{name}={_show(value)}" for name, value in case.items())
        expected = reference(**case)
        try:
            given = convert(student(**{k: _copy(v) for k, v in case.items()}))
        except Exception as error:  # the student's bug, reported, not raised
            return CheckResult(
                exercise,
                False,
                count,
                f"case {count} raised {type(error).__name__}: {error}\n  inputs: {inputs}",
            )
        try:
            same = compare(expected, given)
        except (TypeError, ValueError):
            same = False
        if not same:
            return CheckResult(
                exercise,
                False,
                count,
                f"case {count} is wrong\n  inputs: {inputs}\n  expected: {_show(expected)}\n"
                f"  given:    {_show(given)}",
            )
    return CheckResult(exercise, True, count, f"all {count} cases pass")


def _copy(value: Any) -> Any:
    """Students get copies, so a function that mutates its input cannot corrupt the next case."""
    return value.copy() if isinstance(value, np.ndarray) else value
