"""Bézier curves: de Casteljau's algorithm and the Bernstein form.

A Bézier curve of degree n has n + 1 control points ``P[0] ... P[n]``, given as
a float array of shape ``(N, d)`` (one row per point, N = n + 1, any dimension
d >= 1). The parameter t follows the textbook: one de Casteljau step maps a
level to the next by ``(1 - t) * P[i] + t * P[i + 1]``, so ``B(0) = P[0]`` and
``B(1) = P[n]``. Parameters outside [0, 1] extrapolate the same polynomial.

Every public function validates its input once and never modifies it.

References
----------
.. [1] P. de Casteljau, "Courbes et surfaces à pôles", André Citroën, 1963.
.. [2] G. Farin, *Curves and Surfaces for CAGD*, 5th ed., Morgan Kaufmann, 2002,
   chapters 3-5 (de Casteljau, Bernstein form, subdivision, degree elevation).
.. [3] R. T. Farouki and V. T. Rajan, "On the numerical condition of polynomials
   in Bernstein form", CAGD 4(3), 1987.
"""

from __future__ import annotations

import sys
from typing import Any

import numpy as np

from course import limits
from course._validate import (
    as_choice,
    as_int,
    as_parameter,
    as_points,
    as_scalar_parameter,
)
from course.curves._bernstein import (
    MAX_BERNSTEIN_DEGREE,
    bernstein_loop,
    horner_or_basis,
    require_bernstein_degree,
)
from course.curves._bernstein import bernstein_basis as bernstein_basis_of
from course.curves._bernstein import binomial as binomial_of
from course.curves._bernstein import pascal_row as pascal_row_of
from course.curves._bezier_fast import de_casteljau_chunked, levels_at
from course.curves.flattening import uniform_parameters
from course.i18n import _

__all__ = [
    "BEZIER_BERNSTEIN_METHODS",
    "MAX_BERNSTEIN_DEGREE",
    "bernstein_basis",
    "bezier_bernstein",
    "binomial",
    "clear_pascal_cache",
    "de_casteljau",
    "de_casteljau_levels",
    "de_casteljau_recursive",
    "derivative",
    "elevate",
    "pascal_row",
    "sample_uniform",
    "split",
]


# --- de Casteljau ------------------------------------------------------------


def de_casteljau(points: Any, t: Any) -> np.ndarray:
    """Evaluate the Bézier curve at t by repeated linear interpolation.

    The iterative form: each level replaces N points by the N - 1 points
    ``(1 - t) * P[i] + t * P[i + 1]`` until one is left. It is vectorized over
    an array of parameters.

    Parameters
    ----------
    points : array_like, shape (N, d)
        Control points, one row per point. One point is a degree-0 curve.
    t : float or array_like, shape (M,)
        Parameters. Values outside [0, 1] extrapolate.

    Returns
    -------
    ndarray
        Shape (d,) for scalar t, (M, d) for an array of t.

    Examples
    --------
    >>> de_casteljau([[0, 0], [1, 2], [2, 0]], 0.5)
    array([1., 1.])
    >>> de_casteljau([[0, 0], [1, 2], [2, 0]], [0, 1])
    array([[0., 0.],
           [2., 0.]])
    """
    control = as_points(points)
    values, is_scalar = as_parameter(t)
    curve = _de_casteljau(control, values)
    return curve[0] if is_scalar else curve


def _de_casteljau(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(M, d) curve points; ``control`` (N, d), ``t`` (M,), both validated."""
    # The same step as de_casteljau_levels, on chunks of t that stay in cache.
    return de_casteljau_chunked(control, t)


def de_casteljau_recursive(points: Any, t: Any) -> np.ndarray:
    """The handouts' ``recursive_bezier``: de Casteljau by recursion, scalar t.

    Each call computes one level and recurses on it, so a curve with N control
    points needs N nested calls. Python limits nesting
    (``sys.getrecursionlimit()``, 1000 by default): when a curve would come
    near that limit this raises ``RecursionError`` up front, naming the degree
    and the limit, instead of failing deep inside the recursion.

    Parameters
    ----------
    points : array_like, shape (N, d)
        Control points.
    t : float
        One parameter value.

    Returns
    -------
    ndarray, shape (d,)
        The same value as ``de_casteljau(points, t)``.

    Examples
    --------
    >>> de_casteljau_recursive([[0, 0], [1, 2], [2, 0]], 0.25)
    array([0.5  , 0.75])
    """
    control = as_points(points)
    value = as_scalar_parameter(t)
    depth = _stack_depth()
    limit = sys.getrecursionlimit()
    # Headroom for numpy and the interpreter's own frames.
    needed = len(control) + 50
    if depth + needed > limit:
        raise RecursionError(
            f"de_casteljau_recursive: a degree-{len(control) - 1} curve needs "
            f"{len(control)} nested calls, and the stack is already {depth} deep; "
            f"Python's recursion limit is {limit}. Use de_casteljau (iterative), "
            f"or raise the limit with sys.setrecursionlimit({depth + needed + 100})."
        )
    return _recursive_step(control, value)


def _recursive_step(level: np.ndarray, t: float) -> np.ndarray:
    if len(level) == 1:
        return level[0].copy()
    return _recursive_step(level[:-1] * (1 - t) + level[1:] * t, t)


def _stack_depth() -> int:
    frame, depth = sys._getframe(), 0
    while frame is not None:
        frame, depth = frame.f_back, depth + 1
    return depth


def de_casteljau_levels(points: Any, t: Any) -> list[np.ndarray]:
    """Every intermediate level of de Casteljau's algorithm at one t.

    Returns
    -------
    list of ndarray
        ``[level0 (N, d), level1 (N - 1, d), ..., level(N-1) (1, d)]``:
        level 0 is the control polygon, the last level is the point B(t).
        There are N (N + 1) / 2 points in all: the O(n^2) work of one
        evaluation.

    Examples
    --------
    >>> for level in de_casteljau_levels([[0, 0], [2, 2], [4, 0]], 0.5):
    ...     print(level.tolist())
    [[0.0, 0.0], [2.0, 2.0], [4.0, 0.0]]
    [[1.0, 1.0], [3.0, 1.0]]
    [[2.0, 1.0]]
    """
    return levels_at(as_points(points), as_scalar_parameter(t))


# --- the Bernstein form ------------------------------------------------------


def pascal_row(n: int) -> tuple[int, ...]:
    """Row n of Pascal's triangle, exact: ``(C(n, 0), ..., C(n, n))``.

    Each row is built from the one above it, ``n (n + 1) / 2`` additions,
    and the last 64 rows asked for are kept (:func:`clear_pascal_cache`
    forgets them, to time the cold cost).

    Examples
    --------
    >>> pascal_row(4)
    (1, 4, 6, 4, 1)
    """
    return pascal_row_of(as_int(n, "n", minimum=0, maximum=limits.MAX_DEGREE))


def clear_pascal_cache() -> None:
    """Forget the rows :func:`pascal_row` keeps, so the next call builds its row anew."""
    pascal_row_of.cache_clear()


def binomial(n: int, k: int) -> int:
    """The binomial coefficient C(n, k), exactly, from Pascal's triangle.

    ``C(n, k) = C(n - 1, k - 1) + C(n - 1, k)``, computed row by row (not by
    the handouts' double recursion, which takes exponential time) and cached.
    Zero when k < 0 or k > n.

    Examples
    --------
    >>> [binomial(4, k) for k in range(5)]
    [1, 4, 6, 4, 1]
    >>> binomial(100, 50)
    100891344545564193334812497256
    """
    n = as_int(n, "n", minimum=0, maximum=limits.MAX_DEGREE)
    k = as_int(k, "k")
    return binomial_of(n, k)


def bernstein_basis(n: int, t: Any) -> np.ndarray:
    """The Bernstein basis polynomials of degree n at t.

    ``B[m, i] = C(n, i) * t[m]**i * (1 - t[m])**(n - i)``.

    Parameters
    ----------
    n : int
        Degree, 0 <= n <= 1029 (beyond that some C(n, i) overflows float64).
    t : float or array_like, shape (M,)

    Returns
    -------
    ndarray, shape (M, n + 1)
        One row per parameter (M = 1 for a scalar t). Each row sums to 1.

    Examples
    --------
    >>> bernstein_basis(2, [0.0, 0.5])
    array([[1.  , 0.  , 0.  ],
           [0.25, 0.5 , 0.25]])
    """
    n = as_int(n, "n", minimum=0)
    if n > MAX_BERNSTEIN_DEGREE:
        raise ValueError(
            _(
                "n must be <= {most} for the float Bernstein form (C(n, n/2) "
                "overflows float64 beyond it); got {n}. Use de_casteljau."
            ).format(most=MAX_BERNSTEIN_DEGREE, n=n)
        )
    values, _scalar = as_parameter(t)
    return bernstein_basis_of(n, values)


BEZIER_BERNSTEIN_METHODS = ("horner", "loop")


def bezier_bernstein(points: Any, t: Any, method: str = "horner") -> np.ndarray:
    """Evaluate the curve as ``sum_i C(n, i) t^i (1 - t)^(n - i) P[i]``.

    The handouts' ``naive_bezier``, for any degree: the explicit polynomial,
    no intermediate levels. Same contract as :func:`de_casteljau`.

    Parameters
    ----------
    points : array_like, shape (N, d)
    t : float or array_like, shape (M,)
    method : {"horner", "loop"}
        ``"loop"``: the handouts' sum, one term per control point, each
        with its binomial and two powers. ``"horner"`` (default, fast): the
        same polynomial by Horner's rule in ``u = t / (1 - t)`` (Schumaker
        and Volk), with the points reversed and ``u = (1 - t) / t`` for
        t >= 1/2 so that |u| <= 1; beyond degree 128 a basis-matrix product.
        The two agree to rounding.

    Examples
    --------
    >>> bezier_bernstein([[0, 0], [1, 2], [2, 0]], 0.5)
    array([1., 1.])
    >>> bezier_bernstein([[0, 0], [1, 2], [2, 0]], [0.25], method="loop")
    array([[0.5  , 0.75]])
    """
    control = as_points(points)
    values, is_scalar = as_parameter(t)
    method = as_choice(method, "method", BEZIER_BERNSTEIN_METHODS)
    require_bernstein_degree(control)
    if method == "loop":
        curve = _bezier_bernstein_loop(control, values)
    else:
        curve = _bezier_bernstein_horner(control, values)
    return curve[0] if is_scalar else curve


def _bezier_bernstein_horner(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Horner's rule in t / (1 - t), or the basis matrix beyond degree 128."""
    return horner_or_basis(control, t)


def _bezier_bernstein_loop(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """The handouts' loop: one term C(n, i) (1 - t)^(n - i) t^i P[i] at a time."""
    return bernstein_loop(control, t)


# --- operations on control polygons -------------------------------------------


def split(points: Any, t: Any = 0.5) -> tuple[np.ndarray, np.ndarray]:
    """Subdivide the curve at t into two curves of the same degree.

    The left polygon is the first point of every de Casteljau level, the right
    one the last point of every level, read backwards. The left curve on
    [0, 1] traces the original on [0, t], the right one on [t, 1]. A t outside
    [0, 1] extends the curve instead.

    Returns
    -------
    (left, right) : ndarray, each (N, d)

    Examples
    --------
    >>> left, right = split([[0, 0], [2, 2], [4, 0]])
    >>> left.tolist(), right.tolist()
    ([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0]], [[2.0, 1.0], [3.0, 1.0], [4.0, 0.0]])
    """
    levels = de_casteljau_levels(points, t)
    left = np.array([level[0] for level in levels])
    right = np.array([level[-1] for level in reversed(levels)])
    return left, right


def derivative(points: Any) -> np.ndarray:
    """Control points of the hodograph B'(t): ``n * (P[i + 1] - P[i])``.

    Returns an (N - 1, d) array, the derivative curve of degree n - 1. A
    degree-0 curve is constant: its derivative is the single point 0, (1, d).

    Examples
    --------
    >>> derivative([[0, 0], [1, 2], [3, 3]])
    array([[2., 4.],
           [4., 2.]])
    """
    control = as_points(points)
    if len(control) == 1:
        return np.zeros_like(control)
    return (len(control) - 1) * (control[1:] - control[:-1])


def elevate(points: Any) -> np.ndarray:
    """The same curve with one more control point (degree n + 1).

    ``Q[i] = i / (n + 1) * P[i - 1] + (1 - i / (n + 1)) * P[i]``.

    Examples
    --------
    >>> elevate([[0, 0], [3, 3]])
    array([[0. , 0. ],
           [1.5, 1.5],
           [3. , 3. ]])
    """
    control = as_points(points)
    n = len(control) - 1
    weights = (np.arange(1, n + 1) / (n + 1))[:, None]
    middle = weights * control[:-1] + (1 - weights) * control[1:]
    return np.vstack([control[:1], middle, control[-1:]])


# --- sampling ----------------------------------------------------------------


def sample_uniform(points: Any, step: float, accumulate: str = "exact") -> np.ndarray:
    """Points of the curve at ``uniform_parameters(step, accumulate)``.

    See :func:`course.curves.flattening.uniform_parameters` for the two arguments.

    Examples
    --------
    >>> sample_uniform([[0, 0], [4, 0]], 0.5)
    array([[0., 0.],
           [2., 0.],
           [4., 0.]])
    """
    control = as_points(points)
    return _de_casteljau(control, uniform_parameters(step, accumulate))
