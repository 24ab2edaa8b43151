"""Lesson 03's apps: Bresenham against the report's staircase, and filled triangles.

:class:`LineApp` draws one line three ways on a zoomed 32 x 32 grid, with
the ideal line (from pixel centre to pixel centre) on top. :class:`TriangleApp`
fills two triangles that share an edge, marks the pixel centres that fall
inside, counts the pixels painted twice (or not at all) when the top-left
rule is turned off, and shows the supersampled coverage at a chosen rate.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np
from matplotlib.axes import Axes
from matplotlib.colors import ListedColormap

from course.canvas import blank, paint
from course.raster import hit_counts, line, line_4connected, triangle, triangle_coverage, wu_line
from course.triangles import EDGE_RULES
from course.widgets.base import SliderApp

__all__ = ["LineApp", "TriangleApp", "octant", "pixel_grid", "shared_edge_centres"]

LINE_GRID = 32
TRIANGLE_GRID = 16


def pixel_grid(axes: Axes, size: int, title: str = "") -> None:
    """Set up axes as a zoomed size x size pixel grid in image space (y down)."""
    axes.set_xlim(0, size)
    axes.set_ylim(size, 0)
    axes.set_aspect("equal")
    axes.set_xticks(np.arange(0, size + 1, 4))
    axes.set_yticks(np.arange(0, size + 1, 4))
    axes.set_xticks(np.arange(size + 1), minor=True)
    axes.set_yticks(np.arange(size + 1), minor=True)
    axes.grid(which="minor", color="0.85", linewidth=0.5)
    axes.tick_params(which="both", labelsize=7, length=0)
    axes.set_title(title, fontsize=9)


def octant(dx: int, dy: int) -> int:
    """The octant (0 to 7) of a direction, counted clockwise from +x in image space (y down).

    Octant 0 is x-major going right and (slightly) down; each next octant
    turns 45 degrees clockwise on screen. A line of zero length is in octant 0.

    Examples
    --------
    >>> [octant(5, 2), octant(2, 5), octant(-2, 5), octant(-5, 2)]
    [0, 1, 2, 3]
    >>> [octant(-5, -2), octant(-2, -5), octant(2, -5), octant(5, -2)]
    [4, 5, 6, 7]
    """
    angle = np.degrees(np.arctan2(dy, dx)) % 360
    # Half-open 45-degree sectors: a diagonal starts the next octant.
    return int(angle // 45) % 8


class LineApp(SliderApp):
    """One line, three rasterizers: Bresenham, the report's 4-connected loop, Wu.

    Controls ``x0, y0, x1, y1``: the endpoints, integer pixels on a 32 x 32
    grid; every direction (all eight octants) is reachable. The red segment
    is the ideal line between the two pixel centres.
    """

    def __init__(self, p0: tuple[int, int] = (3, 6), p1: tuple[int, int] = (27, 17)) -> None:
        limit = LINE_GRID - 1
        controls = {
            name: widgets.IntSlider(value=value, min=0, max=limit, description=name)
            for name, value in zip(("x0", "y0", "x1", "y1"), (*p0, *p1), strict=True)
        }
        super().__init__(controls, shape=(380, 960))
        self.panels = {}
        self.ideal = {}
        for index, name in enumerate(("bresenham", "report", "wu")):
            axes = self.figure.add_axes((0.03 + index * 0.33, 0.06, 0.29, 0.78))
            pixel_grid(axes, LINE_GRID)
            self.panels[name] = axes.imshow(
                np.zeros((LINE_GRID, LINE_GRID)),
                cmap="Greys",
                vmin=0,
                vmax=1,
                interpolation="nearest",
                extent=(0, LINE_GRID, LINE_GRID, 0),
            )
            (self.ideal[name],) = axes.plot([], [], color="crimson", linewidth=1.2)
        self.heading = self.figure.suptitle("", fontsize=10)

    def endpoints(self) -> tuple[tuple[int, int], tuple[int, int]]:
        return (self.value("x0"), self.value("y0")), (self.value("x1"), self.value("y1"))

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
            f"Bresenham: {len(bresenham)} px = max(|dx|, |dy|) + 1", fontsize=9
        )
        self.panels["report"].axes.set_title(
            f"report's loop: {len(staircase)} px = |dx| + |dy| + 1", fontsize=9
        )
        self.panels["wu"].axes.set_title(
            f"Wu: {len(wu_pixels)} px, ink {wu_weights.sum():.1f}", fontsize=9
        )
        self.heading.set_text(
            f"({p0[0]}, {p0[1]}) to ({p1[0]}, {p1[1]}): dx = {dx}, dy = {dy}, "
            f"octant {octant(dx, dy)}"
        )


# Colours of a pixel by who paints it: nobody, the first triangle, the second, both.
_OWNERS = ListedColormap(["white", "#9ecae1", "#fdd0a2", "crimson"])


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
    y, x = np.mgrid[0 : shape[0], 0 : shape[1]] + 0.5
    edge = c - a
    along = (x - a[0]) * edge[0] + (y - a[1]) * edge[1]
    across = (x - a[0]) * edge[1] - (y - a[1]) * edge[0]
    return (across == 0) & (along > 0) & (along < edge @ edge)


class TriangleApp(SliderApp):
    """Two triangles sharing the edge AC: ABC and ACD, filled pixel by pixel.

    Controls: the vertices ``ax, ay, ..., dx, dy`` on a 16 x 16 grid (steps
    of 0.25, so vertices and edges can sit exactly on pixel centres), the
    edge ``rule`` (:data:`course.triangles.EDGE_RULES`) and the SSAA
    ``rate``. Left: who paints each pixel, red where both do; dots mark the
    centres inside. Right: the supersampled coverage of both triangles.
    """

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
        controls: dict[str, widgets.ValueWidget] = {}
        for label, (x, y) in zip("abcd", vertices, strict=True):
            for axis, value in (("x", x), ("y", y)):
                controls[f"{label}{axis}"] = widgets.FloatSlider(
                    value=value, min=0, max=TRIANGLE_GRID, step=0.25, description=f"{label}{axis}"
                )
        controls["rule"] = widgets.ToggleButtons(
            options=EDGE_RULES, value=rule, description="rule", style={"button_width": "70px"}
        )
        controls["rate"] = widgets.IntSlider(value=rate, min=1, max=8, description="SSAA rate")
        super().__init__(controls, shape=(460, 860))
        size = TRIANGLE_GRID
        left = self.figure.add_axes((0.04, 0.05, 0.44, 0.8))
        right = self.figure.add_axes((0.53, 0.05, 0.44, 0.8))
        pixel_grid(left, size)
        pixel_grid(right, size)
        extent = (0, size, size, 0)
        self.owners = left.imshow(
            np.zeros((size, size)),
            cmap=_OWNERS,
            vmin=0,
            vmax=3,
            interpolation="nearest",
            extent=extent,
        )
        centres = np.arange(size) + 0.5
        grid_x, grid_y = np.meshgrid(centres, centres)
        left.plot(grid_x.ravel(), grid_y.ravel(), ".", color="0.75", markersize=2)
        (self.inside_centres,) = left.plot([], [], "o", color="black", markersize=3)
        self.coverage = right.imshow(
            np.zeros((size, size)),
            cmap="Greys",
            vmin=0,
            vmax=1,
            interpolation="nearest",
            extent=extent,
        )
        self.outlines = [axes.plot([], [], color="navy", linewidth=1)[0] for axes in (left, right)]
        self.shared = [axes.plot([], [], color="navy", linewidth=2)[0] for axes in (left, right)]
        self.left, self.right = left, right
        self.counts = np.zeros((size, size), dtype=np.int64)

    def vertices(self) -> np.ndarray:
        """A, B, C, D as a (4, 2) array."""
        return np.array([[self.value(f"{label}x"), self.value(f"{label}y")] for label in "abcd"])

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
            f"rule {rule}: {len(first)} + {len(second)} pixels\n"
            f"{doubled} painted twice, {cracks} missed on the shared edge",
            fontsize=9,
        )
        image = blank(shape)
        for triple in ((a, b, c), (a, c, d)):
            pixels, weights = triangle_coverage(*triple, shape, rate, rule=rule)
            paint(image, pixels, 1.0, weight=weights)
        self.coverage.set_data(image)
        self.right.set_title(f"SSAA coverage, {rate} x {rate} samples per pixel", fontsize=9)
        quad = np.array([a, b, c, d, a])
        for outline, shared in zip(self.outlines, self.shared, strict=True):
            outline.set_data(quad[:, 0], quad[:, 1])
            shared.set_data([a[0], c[0]], [a[1], c[1]])
