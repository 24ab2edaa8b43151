"""Anti-aliasing a curve: the handouts' splats, stroke coverage, one render.

The handouts (seeds 000, 002, 003) sample the curve at t = 0, step, 2 step,
... and add a *splat* (:mod:`course.antialias.splats`) for every sample, saturating at
1. A pixel's brightness then counts how many samples land in it, which
depends on the t step and on how fast the curve moves there. The fix
(``weighting="arc_length"``) scales each splat by the length of curve its
sample stands for, so a pixel receives the length of curve passing through it.

What a graphics engineer would do instead is compute each pixel's *coverage*
by a stroke of width w around the curve, once: :func:`stroke_linear` from the
distance to the curve, :func:`stroke_area` exactly, by filling the stroke's
outline (:mod:`course.antialias.stroke`), round joins and caps, sharp corners and cusps
included. :mod:`course.antialias.coverage` holds the exact reference and Agg's
rendering, re-exported here.

:func:`render` draws a curve, or a whole path (a list of curves, a
``matplotlib.path.Path``, a line of text from :func:`text_curves`), with any
of :data:`RENDER_METHODS`. A path is one stroke: where its curves join, the
stroke methods count the overlap once. Each function here checks its arguments once;
the drawing itself runs on checked input in ``_render``.

References
----------
.. [1] GAMES101 (L. Yan), assignment 4: "Bézier curves", optional task.
.. [2] S. Wang, "Curves and surfaces for computer-aided geometric design",
   1984; the flattening bound is quoted in Sederberg, *Computer Aided
   Geometric Design*, BYU 2012, section 10.6 (Wang's formula).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from course import limits
from course._validate import as_choice, as_curve, as_points, as_positive_float, as_shape
from course.antialias._render import (
    DEFAULT_STEP,
    STROKE_TOLERANCE,
    default_arc_length_step,
    evaluate,
    render_path,
    stroke_linear_coverage,
    with_gaps,
)
from course.antialias.coverage import agg_render, reference
from course.antialias.splats import (
    ONE_SAMPLE,
    SPLAT_METHODS,
    SPLATS,
    arc_length_weights,
    bilinear_centres,
    bilinear_corners,
    bilinear_zero_offset,
    nearest_round,
    nearest_truncate,
    normalised_centres,
    splat,
    subsample_falloff,
)
from course.antialias.stroke import stroke_coverage
from course.curves._uniform import uniform_steps
from course.curves.paths import as_path, text_curves
from course.i18n import _
from course.limits import require_step_samples

__all__ = [
    "DEFAULT_STEP",
    "ONE_SAMPLE",
    "RENDER_METHODS",
    "SPLATS",
    "SPLAT_METHODS",
    "STROKES",
    "WEIGHTINGS",
    "agg_render",
    "arc_length_step",
    "arc_length_weights",
    "bilinear_centres",
    "bilinear_corners",
    "bilinear_zero_offset",
    "curve_samples",
    "nearest_round",
    "nearest_truncate",
    "normalised_centres",
    "reference",
    "render",
    "splat",
    "stroke_area",
    "stroke_linear",
    "stroke_polyline",
    "subsample_falloff",
    "text_curves",
    "wang_segments",
]

WEIGHTINGS = ("count", "arc_length")
# Samples per pixel side for the round caps of stroke_area.
CAP_SAMPLES = 16
#: The stroke-coverage methods of :func:`render`.
STROKES = ("stroke_linear", "stroke_area")
RENDER_METHODS = SPLATS + STROKES


# --- what a graphics engineer would use: stroke coverage -------------------------


def wang_segments(points: Any, tolerance: float) -> int:
    """How many equal t steps keep the chords within ``tolerance`` of the curve.

    Wang's formula: on a parameter interval of width h the chord strays from
    a degree-n Bézier curve by at most ``h^2 / 8 * max |B''|``, and
    ``|B''| <= n (n - 1) max_i |P[i] - 2 P[i+1] + P[i+2]|``. Uniform steps
    need no recursion, which makes this the fast way to flatten.

    Examples
    --------
    >>> wang_segments([[0, 0], [50, 100], [100, 0]], 0.25)
    15
    """
    control = as_curve(points)
    return _wang_segments(control, as_positive_float(tolerance, "tolerance"))


def _wang_segments(control: np.ndarray, tolerance: float) -> int:
    """:func:`wang_segments` of a checked curve and tolerance."""
    degree = len(control) - 1
    if degree < 2:
        return 1
    second = control[:-2] - 2 * control[1:-1] + control[2:]
    bound = degree * (degree - 1) * np.hypot(*second.T).max()
    return max(1, math.ceil(math.sqrt(bound / (8 * tolerance))))


def stroke_polyline(points: Any, tolerance: float = STROKE_TOLERANCE) -> np.ndarray:
    """The curve flattened for the stroke methods: Wang's count of uniform steps."""
    control = as_curve(points)
    count = _wang_segments(control, as_positive_float(tolerance, "tolerance"))
    return evaluate(control, np.linspace(0.0, 1.0, count + 1))


def _canvas(
    polyline: np.ndarray, shape: Any, reach: float
) -> tuple[tuple[int, int], tuple[int, int]]:
    """The canvas (H, W) and its origin (x, y): the image's, or one around the curve."""
    if shape is not None:
        return as_shape(shape), (0, 0)
    # No canvas: one just large enough, its origin wherever the curve is.
    low = np.floor(polyline.min(axis=0) - reach - 2)
    extent = np.ceil(polyline.max(axis=0) + reach + 2) - low
    if extent[0] * extent[1] > limits.MAX_PIXELS:
        raise ValueError(
            _(
                "polyline and width span {width} x {height} pixels; without shape at most "
                "{most}: pass shape=(H, W) to clip the stroke to a canvas"
            ).format(width=int(extent[1]), height=int(extent[0]), most=limits.MAX_PIXELS)
        )
    return (int(extent[1]), int(extent[0])), (int(low[0]), int(low[1]))


def _as_polyline(polyline: Any, gaps: Any) -> tuple[np.ndarray, np.ndarray]:
    line = as_points(polyline, "polyline", bound=limits.MAX_COORDINATE)
    if line.shape[1] != 2:
        raise ValueError(
            _("polyline must have shape (K, 2); got shape {line_shape}").format(
                line_shape=line.shape
            )
        )
    return with_gaps(line, gaps)


def stroke_linear(
    polyline: Any, width: float = 1.0, shape: Any = None, gaps: Any = None
) -> tuple[np.ndarray, np.ndarray]:
    """Coverage from the distance d of each pixel centre: ``clamp(w/2 + 0.5 - d, 0, 1)``.

    The distance is to the polyline (the flattened curve or path: the
    nearest of its segments); only pixels within ``w/2 + 0.5`` of it are
    visited. The formula is exact for an axis-aligned stroke: a pixel whose
    centre is d from its middle line overlaps it by ``w/2 + 1/2 - d``. At
    45 degrees it overestimates the pixel on the line (1 instead of 0.91 for
    w = 1) and misses the corners reaching out further.

    Parameters
    ----------
    polyline : array_like, shape (K, 2)
        The curve as a polyline, e.g. :func:`stroke_polyline`.
    width : float
        Stroke width in pixels, > 0.
    shape : (H, W), optional
        Keep only pixels on this canvas.
    gaps : bool array_like, shape (K - 1,), optional
        True for segments not drawn: the pen moving between the subpaths
        of a path (:func:`course.curves.drawable_paths.flatten_uniform`).

    Returns
    -------
    pixels : int ndarray (P, 2), each pixel once
    weights : float ndarray (P,), coverage in (0, 1]

    Examples
    --------
    >>> pixels, weights = stroke_linear([[0.0, 1.25], [3.0, 1.25]], shape=(3, 3))
    >>> pixels.tolist(), weights.tolist()
    ([[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [2, 1]], [0.25, 0.25, 0.25, 0.75, 0.75, 0.75])
    """
    line, gaps = _as_polyline(polyline, gaps)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    canvas, origin = _canvas(line, shape, 0.5 * width + 0.5)
    return stroke_linear_coverage(line, gaps, width, canvas, origin)


def stroke_area(
    polyline: Any, width: float = 1.0, shape: Any = None, gaps: Any = None
) -> tuple[np.ndarray, np.ndarray]:
    """The exact area of each pixel inside the stroke, round joins and caps.

    The stroke is the set of points within w / 2 of the polyline: the
    union of the *stadiums* of its segments. Its outline is drawn (offset
    edges, cut where they cross on the inside of a turn, arcs on the outside
    and at the ends) and filled by signed area, as a font rasterizer fills a
    glyph (:mod:`course.antialias.stroke`): exact at any bend, corner or cusp, up to
    the chords of the arcs (0.002 px for w = 1). Where parts of the path
    that are not neighbours come within w of each other (a loop, two
    subpaths, a hairpin), and at cusps, the few pixels near them are
    integrated instead: 16 rows each, the length of each row inside the
    stroke exact (error at most 1/32 where an edge runs horizontally
    through the pixel, of order 1/256 elsewhere).

    Parameters and returns as :func:`stroke_linear`.

    Examples
    --------
    >>> line = [[0.0, 0.0], [4.0, 4.0]]
    >>> pixels, weights = stroke_area(line, shape=(4, 4))
    >>> round(float(weights[(pixels == [1, 1]).all(axis=1)][0]), 4)
    0.9142

    Past a sharp corner nothing is covered (the join is round, not mitred):

    >>> pixels, weights = stroke_area([[10.5, 10.5], [20.5, 10.5], [10.5, 12.5]], 1.0, (30, 30))
    >>> [[21, 10]] in pixels.tolist()
    False
    """
    line, gaps = _as_polyline(polyline, gaps)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    canvas, origin = _canvas(line, shape, 0.5 * width)
    image = stroke_coverage(line - np.array(origin, dtype=float), gaps, 0.5 * width, canvas)
    y, x = np.nonzero(image)
    pixels = np.stack([x + origin[0], y + origin[1]], axis=1)
    return pixels, image[y, x]


_STROKES = {"stroke_linear": stroke_linear, "stroke_area": stroke_area}


# --- one entry point ---------------------------------------------------------------


def render(
    points: Any,
    shape: Any,
    method: str,
    width: float = 1.0,
    step: float | None = None,
    weighting: str = "count",
) -> np.ndarray:
    """Draw a Bézier curve or a whole path with one anti-aliasing method; [0, 1].

    Parameters
    ----------
    points : array_like (N, 2), list of them, or matplotlib.path.Path
        Control points in image space (x right, y down); or a whole path:
        a list of curves (each (N_i, 2)) or a ``matplotlib.path.Path`` with
        its codes (see :func:`course.curves.paths.as_path`; :func:`course.curves.paths.text_curves`
        gives a line of text). A path is one stroke: where its curves join,
        the stroke methods count the overlap once.
    shape : (H, W)
        Canvas size; pixels off it are dropped, never wrapped.
    method : str
        One of :data:`RENDER_METHODS`. The splat methods sample the curve at
        t = 0, step, 2 step, ... and add every splat with saturation, as the
        handouts do. The stroke methods flatten the curve (Wang's formula,
        within 0.01 px) and compute each nearby pixel's coverage once.
    width : float
        Stroke width in pixels, > 0, for the stroke methods. The splat
        methods draw the handouts' curve about a pixel wide; with
        ``weighting="arc_length"`` they deposit ``width`` per unit of length,
        the area of a stroke of that width.
    step : float, optional
        t step of the splat methods. By default the handouts' 0.001 with
        ``weighting="count"``; with ``"arc_length"`` a step that puts samples
        at most 0.5 px apart (the fix makes brightness independent of the
        step, so it can afford a fine one). Ignored by the stroke methods.
    weighting : {"count", "arc_length"}
        ``"count"``: each sample adds its full splat (the handouts).
        ``"arc_length"``: each splat is scaled by the length of curve its
        sample stands for (:func:`arc_length_weights`) times ``width``.

    Returns
    -------
    ndarray, shape (H, W)

    Examples
    --------
    >>> render([[0.0, 1.75], [4.0, 1.75]], (3, 4), "stroke_area")
    array([[0.  , 0.  , 0.  , 0.  ],
           [0.75, 0.75, 0.75, 0.75],
           [0.25, 0.25, 0.25, 0.25]])
    >>> render([[0.5, 0.5], [3.5, 0.5]], (1, 4), "nearest_truncate", step=0.25)
    array([[1., 1., 1., 1.]])

    A path of two lines meeting at a right angle covers its corner once,
    round: pixel (2, 1) holds 3/4 of a square and a quarter disc of radius 1/2:

    >>> corner = [[[0.0, 1.5], [2.5, 1.5]], [[2.5, 1.5], [2.5, 4.0]]]
    >>> render(corner, (4, 4), "stroke_area")[1:3, 1:4].round(4)
    array([[1.    , 0.9463, 0.    ],
           [0.    , 1.    , 0.    ]])
    """
    path = as_path(points)
    height, canvas_width = as_shape(shape)
    method = as_choice(method, "method", RENDER_METHODS)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    weighting = as_choice(weighting, "weighting", WEIGHTINGS)
    if step is not None:
        step = as_positive_float(step, "step")
    return render_path(path, (height, canvas_width), method, width, step, weighting)


def curve_samples(points: Any, step: float) -> np.ndarray:
    """The handouts' samples: the curve at t = 0, step, 2 step, ... <= 1.

    Cubics and lower are evaluated in the Bernstein form (one small matrix
    product, twice as fast as de Casteljau's levels and as accurate at these
    degrees), higher degrees by de Casteljau. The stroke methods' polyline
    (:func:`stroke_polyline`) is evaluated the same way.

    Examples
    --------
    >>> curve_samples([[0, 0], [2, 4], [4, 0]], 0.5)
    array([[0., 0.],
           [2., 2.],
           [4., 0.]])
    """
    control = as_curve(points)
    step = as_positive_float(step, "step")
    require_step_samples(step, "step")
    return evaluate(control, uniform_steps(step, "exact"))


def arc_length_step(points: Any) -> float:
    """The t step the arc-length fix uses by default: samples at most 0.5 px apart.

    ``|B'(t)| <= n max |P[i+1] - P[i]|`` (the hodograph's control points bound
    the speed), so a step of 0.5 px over that bound never moves further. Never
    coarser than the handouts' 0.001.

    Examples
    --------
    >>> arc_length_step([[0, 0], [100, 0]])
    0.001
    >>> from course.images import SEED_000_CUBIC
    >>> round(arc_length_step(SEED_000_CUBIC), 7)
    0.0001733
    """
    return default_arc_length_step(as_curve(points))
