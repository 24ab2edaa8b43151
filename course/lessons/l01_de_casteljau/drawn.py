"""Lesson 01's graded cases: the families of the fixed cases, drawn per submission.

:func:`draw_curve_cases` draws the curves ``recursive_bezier`` and ``next_level`` are graded
on (and lesson 02's ``naive_bezier``), as :mod:`course.check.grading` asks.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course._validate import as_int, as_rng
from course.curves.bezier import de_casteljau

__all__ = ["draw_curve_cases"]


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
