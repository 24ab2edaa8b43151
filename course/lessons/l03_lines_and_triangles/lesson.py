"""Lesson 03, lines and triangles: its registry entry, pictures, landmarks and printed lines.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

import itertools
from typing import Any

import numpy as np
from matplotlib.colors import to_rgb

from course._validate import as_choice
from course.classroom.pictures import (
    BLACK,
    WHITE,
    app_picture,
    clear_point,
    colormap_color,
    landmark_at,
    panel_picture,
    still_picture,
)
from course.classroom.registry import DragMove, Landmark, Lesson, Picture, SliderMove
from course.i18n import N_, _
from course.lessons.l03_lines_and_triangles import figures
from course.lessons.l03_lines_and_triangles.apps import (
    OWNER_COLORS,
    TRIANGLE_GRID,
    CurveSegmentsApp,
    LineApp,
    TriangleApp,
)
from course.lessons.printed import title_on_one_line as title_on_one_line  # the notebook's
from course.raster import hit_counts, line, line_4connected, triangle, triangle_coverage, wu_line
from course.raster.triangles import EDGE_RULES
from course.widgets.base import SliderApp
from course.widgets.picture import Still

UNCHECKED = True  # see the module docstring

#: The caption of the lesson's opening picture.
OPENING_CAPTION = N_("two triangles sharing an edge, and their 4 x 4 supersampled coverage")
#: The lines the lesson counts pixels of, as the notebook names them.
LINE_NAMES = (N_("Bresenham"), N_("report's loop"), N_("Wu"))


def opening_still() -> Still:
    """The lesson's opening picture: :class:`TriangleApp`, captioned in the current language."""
    return TriangleApp().still(_(OPENING_CAPTION))


def print_lines_agree(lines: int, agree: int) -> None:
    """Print on how many of ``lines`` lines the vectorized and the loop form agree.

    Examples
    --------
    >>> print_lines_agree(256, 256)
    256 lines: the forms agree on 256
    """
    print(_("{lines} lines: the forms agree on {agree}").format(lines=lines, agree=agree))


def print_triangles_agree(agree: int, triangles: int) -> None:
    """Print on how many of ``triangles`` triangles the two forms agree.

    Examples
    --------
    >>> print_triangles_agree(9, 10)
    the two forms agree on 9 of 10 triangles
    """
    print(
        _("the two forms agree on {agree} of {triangles} triangles").format(
            agree=agree, triangles=triangles
        )
    )


def print_ink_per_column(image: np.ndarray) -> None:
    """Print the ink of each column of ``image`` (rows summed), to 3 decimals.

    Examples
    --------
    >>> print_ink_per_column(np.array([[0.25, 1.0], [0.25, 0.0]]))
    ink per column: [0.5 1. ]
    """
    ink = np.asarray(image).sum(axis=0).round(3)
    print(_("ink per column: {ink}").format(ink=ink))


def print_exact_area(area: float, edge_pixels: int) -> None:
    """Print a triangle's exact area and how many pixels its edges cross.

    Examples
    --------
    >>> print_exact_area(63.0249, 47)
    exact area 63.025; 47 edge pixels
    """
    print(
        _("exact area {area:.3f}; {edge_pixels} edge pixels").format(
            area=area, edge_pixels=edge_pixels
        )
    )


def print_coverage_error(rate: int, rms: float, worst: float, total: float) -> None:
    """Print one supersampling rate's coverage error on the edge pixels and its total ink.

    Examples
    --------
    >>> print_coverage_error(4, 0.02114, 0.0521, 63.0625)
    rate  4: RMS 0.0211, worst 0.052, total 63.0625
    """
    print(
        _("rate {rate:>2}: RMS {rms:.4f}, worst {worst:.3f}, total {total:.4f}").format(
            rate=rate, rms=rms, worst=worst, total=total
        )
    )


def print_line_ends(p0: Any, p1: Any) -> None:
    """Print the heading of a line's pixel counts: its two end pixels.

    Examples
    --------
    >>> print_line_ends((3, 6), (27, 17))
    from (3, 6) to (27, 17):
    """
    start, end = (tuple(int(v) for v in point) for point in (p0, p1))
    print(_("from {start} to {end}:").format(start=start, end=end))


def print_line_pixels(name: str, pixels: int, farthest: float | None = None) -> None:
    """Print how many pixels a line drawn by ``name`` lights, and how far its farthest centre is.

    ``name`` is one of :data:`LINE_NAMES`, shown in the current language; ``farthest``
    (in pixels, from the ideal line) is left out when None.

    Examples
    --------
    >>> print_line_pixels("Bresenham", 11, 0.0)
    Bresenham: 11 pixels, farthest centre 0.00 px from the line
    >>> print_line_pixels("Wu", 11)
    Wu: 11 pixels
    """
    if farthest is None:
        print(_("{name}: {pixels} pixels").format(name=_(name), pixels=pixels))
        return
    print(
        _("{name}: {pixels} pixels, farthest centre {farthest:.2f} px from the line").format(
            name=_(name), pixels=pixels, farthest=farthest
        )
    )


def print_segments_report(segments: int, report: dict[str, int]) -> None:
    """Print a curve drawn as ``segments`` Bresenham segments: pixels missed, off and twice.

    ``report`` is :func:`course.curves.bezier_handouts.segments_report`'s.

    Examples
    --------
    >>> print_segments_report(4, {"missed": 0, "off": 28, "twice": 3})
     4 segments: missed 0, off 28, twice 3
    """
    print(
        _("{segments:>2} segments: missed {missed}, off {off}, twice {twice}").format(
            segments=segments, missed=report["missed"], off=report["off"], twice=report["twice"]
        )
    )


def line_landmarks(app: SliderApp) -> list[Landmark]:
    """Every pixel of the three panels: ``raster.line``, ``line_4connected``, ``wu_line``.

    Bresenham's and the report's pixels black on white, Wu's weights in
    grays; a pixel the report lights and Bresenham does not is named so.
    """
    p0, p1 = app.endpoints()
    ideal = np.array([[np.add(p0, 0.5), np.add(p1, 0.5)]])
    bresenham = {tuple(pixel) for pixel in line(p0, p1).tolist()}
    staircase = {tuple(pixel) for pixel in line_4connected(p0, p1).tolist()}
    wu = {}
    for pixel, weight in zip(*wu_line(np.add(p0, 0.5), np.add(p1, 0.5)), strict=True):
        wu[tuple(pixel.tolist())] = min(wu.get(tuple(pixel.tolist()), 0.0) + weight, 1.0)
    grid = app.panels["bresenham"].get_array().shape[0]
    landmarks = []
    for pixel in itertools.product(range(grid), repeat=2):
        if min(np.hypot(*np.subtract(pixel, end)) for end in (p0, p1)) < 1.5:
            continue  # under the end's dot
        point = clear_point(*pixel, ideal)
        drawn = pixel in bresenham
        if drawn:
            role = f"line({p0}, {p1}) pixel {pixel}"
        elif pixel in staircase:
            role = f"not a Bresenham pixel, yet in the report's loop: {pixel}"
        else:
            role = f"background {pixel}"
        for panel, color, what in (
            ("bresenham", BLACK if drawn else WHITE, role),
            ("report", BLACK if pixel in staircase else WHITE, f"line_4connected {pixel}"),
            ("wu", colormap_color("Greys", wu.get(pixel, 0.0)), f"wu_line {pixel}"),
        ):
            landmarks.append(landmark_at(app, app.panels[panel].axes, point, color, what))
    return landmarks


def _triangle_pixels(app: SliderApp) -> list[tuple[tuple[int, int], tuple[float, float]]]:
    """Each pixel of the 16 x 16 grid, and a point in it clear of the outlines and labels."""
    corners = app.vertices()
    a, _, c, _ = corners
    outline = np.array([[corners[i], corners[(i + 1) % 4]] for i in range(4)] + [[a, c]])
    pixels = []
    for column, row in itertools.product(range(TRIANGLE_GRID), repeat=2):
        if np.hypot(*(corners - (column + 0.5, row + 0.5)).T).min() < 2.0:
            continue  # a vertex's label or highlight may cover it
        pixels.append(((column, row), clear_point(column, row, outline)))
    return pixels


def triangle_landmarks(app: SliderApp) -> list[Landmark]:
    """Left panel: who paints each pixel, by ``raster.triangle`` with the app's rule."""
    a, b, c, d = app.vertices()
    shape = (TRIANGLE_GRID, TRIANGLE_GRID)
    rule = app.value("rule")
    first = hit_counts([triangle(a, b, c, shape=shape, rule=rule)], shape) > 0
    second = hit_counts([triangle(a, c, d, shape=shape, rule=rule)], shape) > 0
    owners = np.where(first & second, 3, first + 2 * second)
    names = ("nobody", "ABC", "ACD", "both")
    landmarks = []
    for (column, row), point in _triangle_pixels(app):
        owner = int(owners[row, column])
        color = tuple(round(channel * 255) for channel in to_rgb(OWNER_COLORS[owner]))
        what = f"triangle({rule}) pixel ({column}, {row}) painted by {names[owner]}"
        landmarks.append(landmark_at(app, app.left, point, color, what))
    return landmarks


def coverage_landmarks(app: SliderApp) -> list[Landmark]:
    """Right panel: each pixel's coverage by ``raster.triangle_coverage`` at the app's rate."""
    a, b, c, d = app.vertices()
    shape = (TRIANGLE_GRID, TRIANGLE_GRID)
    rule, rate = app.value("rule"), int(app.value("rate"))
    coverage = np.zeros(shape)
    for triple in ((a, b, c), (a, c, d)):
        pixels, weights = triangle_coverage(*triple, shape, rate, rule=rule)
        np.add.at(coverage, (pixels[:, 1], pixels[:, 0]), weights)
    coverage = np.minimum(coverage, 1.0)
    landmarks = []
    for (column, row), point in _triangle_pixels(app):
        value = float(coverage[row, column])
        what = f"coverage at rate {rate}, pixel ({column}, {row}) = {value:.3f}"
        color = colormap_color("Greys", value)
        # Tolerance 2: the rates next to each other differ by a few grey levels.
        landmarks.append(landmark_at(app, app.right, point, color, what, 2))
    return landmarks


def triangle_picture(rule: str) -> bytes:
    rule = as_choice(rule, "rule", EDGE_RULES)
    app = TriangleApp()
    app.controls["rule"].value = rule
    return app_picture(app)


def preview() -> bytes:
    """The course map's preview: two triangles sharing an edge, filled by the top-left rule."""
    app = TriangleApp()
    return panel_picture(app, app.left)


LESSON = Lesson(
    outcomes=(
        N_("draw a line with Bresenham's algorithm in all eight directions (the lab's DrawLine)"),
        N_(
            "fill a triangle row by row, taking each shared edge's pixels once (DrawTriangleFilled)"
        ),
        N_("interpolate a colour across a triangle with barycentric weights"),
    ),
    minutes=60,
    preview=Picture(
        "03_preview", "two triangles sharing an edge, filled by the top-left rule", preview
    ),
    handout=N_(
        "the lab report (Lab01 Report), Task 4 (Bresenham's line in every octant), Task 5 "
        "(scanline triangle filling) and Task 7 (the Bézier curve drawn with lines)"
    ),
    teaches=N_(
        "Bresenham's line in all eight octants, written and checked, against the report's "
        "4-connected staircase; the scanline fill in flat-top and flat-bottom halves, written and "
        "checked; the top-left rule on shared edges; barycentric colour; a curve as segments"
    ),
    pictures=(
        still_picture(
            "03_scanline_fill",
            "a triangle filled row by row, in a flat-bottom and a flat-top half",
            figures.scanline_figure,
        ),
        still_picture(
            "03_edge_rules",
            "two triangles sharing a diagonal through pixel centres, with each edge rule",
            figures.edge_rules_figure,
        ),
        still_picture(
            "03_barycentric_colour",
            "red, green and blue at the corners, mixed at every pixel centre",
            figures.colour_figure,
        ),
        Picture(
            "03_line_bresenham_report_wu",
            "the line from (3, 6) to (27, 17): Bresenham, the report's staircase "
            "(|dx| + |dy| + 1 pixels) and Wu's anti-aliased line",
            lambda: app_picture(LineApp()),
        ),
        Picture(
            "03_curve_as_4_segments",
            "a cubic drawn as 4 Bresenham segments on a 40 x 40 grid: where the chords "
            "stray off the curve, and how that falls with more segments while the joints "
            "are drawn twice",
            lambda: app_picture(CurveSegmentsApp()),
        ),
        Picture(
            "03_triangles_top_left",
            "two triangles sharing an edge, filled with the top-left rule: every "
            "pixel painted once; right, 4 x 4 supersampled coverage",
            lambda: triangle_picture("top-left"),
        ),
        Picture(
            "03_triangles_closed",
            "the same triangles with the closed rule: the pixels whose centres lie on "
            "the shared edge are painted twice (red)",
            lambda: triangle_picture("closed"),
        ),
    ),
    sliders=(
        SliderMove(
            build=TriangleApp,
            control="rate",
            moves=(("ArrowLeft", "ArrowLeft"), ("Home",), ("End",)),
            landmarks=coverage_landmarks,
            app=1,
        ),
    ),
    drags=(
        DragMove(
            build=LineApp,
            handle="p1",
            path=((-20, 15), (-60, 50), (-110, 90)),
            landmarks=line_landmarks,
        ),
        DragMove(
            build=TriangleApp,
            handle="B",
            path=((-20, 10), (-50, 40), (-70, 55)),
            landmarks=triangle_landmarks,
            app=1,
        ),
    ),
)
