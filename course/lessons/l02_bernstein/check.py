"""Lesson 02's checkers: binomial coefficients by Pascal's rule, and ``naive_bezier``.

``comb(m, n)`` is seed 002's function: the binomial coefficient C(m, n) as
an exact integer (0 when n > m), built by Pascal's rule C(m, n) = C(m - 1, n)
+ C(m - 1, n - 1). Python's own ``math.comb`` and the library's binomials
are not accepted, and the handout's recursion, which computes the same
coefficients again and again, is stopped after a budget of calls and named.
``naive_bezier(control_points, t)`` is the Bernstein form of any degree,
checked up to degree 40, where 32-bit binomials have long overflowed.

Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("comb")`` says more at once and
``check.hint("comb", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

import itertools
import math
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np

from course.check.base import (
    CheckResult,
    Mistake,
    call_budget,
    close,
    hint,
    run_cases,
)
from course.check.exercises import exercise
from course.check.hints import Hints, failure_hint
from course.check.sandbox import run_bounded
from course.curves.bezier import bernstein_basis, bezier_bernstein, binomial, pascal_row
from course.curves.bezier_handouts import (
    comb_recursive_calls,
    de_casteljau_reversed,
    pascal_row_int32,
)
from course.i18n import N_, _
from course.lessons.l01_de_casteljau.check import (
    as_point,
    curve_cases,
    curve_pass_picture,
    library_curves,
    point_picture,
)
from course.lessons.l02_bernstein.code_reading import multiplies, names_comb
from course.lessons.l02_bernstein.drawn import drawn_comb_cases, drawn_naive_cases

__all__ = ["COMB_CASES", "MAX_CALLS", "comb", "hint", "naive_bezier"]

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
        (2, 7),
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
    """An integer equal to C(m, n): a float, even 10.0, is not a sum of integers."""
    integer = isinstance(given, (int, np.integer)) and not isinstance(given, (bool, np.bool_))
    return integer and given == expected


def _binomials(refused: str | None = None) -> dict[Any, str]:
    """The ready-made binomials a comb must not call: Python's, the library's, scipy's.

    ``refused`` says why (by default, comb's own reason: Pascal's rule).
    """
    if refused is None:
        refused = _("this exercise builds the coefficients itself, by Pascal's rule")
    called = _("{function} was called: {refused}")
    forbidden = {
        math.comb: called.format(function="math.comb", refused=refused),
        math.perm: called.format(function="math.perm", refused=refused),
        math.factorial: _("{function} was called: {refused}, not from factorials").format(
            function="math.factorial", refused=refused
        ),
        binomial: called.format(function="course.curves.bezier.binomial", refused=refused),
        pascal_row: called.format(function="course.curves.bezier.pascal_row", refused=refused),
    }
    special = sys.modules.get("scipy.special")  # not imported: the student cannot call it
    if special is not None:
        for name in ("comb", "binom", "perm", "factorial"):
            if hasattr(special, name):
                forbidden[getattr(special, name)] = called.format(
                    function=f"scipy.special.{name}", refused=refused
                )
    return forbidden


def _naive_refusals() -> dict[Any, str]:
    """The library's curves and binomials: naive_bezier weights the points with its own comb."""
    return {
        **library_curves(),
        **_binomials(_("this exercise weights the points with your own comb")),
    }


@contextmanager
def _pascal_only() -> Iterator[None]:
    exponential = Mistake(
        N_("the exponential recursion"),
        _(
            "comb(m - 1, n) + comb(m - 1, n - 1) computes the same coefficients again and "
            "again, as the any-degree report's comb does: comb(40, 20) alone would make "
            "{calls} calls. Keep each coefficient once: build Pascal's triangle row by row (or "
            "remember the coefficients already computed)."
        ).format(calls=f"{comb_recursive_calls(40, 20):.2g}"),
        lambda m, n: None,
    )
    with call_budget(MAX_CALLS, too_many=exponential):
        yield


COMB_HINTS = Hints(
    where=N_("look at the first rows of Pascal's triangle, and at what your code does when n > m."),
    more=N_(
        "row 0 is [1]; each next row is made from the one above it, entry by entry, so "
        "each coefficient is computed once; C(m, n) is entry n of row m, and 0 when n > m."
    ),
    recipe=N_(
        "start from row = [1]; m times, make the next row: 1, then the sums of the "
        "neighbouring pairs of the row above, then 1. Return row[n] (0 if n > m)."
    ),
)


def _graded_comb(m: int, n: int) -> int:
    """The grader's answer to ``comb``: row m of Pascal's triangle, exact integers."""
    row = [1]
    for _row in range(m):
        row = [1, *(a + b for a, b in itertools.pairwise(row)), 1]
    return row[n] if 0 <= n <= m else 0


@exercise(
    hints=COMB_HINTS,
    refuses=_binomials,
    grader_reference=_graded_comb,
    draw=lambda rng: drawn_comb_cases(rng, MAX_CALLS),
)
def comb(function: Callable[..., Any]) -> CheckResult:
    """Check a student's ``comb(m, n)``: C(m, n) by Pascal's rule, as an exact integer.

    Examples
    --------
    >>> import math
    >>> comb(math.comb).passed
    False
    """
    product = multiplies(function)
    not_pascal = _(
        "your comb multiplies or divides ({product}), as the formula m! / (n! (m - n)!) does, "
        "and gets this case wrong. The exercise builds each coefficient from the two above it, "
        "C(m, n) = C(m - 1, n - 1) + C(m - 1, n), adding integers only."
    ).format(product=product)
    if product is not None and "/" in product.replace("//", ""):
        not_pascal += " " + _(
            "With / the product is a float, which keeps about 16 significant digits, and "
            "int(round(...)) cannot bring back the ones lost: C(67, 33) has 20."
        )
    mistakes = [
        Mistake(
            N_("32-bit integers"),
            _(
                "your coefficients wrapped around: C(34, 17) = 2,333,606,220 does not fit in a "
                "32-bit int (the C++ handouts' int), and numpy's int32 wraps silently. Python's "
                "int is exact at any size: keep the row in a list of Python ints."
            ),
            lambda m, n: _entry(_row_with_overflow(m, np.int32), n),
        ),
        Mistake(
            N_("64-bit integers"),
            _(
                "your coefficients wrapped around at C(67, 33), which needs 65 bits: a numpy int64 "
                "array overflows silently. Keep the row in a list of Python ints, which are exact."
            ),
            lambda m, n: _entry(_row_with_overflow(m, np.int64), n),
        ),
        Mistake(
            N_("floating point"),
            _(
                "your answer is a float: a float holds whole numbers exactly only up to "
                "2^53, about 9 * 10^15, and C(67, 33) is about 1.4 * 10^19. A binomial "
                "coefficient is an integer: add integers only (in Python, / makes a float "
                "even when the division is exact; Pascal's rule needs no division)."
            ),
            lambda m, n: binomial(m, n) if n <= m else 0,
            matches=lambda exact, given: (
                isinstance(given, (float, np.floating))
                and math.isclose(given, exact, rel_tol=1e-9, abs_tol=1e-9)
            ),
        ),
        Mistake(
            N_("the arguments swapped"),
            _("you computed C(n, m): comb(m, n) is entry n of row m, the row first."),
            lambda m, n: binomial(n, m) if m <= n else 0,
        ),
        Mistake(
            N_("off by one row"),
            _(
                "you returned C(m - 1, n): the row of Pascal's triangle for m is reached after m "
                "steps from the row [1] (row 0)."
            ),
            lambda m, n: binomial(m - 1, n) if m >= 1 else 0,
        ),
        Mistake(
            N_("off by one row"),
            _(
                "you returned C(m + 1, n): the row of Pascal's triangle for m is reached after m "
                "steps from the row [1] (row 0), not m + 1."
            ),
            lambda m, n: binomial(m + 1, n),
        ),
        # Last: a comb that multiplies and fails in a way none of the above explains (a float
        # product rounded back to an int loses digits past 2^53).
        Mistake(
            N_("not Pascal's rule"),
            not_pascal,
            lambda m, n: None,
            matches=lambda expected, given: product is not None,
        ),
    ]
    result = run_cases(
        "comb",
        function,
        COMB_CASES,
        reference=lambda m, n: binomial(m, n) if n <= m else 0,
        compare=_exact,
        mistakes=mistakes,
        watch=_pascal_only,
    )
    if not result.passed or product is None:
        return result
    lines = [
        _(
            "your comb gives the right numbers, but not by Pascal's rule: it multiplies "
            "or divides ({product}), as the formula m! / (n! (m - n)!) does."
        ).format(product=product),
        _(
            "  The exercise builds each coefficient from the two above it, C(m, n) = "
            "C(m - 1, n - 1) + C(m - 1, n), adding integers only: that is what the lesson's "
            "Bernstein-to-de Casteljau step uses. Well done on the numbers; now try it with "
            "additions."
        ),
        _('Hint: {where}\n(More: check.hint("comb").)').format(where=_(COMB_HINTS.where)),
    ]
    return CheckResult(
        "comb", False, result.cases_run, "\n".join(lines), mistake=N_("not Pascal's rule")
    )


def _degree_off_by_one(control_points: np.ndarray, t: float) -> np.ndarray:
    count = len(control_points)
    return (bernstein_basis(count, t)[0, :count] @ control_points).reshape(-1)


def _int32_weights(control_points: np.ndarray, t: float) -> np.ndarray:
    n = len(control_points) - 1
    i = np.arange(n + 1)
    weights = pascal_row_int32(n).astype(float) * t**i * (1 - t) ** (n - i)
    return weights @ control_points


#: The degree at which the weights are probed for overflow: the high-degree case's.
_PROBED_DEGREE = 40


def _overflowed(student: Callable[..., Any]) -> bool:
    """Whether ``student`` is the Bernstein sum of degree 40 with wrong whole-number binomials,
    as a comb in fixed-width integers gives once C(40, i), or a product that makes it, wraps.

    The curve is linear in its points, so the weight of P[i] is the x of the curve whose
    points are all (0, 0) but P[i] = (1, 0); divided by t^i (1 - t)^(40 - i) it is the
    student's C(40, i), the same at t = 1/2 and t = 1/4 when the sum is the Bernstein form.
    """
    n = _PROBED_DEGREE
    i = np.arange(n + 1)
    binomials = []
    for t in (0.5, 0.25):
        found = []
        for row in range(n + 1):
            unit = np.zeros((n + 1, 2))
            unit[row, 0] = 1.0
            point = run_bounded(lambda unit=unit, t=t: student(unit, t))
            found.append(float(np.asarray(point, dtype=float).reshape(-1)[0]))
        binomials.append(np.array(found) / (t**i * (1 - t) ** (n - i)))
    half, quarter = binomials
    exact = np.array([float(binomial(n, k)) for k in range(n + 1)])
    whole = np.isclose(half, np.round(half), rtol=1e-9, atol=1e-6)
    same = np.isclose(half, quarter, rtol=1e-6, atol=1e-6)
    return bool(whole.all() and same.all() and not np.isclose(half, exact, rtol=1e-9).all())


def _high_degree_cases() -> list[dict[str, Any]]:
    """A curve of 41 control points: C(40, 20) > 2^31, so 32-bit binomials wrap around."""
    rng = np.random.default_rng(41)
    points = rng.uniform(0, 700, (41, 2)).round(1)
    return [{"control_points": points, "t": t} for t in (0.25, 0.5)]


NAIVE_HINTS = Hints(
    where=N_(
        "look at the degree n, at the weight each control point gets, and at where your sum starts."
    ),
    more=N_(
        "a curve of N control points has degree n = N - 1; point i is weighted by "
        "its Bernstein polynomial, built from your comb(n, i) and powers of t and 1 - t, "
        "and the weights add up to 1. Each call starts its sum from zero."
    ),
    recipe=N_(
        "n = len(control_points) - 1; return the sum over i = 0 ... n of comb(n, i) "
        "t^i (1 - t)^(n - i) control_points[i]."
    ),
)


@exercise(
    hints=NAIVE_HINTS,
    refuses=_naive_refusals,
    draw=drawn_naive_cases,
)
def naive_bezier(function: Callable[..., Any]) -> CheckResult:
    """Check a student's Bernstein-form ``naive_bezier(control_points, t)`` of any degree.

    Compared with the library's Bernstein form on curves of 2 to 12 control
    points and one of 41, to 1e-9. Right points computed without ``comb`` (a
    de Casteljau loop) fail as "not the Bernstein sum", when the code can be
    read. A pass shows the student's points on seed 000's curve.

    Examples
    --------
    >>> from course.curves.bezier_handouts import de_casteljau_reversed
    >>> naive_bezier(de_casteljau_reversed).mistake
    'the reversed weights'
    """
    history: list[np.ndarray] = []
    with_comb = names_comb(function)
    another_way = _(
        "your naive_bezier never calls your comb: it computes the curve another way (by "
        "repeated interpolation, as lesson 01's de Casteljau, or by a sum without the "
        "binomial coefficients). The exercise is the Bernstein sum, each control point P[i] "
        "weighted by comb(n, i) t^i (1 - t)^(n - i), with the comb you wrote in exercise 1."
    )

    def curve(control_points: np.ndarray, t: float) -> np.ndarray:
        point = bezier_bernstein(control_points, t)
        history.append(point)
        return point

    mistakes = [
        Mistake(
            _("the reversed weights"),
            _(
                "your curve runs backwards: you weighted P[i] by C(n, i) t^(n-i) (1 - t)^i. The "
                "Bernstein weight of P[i] is C(n, i) t^i (1 - t)^(n-i), so that B(0) = P0."
            ),
            lambda control_points, t: de_casteljau_reversed(control_points, t),
        ),
        Mistake(
            _("the binomial upside down"),
            _(
                "you weighted P[i] by comb(i, n), the binomial upside down, as the any-degree "
                "report's formula writes it (i on top, n - 1 below, for its n points): C(i, n) "
                "is 0 for every i < n, so your curve is t^n P[n] alone. The weight of P[i] is "
                "comb(n, i) t^i (1 - t)^(n - i): n choose i, the degree on top."
            ),
            lambda control_points, t: t ** (len(control_points) - 1) * control_points[-1],
        ),
        Mistake(
            _("the degree off by one"),
            _(
                "you used n = len(control_points); the degree is one less, n = N - 1, so that "
                "the N weights C(n, i) t^i (1 - t)^(n-i), i = 0 ... n, add up to 1."
            ),
            _degree_off_by_one,
        ),
        Mistake(
            _("x and y swapped"),
            _("your point is (y, x): return x first, as the control points' columns are x, y."),
            lambda control_points, t: bezier_bernstein(control_points, t)[::-1],
        ),
        Mistake(
            _("32-bit binomials"),
            _(
                "your binomials wrapped around at degree 40: C(40, 20) does not fit in a 32-bit "
                "int. Use your comb, which gives Python's exact ints."
            ),
            _int32_weights,
        ),
        Mistake(
            _("binomials that overflow"),
            _(
                "your binomials overflowed: your sum is right up to degree 11, but at degree 40 "
                "some of your comb(40, i) are wrong. C(40, 20) = 137,846,528,820 needs 38 bits, "
                "and the products that make it (40!, or 40 * 39 * ... before a division) need "
                "more; numpy's int32 and int64 wrap around silently. Keep np.int32 and np.int64 "
                "out of your comb: Python's int is exact at any size."
            ),
            lambda control_points, t: None if len(control_points) <= 12 else True,
            matches=lambda high_degree, given: high_degree is True and _overflowed(function),
        ),
        Mistake(
            _("an accumulator not reset"),
            _(
                "your answer is the sum of this point and the ones before it: the sum must start "
                "from zero at each call (the any-degree report's own remark about its point "
                "declared outside the loop)."
            ),
            lambda control_points, t: np.sum(history, axis=0),
        ),
        # Last: a wrong answer that weights nothing by comb, and no other mistake explains.
        Mistake(
            N_("not the Bernstein sum"),
            another_way,
            lambda control_points, t: None,
            matches=lambda expected, given: with_comb is False,
        ),
    ]
    result = run_cases(
        "naive_bezier",
        function,
        curve_cases(max_points=12) + _high_degree_cases(),
        reference=curve,
        compare=close(atol=1e-9, rtol=1e-9),
        convert=as_point,
        mistakes=mistakes,
        picture=point_picture(bezier_bernstein, N_("your naive_bezier")),
        pass_picture=curve_pass_picture(bezier_bernstein, "naive_bezier"),
    )
    if not result.passed or with_comb is not False:
        return result
    lines = [
        _("your naive_bezier gives the right points, but not by the Bernstein sum."),
        f"  {another_way}",
        failure_hint("naive_bezier", NAIVE_HINTS, 1),
    ]
    return CheckResult(
        "naive_bezier",
        False,
        result.cases_run,
        "\n".join(lines),
        mistake=N_("not the Bernstein sum"),
    )
