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
the same stroke (:mod:`course.antialias.agg`). The reference's sampling runs on checked
input in ``_reference``.

References
----------
.. [1] E. Catmull, "A hidden-surface algorithm with anti-aliasing", SIGGRAPH 1978
   (coverage as the area of a pixel covered by a shape).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course._validate import (
    as_curve,
    as_flattening,
    as_int,
    as_positive_float,
    as_shape,
)
from course.antialias._polyline import flattened
from course.antialias._reference import REFERENCE_TOLERANCE, reference_coverage
from course.antialias._reference import path_polyline as path_polyline_of
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
from course.curves.paths import Curves, as_path

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
    tolerance, limit = as_flattening(control, tolerance, max_step)
    return flattened(control, tolerance, limit)


def path_polyline(path: Curves, tolerance: float) -> tuple[np.ndarray, np.ndarray]:
    """Every curve of the path by :func:`curve_polyline`: one polyline and its gaps.

    Examples
    --------
    >>> line, gaps = path_polyline(as_path([[[0, 0], [1, 0]], [[3, 0], [3, 1]]]), 0.1)
    >>> line.tolist(), gaps.tolist()
    ([[0.0, 0.0], [1.0, 0.0], [3.0, 0.0], [3.0, 1.0]], [False, True, False])
    """
    return path_polyline_of(path, tolerance)


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
    return reference_coverage(path, (height, canvas_width), width, k)
