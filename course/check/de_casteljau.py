"""Lesson 01's checker: ``recursive_bezier``, and the curve cases lesson 02 shares.

The exercises of lessons 01 and 02 take ``(control_points, t)``, the
handouts' signature, with ``control_points`` a float array (N, 2) and t one
number, and return the curve point (x, y). The cases run from a straight
line to the handouts' degree-9 curve, at t = 0, t = 1 and in between, so a
reversed convention fails at the first asymmetric case.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.bezier import de_casteljau
from course.check.base import CheckResult, close, run_cases
from course.images import SEED_000_CUBIC

__all__ = ["as_point", "curve_cases", "positional", "recursive_bezier"]


def curve_cases(max_points: int) -> list[dict[str, Any]]:
    """Curves of 2 to ``max_points`` control points, each at five values of t."""
    rng = np.random.default_rng(2024)
    polygons = [
        np.array([[0.0, 0.0], [4.0, 2.0]]),
        np.array([[0.0, 0.0], [1.0, 2.0], [4.0, 0.0]]),
        SEED_000_CUBIC.copy(),
    ]
    polygons += [rng.uniform(0, 700, (count, 2)).round(1) for count in range(5, max_points + 1)]
    cases = []
    for points in polygons:
        for t in (0.5, 0.0, 1.0, 0.25, 0.8):
            cases.append({"control_points": points, "t": t})
    return cases


def as_point(value: Any) -> np.ndarray:
    """A student's point, whatever its container, as a flat float array."""
    return np.asarray(value, dtype=float).reshape(-1)


def positional(function: Callable[..., Any]) -> Callable[..., Any]:
    """Call with positional arguments, so the student may name them as they like."""
    if not callable(function):
        return function  # run_cases reports it
    return lambda control_points, t: function(control_points, t)


def recursive_bezier(function: Callable[..., Any]) -> CheckResult:
    """Check a student's de Casteljau ``recursive_bezier(control_points, t)``.

    Compared with :func:`course.bezier.de_casteljau` on curves of 2 to 10
    control points, to 1e-9.

    Examples
    --------
    >>> from course.bezier import de_casteljau
    >>> recursive_bezier(lambda control_points, t: de_casteljau(control_points, t))
    PASS recursive_bezier: all 45 cases pass
    """
    return run_cases(
        "recursive_bezier",
        positional(function),
        curve_cases(max_points=10),
        reference=lambda control_points, t: de_casteljau(control_points, t),
        compare=close(atol=1e-9, rtol=1e-9),
        convert=as_point,
    )
