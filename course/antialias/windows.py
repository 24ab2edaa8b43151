"""A zoom window of a variant or of the exact reference, drawn at the window's cost alone.

Lesson 05's zoom app redraws a small window of every variant (and the
exact reference) as a control point is dragged: :func:`render_window` moves
the curve by the window's corner and draws it on a canvas of the window's
size, with the values of a crop of the whole drawing
(:func:`course.antialias.curve_quality.render_variant`), to rounding.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course._validate import as_choice, as_curve, as_int, as_positive_float, describe
from course.antialias._reference import reference_coverage
from course.antialias._render import one_curve_path, variant_coverage
from course.antialias.curve_quality import REFERENCE, VARIANTS
from course.curves.paths import Curves
from course.i18n import _
from course.raster.canvas import crop_extent

__all__ = ["render_window", "render_windows"]


def render_window(
    name: str, points: Any, shape: Any, centre: Any, size: int, width: float = 1.0, k: int = 64
) -> tuple[np.ndarray, tuple[int, int, int, int]]:
    """A variant, or :data:`REFERENCE`, drawn only in the window
    :func:`~course.raster.canvas.crop` takes.

    The values of ``crop(render_variant(name, points, shape), centre, size)``
    (and of the reference at ``k`` x ``k`` samples per pixel), to rounding,
    at the cost of the window alone: the curve is moved by the window's
    corner, a whole number of pixels, and drawn on a canvas of the window's
    size. For apps that redraw as a control point is dragged. Returns the
    window and its extent ``(left, right, bottom, top)``.

    Examples
    --------
    >>> from course.antialias.curve_quality import render_variant
    >>> from course.raster.canvas import crop
    >>> curve = [[10.0, 10.0], [690.0, 10.0], [10.0, 690.0], [690.0, 690.0]]
    >>> window, extent = render_window("bilinear_centres", curve, (700, 700), (100, 40), 8)
    >>> full = render_variant("bilinear_centres", curve, (700, 700))
    >>> extent, bool(np.allclose(window, crop(full, (100, 40), 8)[0], atol=1e-12))
    ((96, 104, 44, 36), True)
    """
    control = as_curve(points)
    (window,), extent = _windows((_drawn(name, "name"),), control, shape, centre, size, width, k)
    return window, extent


def render_windows(
    names: Any, points: Any, shape: Any, centre: Any, size: int, width: float = 1.0, k: int = 64
) -> tuple[list[np.ndarray], tuple[int, int, int, int]]:
    """:func:`render_window` of each of ``names`` (a list of them), in the same window.

    The splats that sample the curve at the same steps share its samples,
    and the arguments are checked once: an app that shows several variants
    side by side redraws them all at a drag's step.

    Examples
    --------
    >>> curve = [[10.0, 10.0], [690.0, 10.0], [10.0, 690.0], [690.0, 690.0]]
    >>> names = ["bilinear_corners", "bilinear_centres", REFERENCE]
    >>> windows, extent = render_windows(names, curve, (700, 700), (100, 40), 8, k=4)
    >>> alone = [render_window(name, curve, (700, 700), (100, 40), 8, k=4)[0] for name in names]
    >>> extent, all(np.array_equal(a, b) for a, b in zip(windows, alone, strict=True))
    ((96, 104, 44, 36), True)
    """
    if not isinstance(names, (list, tuple)) or not names:
        raise TypeError(
            _("names must be a non-empty list of variant names; got {names}").format(
                names=describe(names)
            )
        )
    names = tuple(_drawn(name, "names") for name in names)
    return _windows(names, as_curve(points), shape, centre, size, width, k)


def _drawn(name: Any, parameter: str) -> str:
    """``name`` checked as one of :data:`VARIANTS` or :data:`REFERENCE`."""
    if isinstance(name, str) and name == REFERENCE:
        return name
    return as_choice(name, parameter, VARIANTS)


def _windows(
    names: tuple[str, ...],
    control: np.ndarray,
    shape: Any,
    centre: Any,
    size: int,
    width: float,
    k: int,
) -> tuple[list[np.ndarray], tuple[int, int, int, int]]:
    """The windows of checked ``names`` and ``control``; the rest checked here, once."""
    left, right, bottom, top = crop_extent(shape, centre, size)
    path = _moved_path(control - (left, top))
    window_shape = (bottom - top, right - left)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    if REFERENCE in names:
        k = as_int(k, "k", minimum=1, maximum=limits.MAX_RATE)
    evaluated: dict = {}  # the splats' samples, shared
    windows = [
        reference_coverage(path, window_shape, width, k)
        if name == REFERENCE
        else variant_coverage(name, path, window_shape, width, evaluated)
        for name in names
    ]
    return windows, (left, right, bottom, top)


def _moved_path(moved: np.ndarray) -> Curves:
    """A checked curve moved by a window's corner, as one curve of a path: its points can
    have left the coordinates' bound, refused then as the curve itself would be."""
    if np.abs(moved).max() > limits.MAX_COORDINATE:
        as_curve(moved)  # refused, as before
    return one_curve_path(moved)
