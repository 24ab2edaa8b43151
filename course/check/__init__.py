"""Exercise checkers: ``check.<exercise>(student_fn)`` returns a CheckResult.

A result is truthy when every case passes; otherwise its message names the
first failing case, its inputs, the expected value and the value given.
"""

from course.check.antialias import bilinear_splat
from course.check.base import CheckResult
from course.check.bezier import naive_bezier, recursive_bezier
from course.check.dither import dithering_error_diffuse
from course.check.filters import blur, edge
from course.check.poisson import poisson_boundary
from course.check.raster import draw_line, draw_triangle_filled
from course.check.resample import image_supersampling

__all__ = [
    "CheckResult",
    "bilinear_splat",
    "blur",
    "dithering_error_diffuse",
    "draw_line",
    "draw_triangle_filled",
    "edge",
    "image_supersampling",
    "naive_bezier",
    "poisson_boundary",
    "recursive_bezier",
]
