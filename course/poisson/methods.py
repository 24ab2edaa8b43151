"""Solving a Poisson problem: by which method, and how fast the iterative ones converge.

:func:`solve` solves a :class:`~course.poisson.problem.PoissonProblem` with one of
:data:`SOLVE_METHODS`: the exact ``"direct"`` (sparse factorisation, any region) and
``"dst"`` (sine transforms, rectangles) of :mod:`course.poisson.solvers`, ``"capacitance"``
(sine transforms on a box around any region, corrected on the region's border) of
:mod:`course.poisson.capacitance`, and the iterative ``"jacobi"``, ``"gauss_seidel"`` and
``"sor"``. The default, ``"auto"``, is exact and fast (:func:`exact_method`).

For the lesson on convergence, :func:`convergence` records an iterative method's residual
and error every few sweeps, :func:`sweeps_to_residual` counts the sweeps to a tolerance
and :func:`iterates` gives the window after each sweep. :mod:`course.poisson.editing`
solves its clones and inpaintings with :func:`solve`; :mod:`course.poisson` re-exports
the names here.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np

from course import limits
from course._validate import as_choice, as_int, as_positive_float, require_finite
from course.i18n import _
from course.poisson import capacitance, solvers
from course.poisson._layout import channels_back, channels_first
from course.poisson.problem import PoissonProblem, as_problem

__all__ = [
    "ITERATIVE_METHODS",
    "LAB_ITERATIONS",
    "SOLVE_METHODS",
    "ConvergenceHistory",
    "convergence",
    "exact_method",
    "iterates",
    "solve",
    "sweeps_to_residual",
]

SOLVE_METHODS = ("auto", "direct", "dst", "capacitance", "jacobi", "gauss_seidel", "sor")
ITERATIVE_METHODS = ("jacobi", "gauss_seidel", "sor")
# The lab's skeleton runs 8000 sweeps; the iterative methods default to it.
LAB_ITERATIONS = 8000
# method="capacitance" refuses a border of more pixels than this: its dense
# matrix would take 800 MB (a speckled mask; "direct" handles it easily).
MAX_CHARGES = 10_000


@dataclass(frozen=True)
class ConvergenceHistory:
    """Residual and error of an iterative method, recorded every few sweeps.

    ``errors`` is the largest ``|u - exact|`` over the region, in image units
    (multiply by 255 for grey levels); NaN when no exact solution was given.
    ``solution`` is the last iterate, a window like ``problem.values``.
    """

    method: str
    sweeps: np.ndarray
    residuals: np.ndarray
    errors: np.ndarray
    solution: np.ndarray


def solve(
    problem: PoissonProblem,
    method: str = "auto",
    iterations: int | None = None,
    tolerance: float | None = None,
    omega: float | None = None,
) -> np.ndarray:
    """Solve a :class:`PoissonProblem`: the values of its window, region filled in.

    Parameters are those of :func:`~course.poisson.seamless_clone`. The result has the shape
    of ``problem.values`` and is not clipped.

    Examples
    --------
    >>> from course.poisson.problem import clone_problem
    >>> problem = clone_problem(np.zeros((5, 5)), np.full((3, 3), 0.5), (1, 1))
    >>> solve(problem)   # a flat foreground in a black frame: black
    array([[0., 0., 0.],
           [0., 0., 0.],
           [0., 0., 0.]])
    """
    problem = as_problem(problem)
    planes, _ = _solve_planes(problem, method, iterations, tolerance, omega)
    return _image_of(planes, problem.values)


def exact_method(problem: PoissonProblem) -> str:
    """The exact method ``method="auto"`` uses for ``problem``.

    ``"dst"`` for a rectangle. For any other region, ``"capacitance"`` if it
    is expected faster than ``"direct"`` (its cost grows with the border's
    length, the factorisation's with the area; see
    :func:`course.poisson.capacitance.faster_than_direct`), else ``"direct"``.

    Examples
    --------
    >>> from course.poisson.problem import clone_problem
    >>> disc = np.hypot(*np.indices((41, 41)) - 20) < 19
    >>> ring = disc & (np.hypot(*np.indices((41, 41)) - 20) > 16)
    >>> background, foreground = np.zeros((50, 50)), np.ones((41, 41))
    >>> [exact_method(clone_problem(background, foreground, (4, 4), mask))
    ...  for mask in (None, disc, ring)]
    ['dst', 'capacitance', 'direct']
    """
    problem = as_problem(problem)
    if problem.rectangular:
        return "dst"
    return "capacitance" if capacitance.faster_than_direct(problem.region) else "direct"


def sweeps_to_residual(
    problem: PoissonProblem,
    method: str,
    tolerance: float = 1e-6,
    max_iterations: int = 100_000,
    omega: float | None = None,
) -> int | None:
    """How many sweeps an iterative method needs to bring the residual down to ``tolerance``.

    None if ``max_iterations`` sweeps are not enough.

    Examples
    --------
    >>> from course.poisson.problem import clone_problem
    >>> problem = clone_problem(np.zeros((7, 7)), np.full((5, 5), 0.5), (1, 1))
    >>> [sweeps_to_residual(problem, m) for m in ("jacobi", "gauss_seidel", "sor")]
    [39, 21, 11]
    """
    problem = as_problem(problem)
    tolerance = as_positive_float(tolerance, "tolerance")
    max_iterations = as_int(
        max_iterations, "max_iterations", minimum=0, maximum=limits.MAX_ITERATIONS
    )
    planes, done = _solve_planes(problem, method, max_iterations, tolerance, omega, checked=True)
    if solvers.residual(planes, *problem.planes()[1:]) > tolerance:
        return None
    return done


def convergence(
    problem: PoissonProblem,
    method: str,
    iterations: int,
    exact: Any = None,
    every: int = 1,
    omega: float | None = None,
) -> ConvergenceHistory:
    """Residual (and error against ``exact``) of an iterative method, every ``every`` sweeps.

    Examples
    --------
    >>> from course.poisson.problem import clone_problem
    >>> problem = clone_problem(np.zeros((7, 7)), np.full((5, 5), 0.5), (1, 1))
    >>> history = convergence(problem, "jacobi", 4, exact=solve(problem), every=2)
    >>> history.sweeps, np.round(history.residuals, 3)
    (array([0, 2, 4]), array([1.  , 0.5 , 0.25]))
    """
    problem = as_problem(problem)
    method = as_choice(method, "method", ITERATIVE_METHODS)
    iterations = as_int(iterations, "iterations", minimum=0, maximum=limits.MAX_ITERATIONS)
    every = as_int(every, "every", minimum=1)
    omega = _as_omega(omega, method, problem.region)
    reference = None if exact is None else channels_first(problem._as_solution(exact))
    values, region, source = problem.planes()
    sweeps = _sweeps(problem, method, omega)
    recorded, residuals, errors = [], [], []
    u = values
    for done in range(iterations + 1):
        if done % every == 0 or done == iterations:
            recorded.append(done)
            residuals.append(solvers.residual(u, region, source))
            error = np.nan if reference is None else np.abs(u - reference)[:, region].max()
            errors.append(error)
        if done < iterations:
            u = next(sweeps)
    return ConvergenceHistory(
        method,
        np.array(recorded),
        np.array(residuals),
        np.array(errors),
        _image_of(u.copy(), problem.values),
    )


def iterates(
    problem: PoissonProblem, method: str, omega: float | None = None
) -> Iterator[np.ndarray]:
    """The window after each sweep of an iterative method, forever.

    Each item is a view of the iterate, which the next sweep overwrites: copy
    it to keep it.

    Examples
    --------
    >>> from course.poisson.problem import clone_problem
    >>> problem = clone_problem(np.zeros((5, 6)), np.full((3, 4), 0.5), (1, 1))
    >>> sweeps = iterates(problem, "jacobi")
    >>> next(sweeps)[1]   # each unknown: three neighbours at 0, one at 0.5
    array([0.   , 0.125, 0.125, 0.   ])
    """
    problem = as_problem(problem)
    method = as_choice(method, "method", ITERATIVE_METHODS)
    omega = _as_omega(omega, method, problem.region)
    return _iterates(problem, method, omega)


def _iterates(problem: PoissonProblem, method: str, omega: float) -> Iterator[np.ndarray]:
    for planes in _sweeps(problem, method, omega):
        yield planes[0] if problem.values.ndim == 2 else np.moveaxis(planes, 0, -1)


def _sweeps(problem: PoissonProblem, method: str, omega: float) -> Iterator[np.ndarray]:
    kind = "jacobi" if method == "jacobi" else "sor"
    return solvers.sweeps(*problem.planes(), kind, omega)


# --- solving ----------------------------------------------------------------


def _solve_planes(
    problem: PoissonProblem,
    method: str,
    iterations: int | None,
    tolerance: float | None,
    omega: float | None,
    checked: bool = False,
) -> tuple[np.ndarray, int]:
    """The solution's planes and the sweeps done; ``checked``: iterations and tolerance are."""
    method = as_choice(method, "method", SOLVE_METHODS)
    if method == "auto":
        method = exact_method(problem)
    values, region, source = problem.planes()
    if method not in ITERATIVE_METHODS:
        for name, given in (("iterations", iterations), ("tolerance", tolerance), ("omega", omega)):
            if given is not None:
                raise ValueError(
                    _(
                        "{name} applies to the iterative methods {most}; "
                        "method={method} is exact, so leave {name} unset (got {given})"
                    ).format(
                        name=name,
                        most=ITERATIVE_METHODS,
                        method=repr(method),
                        given=repr(given),
                    )
                )
        if method == "dst":
            if not problem.rectangular:
                raise ValueError(
                    _(
                        "method='dst' needs a rectangular region (every pixel inside the "
                        "foreground's outer ring); this mask is not a rectangle, so use "
                        "method='capacitance', 'direct' or 'auto'"
                    )
                )
            return solvers.solve_dst(values, region, source), 0
        if method == "capacitance":
            charges = capacitance.charge_pixels(capacitance.embedding(region))[0].size
            if charges > MAX_CHARGES:
                raise ValueError(
                    _(
                        "method='capacitance' needs a dense {charges} x {charges} matrix for this "
                        "region, whose border has {charges} pixels (at most {most}); use "
                        "method='direct' or 'auto' for a ragged or scattered mask"
                    ).format(charges=charges, most=MAX_CHARGES)
                )
            return capacitance.solve_capacitance(values, region, source), 0
        return solvers.solve_direct(values, region, source), 0
    if iterations is None:
        iterations = LAB_ITERATIONS
    if not checked:
        iterations = as_int(iterations, "iterations", minimum=0, maximum=limits.MAX_ITERATIONS)
        if tolerance is not None:
            tolerance = as_positive_float(tolerance, "tolerance")
    omega = _as_omega(omega, method, region)
    kind = "jacobi" if method == "jacobi" else "sor"
    return solvers.iterate(values, region, source, kind, iterations, omega, tolerance)


def _image_of(planes: np.ndarray, like: np.ndarray) -> np.ndarray:
    """:func:`~course.poisson.windows.image_of` of a solver's planes, laid out as the problem's
    ``like``: only their values are checked (a problem of huge finite values may overflow)."""
    require_finite(planes, "planes")
    return channels_back(planes, like)


def _as_omega(omega: float | None, method: str, region: np.ndarray) -> float:
    if method != "sor":
        if omega is not None:
            raise ValueError(
                _("omega applies only to method='sor'; got omega={omega} with {method}").format(
                    omega=repr(omega), method=repr(method)
                )
            )
        return 1.0
    if omega is None:
        return solvers.optimal_omega(region)
    omega = as_positive_float(omega, "omega")
    if omega >= 2:
        raise ValueError(
            _("omega must lie in (0, 2), where SOR converges; got {omega}").format(omega=omega)
        )
    return omega
