"""Checkers for lessons 01 and 02: ``recursive_bezier`` and ``naive_bezier``.

Both exercises take ``(control_points, t)``, the handouts' signature, with
``control_points`` a float array (N, 2) and t one number, and return the
curve point (x, y). The cases run from a straight line to the handouts'
degree-9 curve, at t = 0, t = 1 and in between, so a reversed convention
fails at the first asymmetric case.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.bezier import bezier_bernstein, de_casteljau
from course.check.base import CheckResult, close, run_cases
from course.images import SEED_000_CUBIC

__all__ = ["naive_bezier", "recursive_bezier"]


def _cases(max_points: int) -> list[dict[str, Any]]:
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


def _as_point(value: Any) -> np.ndarray:
    return np.asarray(value, dtype=float).reshape(-1)


def _positional(function: Callable[..., Any]) -> Callable[..., Any]:
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
        _positional(function),
        _cases(max_points=10),
        reference=lambda control_points, t: de_casteljau(control_points, t),
        compare=close(atol=1e-9, rtol=1e-9),
        convert=_as_point,
    )


def naive_bezier(function: Callable[..., Any]) -> CheckResult:
    """Check a student's Bernstein-form ``naive_bezier(control_points, t)`` of any degree.

    Compared with :func:`course.bezier.bezier_bernstein` on curves of 2 to
    12 control points, to 1e-9.

    Examples
    --------
    >>> from course.bezier import bezier_bernstein
    >>> naive_bezier(lambda control_points, t: bezier_bernstein(control_points, t))
    PASS naive_bezier: all 55 cases pass
    """
    return run_cases(
        "naive_bezier",
        _positional(function),
        _cases(max_points=12),
        reference=lambda control_points, t: bezier_bernstein(control_points, t),
        compare=close(atol=1e-9, rtol=1e-9),
        convert=_as_point,
    )
