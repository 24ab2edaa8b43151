"""Integrating the pixels where the outline of a stroke is not its boundary.

Where parts of the path overlap (:mod:`course.antialias._overlaps` finds
them), the outline :mod:`course.antialias.stroke` fills counts the overlap
twice. :func:`integrate` recomputes the pixels near those parts: the exact
length of each of ``ROWS`` rows of the pixel inside the union of the
segments' stadiums, averaged (the midpoint rule in y, exact in x).

Unchecked kernels, like the rest of the stroke: the caller validates.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from course.antialias._overlaps import pieces
from course.antialias._segments import Segments
from course.antialias.near_pixels import HALF_DIAGONAL, first_of_runs, pixels_near, pixels_within

__all__ = ["ROWS", "integrate", "row_coverage"]

#: Rows per pixel where parts of the path overlap.
ROWS = 16
# Up to this many (pixel, segment) candidates, the pairs are measured directly;
# beyond, the segments' own neighbourhoods are searched (pixels_near).
_BRUTE_PAIRS = 1 << 16
# Largest summed-area table of the flagged pixels, in cells per pixel and segment.
_TABLE_CELLS = 64


def integrate(
    image: np.ndarray, s: Segments, doubtful: np.ndarray, dots: np.ndarray, half: float
) -> None:
    """Overwrite the pixels near doubtful segments and dots with their coverage, in place.

    Every segment that reaches such a pixel takes part (not only the
    doubtful ones), and so do isolated points: the coverage is of the whole
    stroke.
    """
    reach = half + HALF_DIAGONAL
    line, gaps = _soup(
        np.concatenate([s.start.compress(doubtful, 0), s.dots.compress(dots, 0)]),
        np.concatenate([s.end.compress(doubtful, 0), s.dots.compress(dots, 0)]),
    )
    flagged = pixels_within(line, image.shape, reach, gaps=gaps)
    if len(flagged) == 0:  # all off the canvas
        return
    starts = np.concatenate([s.start, s.dots])
    ends = np.concatenate([s.end, s.dots])
    nearby = _nearby(flagged, starts, ends, image.shape, reach)
    if len(flagged) * len(nearby) <= _BRUTE_PAIRS:
        starts, ends = starts.take(nearby, 0), ends.take(nearby, 0)
        pixel, segment = _pairs(flagged, starts, ends, image.shape[1], reach)
        start, end = starts.take(segment, 0), ends.take(segment, 0)
    else:  # many pixels and segments: each segment's own neighbourhood
        line, gaps = _soup(starts.take(nearby, 0), ends.take(nearby, 0))
        near = pixels_near(line, image.shape, reach, gaps=gaps)
        pick = np.flatnonzero(np.isin(near.flat, flagged))
        pixel, split = near.flat[pick], near.polyline
        start = split.take(near.segment[pick], 0)
        end = split.take(near.segment[pick] + 1, 0)
    # np.put indexes the flattened image in place, whatever its strides.
    np.put(image, flagged, 0.0)
    if len(pixel):  # none only if every flagged centre lies at reach, to the last bit
        y, x = np.divmod(pixel, image.shape[1])
        coverage = row_coverage(x, y, start, end, pixel, half, ROWS)
        np.put(image, pixel[first_of_runs(pixel)], coverage)


def _nearby(
    flagged: np.ndarray, starts: np.ndarray, ends: np.ndarray, shape: tuple[int, int], reach: float
) -> np.ndarray:
    """The segments whose box, grown by ``reach``, holds a flagged pixel's centre.

    Every segment within ``reach`` of a flagged centre is among them. The
    flagged pixels are counted in a summed-area table over their bounding
    box, so that each segment's box costs four look-ups.
    """
    rows, columns = np.divmod(flagged, shape[1])
    top, left = rows.min(), columns.min()
    height, width = rows.max() - top + 1, columns.max() - left + 1
    if height * width > _TABLE_CELLS * (len(flagged) + len(starts)):
        # Flagged pixels far apart on a large canvas: a k-d tree of their
        # centres instead. A piece (no longer than 2) of a segment within
        # reach of a centre has its middle within reach + 1 of it.
        centres = np.stack([columns + 0.5, rows + 0.5], axis=1)
        owner, middle = pieces(starts, ends, 2.0)
        distance, _ = cKDTree(centres).query(middle, distance_upper_bound=reach + 1.0 + 1e-9)
        return np.unique(owner[np.isfinite(distance)])
    table = np.zeros((height + 1, width + 1), dtype=np.int64)  # cumsum would widen int32 anyway
    table[rows - top + 1, columns - left + 1] = 1
    table = table.cumsum(axis=0).cumsum(axis=1)
    # Pixel (r, c) has its centre in the box when low - reach <= c + 0.5 <= high + reach.
    low = np.minimum(starts, ends) - reach - 0.5
    high = np.maximum(starts, ends) + reach - 0.5
    c0 = np.clip(np.ceil(low[:, 0]) - left, 0, width).astype(np.int64)
    c1 = np.clip(np.floor(high[:, 0]) - left + 1, 0, width).astype(np.int64)
    r0 = np.clip(np.ceil(low[:, 1]) - top, 0, height).astype(np.int64)
    r1 = np.clip(np.floor(high[:, 1]) - top + 1, 0, height).astype(np.int64)
    inside = table[r1, c1] - table[r0, c1] - table[r1, c0] + table[r0, c0]
    return np.flatnonzero((inside > 0) & (c1 > c0) & (r1 > r0))


def _pairs(
    flagged: np.ndarray, starts: np.ndarray, ends: np.ndarray, width: int, reach: float
) -> tuple[np.ndarray, np.ndarray]:
    """Every (flagged pixel, segment) with the pixel's centre within ``reach``, by pixel.

    Measured on the (pixels, segments) grid by broadcasting, coordinate by
    coordinate: no (pairs, 2) arrays gathered.
    """
    rows, columns = np.divmod(flagged, width)
    sx, sy = starts[:, 0], starts[:, 1]
    dx, dy = ends[:, 0] - sx, ends[:, 1] - sy
    length2 = np.maximum(dx * dx + dy * dy, 1e-300)  # a dot: any t, the distance is to it
    ox = (columns + 0.5)[:, None] - sx
    oy = (rows + 0.5)[:, None] - sy
    along = np.clip((ox * dx + oy * dy) / length2, 0.0, 1.0)
    ox -= along * dx
    oy -= along * dy
    pixel, segment = np.nonzero(ox * ox + oy * oy <= reach * reach)
    return flagged[pixel], segment


def row_coverage(
    x: np.ndarray,
    y: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    pixel: np.ndarray,
    half: float,
    rows: int,
) -> np.ndarray:
    """Area of each pixel within ``half`` of any of its segments, row by row.

    One entry per (pixel, segment) pair, grouped by ``pixel`` (equal values
    adjacent). For each of ``rows`` horizontal lines through the pixel, at
    ``y + (j + 0.5) / rows``, the points of the line within ``half`` of a
    segment form an interval (a stadium is convex): the rectangle's and the
    two end discs' intervals, merged. The pixel's intervals are merged along
    the line and their length inside the pixel measured exactly; the
    coverage is the mean over the rows. Exact in x, the midpoint rule in y:
    the error is of order ``1 / rows**2`` except where an edge of the stroke
    runs horizontally inside the pixel (up to ``1 / (2 rows)`` there).

    Returns
    -------
    ndarray, one coverage per group of ``pixel``, in order.

    Examples
    --------
    Two discs of radius 1/2 around (0.5, 0.5) and (1.0, 0.5) (two points):
    pixel (0, 0) holds the first, pi / 4, and the left half of the second,
    pi / 8, less their lens-shaped overlap, pi / 6 - sqrt(3) / 8:

    >>> point = np.array([[0.5, 0.5], [1.0, 0.5]])
    >>> covered = row_coverage(np.zeros(2), np.zeros(2), point, point, np.zeros(2), 0.5, 400)
    >>> round(float(covered[0]), 3), round(float(np.pi * 5 / 24 + np.sqrt(3) / 8), 3)
    (0.871, 0.871)
    """
    j = (np.arange(rows) + 0.5) / rows
    line_y = y[:, None] + j[None, :]  # (pairs, rows)
    # x from the pixel's left side throughout: the intervals end up in [0, 1].
    sx, sy = start[:, 0] - x, start[:, 1]
    ex, ey = end[:, 0] - x, end[:, 1]
    # The end discs: a row misses a disc where the root is NaN, which
    # fmin and fmax skip; NaN is left where a row misses both.
    with np.errstate(invalid="ignore"):
        from_start = line_y - sy[:, None]
        r = np.sqrt(half * half - from_start * from_start)
        lo, hi = sx[:, None] - r, sx[:, None] + r
        dy = line_y - ey[:, None]
        r = np.sqrt(half * half - dy * dy)
        lo, hi = np.fmin(lo, ex[:, None] - r), np.fmax(hi, ex[:, None] + r)
    # The rectangle: 0 <= (p - a) . u <= L and |(p - a) . n| <= half, n = (-u_y, u_x),
    # two slabs; on the row Y = y - a_y each is an interval of X = x - a_x whose
    # ends move linearly with Y: ``first + slope Y`` to ``second + slope Y``.
    direction = end - start
    length = np.hypot(direction[:, 0], direction[:, 1])
    safe = np.where(length > 0, length, 1.0)
    ux, uy = direction[:, 0] / safe, direction[:, 1] / safe
    # A slab parallel to the rows is steep instead (1e-12): the rows it keeps
    # or drops change only within 1e-12 of its sides.
    cx = np.where(np.abs(ux) < 1e-12, 1e-12, ux)
    cy = np.where(np.abs(uy) < 1e-12, 1e-12, uy)
    along = -uy / cx, 0.0 / cx, length / cx  # 0 <= X ux + Y uy <= L
    across = ux / cy, -half / np.abs(cy), half / np.abs(cy)  # |Y ux - X uy| <= half
    bounds = []
    for slope, first, second in (along, across):
        shift = from_start * slope[:, None] + sx[:, None]
        # Rounding is monotonic: min(shift + a, shift + b) is shift + min(a, b).
        low, high = np.minimum(first, second), np.maximum(first, second)
        bounds.append((shift + low[:, None], shift + high[:, None]))
    rect_lo = np.maximum(bounds[0][0], bounds[1][0])
    rect_hi = np.minimum(bounds[0][1], bounds[1][1])
    has = (rect_hi >= rect_lo) & (length > 0)[:, None]
    np.fmin(lo, rect_lo, out=lo, where=has)
    np.fmax(hi, rect_hi, out=hi, where=has)
    # Inside the pixel; a row that misses the stroke becomes (1, 1), no length.
    lo = np.fmax(np.fmin(lo, 1.0), 0.0)
    hi = np.fmax(np.fmin(hi, 1.0), lo)
    # Merge each (pixel, row)'s intervals. How many cover a point counts the
    # starts at or before it less the ends before it, whichever start goes
    # with whichever end: so the starts and the ends are sorted apart, the
    # k-th start paired with the k-th end (still an interval), and the
    # union measured along the sorted starts, each end the largest so far.
    # Groups are 4 apart, so after the sort each pixel's rows are still
    # together, in order.
    first = first_of_runs(pixel)
    key = (((np.cumsum(first) - 1) * rows)[:, None] + np.arange(rows)[None, :]) * 4.0
    lo, hi = np.sort((key + lo).ravel()), np.sort((key + hi).ravel())
    before = np.empty_like(hi)
    before[0], before[1:] = -np.inf, hi[:-1]
    covered = np.maximum(hi - np.maximum(lo, before), 0.0)
    return np.add.reduceat(covered, np.flatnonzero(first) * rows) / rows


def _soup(starts: np.ndarray, ends: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Separate segments as one polyline whose odd segments are gaps."""
    line = np.empty((2 * len(starts), 2))
    line[0::2], line[1::2] = starts, ends
    gaps = np.zeros(max(len(line) - 1, 0), dtype=bool)
    gaps[1::2] = True
    return line, gaps
