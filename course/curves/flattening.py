"""Flattening a Bézier curve: which parameters, and so which points, to draw it with.

Two ways to choose them. :func:`uniform_parameters` gives the handouts' fixed
steps, t = 0, step, 2 step, ..., as their C++ loops accumulate them (or
exactly); :func:`course.curves.bezier.sample_uniform` evaluates the curve there.
:func:`flatten` picks its vertices adaptively, as few as keep the polyline
within a tolerance of the curve (the kernel is :mod:`course.curves._flatten`).

The handouts' loops walk the uniform steps (:mod:`~course.curves.bezier_handouts`,
lesson 01's checkers and figures, :mod:`course.antialias.rendering`); the curve's
own pixels (:func:`course.curves.bezier_handouts.curve_pixels`), lesson 01's gaps
figure and :mod:`course.antialias.coverage` take :func:`flatten`'s polyline. Every
function validates its input once and never modifies it.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course._validate import as_choice, as_points, as_positive_float
from course.curves._flatten import flatten_curve
from course.curves._uniform import uniform_steps
from course.limits import require_bounded_flattening, require_step_samples

__all__ = ["flatten", "uniform_parameters"]

# --- uniform steps of t ------------------------------------------------------

_ACCUMULATE = ("exact", "float32", "float64")


def uniform_parameters(step: float, accumulate: str = "exact") -> np.ndarray:
    """The handouts' parameters t = 0, step, 2 step, ... while t <= 1.

    Parameters
    ----------
    step : float
        Spacing, > 0.
    accumulate : {"exact", "float32", "float64"}
        ``"exact"`` gives ``k * step`` and includes t = 1 when 1 / step is
        a whole number. ``"float32"`` and ``"float64"`` reproduce the C++ loop
        ``for (t = 0; t <= 1; t += step)`` with a ``float`` or ``double`` t:
        the rounding errors add up, and the loop usually stops one step short
        of t = 1, so the curve's last point is never drawn.

    Examples
    --------
    >>> uniform_parameters(0.25)
    array([0.  , 0.25, 0.5 , 0.75, 1.  ])
    >>> float(uniform_parameters(0.001, accumulate="float64")[-1])
    0.9990000000000008
    """
    step = as_positive_float(step, "step")
    accumulate = as_choice(accumulate, "accumulate", _ACCUMULATE)
    require_step_samples(step, "step")
    return uniform_steps(step, accumulate)


# --- adaptive flattening -----------------------------------------------------


def flatten(
    points: Any,
    tolerance: float,
    max_step: float | None = None,
    return_parameters: bool = False,
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """An adaptive polyline within ``tolerance`` of the curve, vertices on it.

    Levien's analytic subdivision [1]_ for quadratics, and for cubics through
    quadratics as kurbo does [2]_; each segment's distance to the curve is
    then bounded rigorously (exactly, in the plane, for a piece beside its
    chord), the count lowered while the same spacing passes, and a segment
    beyond the tolerance split (see :mod:`course.curves._flatten`). Degree 4 and up:
    bisection at t = 1/2. On the glyphs and icons that
    ``benchmarks/bench_bezier.py`` measures, no curve gets more segments than
    the best uniform t step.

    Parameters
    ----------
    points : array_like, shape (N, d)
    tolerance : float
        Largest allowed distance from the curve to the polyline, > 0. Points
        and tolerance needing more than :data:`course.limits.MAX_SAMPLES`
        vertices are rejected (Wang's bound), before any is computed.
    max_step : float, optional
        Also split until consecutive vertices are at most this far apart
        (1.0 on pixel coordinates: their pixels leave no gap).
    return_parameters : bool
        Also return each vertex's t (increasing, 0 first and 1 last).

    Returns
    -------
    ndarray, shape (K, d)
        Vertices on the curve from B(0) to B(1), K >= 2 (1 for a degree-0
        curve). With ``return_parameters``, ``(vertices, t)``.

    References
    ----------
    .. [1] R. Levien, "Flattening quadratic Béziers", 2019, https://raphlinus.github.io/
       graphics/curves/2019/12/23/flatten-quadbez.html
    .. [2] kurbo, ``flatten`` in src/bezpath.rs, https://github.com/linebender/kurbo

    Examples
    --------
    >>> vertices, t = flatten([[0, 0], [2, 4], [4, 0]], 0.25, return_parameters=True)
    >>> t.round(3)
    array([0.   , 0.357, 0.643, 1.   ])
    """
    control = as_points(points)
    tolerance = as_positive_float(tolerance, "tolerance")
    limit = np.inf if max_step is None else as_positive_float(max_step, "max_step")
    require_bounded_flattening(control, tolerance, limit)
    vertices, parameters = flatten_curve(control, tolerance, limit)
    return (vertices, parameters) if return_parameters else vertices
