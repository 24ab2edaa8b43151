"""Matplotlib's Agg renderer stroking a curve or a whole path: the production anchor.

Agg [1]_ flattens the path, builds the outline of its stroke (round caps and
joins here) and computes the exact area of that outline inside each pixel,
quantised to 8 bits: the anti-aliasing most Python plots use, and the one
:mod:`course.antialias` is measured against.

References
----------
.. [1] M. Shemanarev, "Anti-Grain Geometry: the scanline rasterizer", 2006,
   https://agg.sourceforge.net/antigrain.com/doc/introduction/introduction.agdoc.html
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import RendererAgg
from matplotlib.path import Path

from course import limits
from course._validate import as_curve, as_points, as_positive_float, as_shape, describe
from course.antialias._render import agg_coverage, agg_stroke
from course.curves.paths import as_path
from course.i18n import _

__all__ = ["agg_draw", "agg_path", "agg_render"]


def agg_render(points: Any, shape: Any, width: float = 1.0) -> np.ndarray:
    """The curve or path stroked by matplotlib's Agg renderer, as coverage in [0, 1].

    ``points`` is one curve's control points, a list of curves or a
    ``matplotlib.path.Path`` (see :func:`course.curves.paths.as_path`). Each curve
    becomes ``CURVE4`` codes (``CURVE3`` for a quadratic, ``LINETO`` for a
    line) of one ``matplotlib.path.Path``, joined curves in one subpath, drawn by
    ``RendererAgg.draw_path`` with round caps and joins (the stroke is the
    set of points within width / 2 of the curve, like
    :func:`course.antialias.coverage.reference`),
    in white on a transparent canvas; the alpha channel, divided by 255, is
    the coverage. Agg computes the exact area of its own flattened outline,
    quantised to 8 bits.

    Conventions, checked by the tests against :func:`course.antialias.coverage.reference`: at 72 dpi
    one point of line width is one pixel; Agg's y axis points up, so image
    coordinates are mapped by y -> H - y; Agg's pixel (c, r) is the square
    ``[c, c+1) x [r, r+1)`` like this package's, so no half-pixel shift.
    Snapping is turned off (matplotlib snaps straight horizontal and vertical
    paths to pixel centres otherwise).

    Examples
    --------
    >>> agg_render([[0.0, 1.75], [4.0, 1.75]], (4, 4))[:, 1:3].round(3)
    array([[0.   , 0.   ],
           [0.753, 0.753],
           [0.251, 0.251],
           [0.   , 0.   ]])
    """
    path = as_path(points)
    height, canvas_width = as_shape(shape)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    return agg_coverage(path, (height, canvas_width), width)


def agg_path(control: np.ndarray) -> Path:
    """A matplotlib Path for a Bézier curve of degree 1, 2 or 3.

    Examples
    --------
    >>> agg_path(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 2.0], [3.0, 0.0]])).codes
    array([1, 4, 4, 4], dtype=uint8)
    """
    control = as_curve(control, "control")
    codes = {2: Path.LINETO, 3: Path.CURVE3, 4: Path.CURVE4}
    if len(control) not in codes:
        raise ValueError(
            _(
                "points: Agg draws Bézier curves of degree 1 to 3 (2 to 4 control points); got "
                "{control_count} points"
            ).format(control_count=len(control))
        )
    return Path(control, [Path.MOVETO] + [codes[len(control)]] * (len(control) - 1))


def agg_draw(path: Path, shape: tuple[int, int], width: float) -> RendererAgg:
    """Stroke a Path given in image coordinates with ``RendererAgg.draw_path``.

    A new 72 dpi renderer of the canvas's size, white round-capped strokes
    of ``width`` pixels, no snapping, y flipped to Agg's upward axis. The
    caller reads ``renderer.buffer_rgba()``; its alpha channel is coverage.
    """
    if not isinstance(path, Path):
        raise TypeError(
            _("path must be a matplotlib.path.Path; got {path}").format(path=describe(path))
        )
    vertices = as_points(path.vertices, "path.vertices", bound=limits.MAX_COORDINATE)
    if vertices.shape[1] != 2:
        raise ValueError(
            _("path.vertices must have shape (N, 2); got {vertices_shape}").format(
                vertices_shape=vertices.shape
            )
        )
    height, canvas_width = as_shape(shape)
    width = as_positive_float(width, "width", largest=limits.MAX_STROKE_WIDTH)
    return agg_stroke(path, height, canvas_width, width)
