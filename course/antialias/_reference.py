"""The exact reference on a checked path: what :func:`course.antialias.coverage.reference` runs.

Nothing here checks the arguments its callers check (``UNCHECKED = True``): ``path`` is
:class:`course.curves.paths.Curves`, ``canvas`` a shape ``(H, W)``, ``width`` a float > 0
within :data:`course.limits.MAX_STROKE_WIDTH` and ``k`` an integer from 1 to
:data:`course.limits.MAX_RATE`, as :func:`course.antialias.coverage.reference` makes sure
before it calls :func:`reference_coverage`. What flattening each curve costs depends on
the curve and on the reference's own tolerance: :func:`path_polyline` checks it, curve by
curve, as it flattens. :func:`course.antialias.windows.render_window` draws its
window of the reference here.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course._validate import as_curve, as_positive_float, describe
from course.antialias._polyline import flattened
from course.antialias.near_pixels import HALF_DIAGONAL, NearPixels, first_of_runs, pixels_near
from course.curves.drawable_paths import flatten_each
from course.curves.paths import Curves
from course.i18n import _
from course.limits import require_bounded_flattening

__all__ = ["REFERENCE_TOLERANCE", "path_polyline", "polyline_coverage", "reference_coverage"]

UNCHECKED = True  # kernels for checked callers; see the module docstring

# How far the reference's polyline may stray from the true curve, in pixels.
REFERENCE_TOLERANCE = 1e-4
# Rows of samples (a pair's pixel has k) processed at once by the reference (bounds its memory).
_CHUNK_ROWS = 1 << 17
_ONE, _ALL_BITS = np.uint64(1), np.uint64(0xFFFF_FFFF_FFFF_FFFF)
# The bits set in each byte: a word's samples counted without numpy 2's bitwise_count.
_BITS_SET = np.array([bin(byte).count("1") for byte in range(256)], dtype=np.int64)


def path_polyline(
    path: Curves, tolerance: Any, tolerance_checked: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`course.antialias.coverage.path_polyline`, checking what
    :func:`~course.antialias.coverage.curve_polyline` checked of each curve:
    ``tolerance`` (once, at the first curve, unless the caller did) and what flattening the
    curve costs."""
    checked: list[float] = [tolerance] if tolerance_checked else []

    def flatten_one(control: np.ndarray) -> np.ndarray:
        if not 1 <= len(control) <= limits.MAX_SAMPLES:
            as_curve(control)  # no point, or more than a curve may hold: refused as before
        control = control.astype(float)  # Curves may hold integers; curves are float
        if not checked:
            checked.append(as_positive_float(tolerance, "tolerance"))
        require_bounded_flattening(control, checked[0], 1.0)
        return flattened(control, checked[0], 1.0)

    return flatten_each(path, flatten_one)


def reference_coverage(path: Curves, canvas: tuple[int, int], width: float, k: int) -> np.ndarray:
    """:func:`course.antialias.coverage.reference` of checked arguments: (H, W) coverage."""
    line, gaps = path_polyline(path, REFERENCE_TOLERANCE, tolerance_checked=True)
    return polyline_coverage(line, gaps, canvas, width, k)


def polyline_coverage(
    line: np.ndarray, gaps: np.ndarray | None, canvas: tuple[int, int], width: float, k: int
) -> np.ndarray:
    """The reference's (H, W) coverage of a polyline already flattened: ``line``, (K >= 2, 2).

    ``gaps`` marks the segments not drawn, as :func:`path_polyline` returns
    them (or None). Lesson 05's zoom app draws its window during a drag from
    the pieces of its own polyline that pass by it.
    """
    height, canvas_width = canvas
    half = 0.5 * width
    reach = half + HALF_DIAGONAL
    gaps = _beyond_reach(line, gaps, (height, canvas_width), reach)
    near = pixels_near(line, (height, canvas_width), reach, gaps=gaps)
    image = np.zeros(height * canvas_width)
    if len(near.flat) == 0:
        return image.reshape(height, canvas_width)
    nearest = np.full(height * canvas_width, np.inf)
    np.minimum.at(nearest, near.flat, near.distance)
    inside = nearest <= half - HALF_DIAGONAL
    image[inside] = 1.0
    firsts, coverage = _supersample(near, ~inside[near.flat], half, k)
    image[near.flat[firsts]] = coverage
    return image.reshape(height, canvas_width)


def _beyond_reach(
    line: np.ndarray, gaps: np.ndarray | None, canvas: tuple[int, int], reach: float
) -> np.ndarray:
    """``gaps``, and the segments too far from the canvas for any of its pixels to be near.

    Skipped alike by :func:`pixels_near`: a window of a long curve
    (:func:`~course.antialias.windows.render_window`) looks only at the
    few segments that pass by it. The coverage does not change: it takes the
    nearest distance and the union of the samples over a pixel's segments.
    """
    height, width = canvas
    low, high = np.minimum(line[:-1], line[1:]), np.maximum(line[:-1], line[1:])
    far = (
        (high[:, 0] < -reach)
        | (low[:, 0] > width + reach)
        | (high[:, 1] < -reach)
        | (low[:, 1] > height + reach)
    )
    return far if gaps is None else gaps | far


def _supersample(
    near: NearPixels, pairs: np.ndarray, half: float, k: int
) -> tuple[np.ndarray, np.ndarray]:
    """Coverage of the pixels whose pairs are selected, by k x k point samples.

    ``pairs`` is a boolean mask over ``near``'s pairs that selects every pair
    of a pixel or none. A sample of a pixel is inside when it lies within
    ``half`` of any segment paired with that pixel.

    Returns
    -------
    firsts : int ndarray
        For each selected pixel, the index of its first pair in ``near``.
    coverage : float ndarray
        The fraction of its k x k samples inside.
    """
    if not isinstance(near, NearPixels):
        raise TypeError(
            _("near must be NearPixels, from pixels_near; got {near}").format(near=describe(near))
        )
    pairs = np.asarray(pairs)
    if pairs.dtype != bool or pairs.shape != near.flat.shape:
        raise ValueError(
            _(
                "pairs must be a boolean mask of shape {flat_shape}, one per pair of near; got "
                "{pairs}"
            ).format(flat_shape=near.flat.shape, pairs=describe(pairs))
        )
    if half < limits.SMALLEST:
        as_positive_float(half, "half")  # a width below 2 * SMALLEST: refused by its half
    index = np.flatnonzero(pairs)
    if len(index) == 0:
        return index, np.zeros(0)
    flat = near.flat[index]
    # Pairs are sorted by pixel: each pixel's pairs form one run.
    run_starts = np.flatnonzero(first_of_runs(flat))
    run_ends = np.r_[run_starts[1:], len(flat)]
    pairs_per_chunk = max(1, _CHUNK_ROWS // k)
    coverage = np.empty(len(run_starts))
    first = 0
    while first < len(run_starts):
        # Whole runs only, as many as fit in one chunk (at least one).
        limit = run_starts[first] + pairs_per_chunk
        last = max(int(np.searchsorted(run_ends, limit, "right")), first + 1)
        chunk = index[run_starts[first] : run_ends[last - 1]]
        inside = _row_words(*_row_spans(near, chunk, k, half), k)
        covered = np.bitwise_or.reduceat(inside, run_starts[first:last] - run_starts[first], axis=0)
        counts = _BITS_SET[covered.view(np.uint8)].reshape(last - first, -1).sum(axis=1)
        coverage[first:last] = counts / (k * k)
        first = last
    return index[run_starts], coverage


def _row_spans(
    near: NearPixels, chunk: np.ndarray, k: int, half: float
) -> tuple[np.ndarray, np.ndarray]:
    """For each of the chunk's pairs and each row of its pixel's k x k samples, the
    columns ``[first, stop)`` of the samples within ``half`` of the pair's segment.

    A segment's stroke (a capsule) is convex: a row of samples crosses it
    in one interval, the union of what the discs at the segment's ends and
    the band beside it cover. So the square roots and divisions are made
    once a row, not once a sample (the test of :func:`segment_distance`,
    exactly: a sample is within ``half`` of the segment when it is within
    ``half`` of an end, or of the segment's line beside the segment).
    """
    grid = (np.arange(k) + 0.5) / k
    segment = near.segment[chunk]
    start = near.polyline[segment]
    direction = near.polyline[segment + 1] - start
    vx, vy = direction[:, 0, None], direction[:, 1, None]
    # The samples of a pixel, from the segment's start: columns at x + grid, rows at y.
    x = (near.x[chunk] - start[:, 0])[:, None]
    y = (near.y[chunk] - start[:, 1])[:, None] + grid
    with np.errstate(invalid="ignore"):  # NaN where a row misses a disc: fmin/fmax skip it
        start_reach = np.sqrt(half * half - y * y)
        end_reach = np.sqrt(half * half - (y - vy) ** 2)
    low = np.fmin(-start_reach, vx - end_reach)
    high = np.fmax(start_reach, vx + end_reach)
    # The band: 0 <= (x, y) . v <= |v|^2 and |(x, y) x v| <= half |v|, each linear in x.
    length2 = vx * vx + vy * vy
    along_low, along_high = _solutions(vx, -y * vy, length2 - y * vy)
    side = half * np.sqrt(length2)
    across_low, across_high = _solutions(vy, y * vx - side, y * vx + side)
    band_low = np.maximum(along_low, across_low)
    band_high = np.minimum(along_high, across_high)
    # A point (or a segment so short its square is subnormal) has its discs alone.
    band = (band_low <= band_high) & (length2 > 1e-300)
    low = np.fmin(low, np.where(band, band_low, np.inf))
    high = np.fmax(high, np.where(band, band_high, -np.inf))
    # Column i is inside when low <= x + grid[i] <= high; the estimate from the
    # grid's spacing is moved by one where rounding put it past that test.
    columns = np.concatenate(
        [np.full_like(x, -np.inf), x + grid, np.full_like(x, np.inf)], axis=1
    )  # column i at i + 1, beyond either end an infinity
    first = np.clip(np.ceil((low - x) * k - 0.5), 0, k).astype(np.int64)
    first -= np.take_along_axis(columns, first, axis=1) >= low
    first += np.take_along_axis(columns, first + 1, axis=1) < low
    stop = np.clip(np.floor((high - x) * k + 0.5), 0, k).astype(np.int64)
    stop -= np.take_along_axis(columns, stop, axis=1) > high
    stop += np.take_along_axis(columns, stop + 1, axis=1) <= high
    return first, np.maximum(stop, first)


def _solutions(
    scale: np.ndarray, low: np.ndarray, high: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The interval of x with ``low <= scale * x <= high``, each entry: (its start, its end),
    ``(-inf, inf)`` for every x and ``(inf, -inf)`` for none."""
    with np.errstate(divide="ignore", invalid="ignore"):
        first, second = low / scale, high / scale
    rising = scale > 0
    start, end = np.where(rising, first, second), np.where(rising, second, first)
    level = scale == 0
    if level.any():
        every = (low <= 0) & (0 <= high)
        start = np.where(level, np.where(every, -np.inf, np.inf), start)
        end = np.where(level, np.where(every, np.inf, -np.inf), end)
    return start, end


def _row_words(first: np.ndarray, stop: np.ndarray, k: int) -> np.ndarray:
    """The columns ``[first, stop)`` of each row as bits, (..., ceil(k / 64)) 64-bit words.

    A pixel's rows from several segments then join by OR, and its samples
    are counted by the bits set: k numbers a pair, not k x k booleans.
    """
    base = 64 * np.arange(-(-k // 64))
    low = np.clip(first[..., None] - base, 0, 64).astype(np.uint64)
    high = np.clip(stop[..., None] - base, 0, 64).astype(np.uint64)
    # (1 << 64) is out of a uint64's range: a whole word is written as all ones.
    below_high = np.where(high >= 64, _ALL_BITS, (_ONE << np.minimum(high, 63)) - _ONE)
    below_low = np.where(low >= 64, _ALL_BITS, (_ONE << np.minimum(low, 63)) - _ONE)
    return below_high & ~below_low
