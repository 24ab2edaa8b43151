"""The handouts' splats: spreading one curve point over the pixels around it.

Three handouts (seeds 000, 002, 003; GAMES101 assignment 4, optional task)
anti-alias a Bézier curve the same way: walk t from 0 to 1 in small steps and,
for each curve point, brighten a few pixels around it with weights that fall
off with distance. Each of their *splats* is here, faithfully, as a function
``splat(samples) -> (pixels, weights)``: ``pixels`` is an int ``(K, 2)`` array
of (x, y), ``weights`` a float ``(K,)`` array in [0, 1], in sample order,
optionally clipped to a canvas with ``shape=(H, W)``. Beside each splat is its
one-sample form, written like the C++ (:data:`ONE_SAMPLE`), and
``splat(samples, kind, method="loop")`` runs it sample by sample; the vectorized
form, all samples at once, is array code on checked samples in ``_splats``.

:mod:`course.antialias` draws curves with them (and with stroke coverage).

References
----------
.. [1] GAMES101 (L. Yan), assignment 4: "Bézier curves", optional task:
   anti-alias by weighting the pixels around each point by distance.
.. [2] A. R. Smith, "A pixel is not a little square", Microsoft Tech Memo 6, 1995
   (why a sample belongs to the pixel *centres* around it).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from course import limits
from course._validate import as_choice, as_points, as_shape
from course.antialias._splats import SQRT2, SUBSAMPLE_MAX_DISTANCE, splat_points
from course.antialias._splats import arc_length_weights as arc_length_weights_of
from course.i18n import _
from course.raster._paint import on_canvas

__all__ = [
    "ONE_SAMPLE",
    "PIXELS_PER_SAMPLE",
    "SPLATS",
    "SPLAT_METHODS",
    "arc_length_weights",
    "bilinear_centres",
    "bilinear_corners",
    "bilinear_zero_offset",
    "nearest_round",
    "nearest_truncate",
    "normalised_centres",
    "splat",
    "subsample_falloff",
]


def _as_samples(samples: Any) -> np.ndarray:
    array = as_points(samples, "samples", bound=limits.MAX_COORDINATE)
    if array.shape[1] != 2:
        raise ValueError(
            _(
                "samples must have shape (M, 2): (x, y) curve points in image space; got shape "
                "{array_shape}"
            ).format(array_shape=array.shape)
        )
    return array


def _clipped(pixels: np.ndarray, weights: np.ndarray, shape: Any) -> tuple[np.ndarray, np.ndarray]:
    if shape is None:
        return pixels, weights
    keep = on_canvas(pixels, as_shape(shape))
    return pixels[keep], weights[keep]


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
    return _clipped(*splat_points(_as_samples(samples), "nearest_truncate"), shape)


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
    return _clipped(*splat_points(_as_samples(samples), "nearest_round"), shape)


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
    return _clipped(*splat_points(_as_samples(samples), "bilinear_zero_offset"), shape)


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
    return _clipped(*splat_points(_as_samples(samples), "bilinear_corners"), shape)


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
    return _clipped(*splat_points(_as_samples(samples), "bilinear_centres"), shape)


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
    return _clipped(*splat_points(_as_samples(samples), "subsample_falloff"), shape)


def normalised_centres(samples: Any, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """Seed 003's 2x2 splat: the four nearest pixel centres, weights normalised.

    The handout rounds the point half up to a corner p0 (``frac < 0.5 ?
    floor : ceil``) and takes the pixels p0, p0 - (1, 0), p0 - (0, 1),
    p0 - (1, 1), whose centres (+0.5) are the four around the point. Each
    gets ``sqrt(2) - d`` (d: distance from the point to its centre; sqrt(2)
    is the largest possible), divided by their sum, so the weights add to 1.
    Unlike bilinear weights, which give a point at a pixel's centre to that
    pixel alone, these still give its two edge neighbours about 0.18 each
    (the diagonal one gets 0).

    Examples
    --------
    >>> pixels, weights = normalised_centres([[2.5, 1.5]])
    >>> pixels.tolist(), weights.round(4).tolist()
    ([[3, 2], [2, 2], [3, 1], [2, 1]], [0.0, 0.1847, 0.1847, 0.6306])
    """
    return _clipped(*splat_points(_as_samples(samples), "normalised_centres"), shape)


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
#: The handouts' splats, by name.
SPLATS = tuple(_SPLATS)
#: The forms of :func:`splat`: all samples at once, or the one-sample form in a loop.
SPLAT_METHODS = ("vectorized", "loop")
# The one-sample forms, for reading beside the handouts' C++.
ONE_SAMPLE = {name: entry[1] for name, entry in _SPLATS.items()}
# How many (pixel, weight) rows each splat gives per sample, before clipping.
PIXELS_PER_SAMPLE = {name: entry[2] for name, entry in _SPLATS.items()}


def splat(
    samples: Any, kind: str, shape: Any = None, method: str = "vectorized"
) -> tuple[np.ndarray, np.ndarray]:
    """Run the splat ``kind`` (one of :data:`SPLATS`) on the samples.

    ``method="loop"`` is the handouts' form: the splat's one-sample function
    (:data:`ONE_SAMPLE`) called sample by sample, each giving a few (pixel,
    weight) pairs; ``"vectorized"`` (the default) splats every sample at
    once with array operations. Same pixels and weights, in the same order.

    Examples
    --------
    >>> splat([[0.5, 0.5]], "nearest_round")[0].tolist()
    [[0, 0]]
    >>> pixels, weights = splat([[2.25, 1.5]], "bilinear_corners", method="loop")
    >>> pixels.tolist(), weights.tolist()
    ([[2, 1], [3, 1], [2, 2], [3, 2]], [0.375, 0.125, 0.375, 0.125])
    """
    kind = as_choice(kind, "kind", SPLATS)
    method = as_choice(method, "method", SPLAT_METHODS)
    if method == "loop":
        return _clipped(*_splat_loop(_as_samples(samples), kind), shape)
    return _splat_vectorized(samples, kind, shape)


def _splat_vectorized(samples: Any, kind: str, shape: Any) -> tuple[np.ndarray, np.ndarray]:
    return _SPLATS[kind][0](samples, shape)


def _splat_loop(points: np.ndarray, kind: str) -> tuple[np.ndarray, np.ndarray]:
    """The handouts' loop over curve points, each splatted by its one-sample form."""
    one_sample = ONE_SAMPLE[kind]
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
    return arc_length_weights_of(_as_samples(samples))
