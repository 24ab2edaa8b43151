"""The handouts' Bézier code, kept as written so that lessons can measure it.

Each function reproduces one form from the seeds, mistakes included, with
the counters a lesson needs: the recursive ``comb`` of seed 002 (exponential
calls), its 32-bit ``int`` (overflows past C(33, 16)), the reversed
convention ``t * P[i] + (1 - t) * P[i + 1]`` of seeds 002 and 004 (the same
curve run backwards), the recursive and iterative de Casteljau of seeds
000 and 004 with the intermediate points they hold, and the lab's Task 7,
which draws the curve as Bresenham segments between points at equal steps
of t (seed 001). The seeds' drawing loops and the GAMES101 check that
compares them are in :mod:`course.curves.handout_loops`.
"""

from __future__ import annotations

import itertools
import sys
from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np

from course import limits
from course._validate import as_int, as_parameter, as_points, as_scalar_parameter
from course.curves._bezier_fast import de_casteljau_chunked
from course.curves._flatten import flatten_curve
from course.curves._handouts import de_casteljau_swapped
from course.curves.flattening import uniform_parameters
from course.i18n import _
from course.limits import require_bounded_flattening
from course.raster._lines import bresenham_closed_form, pixels_of, require_image_space

__all__ = [
    "MAX_SEGMENTS",
    "DeCasteljauCost",
    "bresenham_curve",
    "comb_recursive",
    "comb_recursive_calls",
    "curve_pixels",
    "de_casteljau_reversed",
    "pascal_row_int32",
    "segments_report",
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
    if m > sys.getrecursionlimit() // 2:
        raise ValueError(
            _("m must be <= {most}; got {m}").format(most=sys.getrecursionlimit() // 2, m=m)
        )
    if _calls(m, n) > limits.MAX_CALLS:
        raise ValueError(
            _(
                "m and n must ask for at most {most} recursive calls; comb_recursive({m}, "
                "{n}) would make {calls} (count them with comb_recursive_calls)"
            ).format(most=limits.MAX_CALLS, m=m, n=n, calls=_calls(m, n))
        )
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
        raise ValueError(
            _("m must be <= {most}; got {m}").format(most=sys.getrecursionlimit() // 2, m=m)
        )
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
    n = as_int(n, "n", minimum=0, maximum=limits.MAX_DEGREE)
    row = np.ones(1, dtype=np.int32)
    for _row in range(n):
        # numpy arrays wrap like C ints (numpy scalars would warn instead).
        row = np.concatenate([row[:1], row[:-1] + row[1:], row[-1:]])
    return row


def de_casteljau_reversed(points: Any, t: Any) -> np.ndarray:
    """Seeds 002 and 004: de Casteljau with the weights swapped.

    Each level is ``t * P[i] + (1 - t) * P[i + 1]``, so this returns the
    point the textbook puts at ``1 - t``: the same curve, traversed from the
    last control point to the first. Same contract as
    :func:`course.curves.bezier.de_casteljau`.

    Examples
    --------
    >>> de_casteljau_reversed([[0, 0], [1, 2], [2, 0]], 0.0)
    array([2., 0.])
    >>> de_casteljau_reversed([[0, 0], [1, 2], [2, 0]], [0.25])
    array([[1.5 , 0.75]])
    """
    control = as_points(points)
    values, is_scalar = as_parameter(t)
    curve = de_casteljau_swapped(control, values)
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
    # One nested call per point: stay well inside Python's recursion limit.
    if len(control) > sys.getrecursionlimit() // 2:
        raise ValueError(
            _(
                "points must hold at most {most} control points (half of Python's "
                "recursion limit, one nested call each); got {control_count}. trace_iterative "
                "counts the same interpolations without recursion"
            ).format(most=sys.getrecursionlimit() // 2, control_count=len(control))
        )
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
    # N (N - 1) / 2 interpolations, one Python step each.
    if len(control) > limits.MAX_HANDOUT_POINTS:
        raise ValueError(
            _(
                "points must hold at most {most} control points for the handout's "
                "loop; got {control_count}"
            ).format(most=limits.MAX_HANDOUT_POINTS, control_count=len(control))
        )
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
    :func:`course.curves.flattening.uniform_parameters`) and each sample lights the pixel
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
    samples = de_casteljau_chunked(as_points(points), t)
    # The samples, not the control points, must lie in image space: refused, as before.
    as_points(samples, bound=limits.MAX_COORDINATE)
    require_image_space(samples)
    pixels = pixels_of(samples, "floor")
    jumps = np.abs(np.diff(pixels, axis=0)).max(axis=1) if len(pixels) > 1 else np.zeros(0)
    # One integer per pixel: np.unique on rows sorts structured records, ten times slower.
    low = pixels.min(axis=0) if len(pixels) else np.zeros(2, np.int64)
    keys = (pixels[:, 0] - low[0]) * (int(pixels[:, 1].max() - low[1]) + 1) + pixels[:, 1] - low[1]
    distinct = len(np.unique(keys))
    return {
        "samples": len(samples),
        "pixels": distinct,
        "gaps": int(np.count_nonzero(jumps > 1)),
        "overdraw": len(samples) / distinct,
        "last_t": float(t[-1]),
        "pixel_list": pixels,
    }


# --- the lab's Task 7: the curve as Bresenham segments ------------------------------

#: More segments than this would draw each pixel many times over: the report's
#: loop is for a handful of segments, a long curve wants ``flatten``.
MAX_SEGMENTS = 4096


def bresenham_curve(points: Any, segments: int) -> np.ndarray:
    """The lab's Task 7: ``segments`` Bresenham lines between curve points at equal t steps.

    The points ``B(k / segments)`` go to the pixels that hold them (floor),
    and each consecutive pair is joined by :func:`course.raster.line`, as
    the lab's loop calls ``DrawLine``. Each joint is drawn twice, once by
    each line that meets there, so the (K, 2) pixels keep their repeats, in
    drawing order.

    Examples
    --------
    >>> bresenham_curve([[0.5, 0.5], [4.5, 0.5], [4.5, 4.5]], 2).tolist()
    [[0, 0], [1, 0], [2, 1], [3, 1], [3, 1], [3, 2], [4, 3], [4, 4]]
    """
    control = _as_image_curve(points)
    return _bresenham_curve(control, _as_segments(segments))


def _as_image_curve(points: Any) -> np.ndarray:
    """The control points of a curve in image space, (N, 2), checked."""
    control = as_points(points, bound=limits.MAX_COORDINATE)
    if control.shape[1] != 2:
        raise ValueError(
            _("points must have shape (N, 2) for image space; got {control_shape}").format(
                control_shape=control.shape
            )
        )
    return control


def _as_segments(segments: Any) -> int:
    segments = as_int(segments, "segments", minimum=1)
    if segments > MAX_SEGMENTS:
        raise ValueError(
            _("segments must be <= {most}; got {segments}").format(
                most=MAX_SEGMENTS, segments=segments
            )
        )
    return segments


def _bresenham_curve(control: np.ndarray, segments: int) -> np.ndarray:
    """:func:`bresenham_curve` of a checked curve and count of segments."""
    t = np.linspace(0.0, 1.0, segments + 1)
    ends = pixels_of(de_casteljau_chunked(control, t), "floor").tolist()
    return np.concatenate([bresenham_closed_form(*a, *b) for a, b in itertools.pairwise(ends)])


def curve_pixels(points: Any) -> np.ndarray:
    """The pixels the curve itself passes through: (K, 2), distinct, in order along it.

    The curve is flattened to points at most half a pixel apart and within
    0.01 pixel of it (:func:`course.curves.flattening.flatten` with ``max_step=0.5``),
    and each point's pixel is taken: consecutive pixels touch (8-connected),
    and only a pixel whose corner the curve clips, along less than about half
    a pixel, can be missed.

    Examples
    --------
    >>> curve_pixels([[0.5, 0.5], [4.5, 0.5]]).tolist()
    [[0, 0], [1, 0], [2, 0], [3, 0], [4, 0]]
    """
    return _curve_pixels(_as_image_curve(points))


def _curve_pixels(control: np.ndarray) -> np.ndarray:
    """:func:`curve_pixels` of a checked curve; what flattening it costs is checked here."""
    require_bounded_flattening(control, 0.01, 0.5)
    pixels = pixels_of(flatten_curve(control, 0.01, 0.5)[0], "floor")
    keep = np.ones(len(pixels), dtype=bool)
    keep[1:] = (np.diff(pixels, axis=0) != 0).any(axis=1)
    pixels = pixels[keep]
    _unique, first = np.unique(pixels, axis=0, return_index=True)
    return pixels[np.sort(first)]


def segments_report(points: Any, segments: int) -> dict[str, Any]:
    """How :func:`bresenham_curve` with ``segments`` lines compares with :func:`curve_pixels`.

    Returns
    -------
    dict
        ``pixels``: distinct pixels drawn; ``twice``: pixels drawn more than
        once (the joints, and pixels two lines share); ``curve``: the
        curve's own pixels; ``off``: drawn pixels the curve does not pass
        through (where the chords stray from it); ``missed``: curve pixels
        with no drawn pixel beside them (not even diagonally), where the
        drawing leaves the curve by more than a pixel. ``off_pixels`` and
        ``missed_pixels`` list them, (K, 2) each.

    Examples
    --------
    A quarter turn drawn with one chord, then with eight:

    >>> turn = [[0.5, 0.5], [10.5, 0.5], [10.5, 10.5]]
    >>> [segments_report(turn, n)[key] for n in (1, 8) for key in ("off", "missed", "twice")]
    [9, 14, 0, 1, 0, 7]
    """
    control = _as_image_curve(points)
    drawn = _bresenham_curve(control, _as_segments(segments))
    painted, counts = np.unique(drawn, axis=0, return_counts=True)
    curve = _curve_pixels(control)
    low = np.minimum(painted.min(axis=0), curve.min(axis=0)) - 1
    high = np.maximum(painted.max(axis=0), curve.max(axis=0)) + 2
    grid = np.zeros((high - low)[::-1], dtype=bool)  # rows y, columns x
    on_curve = grid.copy()
    px, py = (painted - low).T
    cx, cy = (curve - low).T
    grid[py, px] = True
    on_curve[cy, cx] = True
    near = grid.copy()  # within one pixel of a drawn one, diagonals included
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            near[1:-1, 1:-1] |= grid[
                1 + dy : grid.shape[0] - 1 + dy, 1 + dx : grid.shape[1] - 1 + dx
            ]
    off = painted[~on_curve[py, px]]
    missed = curve[~near[cy, cx]]
    return {
        "pixels": len(painted),
        "twice": int(np.count_nonzero(counts > 1)),
        "curve": len(curve),
        "off": len(off),
        "missed": len(missed),
        "off_pixels": off,
        "missed_pixels": missed,
    }
