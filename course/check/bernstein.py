"""Lesson 02's checkers: binomial coefficients by Pascal's rule, and ``naive_bezier``.

``comb(m, n)`` is seed 002's function: the binomial coefficient C(m, n) as
an exact integer (0 when n > m), built by Pascal's rule C(m, n) = C(m - 1, n)
+ C(m - 1, n - 1). Python's own ``math.comb`` and the library's binomials
are not accepted, and the handout's recursion, which computes the same
coefficients again and again, is stopped after a budget of calls and named.
``naive_bezier(control_points, t)`` is the Bernstein form of any degree.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np

from course.bezier import bernstein_basis, bezier_bernstein, binomial, pascal_row
from course.bezier_handouts import comb_recursive_calls, de_casteljau_reversed, pascal_row_int32
from course.check.base import CheckResult, Mistake, call_budget, close, run_cases
from course.check.de_casteljau import as_point, curve_cases, curve_picture_of, positional

__all__ = ["COMB_CASES", "MAX_CALLS", "comb", "naive_bezier"]

#: Small cases first, then the sizes where 32-bit and 64-bit integers overflow
#: (C(34, 17) > 2^31, C(67, 33) > 2^63), and C(100, 50), 30 digits long.
COMB_CASES = tuple(
    {"m": m, "n": n}
    for m, n in (
        (0, 0),
        (1, 0),
        (1, 1),
        (5, 2),
        (6, 3),
        (10, 0),
        (10, 10),
        (3, 5),
        (20, 7),
        (34, 17),
        (40, 20),
        (67, 33),
        (100, 50),
    )
)
#: Python calls allowed per case: enough to build Pascal's triangle to C(100, 50) (about
#: 5000 entries) even one call per entry, far too few for the handout's recursion.
MAX_CALLS = 20_000


def _row_with_overflow(m: int, dtype: type) -> np.ndarray:
    """Pascal's row m in fixed-width integers, wrapping around as C's do."""
    if dtype is np.int32:
        return pascal_row_int32(m)
    row = np.ones(1, dtype=dtype)
    with np.errstate(over="ignore"):
        for _ in range(m):
            row = np.concatenate([row[:1], row[:-1] + row[1:], row[-1:]])
    return row


def _entry(row: np.ndarray, n: int) -> int:
    return int(row[n]) if 0 <= n < len(row) else 0


def _exact(expected: int, given: Any) -> bool:
    return not isinstance(given, bool) and given == expected


@contextmanager
def _pascal_only() -> Iterator[None]:
    refused = "this exercise builds the coefficients itself, by Pascal's rule"
    forbidden = {
        math.comb: f"math.comb was called: {refused}",
        math.perm: f"math.perm was called: {refused}",
        math.factorial: f"math.factorial was called: {refused}, not from factorials",
        binomial: f"course.bezier.binomial was called: {refused}",
        pascal_row: f"course.bezier.pascal_row was called: {refused}",
    }
    exponential = Mistake(
        "the exponential recursion",
        "comb(m - 1, n) + comb(m - 1, n - 1) computes the same coefficients again and again, "
        "as the any-degree report's comb does: comb(40, 20) alone would make "
        f"{comb_recursive_calls(40, 20):.2g} calls. "
        "Keep each coefficient once: build Pascal's triangle row by row (or remember the "
        "coefficients already computed).",
        lambda m, n: None,
    )
    with call_budget(MAX_CALLS, forbidden, too_many=exponential):
        yield


def comb(function: Callable[..., Any]) -> CheckResult:
    """Check a student's ``comb(m, n)``: C(m, n) by Pascal's rule, as an exact integer.

    Examples
    --------
    >>> def comb_by_rows(m, n):
    ...     row = [1]
    ...     for _ in range(m):
    ...         row = [1] + [a + b for a, b in zip(row, row[1:])] + [1]
    ...     return row[n] if n <= m else 0
    >>> comb(comb_by_rows)
    PASS comb: all 13 cases pass
    >>> import math
    >>> comb(math.comb).passed
    False
    """
    student = (lambda m, n: function(m, n)) if callable(function) else function
    mistakes = [
        Mistake(
            "32-bit integers",
            "your coefficients wrapped around: C(34, 17) = 2,333,606,220 does not fit in a "
            "32-bit int (the C++ handouts' int), and numpy's int32 wraps silently. Python's int "
            "is exact at any size: keep the row in a list of Python ints.",
            lambda m, n: _entry(_row_with_overflow(m, np.int32), n),
        ),
        Mistake(
            "64-bit integers",
            "your coefficients wrapped around at C(67, 33), which needs 65 bits: a numpy int64 "
            "array overflows silently. Keep the row in a list of Python ints, which are exact.",
            lambda m, n: _entry(_row_with_overflow(m, np.int64), n),
        ),
        Mistake(
            "floating point",
            "your answer is a float: a float keeps about 16 significant digits, and C(67, 33) "
            "has 20. Add integers only.",
            lambda m, n: binomial(m, n),
            matches=lambda exact, given: (
                isinstance(given, float) and math.isclose(given, exact, rel_tol=1e-9)
            ),
        ),
        Mistake(
            "off by one row",
            "you returned C(m - 1, n): the row of Pascal's triangle for m is reached after m "
            "steps from the row [1] (row 0).",
            lambda m, n: binomial(m - 1, n) if m >= 1 else 0,
        ),
        Mistake(
            "off by one row",
            "you returned C(m + 1, n): the row of Pascal's triangle for m is reached after m "
            "steps from the row [1] (row 0), not m + 1.",
            lambda m, n: binomial(m + 1, n),
        ),
    ]
    return run_cases(
        "comb",
        student,
        COMB_CASES,
        reference=lambda m, n: binomial(m, n) if n <= m else 0,
        compare=_exact,
        hint="start from row 0 = [1]; each next row starts and ends with 1, and every entry "
        "in between is the sum of the two above it. Row m holds C(m, 0) ... C(m, m).",
        mistakes=mistakes,
        watch=_pascal_only,
    )


def _degree_off_by_one(control_points: np.ndarray, t: float) -> np.ndarray:
    count = len(control_points)
    return (bernstein_basis(count, t)[0, :count] @ control_points).reshape(-1)


def naive_bezier(function: Callable[..., Any]) -> CheckResult:
    """Check a student's Bernstein-form ``naive_bezier(control_points, t)`` of any degree.

    Compared with :func:`course.bezier.bezier_bernstein` on curves of 2 to
    12 control points, to 1e-9.

    Examples
    --------
    >>> from course.bezier import bezier_bernstein
    >>> naive_bezier(lambda control_points, t: bezier_bernstein(control_points, t))
    PASS naive_bezier: all 55 cases pass
    """
    student = positional(function)

    def curve(control_points: np.ndarray, t: float) -> np.ndarray:
        return bezier_bernstein(control_points, t)

    mistakes = [
        Mistake(
            "the reversed weights",
            "your curve runs backwards: you weighted P[i] by C(n, i) t^(n-i) (1 - t)^i. The "
            "Bernstein weight of P[i] is C(n, i) t^i (1 - t)^(n-i), so that B(0) = P0.",
            lambda control_points, t: de_casteljau_reversed(control_points, t),
        ),
        Mistake(
            "the degree off by one",
            "you used n = len(control_points); the degree is one less, n = N - 1, so that "
            "the N weights C(n, i) t^i (1 - t)^(n-i), i = 0 ... n, add up to 1.",
            _degree_off_by_one,
        ),
        Mistake(
            "x and y swapped",
            "your point is (y, x): return x first, as the control points' columns are x, y.",
            lambda control_points, t: curve(control_points, t)[::-1],
        ),
    ]
    return run_cases(
        "naive_bezier",
        student,
        curve_cases(max_points=12),
        reference=curve,
        compare=close(atol=1e-9, rtol=1e-9),
        convert=as_point,
        hint="with n = N - 1, add up C(n, i) t^i (1 - t)^(n-i) P[i] for i = 0 ... n; your comb "
        "gives C(n, i).",
        mistakes=mistakes,
        picture=curve_picture_of(student, curve, "your naive_bezier along the curve")
        if callable(function)
        else None,
    )
