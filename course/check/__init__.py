"""Exercise checkers: ``check.<exercise>(student_fn)`` returns a CheckResult.

A result is truthy when every case passes; otherwise its message names the
first failing case, its inputs, the expected value and the value given.
"""

from course.check.antialias import bilinear_splat  # lesson 03
from course.check.base import CheckResult

__all__ = ["CheckResult"]
# lesson 03
__all__ += ["bilinear_splat"]
