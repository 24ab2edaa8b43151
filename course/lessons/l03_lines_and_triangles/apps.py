"""Lesson 03's apps: Bresenham against the report's staircase, and filled triangles.

:class:`LineApp` draws one line three ways on a zoomed 32 x 32 grid, with
the ideal line (from pixel centre to pixel centre) on top; drag either end,
in any panel. :class:`TriangleApp` fills two triangles that share an edge,
marks the pixel centres that fall inside, counts the pixels painted twice
(or not at all) when the top-left rule is turned off, and shows the
supersampled coverage at a chosen rate; drag any vertex. The points can be
typed too (``x, y; x, y``). The lab's Task 7, :class:`CurveSegmentsApp`,
lives in :mod:`.curve_segments` and is listed here with the lesson's other
apps, where the notebook imports it.
"""

from __future__ import annotations

import ipywidgets as widgets
import matplotlib
import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from course import limits
from course._validate import as_app_points, as_choice, as_int, as_point, as_shape
from course.i18n import _
from course.lessons.l03_lines_and_triangles.curve_segments import CurveSegmentsApp
from course.lessons.l03_lines_and_triangles.figures import rule_name
from course.lessons.l03_lines_and_triangles.grid import pixel_grid
from course.raster import (
    distance_from_line,
    hit_counts,
    line,
    line_4connected,
    triangle,
    triangle_coverage,
    wu_line,
)
from course.raster.canvas import blank, paint
from course.raster.triangles import EDGE_RULES
from course.widgets.base import Handle, SliderApp, format_points
from course.widgets.picture import PixelPanel, pixel_axes

__all__ = [
    "LINE_GRID",
    "OWNER_COLORS",
    "TRIANGLE_GRID",
    "CurveSegmentsApp",
    "LineApp",
    "TriangleApp",
    "octant",
    "shared_edge_centres",
]

LINE_GRID = 32
TRIANGLE_GRID = 16


def octant(dx: int, dy: int) -> int:
    """The octant (1 to 8) of a direction, counted clockwise from +x in image space (y down).

    Octant 1 is the lesson's first octant: going right with 0 <= dy <= dx, x the major axis.
    Each next octant turns 45 degrees clockwise on screen. A diagonal belongs to the octant
    whose major axis is x, as Bresenham's loop takes x as the major axis when |dx| = |dy|;
    a line of zero length is in octant 1.

    Examples
    --------
    >>> [octant(5, 2), octant(2, 5), octant(-2, 5), octant(-5, 2)]
    [1, 2, 3, 4]
    >>> [octant(-5, -2), octant(-2, -5), octant(2, -5), octant(5, -2)]
    [5, 6, 7, 8]
    >>> [octant(3, 3), octant(-3, 3), octant(-3, -3), octant(3, -3), octant(0, 0)]
    [1, 4, 5, 8, 1]
    """
    dx, dy = as_int(dx, "dx"), as_int(dy, "dy")
    if abs(dx) >= abs(dy):  # x is the major axis: octants 1, 4, 5 and 8
        if dx >= 0:
            return 1 if dy >= 0 else 8
        return 4 if dy >= 0 else 5
    if dy > 0:  # y is the major axis, going down: 2 and 3
        return 2 if dx >= 0 else 3
    return 7 if dx >= 0 else 6


class LineApp(SliderApp):
    """One line, three rasterizers: Bresenham, the report's 4-connected loop, Wu.

    Drag an end of the line in any panel, or type the two pixels in
    ``endpoints`` (``x0, y0; x1, y1``, integers on the 32 x 32 grid); every
    direction (all eight octants) is reachable. The red segment is the ideal
    line between the two pixel centres.
    """

    BLIT = True
    ZOOM = 9  # screen pixels per grid pixel

    def __init__(self, p0: tuple[int, int] = (3, 6), p1: tuple[int, int] = (27, 17)) -> None:
        ends = [
            as_app_points([point], name, 1, low=0, high=LINE_GRID - 1, whole=True)[0]
            for point, name in ((p0, "p0"), (p1, "p1"))
        ]
        self.ends = np.array(ends, dtype=np.int64)
        controls = {
            "endpoints": widgets.Text(
                value=format_points(self.ends), description="x, y", continuous_update=False
            )
        }
        super().__init__(controls, shape=(380, 960))
        self.panels = {}
        self.ideal = {}
        grids = []
        side = LINE_GRID * self.ZOOM
        for index, name in enumerate(("bresenham", "report", "wu")):
            axes = pixel_axes(self.figure, 24 + index * (side + 24), 30, side, side)
            grids.append(pixel_grid(axes, LINE_GRID))
            self.panels[name] = PixelPanel(self, axes, (LINE_GRID, LINE_GRID), self.ZOOM, "Greys")
            (self.ideal[name],) = axes.plot(
                [], [], color="crimson", linewidth=1.2, marker="o", markersize=4
            )
        self.heading = self.figure.suptitle("", fontsize=10)
        self.animate(
            *grids,
            *self.ideal.values(),
            *(panel.axes.title for panel in self.panels.values()),
            self.heading,
        )

    def endpoints(self) -> tuple[tuple[int, int], tuple[int, int]]:
        """The two pixels the line runs between, as the text describes them."""
        typed = self.typed_points("endpoints", self.ends, 2, 0, LINE_GRID - 1, whole=True)
        self.ends = typed.astype(np.int64)
        (x0, y0), (x1, y1) = self.ends.tolist()
        return (x0, y0), (x1, y1)

    def handles(self) -> list[Handle]:
        return [
            Handle(f"p{end}", panel.axes, tuple(self.ends[end] + 0.5))
            for end in (0, 1)
            for panel in self.panels.values()
        ]

    def drag(self, name: str, point: np.ndarray) -> None:
        ends = self.ends.copy()
        ends[int(name[1])] = np.clip(np.floor(point), 0, LINE_GRID - 1)
        self.controls["endpoints"].value = format_points(ends)

    def update(self) -> None:
        p0, p1 = self.endpoints()
        bresenham = line(p0, p1)
        staircase = line_4connected(p0, p1)
        wu_pixels, wu_weights = wu_line(np.add(p0, 0.5), np.add(p1, 0.5))
        size = LINE_GRID
        self.panels["bresenham"].set_data(paint(blank((size, size)), bresenham, 1.0))
        self.panels["report"].set_data(paint(blank((size, size)), staircase, 1.0))
        self.panels["wu"].set_data(paint(blank((size, size)), wu_pixels, 1.0, weight=wu_weights))
        for ideal in self.ideal.values():
            ideal.set_data([p0[0] + 0.5, p1[0] + 0.5], [p0[1] + 0.5, p1[1] + 0.5])
        dx, dy = p1[0] - p0[0], p1[1] - p0[1]
        self.panels["bresenham"].axes.set_title(
            _("Bresenham: {count} px = max(|dx|, |dy|) + 1").format(count=len(bresenham)),
            fontsize=9,
        )
        self.panels["report"].axes.set_title(
            _("report's loop: {count} px = |dx| + |dy| + 1").format(count=len(staircase)),
            fontsize=9,
        )
        self.panels["wu"].axes.set_title(
            _("Wu: {count} px, ink {ink:.1f}").format(count=len(wu_pixels), ink=wu_weights.sum()),
            fontsize=9,
        )
        farthest = [distance_from_line(pixels, p0, p1).max() for pixels in (bresenham, staircase)]
        self.heading.set_text(
            _("({x0}, {y0}) to ({x1}, {y1}): dx = {dx}, dy = {dy}, octant {octant}").format(
                x0=p0[0], y0=p0[1], x1=p1[0], y1=p1[1], dx=dx, dy=dy, octant=octant(dx, dy)
            )
            + _(
                "; farthest centre from the red line: Bresenham {bresenham:.2f} px, the "
                "report's loop {report:.2f} px"
            ).format(bresenham=farthest[0], report=farthest[1])
        )


#: Colours of a pixel by who paints it: nobody, the first triangle, the second, both.
OWNER_COLORS = ("white", "#9ecae1", "#fdd0a2", "crimson")
_OWNERS = ListedColormap(OWNER_COLORS)


def shared_edge_centres(a: np.ndarray, c: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
    """Boolean (H, W) mask of the pixel centres strictly between a and c on segment ac.

    Exact for coordinates on a binary grid (the app's quarter pixels).

    Examples
    --------
    >>> shared_edge_centres(np.array([0.5, 0.5]), np.array([3.5, 3.5]), (4, 4)).astype(int)
    array([[0, 0, 0, 0],
           [0, 1, 0, 0],
           [0, 0, 1, 0],
           [0, 0, 0, 0]])
    """
    a = as_point(a, "a", dim=2, bound=limits.MAX_COORDINATE)
    c = as_point(c, "c", dim=2, bound=limits.MAX_COORDINATE)
    shape = as_shape(shape)
    y, x = np.mgrid[0 : shape[0], 0 : shape[1]] + 0.5
    edge = c - a
    along = (x - a[0]) * edge[0] + (y - a[1]) * edge[1]
    across = (x - a[0]) * edge[1] - (y - a[1]) * edge[0]
    return (across == 0) & (along > 0) & (along < edge @ edge)


class TriangleApp(SliderApp):
    """Two triangles sharing the edge AC: ABC and ACD, filled pixel by pixel.

    Drag a vertex A, B, C or D in either panel (it snaps to quarter pixels,
    so vertices and edges can sit exactly on pixel centres), or type them in
    ``vertices``; pick the edge ``rule`` (:data:`course.raster.triangles.EDGE_RULES`)
    and the SSAA ``rate``. Left: who paints each pixel, red where both do;
    dots mark the centres inside. Right: the supersampled coverage of both.
    """

    NAMES = "ABCD"
    BLIT = True
    ZOOM = 20  # screen pixels per grid pixel

    def __init__(
        self,
        vertices: tuple[tuple[float, float], ...] = (
            (2.5, 1.5),
            (13.5, 3.0),
            (12.5, 13.5),
            (1.0, 11.5),
        ),
        rule: str = "top-left",
        rate: int = 4,
    ) -> None:
        self.corners = as_app_points(vertices, "vertices", 4, low=0, high=TRIANGLE_GRID)
        rule = as_choice(rule, "rule", EDGE_RULES)
        rate = as_int(rate, "rate", minimum=1, maximum=8)
        controls: dict[str, widgets.ValueWidget] = {
            "vertices": widgets.Textarea(
                value=format_points(self.corners), description="x, y", continuous_update=False
            ),
            "rule": widgets.ToggleButtons(
                options=[(rule_name(name), name) for name in EDGE_RULES],
                value=rule,
                description=_("rule"),
                style={"button_width": "70px"},
            ),
            "rate": widgets.IntSlider(value=rate, min=1, max=8, description=_("SSAA rate")),
        }
        super().__init__(controls, shape=(445, 830))
        size, zoom = TRIANGLE_GRID, self.ZOOM
        left = pixel_axes(self.figure, 40, 75, size * zoom, size * zoom)
        right = pixel_axes(self.figure, 470, 75, size * zoom, size * zoom)
        grids = (pixel_grid(left, size), pixel_grid(right, size))
        self.owners = PixelPanel(self, left, (size, size), zoom, _OWNERS, vmin=0, vmax=3)
        centres = np.arange(size) + 0.5
        grid_x, grid_y = np.meshgrid(centres, centres)
        (all_centres,) = left.plot(grid_x.ravel(), grid_y.ravel(), ".", color="0.75", markersize=2)
        (self.inside_centres,) = left.plot([], [], "o", color="black", markersize=3)
        # Under the left panel, and part of its tight box: the course map shows that panel alone.
        left.legend(
            handles=[
                Patch(facecolor=OWNER_COLORS[1], edgecolor="0.5", label=_("ABC only")),
                Patch(facecolor=OWNER_COLORS[2], edgecolor="0.5", label=_("ACD only")),
                Patch(facecolor=OWNER_COLORS[3], edgecolor="0.5", label=_("both: painted twice")),
                Line2D([], [], marker="o", color="black", ls="", ms=3, label=_("centre inside")),
                Line2D([], [], marker=".", color="0.6", ls="", ms=4, label=_("centre outside")),
                Line2D([], [], color="navy", lw=2, label=_("shared edge AC")),
            ],
            loc="upper center",
            bbox_to_anchor=(0.5, -0.07),
            ncols=3,
            fontsize=7,
            frameon=False,
            handlelength=1.4,
            columnspacing=0.8,
        )
        self.coverage = PixelPanel(self, right, (size, size), zoom, "Greys")
        greys = matplotlib.colormaps["Greys"]
        right.legend(
            handles=[
                Patch(facecolor=greys(1.0), edgecolor="0.5", label=_("fully inside: 1")),
                Patch(
                    facecolor=greys(0.5),
                    edgecolor="0.5",
                    label=_("grey: the share of its samples inside"),
                ),
                Patch(facecolor=greys(0.0), edgecolor="0.5", label=_("outside: 0")),
            ],
            loc="upper center",
            bbox_to_anchor=(0.5, -0.07),
            ncols=2,
            fontsize=7,
            frameon=False,
            handlelength=1.4,
            columnspacing=0.8,
        )
        self.outlines = [axes.plot([], [], color="navy", linewidth=1)[0] for axes in (left, right)]
        self.shared = [axes.plot([], [], color="navy", linewidth=2)[0] for axes in (left, right)]
        self.left, self.right = left, right
        # Never hidden by their point (a drag keeps it on the grid anyway): a drag then
        # moves a label's recorded text with its point (TextReplay), not laid out anew.
        self.labels = [
            left.annotate(
                name,
                (0, 0),
                xytext=(5, 5),
                textcoords="offset points",
                fontsize=10,
                annotation_clip=False,
            )
            for name in self.NAMES
        ]
        self.counts = np.zeros((size, size), dtype=np.int64)
        self.animate(
            *grids,
            all_centres,
            self.inside_centres,
            *self.outlines,
            *self.shared,
            *self.labels,
            left.title,
            right.title,
        )
        self.handle_artists = {
            name: [label] for name, label in zip(self.NAMES, self.labels, strict=True)
        }

    def vertices(self) -> np.ndarray:
        """A, B, C, D as a (4, 2) array, as the text describes them."""
        self.corners = self.typed_points("vertices", self.corners, 4, 0, TRIANGLE_GRID)
        return self.corners.copy()

    def handles(self) -> list[Handle]:
        return [
            Handle(name, axes, tuple(corner))
            for name, corner in zip(self.NAMES, self.corners, strict=True)
            for axes in (self.left, self.right)
        ]

    def drag(self, name: str, point: np.ndarray) -> None:
        corners = self.corners.copy()
        corners[self.NAMES.index(name)] = np.clip(np.round(point * 4) / 4, 0, TRIANGLE_GRID)
        self.controls["vertices"].value = format_points(corners)

    def update(self) -> None:
        a, b, c, d = self.vertices()
        rule, rate = self.value("rule"), self.value("rate")
        shape = (TRIANGLE_GRID, TRIANGLE_GRID)
        first = triangle(a, b, c, shape=shape, rule=rule)
        second = triangle(a, c, d, shape=shape, rule=rule)
        self.counts = hit_counts([first, second], shape)
        in_first = hit_counts([first], shape) > 0
        in_second = hit_counts([second], shape) > 0
        self.owners.set_data(np.where(in_first & in_second, 3, in_first + 2 * in_second))
        rows, columns = np.nonzero(self.counts)
        self.inside_centres.set_data(columns + 0.5, rows + 0.5)
        doubled = int(np.count_nonzero(self.counts == 2))
        cracks = int(np.count_nonzero(shared_edge_centres(a, c, shape) & (self.counts == 0)))
        self.left.set_title(
            _(
                "rule {rule}: {first} + {second} pixels\n"
                "{doubled} painted twice, {cracks} missed on the shared edge"
            ).format(
                rule=rule_name(rule),
                first=len(first),
                second=len(second),
                doubled=doubled,
                cracks=cracks,
            ),
            fontsize=9,
        )
        image = blank(shape)
        for triple in ((a, b, c), (a, c, d)):
            pixels, weights = triangle_coverage(*triple, shape, rate, rule=rule)
            paint(image, pixels, 1.0, weight=weights)
        self.coverage.set_data(image)
        title = _("SSAA coverage, {rate} x {rate} samples per pixel").format(rate=rate)
        if title != self.right.get_title():  # set_title would give it a new layout anyway
            self.right.set_title(title, fontsize=9)
        for label, corner in zip(self.labels, (a, b, c, d), strict=True):
            label.xy = tuple(corner)
        quad = np.array([a, b, c, d, a])
        for outline, shared in zip(self.outlines, self.shared, strict=True):
            outline.set_data(quad[:, 0], quad[:, 1])
            shared.set_data([a[0], c[0]], [a[1], c[1]])
