"""Lesson 03's still pictures: a line's pixels, the report's staircase, a scanline fill,
the edge rules on a shared edge, a mesh's cracks, and colour across a triangle.

Each function returns a :class:`~course.widgets.picture.Still` whose caption
states the numbers it shows. Pixel views are at a whole zoom
(:func:`~course.widgets.picture.pixel_figure`), in Okabe and Ito's colours.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from scipy.spatial import Delaunay

from course._validate import as_choice, as_int, as_point, as_shape
from course.i18n import N_, _
from course.raster import hit_counts, line, line_4connected, triangle
from course.raster.canvas import blank, paint
from course.raster.triangles import interpolate
from course.widgets.picture import Still, pixel_figure

__all__ = [
    "RULE_NAMES",
    "colour_figure",
    "edge_rules_figure",
    "line_figure",
    "mesh_figure",
    "rule_name",
    "scanline_figure",
    "staircase_figure",
]

BLUE, VERMILLION, ORANGE, SKY, GREEN = "#0072B2", "#D55E00", "#E69F00", "#56B4E9", "#009E73"
#: The colour figure's vertex labels: which colour each vertex carries.
_VERTEX_COLOURS = (N_("p0: red"), N_("p1: green"), N_("p2: blue"))
#: The edge rules (:data:`course.raster.triangles.EDGE_RULES`) as a student reads them: the
#: apps' toggle, the titles and the captions; the values stay the code's.
RULE_NAMES = {"top-left": N_("top-left"), "closed": N_("closed"), "open": N_("open")}


def rule_name(rule: str) -> str:
    """An edge rule's name in the current language.

    Examples
    --------
    >>> rule_name("top-left")
    'top-left'
    """
    return _(RULE_NAMES[as_choice(rule, "rule", tuple(RULE_NAMES))])


def _rgb(colour: str) -> tuple[float, float, float]:
    return tuple(int(colour[i : i + 2], 16) / 255 for i in (1, 3, 5))


def _grid(axes: Any, left: int, right: int, top: int, bottom: int) -> None:
    """Thin pixel edges over a pixel view, so that pixels can be counted."""
    lines = [[(x, top), (x, bottom)] for x in range(left, right + 1)]
    lines += [[(left, y), (right, y)] for y in range(top, bottom + 1)]
    axes.add_collection(LineCollection(lines, colors="0.8", linewidths=0.5))


def _legend(figure: Any, handles: list) -> None:
    """Replace :func:`pixel_figure`'s colour patches by handles that show lines and marks too."""
    for legend in list(figure.legends):
        legend.remove()
    figure.legend(
        handles=handles, loc="upper center", ncols=len(handles), fontsize=8, frameon=False
    )


def line_figure(p0: tuple[int, int] = (0, 0), p1: tuple[int, int] = (7, 3)) -> Still:
    """Bresenham's pixels for one line, with the ideal line between the two end centres.

    Examples
    --------
    >>> line_figure()
    (0, 0) to (7, 3): 8 pixels, one per column; the farthest centre is 0.429 px off in y
    """
    p0, p1 = _small_pixel(p0, "p0"), _small_pixel(p1, "p1")
    pixels = line(p0, p1)
    left, top = min(p0[0], p1[0]), min(p0[1], p1[1])
    width, height = abs(p1[0] - p0[0]) + 1, abs(p1[1] - p0[1]) + 1
    image = blank((height, width), (1.0, 1.0, 1.0))
    paint(image, pixels - (left, top), _rgb(BLUE), mode="over")
    extent = (left, left + width, top + height, top)
    figure, (axes,) = pixel_figure(
        [(image, extent, _("line from {p0} to {p1}").format(p0=p0, p1=p1))],
        zoom=48,
        legend=[(BLUE, "")],
    )
    _grid(axes, left, left + width, top, top + height)
    axes.plot([p0[0] + 0.5, p1[0] + 0.5], [p0[1] + 0.5, p1[1] + 0.5], color=VERMILLION, lw=2)
    _legend(
        figure,
        [
            Patch(facecolor=BLUE, edgecolor="0.5", label=_("Bresenham's pixels")),
            Line2D([], [], color=VERMILLION, lw=2, label=_("the ideal line")),
        ],
    )
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    steps = max(abs(dx), abs(dy))
    ideal = np.array(p0) + np.outer(np.arange(steps + 1) / steps, (dx, dy))
    off = np.abs(pixels - ideal).max()
    caption = (
        _(
            "{p0} to {p1}: {count} pixels, one per column; the farthest centre is "
            "{off:.3f} px off in y"
        )
        if abs(dx) >= abs(dy)
        else _(
            "{p0} to {p1}: {count} pixels, one per row; the farthest centre is "
            "{off:.3f} px off in x"
        )
    ).format(p0=p0, p1=p1, count=len(pixels), off=off)
    return Still.of(figure, caption)


def staircase_figure(p0: tuple[int, int] = (0, 0), p1: tuple[int, int] = (14, 9)) -> Still:
    """Bresenham's line beside the lab report's loop, which never steps diagonally.

    Examples
    --------
    >>> staircase_figure()
    (0, 0) to (14, 9): Bresenham 15 pixels, the report's loop 24
    """
    p0, p1 = _small_pixel(p0, "p0"), _small_pixel(p1, "p1")
    width, height = abs(p1[0] - p0[0]) + 1, abs(p1[1] - p0[1]) + 1
    left, top = min(p0[0], p1[0]), min(p0[1], p1[1])
    windows = []
    drawings = (
        (_("Bresenham"), line(p0, p1), BLUE),
        (_("the report's loop"), line_4connected(p0, p1), VERMILLION),
    )
    for title, pixels, colour in drawings:
        image = blank((height, width), (1.0, 1.0, 1.0))
        paint(image, pixels - (left, top), _rgb(colour), mode="over")
        windows.append(
            (
                image,
                (left, left + width, top + height, top),
                _("{title}: {count} pixels").format(title=title, count=len(pixels)),
            )
        )
    figure, axes_list = pixel_figure(windows, zoom=18, legend=[(BLUE, "")])
    for axes in axes_list:
        _grid(axes, left, left + width, top, top + height)
        axes.plot([p0[0] + 0.5, p1[0] + 0.5], [p0[1] + 0.5, p1[1] + 0.5], color="0.2", lw=1)
    _legend(
        figure,
        [
            Patch(facecolor=BLUE, edgecolor="0.5", label=_("Bresenham: 8-connected")),
            Patch(facecolor=VERMILLION, edgecolor="0.5", label=_("the report's: 4-connected")),
            Line2D([], [], color="0.2", lw=1, label=_("the ideal line")),
        ],
    )
    counts = [len(pixels) for _title, pixels, _colour in drawings]
    caption = _("{p0} to {p1}: Bresenham {line} pixels, the report's loop {loop}").format(
        p0=p0, p1=p1, line=counts[0], loop=counts[1]
    )
    return Still.of(figure, caption)


def _rows(p0: Any, p1: Any, p2: Any) -> list[tuple[float, float, float, bool]]:
    """Each row of centres the scanline fill visits: (y, x_left, x_right, upper half?)."""
    top, middle, bottom = sorted([tuple(map(float, p)) for p in (p0, p1, p2)], key=lambda p: p[1])
    rows = []
    for row in range(int(np.ceil(top[1] - 0.5)), int(np.ceil(bottom[1] - 0.5))):
        y = row + 0.5
        x_long = top[0] + (y - top[1]) * (bottom[0] - top[0]) / (bottom[1] - top[1])
        upper = y < middle[1]
        a, b = (top, middle) if upper else (middle, bottom)
        x_short = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        rows.append((y, min(x_long, x_short), max(x_long, x_short), upper))
    return rows


def scanline_figure(
    p0: Any = (1.5, 1.0),
    p1: Any = (12.5, 4.0),
    p2: Any = (5.0, 11.5),
    size: tuple[int, int] = (13, 14),
) -> Still:
    """The lab's scanline fill: rows of pixel centres between two edges, in two halves.

    The row through the middle vertex splits the triangle into a half with a
    flat bottom and a half with a flat top; each row takes the centres from
    its left edge (included) to its right edge (left out).

    Examples
    --------
    >>> scanline_figure()
    10 rows: 3 in the upper half, 7 in the lower; 52 pixels, as the top-left rule takes them
    """
    height, width = as_shape(size, "size", max_pixels=256 * 256)
    p0, p1, p2 = (
        as_point(p, name, dim=2, bound=256.0) for p, name in ((p0, "p0"), (p1, "p1"), (p2, "p2"))
    )
    rows = _rows(p0, p1, p2)
    pixels = triangle(p0, p1, p2, shape=size)
    upper_rows = {int(y) for y, _left, _right, upper in rows if upper}
    image = blank(size, (1.0, 1.0, 1.0))
    for x, y in pixels:
        image[y, x] = _rgb(SKY) if y in upper_rows else _rgb(ORANGE)
    figure, (axes,) = pixel_figure(
        [(image, (0, width, height, 0), _("each row: from the left edge to the right edge"))],
        zoom=30,
        legend=[(SKY, _("upper half (flat bottom)")), (ORANGE, _("lower half (flat top)"))],
    )
    _grid(axes, 0, width, 0, height)
    corners = np.array([p0, p1, p2, p0], dtype=float)
    axes.plot(corners[:, 0], corners[:, 1], color="0.15", lw=1.5)
    middle = sorted([p0, p1, p2], key=lambda p: p[1])[1]
    axes.axhline(middle[1], color="0.4", lw=1, ls="--")
    for y, left, right, _upper in rows:
        axes.plot([left, right], [y, y], color=BLUE, lw=1.2)
        axes.plot([left], [y], "|", color=BLUE, ms=8)
    centres = np.array([(x + 0.5, y + 0.5) for x in range(width) for y in range(height)])
    axes.plot(*centres.T, ".", color="0.55", ms=2)
    upper = sum(1 for *_row, flag in rows if flag)
    caption = _(
        "{rows} rows: {upper} in the upper half, {lower} in the lower; "
        "{pixels} pixels, as the top-left rule takes them"
    ).format(rows=len(rows), upper=upper, lower=len(rows) - upper, pixels=len(pixels))
    return Still.of(figure, caption)


def edge_rules_figure(size: int = 6) -> Still:
    """Two triangles sharing a diagonal through pixel centres, filled with each edge rule.

    Examples
    --------
    >>> edge_rules_figure()
    centres on the shared edge: top-left paints each once; closed paints 6 twice; open misses 6
    """
    a, b, c, d = (0, 0), (size, 0), (size, size), (0, size)
    colours = np.array([(1, 1, 1), _rgb(SKY), _rgb(ORANGE), _rgb(VERMILLION)])
    windows, notes, twice_painted = [], [], []
    for rule in ("top-left", "closed", "open"):
        first = triangle(a, b, c, rule=rule)
        second = triangle(a, c, d, rule=rule)
        counts = hit_counts([first, second], (size, size))
        owner = np.zeros((size, size), dtype=int)
        owner[first[:, 1], first[:, 0]] += 1
        owner[second[:, 1], second[:, 0]] += 2
        twice_painted.append(np.argwhere(owner == 3)[:, ::-1] + 0.5)
        title = _("rule '{rule}'").format(rule=rule_name(rule))
        windows.append((colours[owner], (0, size, size, 0), title))
        notes.append((rule, int((counts == 2).sum()), int((counts == 0).sum())))
    figure, axes_list = pixel_figure(
        windows,
        zoom=34,
        legend=[
            (SKY, _("upper triangle")),
            (ORANGE, _("lower triangle")),
            (VERMILLION, _("both (marked +)")),
            ("white", _("neither")),
        ],
    )
    for axes, twice in zip(axes_list, twice_painted, strict=True):
        _grid(axes, 0, size, 0, size)
        # Both and the lower triangle are close in hue: a mark tells them apart without colour,
        # a + rather than an x, whose arm would lie along the shared diagonal.
        axes.plot(*twice.T, "+", color="black", ms=10, mew=1.5)
        axes.plot([0, size], [0, size], color="0.15", lw=1.5)
        on_edge = np.arange(size) + 0.5
        axes.plot(on_edge, on_edge, "o", color="0.15", ms=4, fillstyle="none")
    parts = []
    for rule, twice, never in notes:
        name = rule_name(rule)
        if twice:
            parts.append(_("{rule} paints {count} twice").format(rule=name, count=twice))
        elif never:
            parts.append(_("{rule} misses {count}").format(rule=name, count=never))
        else:
            parts.append(_("{rule} paints each once").format(rule=name))
    caption = _("centres on the shared edge: {parts}").format(parts=_("; ").join(parts))
    return Still.of(figure, caption)


def mesh_figure(size: int = 64, points: int = 60, seed: int = 4) -> Still:
    """A mesh with integer vertices filled at half opacity with each rule: doubles and cracks.

    Examples
    --------
    >>> print(mesh_figure().caption.replace("; ", "\\n"))
    122 triangles over 4096 pixels: top-left 0 doubled, 0 cracks
    closed 126 doubled
    open 126 cracks
    """
    size = as_int(size, "size", minimum=2, maximum=256)
    points = as_int(points, "points", minimum=0, maximum=1000)
    rng = np.random.default_rng(as_int(seed, "seed", minimum=0))
    corners = [[-1, -1], [size + 1, -1], [size + 1, size + 1], [-1, size + 1]]
    vertices = np.unique(np.vstack([corners, rng.integers(0, size + 1, (points, 2))]), axis=0)
    mesh = Delaunay(vertices.astype(float)).simplices
    colours = np.random.default_rng(1).uniform(0.2, 0.8, (len(mesh), 3))
    windows, counts, doubles = [], {}, []
    for rule in ("closed", "top-left", "open"):
        image = blank((size, size), (1.0, 1.0, 1.0))
        filled = [triangle(*vertices[s], shape=(size, size), rule=rule) for s in mesh]
        for pixels, colour in zip(filled, colours, strict=True):
            paint(image, pixels, colour, weight=0.5, mode="over")
        hits = hit_counts(filled, (size, size))
        counts[rule] = (int((hits == 2).sum()), int((hits == 0).sum()))
        twice, never = counts[rule]
        title = _("{rule}: {twice} doubled, {never} cracks").format(
            rule=rule_name(rule), twice=twice, never=never
        )
        windows.append((image, (0, size, size, 0), title))
        doubles.append(np.argwhere(hits == 2)[:, ::-1] + 0.5)
    figure, axes_list = pixel_figure(windows, zoom=4, legend=[(BLUE, "")])
    for axes, doubled in zip(axes_list, doubles, strict=True):
        # Doubled pixels are only a little darker at half opacity: a dot makes them plain.
        axes.plot(*doubled.T, ".", color="black", markersize=2.5)
    _legend(
        figure,
        [
            Line2D([], [], marker=".", color="black", ls="", label=_("doubled: painted twice")),
            Patch(facecolor="white", edgecolor="0.5", label=_("crack: painted by none")),
        ],
    )
    caption = _(
        "{triangles} triangles over {pixels} pixels: "
        "top-left {top_left_twice} doubled, {top_left_never} cracks; "
        "closed {closed_twice} doubled; "
        "open {open_never} cracks"
    ).format(
        triangles=len(mesh),
        pixels=size * size,
        top_left_twice=counts["top-left"][0],
        top_left_never=counts["top-left"][1],
        closed_twice=counts["closed"][0],
        open_never=counts["open"][1],
    )
    return Still.of(figure, caption)


def colour_figure(
    p0: Any = (4.0, 1.0),
    p1: Any = (22.0, 6.0),
    p2: Any = (9.0, 17.0),
    size: tuple[int, int] = (18, 28),
) -> Still:
    """Red, green and blue at the vertices, mixed at each pixel centre by barycentric weights.

    Examples
    --------
    >>> colour_figure()
    131 pixels; at the centre (14.5, 7.5) the weights are (0.240, 0.515, 0.245)
    """
    size = as_shape(size, "size", max_pixels=128 * 128)
    if max(size) > 128:  # zoomed 16 times, a side of 128 pixels is a 2048-pixel picture
        raise ValueError(
            _("size must have sides of at most 128 pixels; got {size}").format(size=size)
        )
    p0, p1, p2 = (
        as_point(p, name, dim=2, bound=256.0) for p, name in ((p0, "p0"), (p1, "p1"), (p2, "p2"))
    )
    pixels, colours = interpolate(p0, p1, p2, np.eye(3), shape=size)
    if len(pixels) == 0:
        raise ValueError(
            _(
                "p0, p1 and p2 must enclose at least one pixel centre of the {size} canvas to "
                "colour; got {p0}, {p1}, {p2}"
            ).format(size=size, p0=p0.tolist(), p1=p1.tolist(), p2=p2.tolist())
        )
    image = blank(size, (1.0, 1.0, 1.0))
    image[pixels[:, 1], pixels[:, 0]] = colours
    height, width = size
    figure, (axes,) = pixel_figure(
        [(image, (0, width, height, 0), _("colour at each centre"))], zoom=16
    )
    middle = np.mean([p0, p1, p2], axis=0)
    for name, point in zip(_VERTEX_COLOURS, (p0, p1, p2), strict=True):
        axes.plot(*point, "o", color="0.1", ms=4)
        away = np.sign(np.subtract(point, middle)) * (1, -1)  # y down in data, up in offsets
        axes.annotate(
            _(name),
            point,
            xytext=tuple(10 * away),
            textcoords="offset points",
            ha="left" if away[0] > 0 else "right",
            va="bottom" if away[1] > 0 else "top",
            fontsize=8,
        )
    corners = np.array([p0, p1, p2, p0], dtype=float)
    axes.plot(corners[:, 0], corners[:, 1], color="0.15", lw=1)
    probe = pixels[len(pixels) // 2]
    weights = colours[len(pixels) // 2]
    # The centre the caption gives the weights of, marked where the student can find it.
    centre = (probe[0] + 0.5, probe[1] + 0.5)
    axes.plot(*centre, "o", color="white", mec="0.1", mew=1.2, ms=6)
    axes.annotate(
        f"({centre[0]:g}, {centre[1]:g})",
        centre,
        xytext=(7, 7),
        textcoords="offset points",
        fontsize=8,
        bbox={
            "boxstyle": "round,pad=0.2",
            "facecolor": "white",
            "edgecolor": "none",
            "alpha": 0.85,
        },
    )
    caption = _(
        "{count} pixels; at the centre ({x:g}, {y:g}) the "
        "weights are ({w0:.3f}, {w1:.3f}, {w2:.3f})"
    ).format(
        count=len(pixels),
        x=probe[0] + 0.5,
        y=probe[1] + 0.5,
        w0=weights[0],
        w1=weights[1],
        w2=weights[2],
    )
    return Still.of(figure, caption)


def _small_pixel(point: Any, name: str) -> tuple[int, int]:
    """A whole pixel (x, y) within 64 of the origin: a figure draws every pixel between two."""
    array = as_point(point, name, dim=2, bound=64.0)
    if (array != np.round(array)).any():
        raise ValueError(
            _("{name} must be a whole pixel (x, y); got {array}").format(
                name=name, array=array.tolist()
            )
        )
    return int(array[0]), int(array[1])
