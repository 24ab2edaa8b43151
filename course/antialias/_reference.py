"""The exact reference on a checked path: what :func:`course.antialias.coverage.reference` runs.

Nothing here checks the arguments its callers check (``UNCHECKED = True``): ``path`` is
:class:`course.curves.paths.Curves`, ``canvas`` a shape ``(H, W)``, ``width`` a float > 0
within :data:`course.limits.MAX_STROKE_WIDTH` and ``k`` an integer from 1 to
:data:`course.limits.MAX_RATE`, as :func:`course.antialias.coverage.reference` makes sure
before it calls :func:`reference_coverage`. What flattening each curve costs depends on
the curve and on the reference's own tolerance: :func:`path_polyline` checks it, curve by
curve, as it flattens. :func:`course.antialias.curve_quality.render_window` draws its
window of the reference here.
"""

from __future__ import annotations

from functools import lru_cache
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
# Sub-sample rows processed at once by the reference (bounds its memory).
_CHUNK_SAMPLES = 1 << 20


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
    (:func:`~course.antialias.curve_quality.render_window`) looks only at the
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


@lru_cache(maxsize=8)
def _sample_grid(k: int) -> tuple[np.ndarray, np.ndarray]:
    """Offsets (x, y) of the k x k samples inside a pixel, row by row."""
    grid = (np.arange(k) + 0.5) / k
    sub_x, sub_y = (g.ravel() for g in np.meshgrid(grid, grid))
    sub_x.flags.writeable = sub_y.flags.writeable = False
    return sub_x, sub_y


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
    sub_x, sub_y = _sample_grid(k)
    # Pairs are sorted by pixel: each pixel's pairs form one run.
    run_starts = np.flatnonzero(first_of_runs(flat))
    run_ends = np.r_[run_starts[1:], len(flat)]
    pairs_per_chunk = max(1, _CHUNK_SAMPLES // (k * k))
    coverage = np.empty(len(run_starts))
    first = 0
    while first < len(run_starts):
        # Whole runs only, as many as fit in one chunk (at least one).
        limit = run_starts[first] + pairs_per_chunk
        last = max(int(np.searchsorted(run_ends, limit, "right")), first + 1)
        chunk = index[run_starts[first] : run_ends[last - 1]]
        inside = _within(near, chunk, sub_x, sub_y, half)
        covered = np.logical_or.reduceat(inside, run_starts[first:last] - run_starts[first], axis=0)
        coverage[first:last] = covered.mean(axis=1)
        first = last
    return index[run_starts], coverage


def _within(
    near: NearPixels, chunk: np.ndarray, sub_x: np.ndarray, sub_y: np.ndarray, half: float
) -> np.ndarray:
    """Which samples of the chunk's pairs lie within ``half`` of the pair's segment.

    The test of :func:`segment_distance` on squared distances: everything
    that depends on the segment alone is computed once per pair, not once
    per sample, and no square root is taken, which halves the reference's
    time at k = 32.
    """
    segment = near.segment[chunk]
    start = near.polyline[segment]
    direction = near.polyline[segment + 1] - start
    length2 = np.einsum("ij,ij->i", direction, direction)
    # A point (or a segment so short its square is subnormal) is measured from its start.
    inverse = np.where(length2 > 1e-300, 1.0 / np.where(length2 > 1e-300, length2, 1.0), 0.0)
    ux, uy = (direction * inverse[:, None]).T
    dx = (near.x[chunk] - start[:, 0])[:, None] + sub_x
    dy = (near.y[chunk] - start[:, 1])[:, None] + sub_y
    along = np.clip(dx * ux[:, None] + dy * uy[:, None], 0.0, 1.0)
    ex = dx - along * direction[:, 0, None]
    ey = dy - along * direction[:, 1, None]
    return ex * ex + ey * ey <= half * half
