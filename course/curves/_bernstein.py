"""The Bernstein form on checked input: Pascal's rows, binomials, the basis, the two sums.

Kernels behind :func:`course.curves.bezier.pascal_row`, :func:`~course.curves.bezier.binomial`,
:func:`~course.curves.bezier.bernstein_basis` and the two forms of
:func:`~course.curves.bezier.bezier_bernstein` (``"loop"``: :func:`bernstein_loop`,
``"horner"``: :func:`horner_or_basis`), which check their arguments before they call these;
the accuracy study (:mod:`course.curves.bezier_accuracy`) and the handouts' loops
(:mod:`course.curves.handout_loops`) evaluate their checked curves with them. The rows of
Pascal's triangle are kept here, one cache for all of them (:func:`pascal_row`).

Unchecked kernels: this module trusts its callers and checks no input
(``UNCHECKED = True``, which the fuzz test reads). :func:`require_bernstein_degree` bounds
the degree a checked curve may have in the float form, as :mod:`course.limits` bounds work.
"""

from __future__ import annotations

import itertools
from functools import lru_cache

import numpy as np

from course.curves._bezier_fast import bernstein_horner
from course.i18n import _

__all__ = [
    "HORNER_MAX_DEGREE",
    "MAX_BERNSTEIN_DEGREE",
    "bernstein_basis",
    "bernstein_loop",
    "binomial",
    "horner_or_basis",
    "pascal_row",
    "require_bernstein_degree",
]

UNCHECKED = True  # kernels for checked callers; see the module docstring

# Beyond this degree some binomial(n, k) exceeds the largest float64.
MAX_BERNSTEIN_DEGREE = 1029
# Up to this degree Horner's rule in t / (1 - t) cannot overflow for any
# sensible coordinates (C(128, 64) < 2^127); beyond it the basis matrix does.
HORNER_MAX_DEGREE = 128


@lru_cache(maxsize=64)
def pascal_row(n: int) -> tuple[int, ...]:
    """Row n >= 0 of Pascal's triangle, exact, each row built from the one above it;
    the last 64 rows asked for are kept.

    Examples
    --------
    >>> pascal_row(4)
    (1, 4, 6, 4, 1)
    """
    row: tuple[int, ...] = (1,)
    for _row in range(n):
        row = (1, *(a + b for a, b in itertools.pairwise(row)), 1)
    return row


def binomial(n: int, k: int) -> int:
    """C(n, k) of integers n >= 0 and k, read from :func:`pascal_row`; 0 when k < 0 or k > n.

    Examples
    --------
    >>> binomial(4, 2), binomial(4, 5)
    (6, 0)
    """
    if k < 0 or k > n:
        return 0
    return pascal_row(n)[k]


def bernstein_basis(n: int, t: np.ndarray) -> np.ndarray:
    """(M, n + 1) Bernstein polynomials of degree 0 <= n <= 1029 at ``t`` (M,).

    Examples
    --------
    >>> bernstein_basis(2, np.array([0.5]))
    array([[0.25, 0.5 , 0.25]])
    """
    t = t[:, None]
    exponents = np.arange(n + 1)
    coefficients = np.array([float(c) for c in pascal_row(n)])
    # binomial * t^i stays below C(n, n/2) <= 2^n, so no overflow before the
    # (1 - t) power scales it down.
    return (coefficients * t**exponents) * (1.0 - t) ** exponents[::-1]


def horner_or_basis(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(M, d) points of the curve ``control`` (N, d) at ``t`` (M,): Horner's rule in
    t / (1 - t) up to degree 128, the basis matrix beyond.

    Examples
    --------
    >>> horner_or_basis(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]), np.array([0.5]))
    array([[1., 1.]])
    """
    degree = len(control) - 1
    if degree > HORNER_MAX_DEGREE:
        return bernstein_basis(degree, t) @ control
    binomials = np.array([float(c) for c in pascal_row(degree)])
    return bernstein_horner(control, binomials, t)


def bernstein_loop(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(M, d) points of the curve ``control`` (N, d) at ``t`` (M,) by the handouts' sum,
    one term C(n, i) (1 - t)^(n - i) t^i P[i] at a time.

    Examples
    --------
    >>> bernstein_loop(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]), np.array([0.25]))
    array([[0.5 , 0.75]])
    """
    n = len(control) - 1
    t = t[:, None]
    curve = np.zeros((len(t), control.shape[1]))
    for i, point in enumerate(control):
        curve += float(binomial(n, i)) * (1 - t) ** (n - i) * t**i * point
    return curve


def require_bernstein_degree(control: np.ndarray) -> None:
    """ValueError unless the checked curve ``control`` has degree at most 1029, where the
    float Bernstein form's binomials still fit float64."""
    if len(control) - 1 > MAX_BERNSTEIN_DEGREE:
        raise ValueError(
            _(
                "points: the float Bernstein form works up to degree {most} "
                "({most_points} points); got {control_count} points. Use de_casteljau."
            ).format(
                most=MAX_BERNSTEIN_DEGREE,
                most_points=MAX_BERNSTEIN_DEGREE + 1,
                control_count=len(control),
            )
        )
