"""The handouts' Bézier code, kept as written so that lessons can measure it.

Each function reproduces one form from the seeds, mistakes included, with
the counters a lesson needs: the recursive ``comb`` of seed 002 (exponential
calls), its 32-bit ``int`` (overflows past C(33, 16)), the reversed
convention ``t * P[i] + (1 - t) * P[i + 1]`` of seeds 002 and 004 (the same
curve run backwards), and the recursive and iterative de Casteljau of seeds
000 and 004 with the intermediate points they hold.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np

from course._validate import as_int, as_parameter, as_points, as_scalar_parameter
from course.bezier import de_casteljau, uniform_parameters
from course.raster import nearest_pixels

__all__ = [
    "DeCasteljauCost",
    "comb_recursive",
    "comb_recursive_calls",
    "de_casteljau_reversed",
    "pascal_row_int32",
    "step_report",
    "trace_iterative",
    "trace_recursive",
]


def comb_recursive(m: int, n: int) -> tuple[int, int]:
    """Seed 002's ``comb(m, n)`` and how many calls it made.

    ``comb(m, n) = comb(m - 1, n) + comb(m - 1, n - 1)`` with no memory of
    earlier answers: the same values are recomputed over and over, so the
    number of calls is about C(m, n) itself, which grows exponentially in m.

    Returns
    -------
    (value, calls) : (int, int)

    Examples
    --------
    >>> comb_recursive(4, 2)
    (6, 5)
    >>> comb_recursive(20, 10)
    (184756, 184755)
    """
    m = as_int(m, "m", minimum=0)
    n = as_int(n, "n", minimum=0)
    calls = 0

    def comb(m: int, n: int) -> int:
        nonlocal calls
        calls += 1
        if m < n:
            return 0
        if m == n or n == 0:
            return 1
        if n == 1:
            return m
        return comb(m - 1, n) + comb(m - 1, n - 1)

    value = comb(m, n)
    return value, calls


@cache
def _calls(m: int, n: int) -> int:
    if m < n or m == n or n == 0 or n == 1:
        return 1
    return 1 + _calls(m - 1, n) + _calls(m - 1, n - 1)


def comb_recursive_calls(m: int, n: int) -> int:
    """The number of calls ``comb_recursive(m, n)`` makes, without making them.

    The same recursion on the call count, remembered: instant for any m.

    Examples
    --------
    >>> comb_recursive_calls(20, 10)
    184755
    >>> comb_recursive_calls(60, 30)
    118264581564861423
    """
    m = as_int(m, "m", minimum=0)
    n = as_int(n, "n", minimum=0)
    if m > sys.getrecursionlimit() // 2:
        raise ValueError(f"m must be <= {sys.getrecursionlimit() // 2}; got {m}")
    return _calls(m, n)


def pascal_row_int32(n: int) -> np.ndarray:
    """Row n of Pascal's triangle in 32-bit integers, as C++ ``int`` would hold it.

    Additions wrap around silently past 2^31 - 1: the first wrong row is
    n = 34, where C(34, 17) = 2333606220 comes out negative.

    Examples
    --------
    >>> pascal_row_int32(4)
    array([1, 4, 6, 4, 1], dtype=int32)
    >>> int(pascal_row_int32(34)[17])
    -1961361076
    """
    n = as_int(n, "n", minimum=0)
    row = np.ones(1, dtype=np.int32)
    for _ in range(n):
        # numpy arrays wrap like C ints (numpy scalars would warn instead).
        row = np.concatenate([row[:1], row[:-1] + row[1:], row[-1:]])
    return row


def de_casteljau_reversed(points: Any, t: Any) -> np.ndarray:
    """Seeds 002 and 004: de Casteljau with the weights swapped.

    Each level is ``t * P[i] + (1 - t) * P[i + 1]``, so this returns the
    point the textbook puts at ``1 - t``: the same curve, traversed from the
    last control point to the first. Same contract as
    :func:`course.bezier.de_casteljau`.

    Examples
    --------
    >>> de_casteljau_reversed([[0, 0], [1, 2], [2, 0]], 0.0)
    array([2., 0.])
    >>> de_casteljau_reversed([[0, 0], [1, 2], [2, 0]], [0.25])
    array([[1.5 , 0.75]])
    """
    level = as_points(points)
    values, is_scalar = as_parameter(t)
    t_column = values[:, None, None]
    level = np.broadcast_to(level, (len(values), *level.shape))
    while level.shape[1] > 1:
        level = t_column * level[:, :-1] + (1 - t_column) * level[:, 1:]
    curve = level[:, 0]
    return curve[0] if is_scalar else curve


@dataclass(frozen=True)
class DeCasteljauCost:
    """What one evaluation did: calls, interpolations, and the most points held at once."""

    point: np.ndarray
    calls: int
    interpolations: int
    peak_points_held: int


def trace_recursive(points: Any, t: float) -> DeCasteljauCost:
    """Seed 000's ``recursive_bezier``, counting what it computes and holds.

    Every call keeps its level alive until the recursion returns, so at the
    deepest call all levels, N + (N - 1) + ... + 1 points, are held at once.

    Examples
    --------
    >>> cost = trace_recursive([[0, 0], [1, 2], [2, 0], [3, 2]], 0.5)
    >>> cost.calls, cost.interpolations, cost.peak_points_held
    (4, 6, 10)
    """
    control = as_points(points)
    value = as_scalar_parameter(t)
    calls = interpolations = peak = 0

    def recursive_bezier(level: list[np.ndarray], held: int) -> np.ndarray:
        nonlocal calls, interpolations, peak
        calls += 1
        held += len(level)
        peak = max(peak, held)
        if len(level) == 1:
            return level[0]
        new_points = []
        for i in range(len(level) - 1):
            new_points.append((1 - value) * level[i] + value * level[i + 1])
            interpolations += 1
        return recursive_bezier(new_points, held)

    point = recursive_bezier(list(control), 0)
    return DeCasteljauCost(point, calls, interpolations, peak)


def trace_iterative(points: Any, t: float) -> DeCasteljauCost:
    """Seed 004's iterative ``de_Casteljau``: two lists, the old level and the new.

    The same interpolations as the recursion, but only two levels are alive
    at once, at most N + (N - 1) points: O(n) memory instead of O(n^2).

    Examples
    --------
    >>> cost = trace_iterative([[0, 0], [1, 2], [2, 0], [3, 2]], 0.5)
    >>> cost.calls, cost.interpolations, cost.peak_points_held
    (1, 6, 7)
    """
    control = as_points(points)
    value = as_scalar_parameter(t)
    interpolations = peak = 0
    point_list = list(control)
    while len(point_list) != 1:
        new_point_list = []
        for i in range(len(point_list) - 1):
            new_point_list.append((1 - value) * point_list[i] + value * point_list[i + 1])
            interpolations += 1
        peak = max(peak, len(point_list) + len(new_point_list))
        point_list = new_point_list
    return DeCasteljauCost(point_list[0], 1, interpolations, max(peak, 1))


def step_report(points: Any, step: float, accumulate: str = "exact") -> dict[str, Any]:
    """What the handouts' fixed-step loop draws: samples, pixels, gaps, overdraw.

    The curve is sampled at ``t = 0, step, 2 step, ...`` (see
    :func:`course.bezier.uniform_parameters`) and each sample lights the pixel
    it falls in. A *gap* is a pair of consecutive samples whose pixels do not
    touch (not even diagonally); *overdraw* is the mean number of samples per
    lit pixel.

    Returns
    -------
    dict
        ``samples``, ``pixels`` (distinct), ``gaps``, ``overdraw``,
        ``last_t`` and ``pixel_list`` (the (K, 2) pixels in sample order).

    Examples
    --------
    >>> report = step_report([[0, 0], [10, 0]], 0.25)
    >>> report["samples"], report["pixels"], report["gaps"]
    (5, 5, 4)
    """
    t = uniform_parameters(step, accumulate)
    samples = de_casteljau(points, t)
    pixels = nearest_pixels(samples)
    jumps = np.abs(np.diff(pixels, axis=0)).max(axis=1) if len(pixels) > 1 else np.zeros(0)
    distinct = len(np.unique(pixels, axis=0))
    return {
        "samples": len(samples),
        "pixels": distinct,
        "gaps": int(np.count_nonzero(jumps > 1)),
        "overdraw": len(samples) / distinct,
        "last_t": float(t[-1]),
        "pixel_list": pixels,
    }
