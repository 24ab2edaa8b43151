"""Anti-aliasing a curve: every handout's splat, the stroke coverage, one render.

Three handouts (seeds 000, 002, 003; GAMES101 assignment 4, optional task)
anti-alias a Bézier curve the same way: walk t from 0 to 1 in small steps and,
for each curve point, brighten a few pixels around it with weights that fall
off with distance. Each of their *splats* is here, faithfully, as a function
``splat(samples) -> (pixels, weights)``: ``pixels`` is an int ``(K, 2)`` array
of (x, y), ``weights`` a float ``(K,)`` array in [0, 1], in sample order.
Beside each vectorized splat is its one-sample form, written like the C++
(:data:`ONE_SAMPLE`), and :func:`splat_loop` runs it sample by sample.

What a graphics engineer would do instead is compute each pixel's *coverage*
by a stroke of width w around the curve (:func:`stroke_linear`,
:func:`stroke_area`); :mod:`course.coverage` holds the exact reference.

The handouts add every splat with saturation, so a pixel's brightness counts
how many samples land in it, which depends on the t step and on how fast the
curve moves there. The fix (``weighting="arc_length"``) scales each splat by
the length of curve its sample stands for, so a pixel receives the length of
curve passing through it.

:func:`render` draws a curve with any of :data:`METHODS`.

References
----------
.. [1] GAMES101 (L. Yan), assignment 4: "Bézier curves", optional task:
   anti-alias by weighting the pixels around each point by distance.
.. [2] A. R. Smith, "A pixel is not a little square", Microsoft Tech Memo 6, 1995
   (why a sample belongs to the pixel *centres* around it).
.. [3] S. Wang, "Curves and surfaces for computer-aided geometric design",
   1984; the flattening bound is quoted in Sederberg, *Computer Aided
   Geometric Design*, BYU 2012, section 10.6 (Wang's formula).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from course._validate import as_choice, as_points, as_positive_float, as_shape
from course.bezier import bezier_bernstein, de_casteljau, uniform_parameters
from course.canvas import inside, paint
from course.coverage import (
    HALF_DIAGONAL,
    NearPixels,
    agg_render,
    as_curve,
    band_coverage,
    first_of_runs,
    pixels_near,
    reference,
    supersample,
)

__all__ = [
    "DEFAULT_STEP",
    "METHODS",
    "ONE_SAMPLE",
    "SPLAT_METHODS",
    "STROKE_METHODS",
    "WEIGHTINGS",
    "agg_render",
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
    "splat_loop",
    "stroke_area",
    "stroke_linear",
    "stroke_polyline",
    "subsample_falloff",
    "wang_segments",
]

# The handouts' loop: for (t = 0; t <= 1; t += 0.001).
DEFAULT_STEP = 0.001
# Largest distance between samples the arc-length fix picks by itself, in pixels.
ARC_LENGTH_SPACING = 0.25
# Largest distance from the flattened curve to the true one in the stroke methods.
STROKE_TOLERANCE = 0.01
WEIGHTINGS = ("count", "arc_length")
# Samples per pixel side for the round caps of stroke_area.
CAP_SAMPLES = 16
SQRT2 = math.sqrt(2.0)
# Seed 002's normaliser: the farthest a point can be from a sub-sample of its pixel.
SUBSAMPLE_MAX_DISTANCE = math.sqrt(1.125)


def _as_samples(samples: Any) -> np.ndarray:
    array = as_points(samples, "samples")
    if array.shape[1] != 2:
        raise ValueError(
            f"samples must have shape (M, 2): (x, y) curve points in image space; "
            f"got shape {array.shape}"
        )
    return array


def _clipped(pixels: np.ndarray, weights: np.ndarray, shape: Any) -> tuple[np.ndarray, np.ndarray]:
    if shape is None:
        return pixels, weights
    keep = inside(pixels, as_shape(shape))
    return pixels[keep], weights[keep]


def _block(
    corner_x: np.ndarray, corner_y: np.ndarray, weights: list[np.ndarray], order: list[tuple]
) -> tuple[np.ndarray, np.ndarray]:
    """Stack per-sample pixel offsets (dx, dy) from a corner, sample by sample."""
    offsets = np.array(order, dtype=np.int64)
    x = corner_x.astype(np.int64)[:, None] + offsets[:, 0]
    y = corner_y.astype(np.int64)[:, None] + offsets[:, 1]
    pixels = np.stack([x.ravel(), y.ravel()], axis=1)
    return pixels, np.stack(weights, axis=1).ravel()


# --- nearest pixel: no anti-aliasing ------------------------------------------


def nearest_truncate(samples: Any, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """One pixel per sample, coordinates truncated toward zero; weight 1.

    Seeds 002, 003 and 004 write ``window.at<cv::Vec3b>(point.y, point.x)``:
    the float coordinates convert to int by truncation. On the canvas that is
    the pixel whose square contains the point (floor); a point in (-1, 0)
    lands in column or row 0, where floor would put it off the canvas.

    Examples
    --------
    >>> pixels, weights = nearest_truncate([[2.7, 1.2], [-0.5, 0.5]])
    >>> pixels.tolist(), weights.tolist()
    ([[2, 1], [0, 0]], [1.0, 1.0])
    """
    points = _as_samples(samples)
    pixels = np.trunc(points).astype(np.int64)
    return _clipped(pixels, np.ones(len(pixels)), shape)


def nearest_round(samples: Any, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """One pixel per sample, coordinates rounded to the nearest integer; weight 1.

    Seed 000 writes ``window.at<cv::Vec3b>(point)`` with a ``cv::Point2f``;
    OpenCV converts it to ``cv::Point`` with ``cvRound`` (halves to even).
    Pixel k is then lit for points in [k - 0.5, k + 0.5), but its centre is
    k + 0.5: the curve is drawn half a pixel right of and below where it is.

    Examples
    --------
    >>> nearest_round([[2.7, 1.2], [0.5, 1.5]])[0].tolist()
    [[3, 1], [0, 2]]
    """
    points = _as_samples(samples)
    pixels = np.rint(points).astype(np.int64)
    return _clipped(pixels, np.ones(len(pixels)), shape)


# --- seed 000: three versions of addColor ---------------------------------------


def bilinear_zero_offset(samples: Any, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """Seed 000's "left" addColor, exactly: the weights measure a zero offset.

    The handout builds the four corners as ``cv::Point2f p1(point.x,
    point.y)``, ``p2(point.x + 1, point.y)``, ... and then
    ``dx = point.x - p1.x``: since p1 *is* the point, dx = dy = 0, so p1
    gets weight ``(1 - dx) (1 - dy) = 1`` and the other three get 0.
    ``img.at(p1)`` rounds p1 with ``cvRound``. The result is pixel for pixel
    :func:`nearest_round`: no anti-aliasing at all. Returned as four pixels
    per sample (three of weight 0) so the degeneration can be seen.

    Examples
    --------
    >>> pixels, weights = bilinear_zero_offset([[2.7, 1.2]])
    >>> pixels.tolist(), weights.tolist()
    ([[3, 1], [4, 1], [3, 2], [4, 2]], [1.0, 0.0, 0.0, 0.0])
    """
    points = _as_samples(samples)
    x, y = points[:, 0], points[:, 1]
    # Each corner is rounded on its own, as cv::Point(p2) etc. would.
    corners = [(x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)]
    pixels = np.stack([np.rint(np.stack(c, axis=1)) for c in corners], axis=1)
    dx, dy = x - x, y - y
    weights = np.stack([(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy], axis=1).ravel()
    return _clipped(pixels.reshape(-1, 2).astype(np.int64), weights, shape)


def bilinear_corners(samples: Any, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """Seed 000's "middle" addColor: bilinear weights with pixels at integer corners.

    ``cv::Point p1(point.x, point.y)`` truncates, so p1 is the integer
    corner (floor) at the top-left of the point, and ``dx, dy`` are the
    point's fractional parts. The four pixels p1, p1 + (1, 0), p1 + (0, 1),
    p1 + (1, 1) get the bilinear weights ``(1 - dx)(1 - dy), dx (1 - dy),
    (1 - dx) dy, dx dy``, which sum to 1. This treats pixel (c, r) as if it
    sat at the point (c, r), its corner, while its centre is (c + 0.5,
    r + 0.5): the curve is drawn half a pixel right of and below where it
    is. (C++ truncation equals floor on the canvas; floor is used so
    that points left of the canvas give weights in [0, 1] too.)

    Examples
    --------
    >>> pixels, weights = bilinear_corners([[2.25, 1.5]])
    >>> pixels.tolist(), weights.tolist()
    ([[2, 1], [3, 1], [2, 2], [3, 2]], [0.375, 0.125, 0.375, 0.125])
    """
    points = _as_samples(samples)
    corner = np.floor(points)
    dx, dy = (points - corner).T
    weights = [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]
    return _clipped(
        *_block(corner[:, 0], corner[:, 1], weights, [(0, 0), (1, 0), (0, 1), (1, 1)]), shape
    )


def _round_half_away(values: np.ndarray) -> np.ndarray:
    """C++ ``std::round``: halves away from zero (numpy's rint rounds them to even)."""
    return np.copysign(np.floor(np.abs(values) + 0.5), values)


def bilinear_centres(samples: Any, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """Seed 000's "right" addColor: bilinear weights about pixel centres.

    The handout rounds the point to the nearest pixel corner
    ``center = (round(x), round(y))`` and splats the 2x2 block of pixels
    around that corner, ``center - (1, 1)`` to ``center``: exactly the four
    pixels whose centres (c + 0.5, r + 0.5) surround the point. With the
    offsets measured from the centre of the top-left one,
    ``dx = x - (center.x - 0.5)``, the bilinear weights are the correct
    ones for centre-sampled pixels: a point at a pixel's centre lights that
    pixel alone. (The handout elides its weight lines; measured from
    ``p1`` itself, dx would lie in [0.5, 1.5] and weights outside [0, 1].)

    Examples
    --------
    >>> pixels, weights = bilinear_centres([[2.5, 1.5], [2.75, 1.5]])
    >>> pixels.tolist()
    [[2, 1], [3, 1], [2, 2], [3, 2], [2, 1], [3, 1], [2, 2], [3, 2]]
    >>> weights.tolist()
    [1.0, 0.0, 0.0, 0.0, 0.75, 0.25, 0.0, 0.0]
    """
    points = _as_samples(samples)
    center = _round_half_away(points)
    dx, dy = (points - (center - 0.5)).T
    weights = [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]
    return _clipped(
        *_block(center[:, 0] - 1, center[:, 1] - 1, weights, [(0, 0), (1, 0), (0, 1), (1, 1)]),
        shape,
    )


# --- seed 002 and seed 003 -----------------------------------------------------


def subsample_falloff(samples: Any, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """Seed 002's ``antiAliasing``: one pixel, dimmed by distance to four sub-samples.

    The point's own pixel (x, y) = (int(point.x), int(point.y)) is the only
    one written. Its weight is the mean over the four sub-samples at
    (x + 0.25, y + 0.25), (x + 0.75, y + 0.25), (x + 0.25, y + 0.75),
    (x + 0.75, y + 0.75) of ``(maxDis - d) / maxDis``, d the distance from
    the point to the sub-sample and ``maxDis = sqrt(1.125)`` the largest
    such distance (0.75 along both axes). A point at the pixel's centre gets
    about 0.67, one at a corner about 0.29: the weight never reaches 1 and
    no neighbour is touched, so it dims the curve rather than smoothing it.
    (The handout truncates; floor is used, equal on the canvas, so that
    points left of it stay off it instead of folding onto column 0 with a
    negative weight.)

    Examples
    --------
    >>> pixels, weights = subsample_falloff([[2.5, 1.5], [2.0, 1.0]])
    >>> pixels.tolist(), weights.round(4).tolist()
    ([[2, 1], [2, 1]], [0.6667, 0.294])
    """
    points = _as_samples(samples)
    corner = np.floor(points)
    fx, fy = (points - corner).T
    total = np.zeros(len(points))
    for sx, sy in ((0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)):
        distance = np.hypot(fx - sx, fy - sy)
        total += (SUBSAMPLE_MAX_DISTANCE - distance) / SUBSAMPLE_MAX_DISTANCE
    return _clipped(corner.astype(np.int64), total / 4, shape)


def normalised_centres(samples: Any, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """Seed 003's 2x2 splat: the four nearest pixel centres, weights normalised.

    The handout rounds the point half up to a corner p0 (``frac < 0.5 ?
    floor : ceil``) and takes the pixels p0, p0 - (1, 0), p0 - (0, 1),
    p0 - (1, 1), whose centres (+0.5) are the four around the point. Each
    gets ``sqrt(2) - d`` (d: distance from the point to its centre; sqrt(2)
    is the largest possible), divided by their sum, so the weights add to 1.
    Unlike bilinear weights they never vanish: a point at a pixel's centre
    still gives its three neighbours about 0.19 each.

    Examples
    --------
    >>> pixels, weights = normalised_centres([[2.5, 1.5]])
    >>> pixels.tolist(), weights.round(4).tolist()
    ([[3, 2], [2, 2], [3, 1], [2, 1]], [0.0, 0.1847, 0.1847, 0.6306])
    """
    points = _as_samples(samples)
    low = np.floor(points)
    p0 = np.where(points - low < 0.5, low, np.ceil(points))
    order = [(0, 0), (-1, 0), (0, -1), (-1, -1)]
    raw = [
        SQRT2 - np.hypot(points[:, 0] - (p0[:, 0] + ox + 0.5), points[:, 1] - (p0[:, 1] + oy + 0.5))
        for ox, oy in order
    ]
    total = np.sum(raw, axis=0)
    weights = [w / total for w in raw]
    return _clipped(*_block(p0[:, 0], p0[:, 1], weights, order), shape)


# --- the same splats, one sample at a time, as the handouts write them ----------


def _nearest_truncate_one(x: float, y: float) -> list[tuple[tuple[int, int], float]]:
    return [((int(x), int(y)), 1.0)]


def _nearest_round_one(x: float, y: float) -> list[tuple[tuple[int, int], float]]:
    return [((round(x), round(y)), 1.0)]  # Python's round, like cvRound, halves to even


def _bilinear_zero_offset_one(x: float, y: float) -> list[tuple[tuple[int, int], float]]:
    p1, p2, p3, p4 = (x, y), (x + 1, y), (x, y + 1), (x + 1, y + 1)
    dx, dy = x - p1[0], y - p1[1]
    weights = [(1 - dx) * (1 - dy), dx * (1 - dy), (1 - dx) * dy, dx * dy]
    return [((round(p[0]), round(p[1])), w) for p, w in zip((p1, p2, p3, p4), weights, strict=True)]


def _bilinear_corners_one(x: float, y: float) -> list[tuple[tuple[int, int], float]]:
    p1 = (math.floor(x), math.floor(y))
    dx, dy = x - p1[0], y - p1[1]
    return [
        ((p1[0], p1[1]), (1 - dx) * (1 - dy)),
        ((p1[0] + 1, p1[1]), dx * (1 - dy)),
        ((p1[0], p1[1] + 1), (1 - dx) * dy),
        ((p1[0] + 1, p1[1] + 1), dx * dy),
    ]


def _bilinear_centres_one(x: float, y: float) -> list[tuple[tuple[int, int], float]]:
    cx = math.copysign(math.floor(abs(x) + 0.5), x)  # std::round
    cy = math.copysign(math.floor(abs(y) + 0.5), y)
    p1 = (int(cx) - 1, int(cy) - 1)
    dx, dy = x - (p1[0] + 0.5), y - (p1[1] + 0.5)
    return [
        ((p1[0], p1[1]), (1 - dx) * (1 - dy)),
        ((p1[0] + 1, p1[1]), dx * (1 - dy)),
        ((p1[0], p1[1] + 1), (1 - dx) * dy),
        ((p1[0] + 1, p1[1] + 1), dx * dy),
    ]


def _subsample_falloff_one(x: float, y: float) -> list[tuple[tuple[int, int], float]]:
    px, py = math.floor(x), math.floor(y)
    max_dis = SUBSAMPLE_MAX_DISTANCE
    color1 = (max_dis - math.hypot(x - px - 0.25, y - py - 0.25)) / max_dis
    color2 = (max_dis - math.hypot(x - px - 0.75, y - py - 0.25)) / max_dis
    color3 = (max_dis - math.hypot(x - px - 0.25, y - py - 0.75)) / max_dis
    color4 = (max_dis - math.hypot(x - px - 0.75, y - py - 0.75)) / max_dis
    return [((px, py), (color1 + color2 + color3 + color4) / 4)]


def _normalised_centres_one(x: float, y: float) -> list[tuple[tuple[int, int], float]]:
    p0 = (
        math.floor(x) if x - math.floor(x) < 0.5 else math.ceil(x),
        math.floor(y) if y - math.floor(y) < 0.5 else math.ceil(y),
    )
    ps = [p0, (p0[0] - 1, p0[1]), (p0[0], p0[1] - 1), (p0[0] - 1, p0[1] - 1)]
    ds = [SQRT2 - math.hypot(x - (p[0] + 0.5), y - (p[1] + 0.5)) for p in ps]
    sum_d = sum(ds)
    return [(p, d / sum_d) for p, d in zip(ps, ds, strict=True)]


SplatFunction = Callable[..., tuple[np.ndarray, np.ndarray]]

# Method name -> (vectorized splat, one-sample form, pixels per sample).
_SPLATS: dict[str, tuple[SplatFunction, Callable, int]] = {
    "nearest_truncate": (nearest_truncate, _nearest_truncate_one, 1),
    "nearest_round": (nearest_round, _nearest_round_one, 1),
    "bilinear_zero_offset": (bilinear_zero_offset, _bilinear_zero_offset_one, 4),
    "bilinear_corners": (bilinear_corners, _bilinear_corners_one, 4),
    "bilinear_centres": (bilinear_centres, _bilinear_centres_one, 4),
    "subsample_falloff": (subsample_falloff, _subsample_falloff_one, 1),
    "normalised_centres": (normalised_centres, _normalised_centres_one, 4),
}
SPLAT_METHODS = tuple(_SPLATS)
STROKE_METHODS = ("stroke_linear", "stroke_area")
METHODS = SPLAT_METHODS + STROKE_METHODS
# The one-sample forms, for reading beside the handouts' C++.
ONE_SAMPLE = {name: entry[1] for name, entry in _SPLATS.items()}


def splat(samples: Any, method: str, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """Run the splat ``method`` (one of :data:`SPLAT_METHODS`) on the samples.

    Examples
    --------
    >>> splat([[0.5, 0.5]], "nearest_round")[0].tolist()
    [[0, 0]]
    """
    method = as_choice(method, "method", SPLAT_METHODS)
    return _SPLATS[method][0](samples, shape)


def splat_loop(samples: Any, method: str) -> tuple[np.ndarray, np.ndarray]:
    """The readable form: the splat's one-sample function, called sample by sample.

    Same result as :func:`splat`, as the handouts compute it: a loop over
    curve points, each giving a few (pixel, weight) pairs.

    Examples
    --------
    >>> pixels, weights = splat_loop([[2.25, 1.5]], "bilinear_corners")
    >>> pixels.tolist(), weights.tolist()
    ([[2, 1], [3, 1], [2, 2], [3, 2]], [0.375, 0.125, 0.375, 0.125])
    """
    points = _as_samples(samples)
    method = as_choice(method, "method", SPLAT_METHODS)
    one_sample = ONE_SAMPLE[method]
    pixels, weights = [], []
    for x, y in points.tolist():
        for pixel, weight in one_sample(x, y):
            pixels.append(pixel)
            weights.append(weight)
    return np.array(pixels, dtype=np.int64).reshape(-1, 2), np.array(weights, dtype=float)


# --- accumulation: count samples, or weigh them by arc length ---------------------


def arc_length_weights(samples: Any) -> np.ndarray:
    """The length of curve each sample stands for: half of each chord beside it.

    ``w[i] = (|p[i] - p[i-1]| + |p[i+1] - p[i]|) / 2``, with the missing
    chord at either end counted as 0, so the weights add up to the length of
    the polyline through the samples.

    Examples
    --------
    >>> arc_length_weights([[0, 0], [3, 4], [3, 5]])
    array([2.5, 3. , 0.5])
    """
    points = _as_samples(samples)
    chords = np.hypot(*np.diff(points, axis=0).T)
    padded = np.concatenate([[0.0], chords, [0.0]])
    return 0.5 * (padded[:-1] + padded[1:])


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
    tolerance = as_positive_float(tolerance, "tolerance")
    degree = len(control) - 1
    if degree < 2:
        return 1
    second = control[:-2] - 2 * control[1:-1] + control[2:]
    bound = degree * (degree - 1) * np.hypot(*second.T).max()
    return max(1, math.ceil(math.sqrt(bound / (8 * tolerance))))


def stroke_polyline(points: Any, tolerance: float = STROKE_TOLERANCE) -> np.ndarray:
    """The curve flattened for the stroke methods: Wang's count of uniform steps."""
    control = as_curve(points)
    count = wang_segments(control, tolerance)
    return _evaluate(control, np.linspace(0.0, 1.0, count + 1))


def _nearest_pairs(
    polyline: np.ndarray, shape: Any, reach: float
) -> tuple[np.ndarray, NearPixels, np.ndarray]:
    """pixels_near, reduced to the nearest segment of each pixel."""
    if shape is None:
        # No canvas: one just large enough, its origin wherever the curve is.
        low = np.floor(polyline.min(axis=0) - reach - 2)
        extent = np.ceil(polyline.max(axis=0) + reach + 2) - low
        origin = (int(low[0]), int(low[1]))
        near = pixels_near(polyline, (int(extent[1]), int(extent[0])), reach, origin)
    else:
        near = pixels_near(polyline, as_shape(shape), reach)
    # Pairs are sorted by pixel, nearest segment first.
    first = first_of_runs(near.flat)
    pixels = np.stack([near.x[first], near.y[first]], axis=1)
    return pixels, near, first


def _as_polyline(polyline: Any) -> np.ndarray:
    line = as_points(polyline, "polyline")
    if line.shape[1] != 2:
        raise ValueError(f"polyline must have shape (K, 2); got shape {line.shape}")
    if len(line) == 1:
        line = np.vstack([line, line])
    return line


def stroke_linear(
    polyline: Any, width: float = 1.0, shape: Any = None
) -> tuple[np.ndarray, np.ndarray]:
    """Coverage from the distance d of each pixel centre: ``clamp(w/2 + 0.5 - d, 0, 1)``.

    The distance is to the polyline (the flattened curve); only pixels within
    ``w/2 + 0.5`` of it are visited. The formula is exact for an
    axis-aligned stroke: a pixel whose centre is d from its middle line
    overlaps it by ``w/2 + 1/2 - d``. At 45 degrees it overestimates the
    pixel on the line (1 instead of 0.91 for w = 1) and misses the corners
    reaching out further.

    Parameters
    ----------
    polyline : array_like, shape (K, 2)
        The curve as a polyline, e.g. :func:`stroke_polyline`.
    width : float
        Stroke width in pixels, > 0.
    shape : (H, W), optional
        Keep only pixels on this canvas.

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
    line = _as_polyline(polyline)
    width = as_positive_float(width, "width")
    reach = 0.5 * width + 0.5
    pixels, near, first = _nearest_pairs(line, shape, reach)
    weights = np.clip(reach - near.distance[first], 0.0, 1.0)
    keep = weights > 0
    return pixels[keep], weights[keep]


def stroke_area(
    polyline: Any, width: float = 1.0, shape: Any = None
) -> tuple[np.ndarray, np.ndarray]:
    """Coverage as the exact area of the pixel inside the nearest segment's band.

    For each pixel near the curve, take the polyline segment nearest its
    centre and the straight band of width w along that segment's line: the
    area of the pixel square inside that band is
    :func:`course.coverage.slab_coverage`, exact for any direction. Where the
    curve bends little over a pixel this is the exact coverage. Near the
    curve's two ends the stroke is a half disc (round cap), not a band:
    the few pixels there are sampled 16 x 16, as the reference does.

    Parameters and returns as :func:`stroke_linear`.

    Examples
    --------
    >>> line = [[0.0, 0.0], [4.0, 4.0]]
    >>> pixels, weights = stroke_area(line, shape=(4, 4))
    >>> round(float(weights[(pixels == [1, 1]).all(axis=1)][0]), 4)
    0.9142
    """
    line = _as_polyline(polyline)
    width = as_positive_float(width, "width")
    half = 0.5 * width
    pixels, near, first = _nearest_pairs(line, shape, half + HALF_DIAGONAL)
    line = near.polyline
    segment = near.segment[first]
    run_x, run_y = np.abs(line[segment + 1] - line[segment]).T
    length = np.hypot(run_x, run_y)
    safe = np.where(length > 0, length, 1.0)
    # The normal's components are the direction's, swapped: same larger, smaller.
    wide, narrow = np.maximum(run_x, run_y) / safe, np.minimum(run_x, run_y) / safe
    weights = band_coverage(near.across[first], wide, narrow, width)
    weights[length == 0] = 0.0  # a zero-length segment has no band; the caps cover it
    # Near the ends the stroke is a half disc, not a band: sample those pixels.
    x, y = near.x[first] + 0.5, near.y[first] + 0.5
    reach2 = (half + HALF_DIAGONAL) ** 2
    (x0, y0), (x1, y1) = line[0], line[-1]
    at_cap = ((x - x0) ** 2 + (y - y0) ** 2 <= reach2) | ((x - x1) ** 2 + (y - y1) ** 2 <= reach2)
    if at_cap.any():
        run = np.cumsum(first) - 1  # the pixel (run) each pair belongs to
        firsts, cap = supersample(near, at_cap[run], half, CAP_SAMPLES)
        weights[run[firsts]] = cap
    keep = weights > 0
    return pixels[keep], weights[keep]


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
    """Draw the Bézier curve with one anti-aliasing method; intensity in [0, 1].

    Parameters
    ----------
    points : array_like, shape (N, 2)
        Control points in image space (x right, y down).
    shape : (H, W)
        Canvas size; pixels off it are dropped, never wrapped.
    method : str
        One of :data:`METHODS`. The splat methods sample the curve at
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
        at most 0.25 px apart (the fix makes brightness independent of the
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
    """
    control = as_curve(points)
    height, canvas_width = as_shape(shape)
    method = as_choice(method, "method", METHODS)
    width = as_positive_float(width, "width")
    weighting = as_choice(weighting, "weighting", WEIGHTINGS)
    if step is not None:
        step = as_positive_float(step, "step")
    image = np.zeros((height, canvas_width))
    if method in _STROKES:
        pixels, weights = _STROKES[method](stroke_polyline(control), width, (height, canvas_width))
        # Each pixel comes once: "max" writes it without a saturating sum.
        return paint(image, pixels, 1.0, weights, mode="max")
    if step is None:
        step = DEFAULT_STEP if weighting == "count" else _arc_length_step(control)
    samples = curve_samples(control, step)
    splat_function, _, per_sample = _SPLATS[method]
    pixels, weights = splat_function(samples)
    if weighting == "arc_length":
        weights = np.minimum(
            weights * np.repeat(arc_length_weights(samples) * width, per_sample), 1
        )
    return paint(image, pixels, 1.0, weights)


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
    return _evaluate(as_curve(points), uniform_parameters(step))


def _evaluate(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Points of the curve: the Bernstein form up to cubics, de Casteljau beyond."""
    return bezier_bernstein(control, t) if len(control) <= 4 else de_casteljau(control, t)


def _arc_length_step(control: np.ndarray) -> float:
    """A t step that keeps samples within ARC_LENGTH_SPACING px of each other."""
    if len(control) < 2:
        return DEFAULT_STEP
    # |B'(t)| <= n max |P[i+1] - P[i]|: the hodograph's control points bound it.
    speed = (len(control) - 1) * np.hypot(*np.diff(control, axis=0).T).max()
    return float(min(DEFAULT_STEP, ARC_LENGTH_SPACING / speed)) if speed > 0 else DEFAULT_STEP
