"""Input checks shared by every public function: the one home of every validator.

Each public function validates once, at its boundary, with these helpers and
then hands plain arrays to pure array code. Every message names the
parameter, the expected shape or type, and what was given (:func:`describe`),
in the language the lesson set (:mod:`course.i18n`); the parameter's name stays
as the code spells it.
"""

from __future__ import annotations

import numbers
from typing import Any

import numpy as np

from course import limits
from course.i18n import N_, _


def describe(value: Any) -> str:
    """A short description of a value for an error message."""
    if isinstance(value, np.ndarray):
        return _("an array of shape {shape} and dtype {dtype}").format(
            shape=value.shape, dtype=value.dtype
        )
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


def as_float_array(value: Any, name: str) -> np.ndarray:
    """A float64 copy of ``value``; TypeError unless it holds real numbers."""
    try:
        array = np.array(value)
    except ValueError as error:  # ragged nested lists
        raise ValueError(
            _(
                "{name} must be a rectangular array of numbers; got a ragged sequence ({error})"
            ).format(name=name, error=error)
        ) from None
    if array.dtype == bool or not (
        np.issubdtype(array.dtype, np.integer) or np.issubdtype(array.dtype, np.floating)
    ):
        if isinstance(value, np.ndarray):
            message = _("{name} must hold real numbers; got {value}")
        else:
            message = _("{name} must hold real numbers; got {value} with dtype {dtype}")
        raise TypeError(message.format(name=name, value=describe(value), dtype=array.dtype))
    return array.astype(float, copy=True)


def require_finite(array: np.ndarray, name: str) -> None:
    """ValueError naming the first NaN or infinite entry."""
    bad = ~np.isfinite(array)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        if array.ndim:
            message = _("{name} must be finite; got {value} at index {index}")
        else:
            message = _("{name} must be finite; got {value}")
        raise ValueError(message.format(name=name, value=array[bad].flat[0], index=index))


def require_within(
    array: np.ndarray, name: str, bound: float, what: str = N_("coordinates")
) -> None:
    """ValueError unless every entry of ``array`` lies within ``[-bound, bound]``."""
    if array.size and np.abs(array).max() > bound:
        worst = array.flat[int(np.abs(array).argmax())]
        raise ValueError(
            _("{name} {what} must lie within +-{bound:g}; got {worst:g}").format(
                name=name, what=_(what), bound=bound, worst=worst
            )
        )


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


def as_positive_float(
    value: Any,
    name: str,
    allow_zero: bool = False,
    smallest: float = limits.SMALLEST,
    largest: float = limits.LARGEST,
) -> float:
    """A finite real number > 0 (or >= 0 with ``allow_zero``), within a usable range.

    A non-zero value must lie in ``[smallest, largest]`` (by default
    ``limits.SMALLEST`` and ``limits.LARGEST``): beyond them no tolerance, step
    or width can work.
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(
            _("{name} must be a real number; got {value}").format(name=name, value=describe(value))
        )
    number = float(value)
    if not np.isfinite(number):
        raise ValueError(_("{name} must be finite; got {value}").format(name=name, value=number))
    if number < 0 or (number == 0 and not allow_zero):
        bound = ">= 0" if allow_zero else "> 0"
        raise ValueError(
            _("{name} must be {bound}; got {value}").format(name=name, bound=bound, value=number)
        )
    if number != 0 and not smallest <= number <= largest:
        raise ValueError(
            _("{name} must lie between {smallest:g} and {largest:g}; got {value:g}").format(
                name=name, smallest=smallest, largest=largest, value=number
            )
        )
    return number


def as_int(
    value: Any, name: str, minimum: int | None = None, maximum: int = limits.MAX_COUNT
) -> int:
    """An integer (not a bool, not a float), at least ``minimum`` and at most ``maximum``.

    Without ``minimum``, it must also be at least ``-maximum``.
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(
            _("{name} must be an integer; got {value}").format(name=name, value=describe(value))
        )
    number = int(value)
    if minimum is not None and number < minimum:
        raise ValueError(
            _("{name} must be >= {minimum}; got {value}").format(
                name=name, minimum=minimum, value=number
            )
        )
    if number > maximum or (minimum is None and number < -maximum):
        low = minimum if minimum is not None else -maximum
        raise ValueError(
            _("{name} must be between {low} and {high}; got {value}").format(
                name=name, low=low, high=maximum, value=number
            )
        )
    return number


def as_shape(
    shape: Any, name: str = "shape", max_pixels: int = limits.MAX_PIXELS
) -> tuple[int, int]:
    """A canvas shape ``(H, W)`` of positive integers, at most ``max_pixels`` pixels."""
    if not isinstance(shape, (tuple, list)) or len(shape) != 2:
        raise ValueError(
            _("{name} must be a pair (H, W) of positive integers; got {value}").format(
                name=name, value=describe(shape)
            )
        )
    height = as_int(
        shape[0], _("{name}[0] (height)").format(name=name), minimum=1, maximum=max_pixels
    )
    width = as_int(
        shape[1], _("{name}[1] (width)").format(name=name), minimum=1, maximum=max_pixels
    )
    if height * width > max_pixels:
        raise ValueError(
            _("{name} must have at most {limit} pixels (H * W); got {height} x {width}").format(
                name=name, limit=max_pixels, height=height, width=width
            )
        )
    return height, width


def as_pixels(pixels: Any, name: str = "pixels") -> np.ndarray:
    """Validate an integer (K, 2) array of (x, y) pixel coordinates."""
    array = np.asarray(pixels)
    if array.size == 0:
        array = array.reshape(0, 2).astype(np.int64)
    if array.dtype == bool or not np.issubdtype(array.dtype, np.integer):
        raise TypeError(
            _(
                "{name} must be an integer (K, 2) array of (x, y) pixels; got {value} (round or "
                "floor float coordinates first, e.g. with course.raster.nearest_pixels)"
            ).format(name=name, value=describe(pixels))
        )
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(
            _("{name} must have shape (K, 2), one (x, y) per row; got {shape}").format(
                name=name, shape=array.shape
            )
        )
    return array


def as_image(image: Any, name: str = "image", copy: bool = True) -> np.ndarray:
    """A float image ``(H, W)`` or ``(H, W, 3)`` with finite values in [0, 1]."""
    keep = not copy and isinstance(image, np.ndarray) and image.dtype.kind == "f"
    array = image if keep else as_float_array(image, name)
    if not (array.ndim == 2 or (array.ndim == 3 and array.shape[2] == 3)):
        raise ValueError(
            _("{name} must be a gray (H, W) or RGB (H, W, 3) image; got shape {shape}").format(
                name=name, shape=array.shape
            )
        )
    if array.shape[0] == 0 or array.shape[1] == 0:
        raise ValueError(
            _("{name} must not be empty; got shape {shape}").format(name=name, shape=array.shape)
        )
    if array.shape[0] * array.shape[1] > limits.MAX_PIXELS:
        raise ValueError(
            _("{name} must have at most {limit} pixels; got shape {shape}").format(
                name=name, limit=limits.MAX_PIXELS, shape=array.shape
            )
        )
    require_finite(array, name)
    if array.min() < 0 or array.max() > 1:
        raise ValueError(
            _(
                "{name} values must lie in [0, 1]; got values from {low:g} to {high:g} (divide "
                "uint8 images by 255)"
            ).format(name=name, low=array.min(), high=array.max())
        )
    return array


def as_gray(image: Any, name: str = "gray") -> np.ndarray:
    """A gray float image ``(H, W)`` with values in [0, 1]."""
    array = as_image(image, name)
    if array.ndim != 2:
        raise ValueError(
            _(
                "{name} must be a gray (H, W) image; got shape {shape} (convert colour images "
                "with course.images.to_gray)"
            ).format(name=name, shape=array.shape)
        )
    return array


def as_choice(value: Any, name: str, choices: tuple[str, ...] | list[str]) -> str:
    """One of a fixed set of strings."""
    if not isinstance(value, str) or value not in choices:
        options = ", ".join(repr(c) for c in choices)
        raise ValueError(
            _("{name} must be one of {options}; got {value}").format(
                name=name, options=options, value=repr(value)
            )
        )
    return value


def as_rng(rng: Any, name: str = "rng") -> np.random.Generator:
    """A numpy Generator; None gives ``default_rng(0)``, so results are reproducible."""
    if rng is None:
        return np.random.default_rng(0)
    if not isinstance(rng, np.random.Generator):
        raise TypeError(
            _(
                "{name} must be a numpy.random.Generator, e.g. numpy.random.default_rng(0); got "
                "{value}"
            ).format(name=name, value=describe(rng))
        )
    return rng


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


def as_unit(value: Any, name: str) -> float:
    """A real number in [0, 1], as a slider from 0 to 1 takes it.

    Examples
    --------
    >>> as_unit(0.25, "t")
    0.25
    """
    number = as_positive_float(value, name, allow_zero=True, smallest=0.0)
    if number > 1:
        raise ValueError(
            _("{name} must lie in [0, 1]; got {value:g}").format(name=name, value=number)
        )
    return number


def as_option(value: Any, name: str, options: Any) -> Any:
    """One of a control's options (a dropdown's, buttons' or selection slider's).

    Examples
    --------
    >>> as_option("box", "kernel", ("box", "sobel"))
    'box'
    """
    for option in options:
        if type(option) is type(value) and option == value:
            return value
    listed = ", ".join(repr(option) for option in options)
    raise ValueError(
        _("{name} must be one of {options}; got {value}").format(
            name=name, options=listed, value=repr(value)
        )
    )


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
