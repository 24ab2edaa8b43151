"""Bézier curves: de Casteljau's algorithm, the Bernstein form, whole paths.

The handouts' own code is kept as written in :mod:`~course.curves.bezier_handouts`, and
:mod:`~course.curves.bezier_accuracy` measures each form in floating point. The fast
kernels (``_bezier_fast``, ``_flatten``) are unchecked: only :mod:`~course.curves.bezier`
calls them, on validated input.

The public names of :mod:`~course.curves.bezier` are importable from here too.
"""

from course.curves import bezier
from course.curves.bezier import *  # noqa: F403 (the names bezier.__all__ lists)

__all__ = list(bezier.__all__)
