"""How good an anti-aliased curve is: brightness uniformity and position, every variant.

Each measure takes a rendered gray image (intensity in [0, 1]) and the
curve's control points, and returns numbers a lesson can put in a table
beside :func:`course.metrics.rmse` and :func:`course.metrics.max_error`
against the exact reference (:func:`course.antialias.coverage.reference`):

- :func:`uniformity`: the coefficient of variation of the intensity per unit
  length along the curve. A stroke of width w holds w units of intensity per
  unit of length everywhere (the area of a band is its width times its
  length), so a good method's profile (:func:`intensity_along`) is flat.
- :func:`position_error`: how far the intensity centroid across the curve,
  column by column, lies from the true curve (:func:`centroid_offsets`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from course import limits
from course._metrics import max_difference, rms_difference
from course._validate import (
    as_choice,
    as_curve,
    as_gray,
    as_image_like,
    as_positive_float,
    as_shape,
)
from course.antialias import RENDER_METHODS, SPLATS
from course.antialias._polyline import flattened
from course.antialias._render import AGG, ARC_LENGTH, one_curve_path, variant_coverage
from course.antialias.near_pixels import first_of_runs, pixels_near
from course.i18n import _
from course.limits import require_bounded_flattening

__all__ = [
    "AGG",
    "ARC_LENGTH",
    "REFERENCE",
    "VARIANTS",
    "CentroidOffsets",
    "centroid_offsets",
    "intensity_along",
    "position_error",
    "quality_table",
    "render_variant",
    "uniformity",
    "variants",
]

#: Every variant of the lesson, by name: the render methods, the splats with the
#: arc-length fix, and matplotlib's Agg.
VARIANTS = (*RENDER_METHODS, *(splat + ARC_LENGTH for splat in SPLATS), AGG)
#: The name :func:`course.antialias.windows.render_window` gives the exact coverage.
REFERENCE = "exact reference"

# How closely the metrics follow the true curve, in pixels.
METRIC_TOLERANCE = 1e-3
# Pixels farther than this from the curve are not counted as part of it.
METRIC_REACH = 3.0
# Longest segment of the polyline the profile and the centroid offsets measure along.
_PROFILE_STEP = 1.0
_OFFSETS_STEP = 0.5
# The knots' spacing of the uniformity a quality table reports.
_PIECE_LENGTH = 8.0


def _curve_positions(image: np.ndarray, control: np.ndarray) -> tuple[np.ndarray, ...]:
    """Arc length of the nearest curve point of every pixel near the curve."""
    line = flattened(control, METRIC_TOLERANCE, _PROFILE_STEP)
    near = pixels_near(line, image.shape, METRIC_REACH)
    first = first_of_runs(near.flat)
    pieces = np.hypot(*np.diff(near.polyline, axis=0).T)
    start = np.concatenate([[0.0], np.cumsum(pieces)])
    segment = near.segment[first]
    position = start[segment] + near.along[first] * pieces[segment]
    return position, image.ravel()[near.flat[first]], start[-1]


def intensity_along(
    image: Any, points: Any, piece_length: float = 8.0
) -> tuple[np.ndarray, np.ndarray]:
    """Intensity per unit length along the curve, sampled every ``piece_length``.

    Every pixel within 3 px of the curve is attached to the arc length s of
    the curve point nearest its centre. Knots are spread evenly along the
    curve, about ``piece_length`` apart; each pixel's intensity is shared
    between the two knots around its s in proportion to closeness (the
    triangle functions of linear interpolation, which add up to 1), and each
    knot's total is divided by the spacing. The two end knots, which hold
    the round caps, are left out.

    Parameters
    ----------
    image : ndarray (H, W)
    points : array_like (N, 2)
        The curve's control points.
    piece_length : float
        Spacing of the knots, in pixels.

    Returns
    -------
    positions : ndarray
        Arc length of each interior knot.
    density : ndarray
        Intensity per unit length there; the stroke's width for an exact
        rendering.

    Examples
    --------
    >>> from course.antialias.coverage import reference
    >>> line = [[2.0, 4.5], [38.0, 4.5]]
    >>> s, density = intensity_along(reference(line, (9, 40)), line, piece_length=6)
    >>> s.round(1).tolist(), density.round(3).tolist()
    ([6.0, 12.0, 18.0, 24.0, 30.0], [1.0, 1.0, 1.0, 1.0, 1.0])
    """
    return _intensity_along(*_checked_profile(image, points, piece_length))


def _checked_profile(image: Any, points: Any, piece_length: Any) -> tuple[np.ndarray, ...]:
    """:func:`intensity_along`'s checks: the image, the curve, the knots' spacing, and then
    what flattening the curve at the metric's tolerance costs."""
    gray = as_gray(image, "image")
    control = as_curve(points)
    piece_length = as_positive_float(piece_length, "piece_length")
    require_bounded_flattening(control, METRIC_TOLERANCE, _PROFILE_STEP)
    return gray, control, piece_length


def _intensity_along(
    gray: np.ndarray, control: np.ndarray, piece_length: float
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`intensity_along` of checked arguments."""
    position, intensity, length = _curve_positions(gray, control)
    if length <= 0:
        raise ValueError(_("points: the curve has no length, so no intensity per unit length"))
    if length / piece_length > limits.MAX_STEP_SAMPLES:
        raise ValueError(
            _(
                "piece_length must leave at most {most} knots along the {length:.4g} px curve; got "
                "{piece_length:g}"
            ).format(most=limits.MAX_STEP_SAMPLES, length=length, piece_length=piece_length)
        )
    count = max(2, round(length / piece_length))
    spacing = length / count
    scaled = np.clip(position / spacing, 0, count)
    knot = np.minimum(np.floor(scaled).astype(np.int64), count - 1)
    share = scaled - knot
    mass = np.bincount(knot, intensity * (1 - share), minlength=count + 1)
    mass += np.bincount(knot + 1, intensity * share, minlength=count + 1)
    return np.arange(1, count) * spacing, mass[1:-1] / spacing


def uniformity(image: Any, points: Any, piece_length: float = 8.0) -> float:
    """Coefficient of variation (std / mean) of :func:`intensity_along`.

    0 means every stretch of the curve is equally bright per unit length;
    0.05 means a typical stretch differs by 5 % from the average. A method
    whose brightness depends on how densely the samples fall (the handouts'
    saturating sum) scores high.

    Examples
    --------
    >>> from course.antialias.coverage import reference
    >>> line = [[2.0, 4.5], [38.0, 4.5]]
    >>> round(uniformity(reference(line, (9, 40)), line, piece_length=6), 6)
    0.0
    """
    return _uniformity(*_checked_profile(image, points, piece_length))


def _uniformity(gray: np.ndarray, control: np.ndarray, piece_length: float) -> float:
    """:func:`uniformity` of checked arguments."""
    _positions, density = _intensity_along(gray, control, piece_length)
    mean = density.mean()
    if mean <= 0:
        raise ValueError(_("image: nothing is drawn along the curve, uniformity is undefined"))
    return float(density.std() / mean)


@dataclass(frozen=True)
class CentroidOffsets:
    """Centroid offsets across the curve, one per column (or row) measured.

    Attributes
    ----------
    where : ndarray
        The x of the column centre (or y of the row centre).
    along_columns : ndarray of bool
        True where a column was measured (the curve is at most 45 degrees
        from horizontal there), False for a row.
    offset : ndarray
        Intensity centroid minus the true curve's coordinate, in pixels:
        y in a column, x in a row.
    """

    where: np.ndarray
    along_columns: np.ndarray
    offset: np.ndarray


def centroid_offsets(image: Any, points: Any, width: float = 1.0) -> CentroidOffsets:
    """Where the drawn curve's centre lies, column by column, against the true curve.

    For each column whose centre line x = c + 0.5 the curve crosses exactly
    once, at a slope of at most 1, the intensity centroid of the column's
    pixels within ``width / 2 + 1.5`` of the crossing, ``sum I (r + 0.5) /
    sum I``, is compared with the crossing's y. Where the curve is steeper
    than 45 degrees rows are measured the same way, with x. Columns with no
    intensity near the crossing (gaps) are skipped.

    Examples
    --------
    >>> image = np.zeros((5, 8))
    >>> image[2, 1:7] = 1.0
    >>> offsets = centroid_offsets(image, [[1.0, 2.25], [7.0, 2.25]])
    >>> offsets.where.tolist(), offsets.offset.tolist()
    ([1.5, 2.5, 3.5, 4.5, 5.5, 6.5], [0.25, 0.25, 0.25, 0.25, 0.25, 0.25])
    """
    return _centroid_offsets(*_checked_offsets(image, points, width))


def _checked_offsets(image: Any, points: Any, width: Any) -> tuple[np.ndarray, np.ndarray, float]:
    """:func:`centroid_offsets`'s checks: the image, the curve, the stroke's width, and then
    what flattening the curve at the metric's tolerance costs."""
    gray = as_gray(image, "image")
    control = as_curve(points)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    require_bounded_flattening(control, METRIC_TOLERANCE, _OFFSETS_STEP)
    return gray, control, width


def _centroid_offsets(gray: np.ndarray, control: np.ndarray, width: float) -> CentroidOffsets:
    """:func:`centroid_offsets` of checked arguments."""
    line = flattened(control, METRIC_TOLERANCE, _OFFSETS_STEP)
    window = 0.5 * width + 1.5
    results = [
        _offsets(gray, line, window, columns=True),
        _offsets(gray.T, line[:, ::-1], window, columns=False),
    ]
    where, along_columns, offset = (np.concatenate(parts) for parts in zip(*results, strict=True))
    return CentroidOffsets(where=where, along_columns=along_columns, offset=offset)


def _offsets(
    gray: np.ndarray, line: np.ndarray, window: float, columns: bool
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Column offsets of ``gray`` (rows of the caller's image when transposed)."""
    height, width = gray.shape
    x0, x1 = line[:-1, 0], line[1:, 0]
    low, high = np.minimum(x0, x1), np.maximum(x0, x1)
    # The centre line a segment crosses (segments are shorter than a pixel).
    column = np.floor(high - 0.5).astype(np.int64)
    crosses = (low < column + 0.5) & (column + 0.5 <= high) & (column >= 0) & (column < width)
    x0, x1, column = x0[crosses], x1[crosses], column[crosses]
    y0, y1 = line[:-1, 1][crosses], line[1:, 1][crosses]
    fraction = (column + 0.5 - x0) / (x1 - x0)
    crossing = y0 + fraction * (y1 - y0)
    # Columns take the curve up to 45 degrees, rows (transposed) what is steeper.
    rise, run = np.abs(y1 - y0), np.abs(x1 - x0)
    flat = rise <= run if columns else rise < run
    once = np.bincount(column, minlength=width)[column] == 1
    keep = once & flat
    column, crossing = column[keep], crossing[keep]
    reach = int(np.ceil(window)) + 1
    rows = np.floor(crossing).astype(np.int64)[:, None] + np.arange(-reach, reach + 1)
    valid = (np.abs(rows + 0.5 - crossing[:, None]) <= window) & (rows >= 0) & (rows < height)
    values = np.where(valid, gray[np.clip(rows, 0, height - 1), column[:, None]], 0.0)
    total = values.sum(axis=1)
    drawn = total > 0
    centroid = (values * (rows + 0.5)).sum(axis=1)[drawn] / total[drawn]
    where = column[drawn] + 0.5
    return where, np.full(len(where), columns), centroid - crossing[drawn]


def position_error(image: Any, points: Any, width: float = 1.0) -> float:
    """Mean absolute :func:`centroid_offsets`, in pixels.

    Examples
    --------
    >>> image = np.zeros((5, 8))
    >>> image[2, 1:7] = 1.0
    >>> position_error(image, [[1.0, 2.25], [7.0, 2.25]])
    0.25
    """
    return _position_error(*_checked_offsets(image, points, width))


def _position_error(gray: np.ndarray, control: np.ndarray, width: float) -> float:
    """:func:`position_error` of checked arguments."""
    offsets = _centroid_offsets(gray, control, width).offset
    if len(offsets) == 0:
        raise ValueError(_("image: no column or row near the curve is drawn"))
    return float(np.mean(np.abs(offsets)))


def render_variant(name: str, points: Any, shape: Any, width: float = 1.0) -> np.ndarray:
    """The variant ``name`` of :data:`VARIANTS` drawn on a canvas of ``shape``, (H, W).

    Examples
    --------
    >>> render_variant(AGG, [[1.0, 2.0], [9.0, 2.0]], (4, 10)).shape
    (4, 10)
    """
    name = as_choice(name, "name", VARIANTS)
    path = one_curve_path(as_curve(points))
    canvas = as_shape(shape)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    return variant_coverage(name, path, canvas, width)


def variants(points: Any, shape: Any, width: float = 1.0) -> dict[str, np.ndarray]:
    """Every way this lesson draws a curve, by name, as (H, W) images: :data:`VARIANTS`.

    Each of :data:`course.antialias.RENDER_METHODS` as the handouts accumulate
    (saturating count, their step), each splat method again with the
    arc-length fix (named ``"<method> + arc length"``), and Agg.

    Examples
    --------
    >>> images = variants([[1.0, 2.0], [9.0, 2.0]], (4, 10))
    >>> len(images), images[AGG].shape
    (17, (4, 10))
    """
    path = one_curve_path(as_curve(points))
    canvas = as_shape(shape)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    # Agg takes degrees 1 to 3 only: drawn first, a curve it refuses costs nothing else.
    drawn = {AGG: variant_coverage(AGG, path, canvas, width)}
    return {
        name: drawn[name] if name in drawn else variant_coverage(name, path, canvas, width)
        for name in VARIANTS
    }


def quality_table(
    images: dict[str, np.ndarray], points: Any, reference: Any, width: float = 1.0
) -> list[dict[str, Any]]:
    """One row per image: RMSE, maximum error, uniformity CV, position error.

    Examples
    --------
    >>> from course.antialias.coverage import reference as exact
    >>> line = [[2.0, 4.5], [30.0, 4.5]]
    >>> row = quality_table({"exact": exact(line, (9, 32))}, line, exact(line, (9, 32)))[0]
    >>> row["name"], row["rmse"], row["position"]
    ('exact', 0.0, 0.0)
    """
    control = as_curve(points)
    truth = as_gray(reference, "reference")
    if not isinstance(images, dict) or not all(isinstance(name, str) for name in images):
        raise TypeError(
            _("images must map variant names to images; got {images_type}").format(
                images_type=type(images).__name__
            )
        )
    rows = []
    for name, image in images.items():
        array = as_image_like(image, truth)  # gray, since the reference is
        gray = array.astype(float)
        first = not rows
        row = {
            "name": name,
            "rmse": rms_difference(array, truth),
            "max": max_difference(array, truth),
        }
        # The curve's flattening and the width, checked at the first image, where the
        # measures of the profile and of the offsets check them.
        if first:
            require_bounded_flattening(control, METRIC_TOLERANCE, _PROFILE_STEP)
        row["cv"] = _uniformity(gray, control, _PIECE_LENGTH)
        if first:
            width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
            require_bounded_flattening(control, METRIC_TOLERANCE, _OFFSETS_STEP)
        row["position"] = _position_error(gray, control, width)
        rows.append(row)
    return rows
