"""Points and curves: point lists, curves, curve parameters, and what they may cost.

Part of :mod:`course._validate`, which re-exports every name. The ``require_bounded_*``
checks bound the work a curve asks for (vertices, samples, interpolations) before any
is done; :func:`as_flattening` checks a flattening's tolerance and step with it, in one
call.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course._validate.arrays import as_float_array, require_finite, require_within
from course._validate.scalars import as_positive_float
from course.i18n import N_, _

__all__ = [
    "as_app_points",
    "as_curve",
    "as_figure_curve",
    "as_flattening",
    "as_parameter",
    "as_point",
    "as_points",
    "as_scalar_parameter",
    "require_bounded_evaluation",
    "require_bounded_flattening",
    "require_step_samples",
]


def as_points(points: Any, name: str = "points", bound: float | None = None) -> np.ndarray:
    """Validate a point list: a finite float ``(N, d)`` array, N >= 1, d >= 1.

    With ``bound``, every coordinate must also lie within ``[-bound, bound]``.
    Returns a new float64 array, so callers may work on it freely.
    """
    array = as_float_array(points, name)
    if array.ndim != 2:
        if array.ndim == 1 and array.size:
            message = _(
                "{name} must be a 2-D array of shape (N, d), one row per point; got shape "
                "{shape}; a flat list of numbers is missing its second axis, e.g. "
                "{name}.reshape(-1, 2) for 2-D points"
            )
        else:
            message = _(
                "{name} must be a 2-D array of shape (N, d), one row per point; got shape {shape}"
            )
        raise ValueError(message.format(name=name, shape=array.shape))
    if array.shape[0] == 0:
        raise ValueError(
            _("{name} must hold at least one point (N >= 1); got shape {shape}").format(
                name=name, shape=array.shape
            )
        )
    if array.shape[1] == 0:
        raise ValueError(
            _(
                "{name} must have at least one coordinate per point (d >= 1); got shape {shape}"
            ).format(name=name, shape=array.shape)
        )
    require_finite(array, name)
    if array.shape[0] > limits.MAX_SAMPLES:
        raise ValueError(
            _("{name} must hold at most {limit} points; got {count}").format(
                name=name, limit=limits.MAX_SAMPLES, count=len(array)
            )
        )
    if bound is not None:
        require_within(array, name, bound)
    return array


def as_curve(points: Any, name: str = "points") -> np.ndarray:
    """Validate control points of a curve in image space: finite, shape (N, 2).

    Coordinates must lie within ``limits.MAX_COORDINATE`` of the origin.
    """
    control = as_points(points, name, bound=limits.MAX_COORDINATE)
    if control.shape[1] != 2:
        raise ValueError(
            _(
                "{name} must have shape (N, 2): (x, y) control points in image space; got shape "
                "{shape}"
            ).format(name=name, shape=control.shape)
        )
    return control


def as_figure_curve(points: Any, name: str = "points") -> np.ndarray:
    """:func:`as_curve` for a figure that draws and labels every control point: at most
    ``limits.MAX_FIGURE_POINTS`` of them.

    Examples
    --------
    >>> as_figure_curve([[0, 0], [1, 2]]).shape
    (2, 2)
    """
    control = as_curve(points, name)
    if len(control) > limits.MAX_FIGURE_POINTS:
        raise ValueError(
            _(
                "{name} must hold at most {limit} control points for a figure that draws each of "
                "them; got {count}"
            ).format(name=name, limit=limits.MAX_FIGURE_POINTS, count=len(control))
        )
    return control


def as_point(
    point: Any, name: str, dim: int | None = None, bound: float | None = None
) -> np.ndarray:
    """Validate one point: a finite float ``(d,)`` array, within ``bound`` if given."""
    array = as_float_array(point, name)
    if array.ndim != 1 or array.size == 0 or (dim is not None and array.size != dim):
        expected = f"({dim},)" if dim is not None else "(d,)"
        raise ValueError(
            _("{name} must be one point of shape {expected}; got shape {shape}").format(
                name=name, expected=expected, shape=array.shape
            )
        )
    require_finite(array, name)
    if bound is not None:
        require_within(array, name, bound)
    return array


def as_parameter(t: Any, name: str = "t") -> tuple[np.ndarray, bool]:
    """Validate a curve parameter: a finite scalar or 1-D array within ``+-MAX_PARAMETER``.

    Returns ``(values, is_scalar)`` with ``values`` a 1-D float64 array.
    """
    array = as_float_array(t, name)
    if array.ndim > 1:
        raise ValueError(
            _("{name} must be a scalar or a 1-D array; got shape {shape}").format(
                name=name, shape=array.shape
            )
        )
    require_finite(array, name)
    require_within(array, name, limits.MAX_PARAMETER, N_("values"))
    if array.size > limits.MAX_SAMPLES:
        raise ValueError(
            _("{name} must hold at most {limit} values; got {count}").format(
                name=name, limit=limits.MAX_SAMPLES, count=array.size
            )
        )
    return np.atleast_1d(array), array.ndim == 0


def as_scalar_parameter(t: Any, name: str = "t") -> float:
    """Validate a single finite real number."""
    values, is_scalar = as_parameter(t, name)
    if not is_scalar:
        raise ValueError(
            _("{name} must be a single number; got an array of shape {shape}").format(
                name=name, shape=values.shape
            )
        )
    return float(values[0])


def as_app_points(
    value: Any,
    name: str,
    count: int | None = None,
    low: float = -limits.MAX_COORDINATE,
    high: float = limits.MAX_COORDINATE,
    whole: bool = False,
) -> np.ndarray:
    """Validate points given to an app's constructor: the bounds its text box enforces.

    Examples
    --------
    >>> as_app_points([(1, 2), (3, 4)], "p", count=2, low=0, high=9).tolist()
    [[1.0, 2.0], [3.0, 4.0]]
    """
    points = as_points(value, name)
    if points.shape[1] != 2 or (count is not None and len(points) != count):
        expected = f"({count}, 2)" if count is not None else "(N, 2)"
        raise ValueError(
            _("{name} must have shape {expected}, (x, y) rows; got {shape}").format(
                name=name, expected=expected, shape=points.shape
            )
        )
    if whole and (points != np.round(points)).any():
        raise ValueError(
            _("{name} must be whole pixels; got {value}").format(name=name, value=points.tolist())
        )
    if points.min() < low or points.max() > high:
        raise ValueError(
            _("{name} must lie from {low:g} to {high:g}; got {value}").format(
                name=name, low=low, high=high, value=points.tolist()
            )
        )
    return points


def require_bounded_flattening(control: np.ndarray, tolerance: float, max_step: float) -> None:
    """ValueError unless flattening needs at most ``limits.MAX_SAMPLES`` vertices.

    Wang's formula bounds the segments needed for ``tolerance``; the control
    polygon's length over ``max_step`` bounds those needed for ``max_step``.
    """
    degree = len(control) - 1
    with np.errstate(over="ignore", invalid="ignore"):
        needed = 1.0
        if degree >= 2:
            second = np.linalg.norm(np.diff(control, n=2, axis=0), axis=1).max()
            needed = max(needed, np.sqrt(degree * (degree - 1) * second / (8 * tolerance)))
        if degree >= 1 and np.isfinite(max_step):
            length = np.linalg.norm(np.diff(control, axis=0), axis=1).sum()
            needed = max(needed, length / max_step)
    if not needed <= limits.MAX_SAMPLES:
        raise ValueError(
            _(
                "points, tolerance and max_step would need about {needed:.3g} vertices, more than "
                "the {limit} allowed; raise tolerance (or max_step), or bring the control points "
                "closer together"
            ).format(needed=needed, limit=limits.MAX_SAMPLES)
        )
    # Degree 4 and up is evaluated by de Casteljau, (degree + 1)**2 / 2 steps a vertex.
    if degree >= 4 and not needed * (degree + 1) ** 2 <= limits.MAX_EVALUATION_WORK:
        raise ValueError(
            _(
                "points: a curve of {count} control points within this tolerance would need about "
                "{needed:.3g} vertices of {work} interpolations each, more than the {limit} "
                "allowed; split the curve into pieces of low degree, or raise tolerance"
            ).format(
                count=degree + 1,
                needed=needed,
                work=(degree + 1) ** 2,
                limit=limits.MAX_EVALUATION_WORK,
            )
        )


def as_flattening(control: np.ndarray, tolerance: Any, max_step: Any = None) -> tuple[float, float]:
    """``(tolerance, max_step)`` for flattening the checked curve ``control``, in one check.

    Both must be real numbers > 0 (``max_step`` None is no limit: ``inf``), and
    :func:`require_bounded_flattening` must pass for them.

    Examples
    --------
    >>> as_flattening(np.array([[0.0, 0.0], [4.0, 0.0]]), 0.25)
    (0.25, inf)
    """
    tolerance = as_positive_float(tolerance, "tolerance")
    limit = np.inf if max_step is None else as_positive_float(max_step, "max_step")
    require_bounded_flattening(control, tolerance, limit)
    return tolerance, limit


def require_step_samples(step: float, name: str = "step", curves: int = 1) -> None:
    """ValueError unless a t step gives at most ``limits.MAX_STEP_SAMPLES`` samples in all.

    ``curves`` curves are each sampled at t = 0, step, 2 step, ... <= 1.
    """
    count = (np.floor(1 / step * (1 + 1e-12)) + 2) * curves
    if count > limits.MAX_STEP_SAMPLES:
        per_curve = _(" over {curves} curves").format(curves=curves) if curves > 1 else ""
        room = limits.MAX_STEP_SAMPLES / curves - 2
        smallest = _(", a step of at least {step:.3g}").format(step=1 / room) if room >= 1 else ""
        raise ValueError(
            _(
                "{name} must give at most {limit} samples{per_curve}{smallest}; got {step:g}, "
                "which gives about {count:.3g}"
            ).format(
                name=name,
                limit=limits.MAX_STEP_SAMPLES,
                per_curve=per_curve,
                smallest=smallest,
                step=step,
                count=count,
            )
        )


def require_bounded_evaluation(points: int, samples: int, name: str = "points") -> None:
    """ValueError unless ``samples`` evaluations of a curve of ``points`` control points fit
    ``limits.MAX_EVALUATION_WORK`` interpolations (de Casteljau's (N + 1)**2 / 2 per sample)."""
    work = float(samples) * points**2
    if work > limits.MAX_EVALUATION_WORK:
        raise ValueError(
            _(
                "{name}: {samples} samples of a curve of {points} control points would take about "
                "{work:.3g} interpolations, more than the {limit} allowed; split the curve into "
                "pieces of low degree, or raise the tolerance or step"
            ).format(
                name=name,
                samples=samples,
                points=points,
                work=work,
                limit=limits.MAX_EVALUATION_WORK,
            )
        )
