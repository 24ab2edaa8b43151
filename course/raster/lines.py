"""Rasterization: from geometry to pixel coordinates.

Lines (Bresenham, the report's 4-connected pitfall, Wu's anti-aliased line)
live here; filled triangles live in :mod:`course.raster.triangles` and are
re-exported. Rasterizers return pixels, they do not draw: an int array ``(K, 2)`` of
(x, y), optionally clipped to a canvas with ``shape=(H, W)``.
:func:`course.raster.canvas.paint` writes them. Pixel (row r, column c) is the unit
square ``[c, c+1) x [r, r+1)``, with its centre at ``(c + 0.5, r + 0.5)``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course._validate import as_choice, as_point, as_points, as_shape
from course.i18n import _
from course.raster._lines import bresenham_closed_form, pixels_of, require_image_space
from course.raster._paint import on_canvas
from course.raster.triangles import hit_counts, triangle, triangle_coverage

__all__ = [
    "LINE_METHODS",
    "ROUNDING",
    "distance_from_line",
    "hit_counts",
    "line",
    "line_4connected",
    "nearest_pixels",
    "triangle",
    "triangle_coverage",
    "wu_line",
]

ROUNDING = ("floor", "round", "trunc")


def nearest_pixels(points: Any, rounding: str = "floor", shape: Any = None) -> np.ndarray:
    """The pixel of each point: one (x, y) per sample, in order, repeats kept.

    Parameters
    ----------
    points : array_like, shape (K, 2)
        Continuous image-space points (x right, y down).
    rounding : {"floor", "round", "trunc"}
        ``"floor"``: the pixel whose square contains the point (this package's
        convention). ``"round"``: the nearest integer, as OpenCV's
        ``cv::Point(Point2f)`` does (seed 000's ``window.at<cv::Vec3b>(point)``),
        which is off by half a pixel when pixel centres are at +0.5.
        ``"trunc"``: toward zero, as C++'s float-to-int conversion in
        ``window.at<cv::Vec3b>(point.y, point.x)`` (seeds 002-004); it equals
        floor on the canvas but folds x in (-1, 0) onto column 0.
    shape : (H, W), optional
        Drop pixels off a canvas of this shape.

    Examples
    --------
    >>> nearest_pixels([[0.4, 0.6], [1.5, 2.5], [-0.5, 1.0]])
    array([[ 0,  0],
           [ 1,  2],
           [-1,  1]])
    >>> nearest_pixels([[0.4, 0.6], [1.5, 2.5], [-0.5, 1.0]], rounding="trunc")
    array([[0, 0],
           [1, 2],
           [0, 1]])
    >>> nearest_pixels([[0.4, 0.6], [1.5, 2.5], [-0.5, 1.0]], shape=(2, 2))
    array([[0, 0]])
    """
    samples = as_points(points, bound=limits.MAX_COORDINATE)
    require_image_space(samples)
    rounding = as_choice(rounding, "rounding", ROUNDING)
    pixels = pixels_of(samples, rounding)
    if shape is not None:
        pixels = pixels[on_canvas(pixels, as_shape(shape))]
    return pixels


# --- lines -------------------------------------------------------------------

LINE_METHODS = ("closed_form", "loop")

# Within this, 2 * n * |minor delta| in the closed form cannot overflow int64.
_MAX_PIXEL_COORDINATE = int(limits.MAX_COORDINATE)


def _as_pixel(point: Any, name: str) -> tuple[int, int]:
    """An integer pixel (x, y) as two Python ints: float values must be whole."""
    if type(point) in (tuple, list) and len(point) == 2 and type(point[0]) is type(point[1]) is int:
        x, y = point  # the common case, checked without numpy (lines are short)
    else:
        array = as_point(point, name, dim=2)
        if not np.all(array == np.round(array)):
            raise ValueError(
                _(
                    "{name} must be an integer pixel (x, y); got {array} (choose the pixel of a "
                    "float point with course.raster.nearest_pixels)"
                ).format(name=name, array=array.tolist())
            )
        x, y = (int(v) for v in array)
    if max(abs(x), abs(y)) > _MAX_PIXEL_COORDINATE:
        raise ValueError(
            _("{name} coordinates must lie within +-{bound}; got ({x}, {y})").format(
                name=name, bound=_MAX_PIXEL_COORDINATE, x=x, y=y
            )
        )
    return x, y


def line(p0: Any, p1: Any, shape: Any = None, method: str = "closed_form") -> np.ndarray:
    """Bresenham's line: the pixels from pixel ``p0`` to pixel ``p1``.

    One pixel per step along the major axis (the axis with the larger
    difference), so a line has ``max(|dx|, |dy|) + 1`` pixels, is
    8-connected (neighbours may touch at a corner), includes both endpoints,
    and runs from ``p0`` to ``p1``. Along the minor axis each pixel is the
    nearest to the ideal line through the two pixel centres; when two are
    equally near, the one toward ``p0`` is chosen, as the handout's loop does.
    So ``line(p1, p0)`` can differ from ``line(p0, p1)[::-1]`` at such ties.

    Parameters
    ----------
    p0, p1 : (x, y) integer pixels
        Float values must be whole numbers.
    shape : (H, W), optional
        Drop pixels off a canvas of this shape (the line itself is unchanged).
    method : {"closed_form", "loop"}
        ``"loop"`` is the handout's integer-only loop (Task 4), with its bug
        fixed; ``"closed_form"`` computes the same pixels at once, each row's
        minor coordinate by one floor division.

    Returns
    -------
    ndarray of int, shape (K, 2)
        (x, y) per row, ordered from ``p0`` to ``p1``.

    See Also
    --------
    line_4connected : the report's version, which never steps diagonally.
    wu_line : the anti-aliased line.

    References
    ----------
    .. [1] J. E. Bresenham, "Algorithm for computer control of a digital
       plotter", IBM Systems Journal 4(1), 1965.

    Examples
    --------
    >>> from course.raster.canvas import blank, paint
    >>> line((0, 0), (5, 2))
    array([[0, 0],
           [1, 0],
           [2, 1],
           [3, 1],
           [4, 2],
           [5, 2]])
    >>> print(paint(blank((4, 6)), line((5, 0), (1, 3)), 1.0).astype(int))
    [[0 0 0 0 0 1]
     [0 0 0 1 1 0]
     [0 0 1 0 0 0]
     [0 1 0 0 0 0]]
    """
    x0, y0 = _as_pixel(p0, "p0")
    x1, y1 = _as_pixel(p1, "p1")
    if method != "closed_form":  # the default skips the check: meshes draw lines by the thousand
        method = as_choice(method, "method", LINE_METHODS)
    if method == "loop":
        pixels = np.array(_line_loop(x0, y0, x1, y1), dtype=np.int64)
    else:
        pixels = _line_closed_form(x0, y0, x1, y1)
    if shape is not None:
        pixels = pixels[on_canvas(pixels, as_shape(shape))]
    return pixels


def _line_loop(
    x0: int, y0: int, x1: int, y1: int, diagonal_steps: bool = True
) -> list[tuple[int, int]]:
    """The handout's all-octant Bresenham loop, integers only.

    ``diagonal_steps=False`` is the report's bug: ``else`` between the two
    tests, so a step moves x or y but never both.
    """
    dx, dy = abs(x1 - x0), abs(y1 - y0)
    sx = 1 if x0 < x1 else -1
    sy = 1 if y0 < y1 else -1
    # err is dx * dy times the signed distance of the next corner from the line.
    err = dx - dy
    x, y = x0, y0
    pixels = []
    while True:
        pixels.append((x, y))
        if x == x1 and y == y1:
            break
        err2 = 2 * err
        step_x = err2 > -dy
        step_y = err2 < dx if diagonal_steps else not step_x
        if step_x:
            err -= dy
            x += sx
        if step_y:
            err += dx
            y += sy
    return pixels


def _line_closed_form(x0: int, y0: int, x1: int, y1: int) -> np.ndarray:
    """Bresenham in closed form: step i moves the minor axis by round(i * a / n)."""
    return bresenham_closed_form(x0, y0, x1, y1)


def line_4connected(p0: Any, p1: Any, shape: Any = None) -> np.ndarray:
    """The report's line (seed 001, Task 4): a pitfall, kept to be measured.

    Its loop is Bresenham's with ``else`` where two independent tests belong,
    so each step moves in x or in y, never both. The line is a 4-connected
    staircase of ``|dx| + |dy| + 1`` pixels instead of ``max(|dx|, |dy|) + 1``:
    a 45-degree line gets twice the pixels and looks thicker and jagged.

    Examples
    --------
    >>> from course.raster.canvas import blank, paint
    >>> print(paint(blank((4, 4)), line_4connected((0, 0), (3, 3)), 1.0).astype(int))
    [[1 1 0 0]
     [0 1 1 0]
     [0 0 1 1]
     [0 0 0 1]]
    >>> len(line_4connected((0, 0), (3, 3))), len(line((0, 0), (3, 3)))
    (7, 4)
    """
    x0, y0 = _as_pixel(p0, "p0")
    x1, y1 = _as_pixel(p1, "p1")
    pixels = np.array(_line_loop(x0, y0, x1, y1, diagonal_steps=False), dtype=np.int64)
    if shape is not None:
        pixels = pixels[on_canvas(pixels, as_shape(shape))]
    return pixels


def distance_from_line(pixels: Any, p0: Any, p1: Any) -> np.ndarray:
    """How far each pixel's centre lies from the ideal line between the centres of p0 and p1.

    The measure of a rasterised line: Bresenham's pixels stay within half a
    pixel of it; the report's 4-connected loop (:func:`line_4connected`) strays
    further, since it takes its y steps late.

    Parameters
    ----------
    pixels : array_like, shape (K, 2)
        Pixels (x, y), such as :func:`line` returns.
    p0, p1 : (x, y) ints
        The line's end pixels; when they are one pixel, the distance is to its centre.

    Returns
    -------
    ndarray, shape (K,)
        Distances in pixels, perpendicular to the (infinite) line.

    Examples
    --------
    >>> distance_from_line(line_4connected((0, 0), (2, 2)), (0, 0), (2, 2)).round(3)
    array([0.   , 0.707, 0.   , 0.707, 0.   ])
    """
    x0, y0 = _as_pixel(p0, "p0")
    x1, y1 = _as_pixel(p1, "p1")
    centres = as_points(pixels, "pixels", bound=limits.MAX_COORDINATE)
    if centres.shape[1] != 2:
        raise ValueError(
            _("pixels must have shape (K, 2), one (x, y) per pixel; got {shape}").format(
                shape=centres.shape
            )
        )
    offsets = centres - (x0, y0)  # centre to centre: the half pixels cancel
    dx, dy = x1 - x0, y1 - y0
    if dx == dy == 0:
        return np.hypot(offsets[:, 0], offsets[:, 1])
    return np.abs(dx * offsets[:, 1] - dy * offsets[:, 0]) / np.hypot(dx, dy)


def wu_line(p0: Any, p1: Any, shape: Any = None) -> tuple[np.ndarray, np.ndarray]:
    """Xiaolin Wu's anti-aliased line between two continuous points.

    Along the major axis, at each pixel centre, the ideal line passes between
    two pixel centres of the minor axis; Wu splits one unit of ink between
    those two pixels in proportion to nearness. At the two ends the ink is
    scaled by how much of the end pixel the segment spans along the major
    axis, so the ends fade instead of stopping abruptly.

    Parameters
    ----------
    p0, p1 : (x, y) floats
        Continuous image-space points (pixel (r, c) is ``[c, c+1) x [r, r+1)``).
        To draw the line that ``line(q0, q1)`` draws, pass the pixel centres
        ``q0 + 0.5`` and ``q1 + 0.5``.
    shape : (H, W), optional
        Drop pixels off a canvas of this shape.

    Returns
    -------
    pixels : ndarray of int, shape (K, 2)
        (x, y), from ``p0`` to ``p1``, two per major-axis step (one where the
        line passes exactly through a pixel centre).
    weights : ndarray of float, shape (K,)
        Ink in (0, 1] for :func:`course.raster.canvas.paint`.

    References
    ----------
    .. [1] X. Wu, "An efficient antialiasing technique", SIGGRAPH 1991,
       Computer Graphics 25(4), 143-152.

    Examples
    --------
    >>> pixels, weights = wu_line((0.5, 0.5), (4.5, 1.5))
    >>> for (x, y), w in zip(pixels, weights):
    ...     print(x, y, w)
    0 0 0.5
    1 0 0.75
    1 1 0.25
    2 0 0.5
    2 1 0.5
    3 0 0.25
    3 1 0.75
    4 1 0.5
    """
    start = as_point(p0, "p0", dim=2, bound=limits.MAX_COORDINATE)
    end = as_point(p1, "p1", dim=2, bound=limits.MAX_COORDINATE)
    steep = abs(end[1] - start[1]) > abs(end[0] - start[0])
    if steep:  # work with x as the major axis, swap back at the end
        start, end = start[::-1], end[::-1]
    length = abs(end[0] - start[0])
    if length == 0:
        return np.empty((0, 2), dtype=np.int64), np.empty(0)
    low, high = min(start[0], end[0]), max(start[0], end[0])
    columns = np.arange(np.floor(low), np.ceil(high), dtype=np.int64)
    if end[0] < start[0]:
        columns = columns[::-1]
    gradient = (end[1] - start[1]) / (end[0] - start[0])
    centre_y = start[1] + gradient * (columns + 0.5 - start[0])
    # The line passes between the centres of rows `row` and `row + 1`; the
    # nearer centre gets the larger share (all of it when the line hits it).
    row = np.floor(centre_y - 0.5).astype(np.int64)
    far_share = centre_y - 0.5 - row
    span = np.minimum(columns + 1, high) - np.maximum(columns, low)
    major = np.repeat(columns, 2)
    minor = np.stack((row, row + 1), axis=1).ravel()
    weights = (np.stack((1 - far_share, far_share), axis=1) * span[:, None]).ravel()
    pixels = np.stack((minor, major) if steep else (major, minor), axis=1)
    keep = weights > 0
    if shape is not None:
        keep &= on_canvas(pixels, as_shape(shape))
    return pixels[keep], weights[keep]
