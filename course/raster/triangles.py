"""Filled triangles: the pixels whose centres lie inside, painted exactly once.

A pixel belongs to a triangle when its centre ``(c + 0.5, r + 0.5)`` lies
inside. A centre exactly on an edge needs a rule, or two triangles sharing
that edge would both paint it (or both skip it). The top-left rule, used by
Direct3D and by OpenGL implementations on GPUs, keeps a centre on an edge
only if the edge is a *left* edge (the interior is to its right) or a *top*
edge (horizontal, interior below). Every edge shared by two triangles is left
or top for exactly one of them, so a triangulated region paints each pixel
centre inside it exactly once: it is watertight.

Equivalently: a centre p is inside when ``p + delta * (1, epsilon)`` is
strictly inside for infinitesimal ``0 < epsilon << delta``. That view also
settles the centres that sit exactly on a vertex shared by a fan of
triangles: exactly one triangle of the fan contains the direction (1, epsilon).

Vertices are snapped to 1/256 of a pixel, as GPUs snap to their sub-pixel
grid (8 bits in Direct3D 11), so every edge test is exact integer arithmetic:
no rounding can open a crack or double a pixel, whatever the floats.

References
----------
.. [1] J. Pineda, "A parallel algorithm for polygon rasterization",
   SIGGRAPH 1988, Computer Graphics 22(4), 17-20 (edge functions).
.. [2] Microsoft, "Rasterization rules (Direct3D 11)", the top-left rule.
.. [3] F. Giesen, "The barycentric conspiracy" and "Optimizing the basic
   rasterizer", The ryg blog, 2013.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import numpy as np

from course import limits
from course._validate import (
    as_choice,
    as_int,
    as_pixels,
    as_point,
    as_points,
    as_shape,
    describe,
    require_finite,
)
from course.i18n import _
from course.raster._paint import on_canvas

__all__ = [
    "EDGE_RULES",
    "SUBPIXEL",
    "TRIANGLE_METHODS",
    "barycentric",
    "hit_counts",
    "interpolate",
    "triangle",
    "triangle_coverage",
]

SUBPIXEL = 256
TRIANGLE_METHODS = ("edge_functions", "loop")
EDGE_RULES = ("top-left", "closed", "open")

_HALF = SUBPIXEL // 2
# Snapped coordinates stay below 2**29, so edge functions stay below 2**61.
_MAX_VERTEX_COORDINATE = int(limits.MAX_COORDINATE)
# Pixel centres tested at once by the edge-function form (bounds its memory).
_BLOCK = 1 << 18
# A caller's own choice of the edge functions, which it does not ask to be checked.
_EDGE_FUNCTIONS = object()


def triangle(
    p0: Any,
    p1: Any,
    p2: Any,
    shape: Any = None,
    rule: str = "top-left",
    method: str = "edge_functions",
) -> np.ndarray:
    """The pixels whose centres lie inside the triangle ``p0 p1 p2``.

    Parameters
    ----------
    p0, p1, p2 : (x, y) floats
        Vertices in continuous image space, in either winding order. They are
        snapped to the nearest 1/256 of a pixel.
    shape : (H, W), optional
        Only pixels on a canvas of this shape (and only those are visited).
    rule : {"top-left", "closed", "open"}
        Which centres exactly on an edge count. ``"top-left"``: those on left
        and top edges, so shared edges are painted once. ``"closed"``: all of
        them, so a shared edge is painted twice. ``"open"``: none, so a shared
        edge through pixel centres leaves a crack.
    method : {"edge_functions", "loop"}
        ``"loop"`` is the handout's Task 5, a scanline fill: sort the vertices
        by y, fill the upper and lower halves row by row between the left
        and right edges. ``"edge_functions"`` (the default) tests every centre
        of the bounding box against the three edge functions at once. Both
        return the same array.

    Returns
    -------
    ndarray of int, shape (K, 2)
        (x, y) per row, row by row from the top, left to right in each row.
        A triangle of zero area has no pixels.

    Examples
    --------
    >>> from course.raster.canvas import blank, paint
    >>> print(paint(blank((4, 6)), triangle((0, 0), (6, 0), (0, 4)), 1.0).astype(int))
    [[1 1 1 1 1 0]
     [1 1 1 1 0 0]
     [1 1 0 0 0 0]
     [1 0 0 0 0 0]]

    The diagonal of a square passes through four pixel centres; the top-left
    rule gives them to exactly one of the two halves:

    >>> upper = triangle((0, 0), (4, 0), (4, 4))
    >>> lower = triangle((0, 0), (4, 4), (0, 4))
    >>> len(upper), len(lower), int(hit_counts([upper, lower], (4, 4)).max())
    (10, 6, 1)
    >>> len(triangle((0, 0), (4, 4), (0, 4), rule="closed"))
    10
    """
    _points, vertices, canvas, rule, method = _checked_triangle(p0, p1, p2, shape, rule, method)
    if method == "loop":
        pixels = np.array(_triangle_loop(vertices, canvas, rule), dtype=np.int64)
        return pixels.reshape(-1, 2)
    return _triangle_edge_functions(vertices, canvas, rule)


def _checked_triangle(
    p0: Any, p1: Any, p2: Any, shape: Any, rule: str, method: Any = _EDGE_FUNCTIONS
) -> tuple[list[np.ndarray], list[tuple[int, int]], tuple[int, int] | None, str, str]:
    """:func:`triangle`'s checks, in its order: the vertices as given and snapped, the canvas,
    the rule and the method (by default the edge functions, which need no check)."""
    points, vertices = [], []
    for name, point in (("p0", p0), ("p1", p1), ("p2", p2)):
        points.append(as_point(point, name, dim=2))
        vertices.append(_snapped(points[-1], name))
    rule = as_choice(rule, "rule", EDGE_RULES)
    if method is _EDGE_FUNCTIONS:
        method = "edge_functions"
    else:
        method = as_choice(method, "method", TRIANGLE_METHODS)
    canvas = None if shape is None else as_shape(shape)
    if canvas is None:
        _require_bounded_box(vertices)
    return points, vertices, canvas, rule, method


def _require_bounded_box(vertices: list[tuple[int, int]]) -> None:
    """Without a canvas to clip to, the triangle's bounding box must be a bounded picture."""
    xs, ys = zip(*vertices, strict=True)
    columns = (max(xs) - min(xs)) // SUBPIXEL + 2
    rows = (max(ys) - min(ys)) // SUBPIXEL + 2
    if rows * columns > limits.MAX_PIXELS:
        raise ValueError(
            _(
                "p0, p1, p2 span about {rows} x {columns} pixels; without shape at most "
                "{most}: pass shape=(H, W) to clip the triangle to a canvas"
            ).format(rows=rows, columns=columns, most=limits.MAX_PIXELS)
        )


def _snapped(array: np.ndarray, name: str) -> tuple[int, int]:
    """A checked vertex in integers of 1/SUBPIXEL units, within the coordinates they allow."""
    if np.abs(array).max() > _MAX_VERTEX_COORDINATE:
        raise ValueError(
            _("{name} coordinates must lie within +-{most}; got {array}").format(
                name=name, most=_MAX_VERTEX_COORDINATE, array=array.tolist()
            )
        )
    x, y = (int(v) for v in np.rint(array * SUBPIXEL))
    return x, y


def _floor_div(a: int, b: int) -> int:
    return a // b


def _ceil_div(a: int, b: int) -> int:
    return -(-a // b)


def _centre_range(low: int, high: int, low_in: bool, high_in: bool) -> tuple[int, int]:
    """First and last index i whose centre SUBPIXEL * i + HALF lies between low and high.

    ``low_in`` / ``high_in``: whether a centre exactly at the bound counts.
    """
    first = _ceil_div(low - _HALF, SUBPIXEL) if low_in else _floor_div(low - _HALF, SUBPIXEL) + 1
    last = _floor_div(high - _HALF, SUBPIXEL) if high_in else _ceil_div(high - _HALF, SUBPIXEL) - 1
    return first, last


def _triangle_loop(
    vertices: list[tuple[int, int]], canvas: tuple[int, int] | None, rule: str
) -> list[tuple[int, int]]:
    """The handout's scanline fill, in exact integer arithmetic (1/SUBPIXEL units)."""
    top, middle, bottom = sorted(vertices, key=lambda vertex: vertex[1])
    # Where does the middle vertex lie relative to the long edge top-bottom?
    side = (middle[0] - top[0]) * (bottom[1] - top[1]) - (middle[1] - top[1]) * (bottom[0] - top[0])
    if side == 0:
        return []  # zero area: no interior (and no division by zero below)
    middle_on_left = side < 0
    # Rows with centres at the top are in (top-left, closed) and at the bottom
    # only when closed; columns likewise at the left and right edges.
    left_in = rule in ("top-left", "closed")
    right_in = rule == "closed"
    first_row, last_row = _centre_range(top[1], bottom[1], left_in, right_in)
    if canvas is not None:
        first_row, last_row = max(first_row, 0), min(last_row, canvas[0] - 1)
    pixels = []
    for row in range(first_row, last_row + 1):
        y = SUBPIXEL * row + _HALF
        # The upper half (top to middle) serves rows above the middle vertex;
        # it is used only when it has height, so no edge below has dy == 0.
        # A row exactly at the middle vertex belongs to the lower half, which
        # is what a point nudged down by epsilon sees.
        upper = y < middle[1] or (y == middle[1] and middle[1] == bottom[1])
        short_edge = (top, middle) if upper else (middle, bottom)
        long_edge = (top, bottom)
        left, right = (short_edge, long_edge) if middle_on_left else (long_edge, short_edge)
        first_column, last_column = _row_span(left, right, y, left_in, right_in)
        if canvas is not None:
            first_column, last_column = max(first_column, 0), min(last_column, canvas[1] - 1)
        for column in range(first_column, last_column + 1):
            pixels.append((column, row))
    return pixels


def _row_span(left, right, y: int, left_in: bool, right_in: bool) -> tuple[int, int]:
    """The columns whose centres lie between the two edges at height y."""
    # x on edge (a, b) at y is num / den with den = b.y - a.y > 0; compare
    # centre * den with num instead of dividing, so the test stays exact.
    bounds = []
    for (ax, ay), (bx, by) in (left, right):
        den = by - ay
        num = ax * den + (y - ay) * (bx - ax)
        bounds.append((num - _HALF * den, SUBPIXEL * den))
    (left_num, left_den), (right_num, right_den) = bounds
    first = _ceil_div(left_num, left_den) if left_in else _floor_div(left_num, left_den) + 1
    last = _floor_div(right_num, right_den) if right_in else _ceil_div(right_num, right_den) - 1
    return first, last


def _edge_functions(
    vertices: list[tuple[int, int]], rule: str
) -> list[tuple[int, int, int, int, int]]:
    """Each edge as (ax, ay, dx, dy, bias), wound so the interior is positive.

    The edge function of a -> b at p is ``dx * (p.y - a.y) - dy * (p.x - a.x)``.
    A centre passes an edge when its value plus the bias is > 0: bias 1 keeps
    centres exactly on the edge, bias 0 drops them.
    """
    (x0, y0), (x1, y1), (x2, y2) = vertices
    if (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0) < 0:
        vertices = [vertices[0], vertices[2], vertices[1]]
    edges = []
    for k in range(3):
        (ax, ay), (bx, by) = vertices[k], vertices[(k + 1) % 3]
        dx, dy = bx - ax, by - ay
        if rule == "closed":
            bias = 1
        elif rule == "open":
            bias = 0
        else:
            # y points down: the interior lies to the right of a -> b when
            # walking it, so an edge going up (dy < 0) is a left edge, and a
            # horizontal edge going right is a top edge.
            bias = int(dy < 0 or (dy == 0 and dx > 0))
        edges.append((ax, ay, dx, dy, bias))
    return edges


def _triangle_edge_functions(
    vertices: list[tuple[int, int]], canvas: tuple[int, int] | None, rule: str
) -> np.ndarray:
    """Test every pixel centre of the bounding box against the three edge functions."""
    (x0, y0), (x1, y1), (x2, y2) = vertices
    empty = np.empty((0, 2), dtype=np.int64)
    if (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0) == 0:
        return empty
    first_row, last_row = _centre_range(min(y0, y1, y2), max(y0, y1, y2), True, True)
    first_column, last_column = _centre_range(min(x0, x1, x2), max(x0, x1, x2), True, True)
    if canvas is not None:
        first_row, last_row = max(first_row, 0), min(last_row, canvas[0] - 1)
        first_column, last_column = max(first_column, 0), min(last_column, canvas[1] - 1)
    if first_row > last_row or first_column > last_column:
        return empty
    edges = _edge_functions(vertices, rule)
    columns = np.arange(first_column, last_column + 1, dtype=np.int64)
    centre_x = SUBPIXEL * columns + _HALF
    # Each edge function is linear: a row term plus a column term.
    column_terms = [-dy * (centre_x - ax) for ax, _, _, dy, _ in edges]
    row_terms = [(ay, dx, bias) for _, ay, dx, _, bias in edges]
    rows_per_block = max(1, _BLOCK // len(columns))
    found = []
    for block_start in range(first_row, last_row + 1, rows_per_block):
        rows = np.arange(block_start, min(block_start + rows_per_block, last_row + 1))
        centre_y = SUBPIXEL * rows + _HALF
        passed = None
        for (ay, dx, bias), column_term in zip(row_terms, column_terms, strict=True):
            value = (dx * (centre_y - ay) + bias)[:, None] + column_term[None, :]
            passed = value > 0 if passed is None else passed & (value > 0)
        block_rows, block_columns = np.nonzero(passed)
        found.append(np.stack((columns[block_columns], rows[block_rows]), axis=1))
    return np.concatenate(found) if len(found) > 1 else found[0]


def triangle_coverage(
    p0: Any, p1: Any, p2: Any, shape: Any, rate: int, rule: str = "top-left"
) -> tuple[np.ndarray, np.ndarray]:
    """Supersampled (SSAA) coverage: the share of rate x rate samples inside.

    Each pixel (r, c) is sampled at the centres of a rate x rate grid of
    sub-pixels, ``(c + (i + 0.5) / rate, r + (j + 0.5) / rate)``, with the same
    inside test (and rule) as :func:`triangle`. That is the triangle scaled by
    ``rate`` and filled on a canvas ``rate`` times finer, each fine pixel then
    counted into its coarse pixel. Coverage converges to the area of the
    pixel inside the triangle as the rate grows; rate 1 is :func:`triangle`.

    Returns
    -------
    pixels : ndarray of int, shape (K, 2)
        The (x, y) pixels with any coverage, row by row.
    weights : ndarray of float, shape (K,)
        Coverage in (0, 1], a multiple of 1 / rate**2.

    Examples
    --------
    >>> pixels, weights = triangle_coverage((0, 0), (2, 0), (0, 2), (2, 2), rate=4)
    >>> pixels.tolist(), weights.tolist()
    ([[0, 0], [1, 0], [0, 1]], [1.0, 0.375, 0.375])
    """
    height, width = as_shape(shape)
    rate = as_int(rate, "rate", minimum=1, maximum=limits.MAX_RATE)
    if height * width * rate**2 > limits.MAX_PIXELS:
        raise ValueError(
            _(
                "shape and rate must give at most {most} samples (H * W * rate**2); got "
                "{height} x {width} x {rate}**2"
            ).format(most=limits.MAX_PIXELS, height=height, width=width, rate=rate)
        )
    names = ("p0", "p1", "p2")
    scaled = [
        rate * as_point(point, name, dim=2) for name, point in zip(names, (p0, p1, p2), strict=True)
    ]
    vertices = []
    for name, point in zip(names, scaled, strict=True):
        if not np.isfinite(point).all():
            require_finite(point, name)  # rate times a huge coordinate: inf, refused as before
        vertices.append(_snapped(point, name))
    rule = as_choice(rule, "rule", EDGE_RULES)
    fine = _triangle_edge_functions(vertices, (height * rate, width * rate), rule)
    coarse = fine[:, 1] // rate * width + fine[:, 0] // rate
    counts = np.bincount(coarse, minlength=height * width)
    index = np.flatnonzero(counts)
    rows, columns = np.divmod(index, width)
    return np.stack((columns, rows), axis=1), counts[index] / rate**2


def hit_counts(pixel_sets: Iterable[Any], shape: Any) -> np.ndarray:
    """How many times each pixel of a canvas appears in the given pixel arrays.

    1 everywhere inside a triangulated region and 0 outside is the watertight
    property; a 2 is a pixel painted twice, a 0 inside is a crack.

    Examples
    --------
    >>> hit_counts([np.array([[0, 0], [1, 0]]), np.array([[1, 0], [5, 5]])], (1, 3))
    array([[1, 2, 0]])
    """
    height, width = as_shape(shape)
    counts = np.zeros(height * width, dtype=np.int64)
    for index, pixels in enumerate(pixel_sets):
        array = as_pixels(pixels, f"pixel_sets[{index}]")
        array = array[on_canvas(array, (height, width))]
        counts += np.bincount(array[:, 1] * width + array[:, 0], minlength=height * width)
    return counts.reshape(height, width)


def barycentric(p0: Any, p1: Any, p2: Any, points: Any) -> np.ndarray:
    """The barycentric coordinates of ``points`` in the triangle p0 p1 p2: (K, 3).

    Row k holds the weights (w0, w1, w2) with ``w0 + w1 + w2 = 1`` and
    ``w0 p0 + w1 p1 + w2 p2 = points[k]``: each weight is the area of the
    triangle the point makes with the opposite edge, over the whole area
    (edge functions, as :func:`triangle` uses, divided by twice the area).
    All three are in [0, 1] exactly when the point is inside.

    Examples
    --------
    >>> barycentric((0, 0), (4, 0), (0, 4), [[1.0, 1.0], [0.0, 0.0], [2.0, 2.0]])
    array([[0.5 , 0.25, 0.25],
           [1.  , 0.  , 0.  ],
           [0.  , 0.5 , 0.5 ]])
    """
    a, b, c = (
        as_point(p, name, dim=2, bound=limits.MAX_COORDINATE)
        for p, name in ((p0, "p0"), (p1, "p1"), (p2, "p2"))
    )
    if np.size(points) == 0:  # no point: no weights (a triangle with no pixel centre inside)
        at = np.zeros((0, 2))
    else:
        at = as_points(points, "points", bound=limits.MAX_COORDINATE)
    if at.shape[1] != 2:
        raise ValueError(
            _("points must have shape (K, 2); got shape {at_shape}").format(at_shape=at.shape)
        )
    return _barycentric(a, b, c, at)


def _barycentric(a: np.ndarray, b: np.ndarray, c: np.ndarray, at: np.ndarray) -> np.ndarray:
    """:func:`barycentric` of checked points: a, b, c (2,), ``at`` (K, 2)."""
    twice_area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    if twice_area == 0:
        raise ValueError(
            _(
                "p0, p1, p2 must span a triangle of non-zero area; got {a}, {b}, {c} on one line"
            ).format(a=tuple(a), b=tuple(b), c=tuple(c))
        )

    def edge(start: np.ndarray, end: np.ndarray) -> np.ndarray:
        """Twice the signed area of (start, end, point): zero on the line start -> end."""
        offset = at - start
        return (end[0] - start[0]) * offset[:, 1] - (end[1] - start[1]) * offset[:, 0]

    return np.column_stack([edge(b, c), edge(c, a), edge(a, b)]) / twice_area


def interpolate(
    p0: Any, p1: Any, p2: Any, values: Any, shape: Any = None, rule: str = "top-left"
) -> tuple[np.ndarray, np.ndarray]:
    """Values given at the vertices, interpolated at the centres of the triangle's pixels.

    The step every rasterizer takes after deciding which pixels a triangle
    covers: a colour, a depth or a texture coordinate at each pixel centre,
    as the barycentric mix of its values at p0, p1, p2. ``values`` is (3,)
    or (3, C), one row per vertex. Returns the pixels of
    :func:`triangle` ``(p0, p1, p2, shape, rule)`` and the (K,) or (K, C)
    values at their centres.

    Examples
    --------
    >>> pixels, red = interpolate((0, 0), (4, 0), (0, 4), [1.0, 0.0, 0.0])
    >>> pixels[:3].tolist(), red[:3].round(3).tolist()
    ([[0, 0], [1, 0], [2, 0]], [0.75, 0.5, 0.25])
    """
    table = np.asarray(values, dtype=float)
    if table.ndim not in (1, 2) or table.shape[0] != 3 or not np.isfinite(table).all():
        raise ValueError(
            _(
                "values must be finite numbers, one row per vertex: shape (3,) or (3, C); got "
                "{values}"
            ).format(values=describe(values))
        )
    points, vertices, canvas, rule, _method = _checked_triangle(p0, p1, p2, shape, rule)
    pixels = _triangle_edge_functions(vertices, canvas, rule)
    if len(pixels) == 0:
        return pixels, np.zeros((0, *table.shape[1:]))
    weights = _barycentric(*points, pixels + 0.5)
    return pixels, weights @ table
