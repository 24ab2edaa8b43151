"""Poisson image editing: seamless cloning and inpainting.

To paste a foreground into a background without a seam, Pérez, Gangnet and
Blake (2003) keep the foreground's *gradients* and the background's *values*
on the border of the pasted region: inside the region the result ``u`` solves
the Poisson equation ``laplacian(u) = laplacian(f)`` (``f`` the foreground),
and on its border ``u`` equals the background. Inpainting is the case without
a foreground: ``laplacian(u) = 0``, the smoothest (membrane) fill of a hole.

Discretely, for every region pixel ``p`` and its four neighbours ``q``::

    4 u_p - sum_q u_q = sum_q v_pq,      v_pq = f_p - f_q  ("plain" guidance)

where a neighbour outside the region keeps the background's value. The lab
("Inpainting", seed 001) solves it for the correction ``g = u - f``, which is
harmonic (``laplacian(g) = 0``) and equals ``background - foreground`` on the
border; :func:`lab_clone` is its loop, :func:`correction_boundary` its
boundary setup.

The solvers are in :mod:`course.poisson_solvers`: ``"direct"`` (sparse
factorisation, any region), ``"dst"`` (sine transforms, rectangles),
``"jacobi"``, ``"gauss_seidel"`` and ``"sor"``. The default, ``"auto"``, is
exact and fast: ``"dst"`` for a rectangle, ``"direct"`` otherwise.

References
----------
.. [1] P. Pérez, M. Gangnet and A. Blake, "Poisson image editing",
   ACM Transactions on Graphics 22(3), 313-318, 2003.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np

from course import poisson_solvers as solvers
from course._validate import (
    _describe,
    as_choice,
    as_float_array,
    as_image,
    as_int,
    as_positive_float,
    require_finite,
)

__all__ = [
    "GUIDANCE",
    "LAB_ITERATIONS",
    "METHODS",
    "ConvergenceHistory",
    "PoissonProblem",
    "clone_problem",
    "convergence",
    "correction_boundary",
    "inpaint",
    "inpaint_problem",
    "iterates",
    "lab_clone",
    "naive_paste",
    "seamless_clone",
    "solve",
    "sweeps_to_residual",
]

METHODS = ("auto", "direct", "dst", "jacobi", "gauss_seidel", "sor")
ITERATIVE = ("jacobi", "gauss_seidel", "sor")
GUIDANCE = ("plain", "mixed")
# The lab's skeleton runs 8000 sweeps; the iterative methods default to it.
LAB_ITERATIONS = 8000


@dataclass(frozen=True)
class PoissonProblem:
    """The discrete Poisson equation on a region, cut out of a larger image.

    Attributes
    ----------
    values : ndarray, (h, w) or (h, w, 3)
        Outside the region, the fixed boundary values; inside it, the
        iterative methods' starting guess (the foreground, as in the lab).
    region : ndarray of bool, (h, w)
        The unknown pixels; False on the outer ring, so each has 4 neighbours.
    source : ndarray, like ``values``
        ``b_p = sum_q v_pq`` at each region pixel (0 elsewhere): the guidance.
    corner : (int, int)
        ``(x, y)`` of ``values[0, 0]`` in the image the result goes into.
    """

    values: np.ndarray
    region: np.ndarray
    source: np.ndarray
    corner: tuple[int, int]

    @property
    def rectangular(self) -> bool:
        """True when the region is every pixel inside the outer ring."""
        return bool(self.region[1:-1, 1:-1].all())

    def planes(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(values, region, source)`` as :mod:`course.poisson_solvers` takes them.

        Channels first, ``(C, h, w)``, so that each channel is one plane; copies.

        Examples
        --------
        >>> problem = clone_problem(np.zeros((5, 5, 3)), np.ones((3, 4, 3)), (0, 1))
        >>> [array.shape for array in problem.planes()]
        [(3, 3, 4), (3, 4), (3, 3, 4)]
        """
        return _planes(self.values), self.region.copy(), _planes(self.source)

    def residual(self, solution: Any) -> float:
        """Largest ``|b_p + sum_q u_q - 4 u_p|`` over the region: 0 for the exact solution."""
        return solvers.residual(
            _planes(self._as_solution(solution)), self.region, _planes(self.source)
        )

    def paste(self, image: np.ndarray, solution: Any) -> np.ndarray:
        """A copy of ``image`` whose region pixels are ``solution``'s."""
        solution = self._as_solution(solution)
        x, y = self.corner
        height, width = self.region.shape
        result = np.array(image, dtype=float)
        window = result[y : y + height, x : x + width]
        window[self.region] = solution[self.region]
        return result

    def seam(self, image: np.ndarray) -> float:
        """Mean absolute step across the region's border in ``image`` (which holds the region).

        Over every pair of a region pixel and its neighbour outside the region.
        A visible seam is a step much larger than the image's own texture.

        Examples
        --------
        >>> problem = clone_problem(np.zeros((5, 5)), np.zeros((3, 3)), (1, 1))
        >>> image = np.zeros((5, 5)); image[2, 2] = 0.5   # the one region pixel
        >>> problem.seam(image), problem.texture(image)
        (0.5, nan)
        """
        return self._mean_step(image, across_border=True)

    def texture(self, image: np.ndarray) -> float:
        """Mean absolute step between neighbouring region pixels of ``image``.

        NaN for a region without two neighbouring pixels.
        """
        return self._mean_step(image, across_border=False)

    def _mean_step(self, image: np.ndarray, across_border: bool) -> float:
        x, y = self.corner
        height, width = self.region.shape
        window = np.asarray(image, dtype=float)[y : y + height, x : x + width]
        steps = []
        for dy, dx in solvers.NEIGHBOURS:
            neighbour = (slice(1 + dy, height - 1 + dy), slice(1 + dx, width - 1 + dx))
            other = self.region[neighbour]
            pairs = self.region[1:-1, 1:-1] & (~other if across_border else other)
            steps.append(np.abs(window[1:-1, 1:-1][pairs] - window[neighbour][pairs]).reshape(-1))
        steps = np.concatenate(steps)
        return float(steps.mean()) if steps.size else float("nan")

    def _as_solution(self, solution: Any) -> np.ndarray:
        array = as_float_array(solution, "solution")
        if array.shape != self.values.shape:
            raise ValueError(
                f"solution must have the problem's shape {self.values.shape}; got {array.shape}"
            )
        require_finite(array, "solution")
        return array


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


def seamless_clone(
    background: Any,
    foreground: Any,
    offset: Any,
    mask: Any = None,
    method: str = "auto",
    guidance: str = "plain",
    iterations: int | None = None,
    tolerance: float | None = None,
    omega: float | None = None,
    clip: bool = True,
) -> np.ndarray:
    """Paste ``foreground`` into ``background`` at ``offset`` without a seam.

    The region keeps the foreground's gradients and meets the background on
    its border [1]_. Without a mask the region is the foreground rectangle
    inside its outer ring of pixels, and the ring takes the background's values
    (the lab's boundary condition); a mask selects any region inside that ring,
    and its border is the masked pixels' unmasked neighbours.

    Parameters
    ----------
    background : array_like, (H, W) or (H, W, 3)
        Float image in [0, 1]; not modified.
    foreground : array_like, (h, w) or (h, w, 3)
        Float image in [0, 1], gray if the background is gray, RGB if RGB.
    offset : (int, int)
        ``(x, y)``: column and row of the foreground's top-left pixel in the
        background. The whole foreground must lie inside the background.
    mask : array_like of bool, (h, w), optional
        The pixels to clone; False on the foreground's outer ring.
    method : {"auto", "direct", "dst", "jacobi", "gauss_seidel", "sor"}
        ``"auto"`` (exact and fast) is ``"dst"`` for a rectangle, ``"direct"``
        otherwise. ``"dst"`` needs a rectangular region.
    guidance : {"plain", "mixed"}
        ``"plain"`` follows the foreground's gradients; ``"mixed"`` takes, on
        each edge and channel, whichever of the foreground's and background's
        differences is larger, so background texture shows through flat parts
        of the foreground [1]_.
    iterations : int, optional
        Sweeps of an iterative method; 8000 (the lab's count) by default.
    tolerance : float, optional
        Stop an iterative method early once its residual is at most this.
    omega : float, optional
        Over-relaxation factor of ``"sor"``, in (0, 2); by default the optimal
        factor of the region's bounding rectangle.
    clip : bool
        Clip the result to [0, 1]. The exact solution can overshoot where the
        foreground's gradients ask for more contrast than the range allows.

    Returns
    -------
    ndarray
        A new image of the background's shape.

    Examples
    --------
    A foreground that only differs from the background by a constant
    disappears: its gradients are the background's.

    >>> background = np.tile(np.linspace(0, 1, 5), (5, 1))
    >>> foreground = background[1:4, 1:4] * 0 + 0.75   # flat: no gradient
    >>> seamless_clone(background, foreground, (1, 1))[2]   # the harmonic fill
    array([0.  , 0.25, 0.5 , 0.75, 1.  ])
    """
    background, foreground, corner, mask = _clone_inputs(background, foreground, offset, mask)
    guidance = as_choice(guidance, "guidance", GUIDANCE)
    problem = _clone_problem(background, foreground, corner, mask, guidance)
    solution = solve(problem, method, iterations, tolerance, omega)
    if clip:
        solution = np.clip(solution, 0.0, 1.0)
    return problem.paste(background, solution)


def inpaint(
    image: Any,
    mask: Any,
    method: str = "auto",
    iterations: int | None = None,
    tolerance: float | None = None,
    omega: float | None = None,
) -> np.ndarray:
    """Fill the masked pixels with the membrane (harmonic) interpolant of their border.

    Inside the hole the result solves Laplace's equation, each pixel the
    average of its four neighbours; the hole's border, its unmasked
    neighbours, keeps the image's values. Good for thin scratches and small
    removed objects; a wide hole comes out smooth, without texture.

    Parameters
    ----------
    image : array_like, (H, W) or (H, W, 3)
        Float image in [0, 1]; not modified. Masked pixels are only the
        iterative methods' starting guess.
    mask : array_like of bool, (H, W)
        The pixels to fill; not empty, and not touching the image border,
        which would leave the hole without a boundary there.
    method, iterations, tolerance, omega
        As for :func:`seamless_clone`.

    Returns
    -------
    ndarray
        A new image of the image's shape.

    Examples
    --------
    >>> image = np.array([[0, 1, 0], [0.25, 0, 0.75], [0, 0, 0]])
    >>> hole = np.array([[0, 0, 0], [0, 1, 0], [0, 0, 0]], bool)
    >>> inpaint(image, hole)[1]   # the centre becomes (1 + 0 + 0.25 + 0.75) / 4
    array([0.25, 0.5 , 0.75])
    """
    problem = inpaint_problem(image, mask)
    solution = solve(problem, method, iterations, tolerance, omega)
    return problem.paste(as_image(image), solution)


def clone_problem(
    background: Any, foreground: Any, offset: Any, mask: Any = None, guidance: str = "plain"
) -> PoissonProblem:
    """The Poisson problem :func:`seamless_clone` solves, for :func:`solve` and :func:`convergence`.

    Examples
    --------
    >>> problem = clone_problem(np.zeros((6, 6)), np.ones((4, 5)), (1, 2))
    >>> problem.corner, problem.region.shape, problem.rectangular
    ((1, 2), (4, 5), True)
    """
    background, foreground, corner, mask = _clone_inputs(background, foreground, offset, mask)
    guidance = as_choice(guidance, "guidance", GUIDANCE)
    return _clone_problem(background, foreground, corner, mask, guidance)


def inpaint_problem(image: Any, mask: Any) -> PoissonProblem:
    """The Laplace problem :func:`inpaint` solves: the hole, cropped with a ring around it.

    Examples
    --------
    >>> hole = np.zeros((6, 6), bool); hole[2:4, 3] = True
    >>> problem = inpaint_problem(np.zeros((6, 6)), hole)
    >>> problem.corner, problem.region.astype(int)
    ((2, 1), array([[0, 0, 0],
           [0, 1, 0],
           [0, 1, 0],
           [0, 0, 0]]))
    """
    image = as_image(image, "image")
    mask = _as_mask(mask, "mask", image.shape[:2], "the image's (H, W)")
    rows, columns = np.nonzero(mask)
    height, width = mask.shape
    edge = (rows == 0) | (rows == height - 1) | (columns == 0) | (columns == width - 1)
    if edge.any():
        where = (int(columns[edge][0]), int(rows[edge][0]))
        raise ValueError(
            f"mask touches the image border, e.g. at (x, y) = {where}: inpaint needs known "
            "pixels all around the hole, so leave the first and last rows and columns "
            "unmasked (or pad the image)"
        )
    top, left = rows.min() - 1, columns.min() - 1
    window = (slice(top, rows.max() + 2), slice(left, columns.max() + 2))
    values = image[window].copy()
    return PoissonProblem(values, mask[window].copy(), np.zeros_like(values), (int(left), int(top)))


def solve(
    problem: PoissonProblem,
    method: str = "auto",
    iterations: int | None = None,
    tolerance: float | None = None,
    omega: float | None = None,
) -> np.ndarray:
    """Solve a :class:`PoissonProblem`: the values of its window, region filled in.

    Parameters are those of :func:`seamless_clone`. The result has the shape
    of ``problem.values`` and is not clipped.

    Examples
    --------
    >>> problem = clone_problem(np.zeros((5, 5)), np.full((3, 3), 0.5), (1, 1))
    >>> solve(problem)   # a flat foreground in a black frame: black
    array([[0., 0., 0.],
           [0., 0., 0.],
           [0., 0., 0.]])
    """
    planes, _ = _solve_planes(problem, method, iterations, tolerance, omega)
    return _image(planes, problem.values)


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
    >>> problem = clone_problem(np.zeros((7, 7)), np.full((5, 5), 0.5), (1, 1))
    >>> [sweeps_to_residual(problem, m) for m in ("jacobi", "gauss_seidel", "sor")]
    [39, 21, 11]
    """
    tolerance = as_positive_float(tolerance, "tolerance")
    planes, done = _solve_planes(problem, method, max_iterations, tolerance, omega)
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
    >>> problem = clone_problem(np.zeros((7, 7)), np.full((5, 5), 0.5), (1, 1))
    >>> history = convergence(problem, "jacobi", 4, exact=solve(problem), every=2)
    >>> history.sweeps, np.round(history.residuals, 3)
    (array([0, 2, 4]), array([1.  , 0.5 , 0.25]))
    """
    method = as_choice(method, "method", ITERATIVE)
    iterations = as_int(iterations, "iterations", minimum=0)
    every = as_int(every, "every", minimum=1)
    omega = _as_omega(omega, method, problem.region)
    reference = None if exact is None else _planes(problem._as_solution(exact))
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
        _image(u.copy(), problem.values),
    )


def iterates(
    problem: PoissonProblem, method: str, omega: float | None = None
) -> Iterator[np.ndarray]:
    """The window after each sweep of an iterative method, forever.

    Each item is a view of the iterate, which the next sweep overwrites: copy
    it to keep it.

    Examples
    --------
    >>> problem = clone_problem(np.zeros((5, 6)), np.full((3, 4), 0.5), (1, 1))
    >>> sweeps = iterates(problem, "jacobi")
    >>> next(sweeps)[1]   # each unknown: three neighbours at 0, one at 0.5
    array([0.   , 0.125, 0.125, 0.   ])
    """
    method = as_choice(method, "method", ITERATIVE)
    omega = _as_omega(omega, method, problem.region)
    for planes in _sweeps(problem, method, omega):
        yield planes[0] if problem.values.ndim == 2 else np.moveaxis(planes, 0, -1)


def _sweeps(problem: PoissonProblem, method: str, omega: float) -> Iterator[np.ndarray]:
    values, region, source = problem.planes()
    if method == "jacobi":
        return solvers.jacobi_sweeps(values, region, source)
    return solvers.sor_sweeps(values, region, source, omega)


def naive_paste(background: Any, foreground: Any, offset: Any, mask: Any = None) -> np.ndarray:
    """Copy the foreground's pixels over the region :func:`seamless_clone` would change.

    The comparison a seamless clone is judged against: the same pixels, the
    foreground's values instead of a solution.

    Examples
    --------
    >>> naive_paste(np.zeros((4, 4)), np.ones((4, 3)), (1, 0))
    array([[0., 0., 0., 0.],
           [0., 0., 1., 0.],
           [0., 0., 1., 0.],
           [0., 0., 0., 0.]])
    """
    background, foreground, corner, mask = _clone_inputs(background, foreground, offset, mask)
    problem = _clone_problem(background, foreground, corner, mask, "plain")
    window = _window(problem, foreground, corner)
    return problem.paste(background, window)


def correction_boundary(background: Any, foreground: Any, offset: Any) -> np.ndarray:
    """The lab's boundary setup: ``g = background - foreground`` on the outer ring, 0 inside.

    ``g`` has the foreground's shape. The solution is ``foreground + g`` once
    ``g`` is made harmonic inside; see :func:`lab_clone`.

    Examples
    --------
    >>> correction_boundary(np.ones((4, 5)), np.full((3, 3), 0.25), (2, 1))
    array([[0.75, 0.75, 0.75],
           [0.75, 0.  , 0.75],
           [0.75, 0.75, 0.75]])
    """
    background, foreground, (x, y), _ = _clone_inputs(background, foreground, offset, None)
    height, width = foreground.shape[:2]
    g = np.zeros_like(foreground)
    window = background[y : y + height, x : x + width]
    ring = np.ones((height, width), bool)
    ring[1:-1, 1:-1] = False
    g[ring] = window[ring] - foreground[ring]
    return g


def lab_clone(
    background: Any, foreground: Any, offset: Any, iterations: int = LAB_ITERATIONS
) -> np.ndarray:
    """The lab's skeleton, line for line: solve for ``g = u - f`` in place, then add ``f``.

    Its comment says "Jacobi iteration", but the loop overwrites ``g`` as it
    goes, so each pixel already sees its new upper and left neighbours: that
    is Gauss-Seidel, ``method="gauss_seidel"`` of :func:`seamless_clone`.
    Pure Python, about a microsecond per pixel per sweep: for small images.
    Like the lab, the result is not clipped to [0, 1].

    Examples
    --------
    >>> background = np.tile(np.linspace(0, 1, 5), (5, 1))
    >>> lab_clone(background, np.full((3, 3), 0.75), (1, 1), iterations=30)[2]
    array([0.  , 0.25, 0.5 , 0.75, 1.  ])
    """
    background, foreground, (x0, y0), _ = _clone_inputs(background, foreground, offset, None)
    iterations = as_int(iterations, "iterations", minimum=0)
    g = correction_boundary(background, foreground, (x0, y0))
    height, width = foreground.shape[:2]
    for _ in range(iterations):
        for y in range(1, height - 1):
            for x in range(1, width - 1):
                g[y, x] = (g[y - 1, x] + g[y + 1, x] + g[y, x - 1] + g[y, x + 1]) * 0.25
    result = background.copy()
    result[y0 : y0 + height, x0 : x0 + width] = foreground + g
    return result


# --- building the problem -------------------------------------------------


def _clone_problem(
    background: np.ndarray,
    foreground: np.ndarray,
    corner: tuple[int, int],
    mask: np.ndarray | None,
    guidance: str,
) -> PoissonProblem:
    height, width = foreground.shape[:2]
    if mask is None:
        mask = np.zeros((height, width), bool)
        mask[1:-1, 1:-1] = True
    rows, columns = np.nonzero(mask)
    top, bottom = rows.min() - 1, rows.max() + 2
    left, right = columns.min() - 1, columns.max() + 2
    region = mask[top:bottom, left:right].copy()
    crop = (corner[0] + left, corner[1] + top)
    f = foreground[top:bottom, left:right]
    b = _window_of(background, crop, region.shape)
    values = np.where(_channels_last(region, f), f, b)
    source = _guidance_sum(_planes(f), _planes(b), region, guidance)
    return PoissonProblem(values, region, _image(source, f), (int(crop[0]), int(crop[1])))


def _guidance_sum(f: np.ndarray, b: np.ndarray, region: np.ndarray, guidance: str) -> np.ndarray:
    """``sum_q v_pq`` over the four neighbours of each region pixel (channels first)."""
    _, height, width = f.shape
    total = np.zeros_like(f)
    for dy, dx in solvers.NEIGHBOURS:
        neighbour = (slice(None), slice(1 + dy, height - 1 + dy), slice(1 + dx, width - 1 + dx))
        step = f[:, 1:-1, 1:-1] - f[neighbour]
        if guidance == "mixed":
            background_step = b[:, 1:-1, 1:-1] - b[neighbour]
            step = np.where(np.abs(step) > np.abs(background_step), step, background_step)
        total[:, 1:-1, 1:-1] += step
    return total * region


def _window(problem: PoissonProblem, image: np.ndarray, corner: tuple[int, int]) -> np.ndarray:
    """The problem's window cut from ``image``, whose top-left pixel sits at ``corner``."""
    x = problem.corner[0] - corner[0]
    y = problem.corner[1] - corner[1]
    height, width = problem.region.shape
    return image[y : y + height, x : x + width]


def _window_of(image: np.ndarray, corner: tuple[int, int], shape: tuple[int, int]) -> np.ndarray:
    x, y = corner
    return image[y : y + shape[0], x : x + shape[1]]


def _channels_last(mask: np.ndarray, like: np.ndarray) -> np.ndarray:
    return mask if like.ndim == 2 else mask[..., None]


def _planes(image: np.ndarray) -> np.ndarray:
    """``(h, w)`` or ``(h, w, 3)`` to channels first, ``(C, h, w)``."""
    if image.ndim == 2:
        return image[None].astype(float)
    return np.ascontiguousarray(np.moveaxis(image, -1, 0), dtype=float)


def _image(planes: np.ndarray, like: np.ndarray) -> np.ndarray:
    """Back from channels first to the layout of ``like``."""
    if like.ndim == 2:
        return planes[0].copy()
    return np.ascontiguousarray(np.moveaxis(planes, 0, -1))


# --- solving ----------------------------------------------------------------


def _solve_planes(
    problem: PoissonProblem,
    method: str,
    iterations: int | None,
    tolerance: float | None,
    omega: float | None,
) -> tuple[np.ndarray, int]:
    method = as_choice(method, "method", METHODS)
    if method == "auto":
        method = "dst" if problem.rectangular else "direct"
    values, region, source = problem.planes()
    if method not in ITERATIVE:
        for name, given in (("iterations", iterations), ("tolerance", tolerance), ("omega", omega)):
            if given is not None:
                raise ValueError(
                    f"{name} applies to the iterative methods {ITERATIVE}; "
                    f"method={method!r} is exact, so leave {name} unset (got {given!r})"
                )
        if method == "dst":
            if not problem.rectangular:
                raise ValueError(
                    "method='dst' needs a rectangular region (every pixel inside the "
                    "foreground's outer ring); this mask is not a rectangle, so use "
                    "method='direct' or 'auto'"
                )
            return solvers.solve_dst(values, region, source), 0
        return solvers.solve_direct(values, region, source), 0
    iterations = LAB_ITERATIONS if iterations is None else as_int(iterations, "iterations", 0)
    if tolerance is not None:
        tolerance = as_positive_float(tolerance, "tolerance")
    omega = _as_omega(omega, method, region)
    kind = "jacobi" if method == "jacobi" else "sor"
    return solvers.iterate(values, region, source, kind, iterations, omega, tolerance)


def _as_omega(omega: float | None, method: str, region: np.ndarray) -> float:
    if method != "sor":
        if omega is not None:
            raise ValueError(
                f"omega applies only to method='sor'; got omega={omega!r} with {method!r}"
            )
        return 1.0
    if omega is None:
        return solvers.optimal_omega(region)
    omega = as_positive_float(omega, "omega")
    if omega >= 2:
        raise ValueError(f"omega must lie in (0, 2), where SOR converges; got {omega}")
    return omega


# --- input checks -------------------------------------------------------------


def _clone_inputs(
    background: Any, foreground: Any, offset: Any, mask: Any
) -> tuple[np.ndarray, np.ndarray, tuple[int, int], np.ndarray | None]:
    """Validate seamless_clone's inputs once; every message names the parameter."""
    _same_kind_of_dtype(background, foreground)
    background = as_image(background, "background")
    foreground = as_image(foreground, "foreground")
    if background.ndim != foreground.ndim:
        kinds = {2: "gray", 3: "RGB"}
        raise ValueError(
            f"foreground is {kinds[foreground.ndim]} (shape {foreground.shape}) but background "
            f"is {kinds[background.ndim]} (shape {background.shape}): both must be gray or "
            "both RGB (course.images.to_gray converts)"
        )
    x, y = _as_offset(offset)
    height, width = foreground.shape[:2]
    full_height, full_width = background.shape[:2]
    if not (0 <= x and x + width <= full_width and 0 <= y and y + height <= full_height):
        raise ValueError(
            f"foreground of shape {foreground.shape[:2]} at offset (x, y) = ({x}, {y}) does not "
            f"fit inside background of shape {background.shape[:2]}: it would cover columns "
            f"{x} to {x + width - 1} and rows {y} to {y + height - 1}; the background has "
            f"columns 0 to {full_width - 1} and rows 0 to {full_height - 1}"
        )
    if height < 3 or width < 3:
        raise ValueError(
            f"foreground must be at least 3 x 3 pixels: its outer ring is the boundary and the "
            f"region lies inside it; got shape {foreground.shape[:2]}"
        )
    if mask is not None:
        mask = _as_mask(mask, "mask", (height, width), "the foreground's (h, w)")
        ring = mask.copy()
        ring[1:-1, 1:-1] = False
        if ring.any():
            rows, columns = np.nonzero(ring)
            raise ValueError(
                "mask must be False on the foreground's outer ring (its first and last rows "
                "and columns), which is the boundary and takes the background's values; got "
                f"{rows.size} masked pixels there, e.g. (x, y) = ({columns[0]}, {rows[0]})"
            )
    return background, foreground, (x, y), mask


def _same_kind_of_dtype(background: Any, foreground: Any) -> None:
    kinds = [np.asarray(image).dtype for image in (background, foreground)]
    floating = [np.issubdtype(kind, np.floating) for kind in kinds]
    if floating[0] != floating[1]:
        raise TypeError(
            f"foreground has dtype {kinds[1]} but background has dtype {kinds[0]}: convert both "
            "to float images in [0, 1] (a uint8 image / 255)"
        )


def _as_offset(offset: Any) -> tuple[int, int]:
    if isinstance(offset, (str, bytes)) or not hasattr(offset, "__len__") or len(offset) != 2:
        raise ValueError(
            "offset must be a pair (x, y) of integers, the column and row of the foreground's "
            f"top-left pixel in the background; got {_describe(offset)}"
        )
    return as_int(offset[0], "offset[0] (x)"), as_int(offset[1], "offset[1] (y)")


def _as_mask(mask: Any, name: str, shape: tuple[int, int], what: str) -> np.ndarray:
    array = np.asarray(mask)
    if array.dtype != bool:
        values = as_float_array(array, name)
        require_finite(values, name)
        if not np.isin(values, (0.0, 1.0)).all():
            raise ValueError(
                f"{name} must be boolean (or 0 and 1); got values from {values.min():g} to "
                f"{values.max():g}"
            )
        array = values == 1.0
    if array.shape != shape:
        raise ValueError(f"{name} must have shape {shape}, {what}; got shape {array.shape}")
    if not array.any():
        raise ValueError(f"{name} is empty: it selects no pixel, so there is nothing to solve")
    return array.copy()
