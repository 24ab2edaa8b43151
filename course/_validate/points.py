"""Points and curves: point lists, curves, curve parameters, and what they may cost.

Part of :mod:`course._validate`, which re-exports every name. :func:`as_flattening`
checks a flattening's tolerance and step, and the work they ask for
(:func:`course.limits.require_bounded_flattening`), in one call.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.path import Path

from course import limits
from course._validate.arrays import as_float_array, require_finite, require_within
from course._validate.scalars import as_positive_float
from course.i18n import N_, _
from course.limits import require_bounded_flattening

__all__ = [
    "as_app_points",
    "as_curve",
    "as_figure_curve",
    "as_flattening",
    "as_parameter",
    "as_path_arrays",
    "as_point",
    "as_points",
    "as_scalar_parameter",
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


_CODE_NAMES = "MOVETO (1), LINETO (2), CURVE3 (3), CURVE4 (4), CLOSEPOLY (79) or STOP (0)"


def as_path_arrays(
    path: Path, name: str = "points", height: float | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """A ``matplotlib.path.Path``'s vertices (a float copy, cut at STOP; y flipped to
    ``height - y`` with a checked ``height``) and codes, in one check.

    The vertices are real numbers of shape (V, 2), the codes one known code per vertex,
    starting with MOVETO, CURVE3 runs in pairs and CURVE4 runs in threes; every vertex but
    a CLOSEPOLY's (which is ignored, whatever it holds) is finite, and every vertex a curve
    is drawn through is, once flipped, within ``limits.MAX_COORDINATE``.

    Examples
    --------
    >>> vertices, codes = as_path_arrays(Path([[0, 0], [2, 0], [0, 0]], [1, 2, 79]), height=4)
    >>> vertices.tolist(), codes.tolist()
    ([[0.0, 4.0], [2.0, 4.0], [0.0, 4.0]], [1, 2, 79])
    """
    vertices = as_float_array(path.vertices, f"{name}.vertices")
    if vertices.ndim != 2 or vertices.shape[1] != 2:
        raise ValueError(
            _(
                "{name}.vertices must have shape (V, 2) in the plane; got shape {vertices_shape}"
            ).format(name=name, vertices_shape=vertices.shape)
        )
    codes = path.codes
    if codes is None:
        codes = np.full(len(vertices), Path.LINETO, dtype=np.uint8)
        codes[:1] = Path.MOVETO
    codes = np.asarray(codes)
    if codes.shape != (len(vertices),):
        raise ValueError(
            _(
                "{name}.codes must have shape ({vertices_count},), one code per vertex; got shape "
                "{codes_shape}"
            ).format(name=name, vertices_count=len(vertices), codes_shape=codes.shape)
        )
    stop = np.flatnonzero(codes == Path.STOP)
    if len(stop):
        vertices, codes = vertices[: stop[0]], codes[: stop[0]]
    if len(codes) == 0:
        return vertices, codes
    known = np.isin(codes, [Path.MOVETO, Path.LINETO, Path.CURVE3, Path.CURVE4, Path.CLOSEPOLY])
    if not known.all():
        index = int(np.flatnonzero(~known)[0])
        raise ValueError(
            _("{name}.codes must hold only {most}; got code {codes} at vertex {index}").format(
                name=name, most=_CODE_NAMES, codes=codes[index], index=index
            )
        )
    if codes[0] != Path.MOVETO:
        raise ValueError(
            _("{name}.codes must start with MOVETO (1); got code {codes}").format(
                name=name, codes=codes[0]
            )
        )
    # CLOSEPOLY's vertex is ignored, whatever it holds (often 0 or NaN).
    require_finite(vertices[codes != Path.CLOSEPOLY], f"{name}.vertices")
    if height is not None:
        vertices[:, 1] = height - vertices[:, 1]
    change = np.concatenate([[True], codes[1:] != codes[:-1]])
    run = np.cumsum(change) - 1
    lengths, run_codes = np.bincount(run), codes[change]
    broken = ((run_codes == Path.CURVE3) & (lengths % 2 != 0)) | (
        (run_codes == Path.CURVE4) & (lengths % 3 != 0)
    )
    if broken.any():
        raise ValueError(
            _(
                "{name}.codes: CURVE3 vertices come in pairs and CURVE4 vertices in threes; a run "
                "of {length} code-{code} vertices ends at vertex {end}"
            ).format(
                name=name,
                length=lengths[broken][0],
                code=run_codes[broken][0],
                end=int(np.cumsum(lengths)[broken][0]) - 1,
            )
        )
    # Bound what is drawn: a subpath's MOVETO only if the subpath draws something.
    drawing = np.isin(codes, [Path.LINETO, Path.CURVE3, Path.CURVE4])
    subpath = np.cumsum(codes == Path.MOVETO) - 1
    draws = np.bincount(subpath[drawing], minlength=subpath[-1] + 1) > 0
    drawn = drawing | ((codes == Path.MOVETO) & draws[subpath])
    require_within(vertices[drawn], "points", limits.MAX_COORDINATE)
    return vertices, codes
