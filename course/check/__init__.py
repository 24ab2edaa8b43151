"""Exercise checkers: ``check.<exercise>(student_fn)`` returns a CheckResult.

A result is truthy when every case passes; otherwise its message names the
first failing case, its inputs, the expected value and the value given.
"""

from course.check.base import CheckResult

__all__ = ["CheckResult"]

# Lesson 08: Poisson image editing.
from course.check.poisson import poisson_boundary

__all__ += ["poisson_boundary"]
