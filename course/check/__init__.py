"""Exercise checkers: ``check.<exercise>(student_fn)`` returns a CheckResult.

A result is truthy when every case passes; otherwise its message names the
first failing case, its inputs, the expected value and the value given.
"""

from course.check.base import CheckResult

__all__ = ["CheckResult"]

# Lessons 06-07: dithering and filtering.
from course.check.dither import dithering_error_diffuse
from course.check.filters import blur, edge

__all__ += ["blur", "dithering_error_diffuse", "edge"]
