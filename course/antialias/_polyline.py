"""A checked curve flattened for the exact reference and the measures: pure array code.

Nothing here checks its input (``UNCHECKED = True``): ``control`` is a finite
float ``(N, 2)`` curve, ``tolerance`` a float > 0 and ``max_step`` a float > 0
or ``inf``, for which :func:`course.limits.require_bounded_flattening` passed,
as :func:`course.antialias.coverage.curve_polyline` makes sure before it calls
:func:`flattened`. :mod:`course.antialias.curve_quality` flattens its checked
curves here too.
"""

from __future__ import annotations

import numpy as np

from course.curves._flatten import flatten_curve

__all__ = ["flattened"]

UNCHECKED = True  # kernels for checked callers; see the module docstring


def flattened(control: np.ndarray, tolerance: float, max_step: float) -> np.ndarray:
    """The curve as a polyline within ``tolerance`` of it, segments <= ``max_step``.

    Examples
    --------
    >>> flattened(np.array([[0.0, 0.0], [2.0, 0.0]]), 0.1, 1.0)
    array([[0., 0.],
           [1., 0.],
           [2., 0.]])
    """
    line, _parameters = flatten_curve(control, tolerance, max_step)
    if len(line) == 1:  # a single point: a zero-length segment keeps the caps
        line = np.vstack([line, line])
    return line
