"""Lesson 02's checker: ``naive_bezier``, the Bernstein form of any degree."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from course.bezier import bezier_bernstein
from course.check.base import CheckResult, close, run_cases
from course.check.de_casteljau import as_point, curve_cases, positional

__all__ = ["naive_bezier"]


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
        positional(function),
        curve_cases(max_points=12),
        reference=lambda control_points, t: bezier_bernstein(control_points, t),
        compare=close(atol=1e-9, rtol=1e-9),
        convert=as_point,
    )
