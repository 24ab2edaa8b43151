"""Lesson 03, lines and triangles: its registry entry, pictures and landmarks."""

from __future__ import annotations

import itertools

import numpy as np

from course.classroom.pictures import (
    BLACK,
    WHITE,
    app_picture,
    clear_point,
    colormap_color,
    landmark_at,
)
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.raster import line, line_4connected, wu_line
from course.widgets.base import SliderApp
from course.widgets.lines_and_triangles import LineApp, TriangleApp


def line_landmarks(app: SliderApp) -> list[Landmark]:
    """Every pixel of the three panels: ``raster.line``, ``line_4connected``, ``wu_line``.

    Bresenham's and the report's pixels black on white, Wu's weights in
    grays; a pixel the report lights and Bresenham does not is named so.
    """
    p0 = (int(app.value("x0")), int(app.value("y0")))
    p1 = (int(app.value("x1")), int(app.value("y1")))
    ideal = np.array([[np.add(p0, 0.5), np.add(p1, 0.5)]])
    bresenham = {tuple(pixel) for pixel in line(p0, p1).tolist()}
    staircase = {tuple(pixel) for pixel in line_4connected(p0, p1).tolist()}
    wu = {}
    for pixel, weight in zip(*wu_line(np.add(p0, 0.5), np.add(p1, 0.5)), strict=True):
        wu[tuple(pixel.tolist())] = min(wu.get(tuple(pixel.tolist()), 0.0) + weight, 1.0)
    grid = app.panels["bresenham"].get_array().shape[0]
    landmarks = []
    for pixel in itertools.product(range(grid), repeat=2):
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


def triangle_picture(rule: str) -> bytes:
    app = TriangleApp()
    app.controls["rule"].value = rule
    return app_picture(app)


LESSON = Lesson(
    handout="Lab 1 report (seed 001), Task 4 (Bresenham's line in every octant) and "
    "Task 5 (scanline triangle filling)",
    teaches="Bresenham's line in all eight octants against the report's 4-connected "
    "staircase; filled triangles with the top-left rule, no cracks and no double paint",
    pictures=(
        Picture(
            "03_line_bresenham_report_wu",
            "the line from (3, 6) to (27, 17): Bresenham, the report's staircase "
            "(|dx| + |dy| + 1 pixels) and Wu's anti-aliased line",
            lambda: app_picture(LineApp()),
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
            build=LineApp,
            control="y1",
            moves=(("ArrowRight",) * 4, ("Home",), ("End",)),
            landmarks=line_landmarks,
        ),
    ),
)
