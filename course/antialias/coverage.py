"""How much of each pixel a stroked curve or path covers: the exact reference.

A stroke of width w around a curve is the set of points within w / 2 of it
(round caps at the ends, round joins where the curves of a path meet). A
pixel is the unit square ``[c, c+1) x [r, r+1)``; its *coverage* is the area
of the square inside the stroke, a number in [0, 1]. That is the quantity
every anti-aliasing method in :mod:`course.antialias` approximates, and
:func:`reference` computes it by brute force: k x k point samples per
pixel, each tested with its exact distance to the curve flattened far below
a pixel (1e-4 px). Only pixels near the curve are sampled, so a 700 x 700
canvas costs what its curve costs. A whole path (a list of curves, or a
``matplotlib.path.Path``) is one stroke: a sample is inside when it lies
within w / 2 of *any* of its curves, so joins are counted once.

The geometry lives in its own modules, re-exported here for the lessons:
which pixels lie near which segment (:mod:`course.antialias.near_pixels`), the exact
area of a pixel inside a band (:mod:`course.antialias.slab`), and Agg's rendering of
the same stroke (:mod:`course.antialias.agg`).

References
----------
.. [1] E. Catmull, "A hidden-surface algorithm with anti-aliasing", SIGGRAPH 1978
   (coverage as the area of a pixel covered by a shape).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import numpy as np

from course import limits
from course._validate import as_curve, as_int, as_positive_float, as_shape, describe
from course.antialias.agg import agg_draw, agg_path, agg_render
from course.antialias.near_pixels import (
    HALF_DIAGONAL,
    NearPixels,
    first_of_runs,
    pixels_near,
    segment_distance,
    subdivide,
)
from course.antialias.slab import band_coverage, slab_coverage
from course.curves.bezier import flatten
from course.curves.paths import Curves, as_path, flatten_each
from course.i18n import _

__all__ = [
    "HALF_DIAGONAL",
    "REFERENCE_TOLERANCE",
    "NearPixels",
    "agg_draw",
    "agg_path",
    "agg_render",
    "band_coverage",
    "curve_polyline",
    "first_of_runs",
    "path_polyline",
    "pixels_near",
    "reference",
    "segment_distance",
    "slab_coverage",
    "subdivide",
]

# How far the reference's polyline may stray from the true curve, in pixels.
REFERENCE_TOLERANCE = 1e-4
# Sub-sample rows processed at once by the reference (bounds its memory).
_CHUNK_SAMPLES = 1 << 20


def curve_polyline(points: Any, tolerance: float, max_step: float = 1.0) -> np.ndarray:
    """The curve as a polyline within ``tolerance`` of it, segments <= ``max_step``.

    Short segments keep the neighbourhood of each segment small, which is what
    lets :func:`pixels_near` look only near the curve.

    Examples
    --------
    >>> curve_polyline([[0, 0], [2, 0]], tolerance=0.1)
    array([[0., 0.],
           [1., 0.],
           [2., 0.]])
    """
    control = as_curve(points)
    line = flatten(control, tolerance, max_step=max_step)
    if len(line) == 1:  # a single point: a zero-length segment keeps the caps
        line = np.vstack([line, line])
    return line


def path_polyline(path: Curves, tolerance: float) -> tuple[np.ndarray, np.ndarray]:
    """Every curve of the path by :func:`curve_polyline`: one polyline and its gaps.

    Examples
    --------
    >>> line, gaps = path_polyline(as_path([[[0, 0], [1, 0]], [[3, 0], [3, 1]]]), 0.1)
    >>> line.tolist(), gaps.tolist()
    ([[0.0, 0.0], [1.0, 0.0], [3.0, 0.0], [3.0, 1.0]], [False, True, False])
    """
    return flatten_each(path, lambda control: curve_polyline(control, tolerance))


def reference(points: Any, shape: Any, width: float = 1.0, k: int = 16) -> np.ndarray:
    """Exact coverage of every pixel by the stroked curve or path, by k x k supersampling.

    Each pixel is sampled at the k x k points ``(c + (i + 0.5) / k,
    r + (j + 0.5) / k)``; a sample is inside when its exact distance to the
    curve (flattened to within 1e-4 px) is at most ``width / 2``. The
    coverage is the fraction inside. For a path, the distance is to the
    nearest of its curves: the union of their strokes, exact at the joins.
    Only pixels whose centre lies within ``width / 2 + sqrt(2) / 2`` of the
    curve can hold an inside sample; those
    within ``width / 2 - sqrt(2) / 2`` are wholly inside; only the pixels in
    between are sampled.

    The error of one pixel is at most about 1 / k (a straight edge parallel
    to the sample rows) and usually far less; it shrinks as k grows.

    Parameters
    ----------
    points : array_like (N, 2), list of them, or matplotlib.path.Path
        Control points in image space (x right, y down), or a whole path
        (:func:`course.curves.paths.as_path`).
    shape : (H, W)
        Canvas size.
    width : float
        Stroke width in pixels, > 0.
    k : int
        Samples per pixel side; 16 or more for a reference.

    Returns
    -------
    ndarray, shape (H, W)
        Coverage in [0, 1].

    Examples
    --------
    A horizontal stroke of width 1 centred a quarter pixel below row 1's
    centre covers row 1 by 3/4 and row 2 by 1/4:

    >>> reference([[0.0, 1.75], [4.0, 1.75]], (4, 4), width=1.0, k=16)[:, 1:3]
    array([[0.  , 0.  ],
           [0.75, 0.75],
           [0.25, 0.25],
           [0.  , 0.  ]])
    """
    path = as_path(points)
    height, canvas_width = as_shape(shape)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    k = as_int(k, "k", minimum=1, maximum=limits.MAX_RATE)
    half = 0.5 * width
    line, gaps = path_polyline(path, REFERENCE_TOLERANCE)
    near = pixels_near(line, (height, canvas_width), half + HALF_DIAGONAL, gaps=gaps)
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
    half = as_positive_float(half, "half")
    k = as_int(k, "k", minimum=1, maximum=limits.MAX_RATE)
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
