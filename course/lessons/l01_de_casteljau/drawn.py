"""Lesson 01's graded cases: the families of the fixed cases, drawn per submission.

:func:`draw_curve_cases` draws the curves ``recursive_bezier`` and ``next_level`` are graded
on (and lesson 02's ``naive_bezier``), and :func:`draw_bezier_cases` the windows and curves
of the drawing loop ``bezier``, as :mod:`course.check.grading` asks.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course._validate import as_int, as_rng
from course.curves.bezier import de_casteljau
from course.curves.flattening import uniform_parameters
from course.lessons.l01_de_casteljau.drawing_loop import (
    GREY_CASE,
    STEP,
    curve_pixels,
    loop_parameters,
    rounding_sensitive_pixels,
    window_for,
)
from course.lessons.l01_de_casteljau.mistakes import half_up_pixels, wrapped_pixels

__all__ = ["draw_bezier_cases", "draw_curve_cases"]


def draw_curve_cases(rng: Any, max_points: int) -> list[dict[str, Any]]:
    """Graded cases of :func:`curve_cases`' families, drawn from ``rng`` (a numpy Generator).

    The same number of cases, in the same order: an asymmetric quadratic (coordinates in
    [0, 5]), a line (in [0, 10]), a cubic across seed 000's 700 x 700 window, then random
    curves of 5 to ``max_points`` control points in that window, each at five values of t:
    one in [0.1, 0.4) first, 0.5, the ends 0 and 1, and one in [0.6, 0.95). At the first
    case the quadratic's point and next level, run backwards or with x and y swapped, stand
    at least 0.1 apart from the answer, so that every mistake shows there.

    Examples
    --------
    >>> cases = draw_curve_cases(np.random.default_rng(1), max_points=6)
    >>> len(cases), [len(c["control_points"]) for c in cases[::5]]
    (25, [3, 2, 4, 5, 6])
    >>> [c["t"] for c in cases[1:4]]
    [0.5, 0.0, 1.0]
    """
    rng = as_rng(rng)
    max_points = as_int(max_points, "max_points", minimum=2, maximum=100)
    first_t = rng.integers(100, 400) / 1000
    while True:  # rarely more than once
        quadratic = rng.uniform(0, 5, (3, 2)).round(2)
        # The point and the next level, beside the same run backwards and with x and y swapped.
        for points in (quadratic, quadratic[:2], quadratic[1:]):
            point = de_casteljau(points, first_t)
            backwards = de_casteljau(points, 1 - first_t)
            if min(np.hypot(*(point - backwards)), abs(point[0] - point[1])) <= 0.1:
                break
        else:
            break
    polygons = [
        quadratic,
        rng.uniform(0, 10, (2, 2)).round(1),
        rng.uniform(10, 690, (4, 2)).round(1),
        *(rng.uniform(0, 700, (count, 2)).round(1) for count in range(5, max_points + 1)),
    ]
    cases = []
    for number, points in enumerate(polygons):
        first = first_t if number == 0 else rng.integers(100, 400) / 1000
        for t in (first, 0.5, 0.0, 1.0, rng.integers(600, 950) / 1000):
            cases.append({"control_points": points, "t": float(t)})
    return cases


def draw_bezier_cases(rng: Any) -> list[dict[str, Any]]:
    """Graded cases of :data:`~course.lessons.l01_de_casteljau.drawing_loop.BEZIER_SHAPES`'
    families, drawn from ``rng`` (a numpy Generator), each with its window.

    In the same order: a cubic across a 700 x 700 window with a long last leg, on which the
    drawing loop's mistakes each paint pixels of their own (the loop stopped before t = 1,
    float32 t, rounding, rounding half up (a coordinate exactly half-way, as at a control point
    x.5), both, x and y swapped, a step of 0.01); a cubic that leaves a window
    of about 60 x 80 on the left and the right, on which int() before the window test and
    the two wrapped negative indices each paint pixels of their own; a quadratic inside a
    24 x 24 window painted grey; then lines of drawn lengths on the 700 x 700 window's edges,
    either way round: on x = 0, ending at x = width, on y = 0, ending at y = height, and on
    y = -0.5. Each is drawn again until no point of it lies within rounding of a pixel edge
    where its side matters
    (:func:`~course.lessons.l01_de_casteljau.drawing_loop.rounding_sensitive_pixels`).

    Examples
    --------
    >>> cases = draw_bezier_cases(np.random.default_rng(1))
    >>> [case["window"].shape[:2] for case in cases][:3], len(cases)
    ([(700, 700), (59, 77), (24, 24)], 8)
    >>> cases[3]["control_points"][:, 0].tolist(), cases[7]["control_points"][:, 1].tolist()
    ([0.0, 0.0], [-0.5, -0.5])
    """
    rng = as_rng(rng)
    shapes = [(700, 700)]

    def spanning() -> np.ndarray:  # a long last leg: the pixel of t = 1 is its own
        while True:
            points = rng.uniform(10, 690, (4, 2)).round(1)
            if np.hypot(*(points[3] - points[2])) >= 300:
                return points

    every_t = loop_parameters()
    float32_loop = uniform_parameters(STEP, accumulate="float32")
    cubic = _drawn_until_apart(
        spanning,
        shapes[0],
        [
            lambda points, shape: curve_pixels(points, shape, every_t),
            lambda points, shape: curve_pixels(points, shape, float32_loop),
            lambda points, shape: curve_pixels(points, shape, every_t[:-1]),
            lambda points, shape: curve_pixels(points, shape, every_t, "round"),
            lambda points, shape: half_up_pixels(points, np.zeros(shape)),
            lambda points, shape: curve_pixels(points, shape, float32_loop, "round"),
            lambda points, shape: curve_pixels(points, shape[1::-1], every_t)[:, ::-1],
            lambda points, shape: curve_pixels(points, shape, np.arange(101) / 100),
        ],
    )
    height, width = int(rng.integers(50, 71)), int(rng.integers(70, 91))
    shapes.append((height, width))

    def leaving() -> np.ndarray:
        while True:
            points = np.array(
                [
                    [-rng.uniform(15, 30), rng.uniform(0.7, 0.9) * height],
                    [rng.uniform(0.3, 0.45) * width, -rng.uniform(0.5, 0.8) * height],
                    [rng.uniform(0.8, 0.95) * width, rng.uniform(1.3, 1.6) * height],
                    [rng.uniform(1.15, 1.35) * width, rng.uniform(0.25, 0.45) * height],
                ]
            ).round(1)
            curve = de_casteljau(points, every_t)
            if curve[:, 0].min() < -1 and curve[:, 0].max() > width:
                return points

    off_window = _drawn_until_apart(
        leaving,
        shapes[1],
        [
            lambda points, shape: curve_pixels(points, shape, every_t),
            lambda points, shape: curve_pixels(points, shape, every_t, "trunc"),
            lambda points, shape: wrapped_pixels("trunc")(points, np.zeros(shape)),
            lambda points, shape: wrapped_pixels("floor")(points, np.zeros(shape)),
        ],
    )
    shapes.append((24, 24))
    quadratic = _drawn_until_apart(lambda: rng.uniform(1.5, 22.5, (3, 2)).round(1), (24, 24), [])
    polygons = [cubic, off_window, quadratic]

    def either_way(points: list[list[float]]) -> np.ndarray:
        return np.array(points if rng.random() < 0.5 else points[::-1])

    def length(start: float) -> float:
        return round(start + float(rng.uniform(50, 350)), 1)

    def at_x_0() -> np.ndarray:
        top = round(float(rng.uniform(5, 300)), 1)
        return either_way([[0.0, top], [0.0, length(top)]])

    def to_width() -> np.ndarray:  # a row's middle, y + 0.5: clear of the rows' edges
        row = float(rng.integers(20, 680)) + 0.5
        return either_way([[round(float(rng.uniform(550, 680)), 1), row], [700.0, row]])

    def at_y_0() -> np.ndarray:
        left = round(float(rng.uniform(50, 300)), 1)
        return either_way([[left, 0.0], [length(left), 0.0]])

    def to_height() -> np.ndarray:  # a column's middle, x + 0.5
        column = float(rng.integers(50, 650)) + 0.5
        return either_way([[column, round(700 - float(rng.uniform(50, 350)), 1)], [column, 700.0]])

    def at_y_half() -> np.ndarray:
        left = round(float(rng.uniform(110, 360)), 1)
        return either_way([[left, -0.5], [length(left), -0.5]])

    for line in (at_x_0, to_width, at_y_0, to_height, at_y_half):
        polygons.append(_drawn_until_apart(line, (700, 700), []))
        shapes.append((700, 700))
    return [
        {"control_points": points, "window": window_for(shape, grey=number == GREY_CASE)}
        for number, (points, shape) in enumerate(zip(polygons, shapes, strict=True))
    ]


def _drawn_until_apart(
    draw: Callable[[], np.ndarray],
    shape: tuple[int, int],
    paintings: list[Callable[[np.ndarray, tuple[int, int]], np.ndarray]],
) -> np.ndarray:
    """Control points from ``draw``, drawn again until no point of them lies within rounding
    of a pixel edge where its side matters, and the ``paintings`` of them (the reference's
    and mistakes') are pixel sets all different from each other."""
    while True:
        points, seen = draw(), set()
        if rounding_sensitive_pixels(points, shape).size:
            continue
        for painting in paintings:
            pixels = frozenset(map(tuple, painting(points, shape).tolist()))
            if pixels in seen:
                break
            seen.add(pixels)
        else:
            return points
