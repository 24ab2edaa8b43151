"""Bézier curves: de Casteljau's algorithm, the Bernstein form, whole paths.

The handouts' own code is kept as written in :mod:`~course.curves.bezier_handouts`, and
:mod:`~course.curves.bezier_accuracy` measures each form in floating point. The kernels
(``_bernstein``, ``_bezier_fast``, ``_flatten``, ``_uniform``, ``_handouts``) are unchecked:
the public functions of this package call them on input they have validated.

The public names of :mod:`~course.curves.bezier` and :mod:`~course.curves.flattening` are
importable from here too.
"""

from course.curves import bezier, flattening
from course.curves.bezier import *  # noqa: F403 (the names bezier.__all__ lists)
from course.curves.flattening import *  # noqa: F403 (the names flattening.__all__ lists)

__all__ = [*bezier.__all__, *flattening.__all__]
