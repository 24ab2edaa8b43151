"""How accurate is each way of evaluating a Bézier curve in floating point?

Three float evaluations of the same polynomial are measured against exact
rational arithmetic: de Casteljau (convex combinations only), the Bernstein
sum, and the power basis ``sum_j a_j t^j`` that a first course in algebra
would write down. Every float is a dyadic rational, so the exact value of a
curve at a float t is computed with Python integers and returned as a
:class:`fractions.Fraction`.

References
----------
.. [1] R. T. Farouki and V. T. Rajan, "On the numerical condition of
   polynomials in Bernstein form", CAGD 4(3), 1987, pp. 191-216.
.. [2] R. T. Farouki, "The Bernstein polynomial basis: a centennial
   retrospective", CAGD 29(6), 2012, pp. 379-419.
"""

from __future__ import annotations

import numbers
from collections.abc import Callable
from fractions import Fraction
from functools import partial
from typing import Any

import numpy as np

from course import limits
from course._validate import as_finite_array, as_int, as_parameter, as_points, as_rng
from course.curves._bernstein import (
    bernstein_loop,
    horner_or_basis,
    pascal_row,
    require_bernstein_degree,
)
from course.curves._bezier_fast import de_casteljau_chunked
from course.i18n import _

__all__ = [
    "ACCURACY_BY_DEGREE_METHODS",
    "MAX_POWER_DEGREE",
    "accuracy_by_degree",
    "bezier_exact",
    "bezier_power",
    "power_coefficients",
    "relative_errors",
]

ACCURACY_BY_DEGREE_METHODS = ("de_casteljau", "bernstein_loop", "bernstein_horner", "power")

MAX_POWER_DEGREE = 500
"""Highest degree :func:`power_coefficients` converts: beyond, coefficients overflow float64."""


def _as_integers(control: np.ndarray) -> tuple[list[list[int]], int]:
    """Integer coordinates and one power-of-two denominator: control = ints / denominator."""
    fractions = [[Fraction(float(value)) for value in row] for row in control]
    denominator = max(f.denominator for row in fractions for f in row)
    return [[int(f * denominator) for f in row] for row in fractions], denominator


def bezier_exact(points: Any, t: Any) -> np.ndarray:
    """The exact value of the curve at float parameters, as Fractions.

    The control points and t are read as the exact dyadic rationals their
    floats hold; ``sum_i C(n, i) t^i (1 - t)^(n - i) P[i]`` is then summed
    in integers, so the result carries no rounding error at all.

    Returns
    -------
    ndarray of Fraction, dtype object
        Shape (d,) for scalar t, (M, d) for an array of t.

    Examples
    --------
    >>> [str(v) for v in bezier_exact([[0, 0], [1, 3], [3, 3], [4, 0]], 0.25)]
    ['29/32', '27/16']
    """
    control = as_points(points)
    values, is_scalar = as_parameter(t)
    result = _bezier_exact(control, values)
    return result[0] if is_scalar else result


def _bezier_exact(control: np.ndarray, values: np.ndarray) -> np.ndarray:
    """(M, d) Fractions: :func:`bezier_exact` of a checked curve at checked parameters."""
    integers, denominator = _as_integers(control)
    degree = len(control) - 1
    binomials = _pascal_row_of_degree(degree)
    result = np.empty((len(values), control.shape[1]), dtype=object)
    for row, value in enumerate(values):
        exact_t = Fraction(float(value))
        p, q = exact_t.numerator, exact_t.denominator
        weights = [c * p**i * (q - p) ** (degree - i) for i, c in enumerate(binomials)]
        scale = q**degree * denominator
        for axis in range(control.shape[1]):
            total = sum(w * point[axis] for w, point in zip(weights, integers, strict=True))
            result[row, axis] = Fraction(total, scale)
    return result


def _pascal_row_of_degree(degree: int) -> tuple[int, ...]:
    """Row ``degree`` of Pascal's triangle for a checked curve of that degree.

    Past ``limits.MAX_DEGREE`` it is refused as :func:`course.curves.bezier.pascal_row`
    refuses its ``n``, in the words it always was (:func:`course._validate.as_int`'s).
    """
    if degree > limits.MAX_DEGREE:
        as_int(degree, "n", minimum=0, maximum=limits.MAX_DEGREE)
    return pascal_row(degree)


def power_coefficients(points: Any) -> np.ndarray:
    """Coefficients a_j of the curve in the power basis, ``B(t) = sum_j a_j t^j``.

    ``a_j = C(n, j) sum_{i <= j} (-1)^(j - i) C(j, i) P[i]``, computed
    exactly and rounded to float once: any error the power basis shows later
    comes from evaluating it, not from converting to it.

    Examples
    --------
    >>> power_coefficients([[0, 0], [1, 3], [3, 3], [4, 0]])
    array([[ 0.,  0.],
           [ 3.,  9.],
           [ 3., -9.],
           [-2.,  0.]])
    """
    return _power_coefficients(as_points(points))


def _power_coefficients(control: np.ndarray) -> np.ndarray:
    """:func:`power_coefficients` of a checked curve."""
    degree = len(control) - 1
    # |a_j| reaches 4**n |P| / sqrt(n): past float64's 2**1024 near degree 500.
    if degree > MAX_POWER_DEGREE:
        raise ValueError(
            _(
                "points must be at most {most} control points: the power basis' "
                "coefficients of higher degrees overflow float64; got {control_count}"
            ).format(most=MAX_POWER_DEGREE + 1, control_count=len(control))
        )
    integers, denominator = _as_integers(control)
    coefficients = np.empty(control.shape)
    for j in range(degree + 1):
        row = pascal_row(j)
        for axis in range(control.shape[1]):
            alternating = sum((-1) ** (j - i) * row[i] * integers[i][axis] for i in range(j + 1))
            try:
                coefficients[j, axis] = float(
                    Fraction(pascal_row(degree)[j] * alternating, denominator)
                )
            except OverflowError:
                raise ValueError(
                    _(
                        "points: coefficient a_{index} of this degree-{degree} curve in the power "
                        "basis overflows float64; bring the control points closer to the origin"
                    ).format(index=j, degree=degree)
                ) from None
    return coefficients


def bezier_power(points: Any, t: Any) -> np.ndarray:
    """Evaluate the curve in the power basis by Horner's rule, in floats.

    Cheap, O(n), and the form most people would write, but the coefficients
    a_j grow like 2^n with alternating signs, so for high degrees the sum
    cancels catastrophically on [0, 1].

    Examples
    --------
    >>> bezier_power([[0, 0], [1, 3], [3, 3], [4, 0]], 0.5)
    array([2.  , 2.25])
    """
    coefficients = _power_coefficients(as_points(points))
    values, is_scalar = as_parameter(t)
    curve = _power_horner(coefficients, values)
    return curve[0] if is_scalar else curve


def _power_horner(coefficients: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(M, d) points ``sum_j a_j t^j`` of the coefficients (N, d) at ``t`` (M,), by Horner."""
    curve = np.broadcast_to(coefficients[-1], (len(t), coefficients.shape[1])).copy()
    for coefficient in coefficients[-2::-1]:
        curve *= t[:, None]
        curve += coefficient
    return curve


def relative_errors(points: Any, t: Any, computed: Any) -> np.ndarray:
    """Per-parameter error of ``computed`` (M, d) against the exact curve.

    The largest coordinate error at each t, divided by the size of the
    control polygon (its largest absolute coordinate), computed exactly and
    rounded once.
    """
    control = as_points(points)
    values_t, _scalar = as_parameter(t)
    exact = _bezier_exact(control, values_t)
    values = as_finite_array(computed, "computed", shape=partial(_require_one_point_per_t, exact))
    return _relative_errors(control, exact, values)


def _require_one_point_per_t(exact: np.ndarray, values: np.ndarray) -> None:
    if values.size != exact.size:
        raise ValueError(
            _(
                "computed must hold one point per t, shape {exact_shape}; got shape {values_shape}"
            ).format(exact_shape=exact.shape, values_shape=values.shape)
        )


def _relative_errors(control: np.ndarray, exact: np.ndarray, computed: np.ndarray) -> np.ndarray:
    """:func:`relative_errors` of a checked curve, its exact points (M, d) and as many
    finite computed values."""
    values = computed.reshape(exact.shape)
    size = Fraction(float(np.abs(control).max()) or 1.0)
    errors = [
        max(abs(Fraction(float(v)) - e) for v, e in zip(row, exact_row, strict=True)) / size
        for row, exact_row in zip(values, exact, strict=True)
    ]
    return np.array([float(e) for e in errors])


def accuracy_by_degree(
    degrees: Any,
    samples: int = 17,
    rng: np.random.Generator | None = None,
    methods: tuple[str, ...] = ACCURACY_BY_DEGREE_METHODS,
) -> dict[str, np.ndarray]:
    """The worst relative error of each method for random curves of each degree.

    For every degree n, n + 1 control points are drawn uniformly from
    [-1, 1]^2 and the curve is evaluated at ``samples`` parameters spread
    over [0, 1] (a jittered grid, endpoints excluded). Each method's largest
    error against :func:`bezier_exact`, relative to the polygon size, is
    recorded.

    Returns
    -------
    dict
        ``"degree"`` and one array per method, each of shape (len(degrees),).

    Examples
    --------
    >>> errors = accuracy_by_degree([3], rng=np.random.default_rng(0))
    >>> bool(errors["de_casteljau"][0] < 1e-15)
    True
    """
    generator = as_rng(rng)
    samples = as_int(samples, "samples", minimum=1)
    evaluate: dict[str, Callable[[np.ndarray, np.ndarray], np.ndarray]] = {
        "de_casteljau": de_casteljau_chunked,
        "bernstein_loop": partial(_bernstein, bernstein_loop),
        "bernstein_horner": partial(_bernstein, horner_or_basis),
        "power": lambda control, t: _power_horner(_power_coefficients(control), t),
    }
    unknown = [m for m in methods if m not in evaluate]
    if unknown:
        raise ValueError(
            _("methods must be among {choices}; got {unknown}").format(
                choices=ACCURACY_BY_DEGREE_METHODS, unknown=unknown
            )
        )
    degree_list = _as_degrees(degrees)
    if "power" in methods and max(degree_list, default=0) > MAX_POWER_DEGREE:
        raise ValueError(
            _(
                "degrees must be at most {most} with the method 'power', whose "
                "coefficients overflow float64 beyond; got {highest}"
            ).format(most=MAX_POWER_DEGREE, highest=max(degree_list))
        )
    # Exact sums cost (degree + 1)**2 big-integer steps per sample, and each sample of each
    # degree about 150 more in Fractions, whatever its degree.
    work = samples * sum((degree + 1) ** 2 + 150 for degree in degree_list)
    if work > limits.MAX_CALLS:
        raise ValueError(
            _(
                "degrees and samples ask for {work} exact operations (samples * sum of ((degree + "
                "1)**2 + 150)); at most {most}: ask for fewer or lower degrees, or fewer "
                "samples"
            ).format(work=work, most=limits.MAX_CALLS)
        )
    results: dict[str, list[float]] = {method: [] for method in methods}
    for degree in degree_list:
        control = generator.uniform(-1, 1, (degree + 1, 2))
        t = (np.arange(samples) + generator.uniform(0.1, 0.9, samples)) / samples
        for method in methods:
            computed = evaluate[method](control, t)
            errors = _relative_errors(control, _bezier_exact(control, t), computed)
            results[method].append(float(errors.max()))
    return {"degree": np.array(degree_list)} | {m: np.array(v) for m, v in results.items()}


def _as_degrees(degrees: Any) -> list[int]:
    """The degrees as ints, each from 0 to ``limits.MAX_DEGREE``, checked in one pass.

    A list of such integers passes at once; any other is read by
    :func:`course._validate.as_int`, degree after degree, which words the first refusal.
    """
    listed = np.atleast_1d(np.asarray(degrees, dtype=object)).tolist()
    if all(_is_degree(n) for n in listed):
        return [int(n) for n in listed]
    return [as_int(n, "degrees", minimum=0, maximum=limits.MAX_DEGREE) for n in listed]


def _is_degree(value: Any) -> bool:
    return (
        isinstance(value, numbers.Integral)
        and not isinstance(value, bool)
        and 0 <= value <= limits.MAX_DEGREE
    )


def _bernstein(
    form: Callable[[np.ndarray, np.ndarray], np.ndarray], control: np.ndarray, t: np.ndarray
) -> np.ndarray:
    """A Bernstein form of a checked curve, refused past the float form's degree."""
    require_bernstein_degree(control)
    return form(control, t)
