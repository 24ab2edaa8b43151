"""Exercise checkers: ``check.<exercise>(student_fn)`` returns a CheckResult.

A result is truthy when every case passes; otherwise its message names the
first failing case, its inputs, the expected value and the value given.
"""

from course.check.base import CheckResult

__all__ = ["CheckResult"]

# Lessons 01-02: Bézier curves.
from course.check.bezier import naive_bezier, recursive_bezier

__all__ += ["naive_bezier", "recursive_bezier"]
