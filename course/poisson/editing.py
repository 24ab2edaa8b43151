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

The edits solve with :func:`~course.poisson.methods.solve`
(:mod:`course.poisson.methods`), by the solvers in :mod:`course.poisson.solvers`:
``"direct"`` (sparse factorisation, any region), ``"dst"`` (sine transforms,
rectangles), ``"jacobi"``, ``"gauss_seidel"`` and ``"sor"``; and in
:mod:`course.poisson.capacitance`: ``"capacitance"`` (sine transforms on a box
around any region, corrected on the region's border). The default, ``"auto"``,
is exact and fast: ``"dst"`` for a rectangle, otherwise ``"capacitance"`` or
``"direct"``, whichever is expected faster for the region's shape
(:func:`~course.poisson.methods.exact_method`).

References
----------
.. [1] P. Pérez, M. Gangnet and A. Blake, "Poisson image editing",
   ACM Transactions on Graphics 22(3), 313-318, 2003.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from course import limits
from course._validate import as_choice, as_int
from course.poisson._build import clone_problem_of, inpaint_problem_of, paste
from course.poisson.inputs import clone_inputs, inpaint_inputs
from course.poisson.methods import LAB_ITERATIONS, solve
from course.poisson.problem import (
    GUIDANCE,
    PoissonProblem,
    clone_problem,
    inpaint_problem,
)

__all__ = [
    "GUIDANCE",
    "PoissonProblem",
    "clone_problem",
    "correction_boundary",
    "inpaint",
    "inpaint_problem",
    "lab_clone",
    "naive_paste",
    "seamless_clone",
]


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
    method : {"auto", "direct", "dst", "capacitance", "jacobi", "gauss_seidel", "sor"}
        ``"auto"`` (exact and fast) is ``"dst"`` for a rectangle, and for a
        mask ``"capacitance"`` when its border is short for its area (an
        ellipse), ``"direct"`` when long (a thin ring, a ragged silhouette):
        see :func:`exact_method`. ``"dst"`` needs a rectangular region. The
        exact methods agree to rounding.
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
    background, foreground, corner, mask = clone_inputs(background, foreground, offset, mask)
    guidance = as_choice(guidance, "guidance", GUIDANCE)
    problem = clone_problem_of(PoissonProblem, background, foreground, corner, mask, guidance)
    solution = solve(problem, method, iterations, tolerance, omega)
    if clip:
        solution = np.clip(solution, 0.0, 1.0)
    return paste(problem, background, solution)


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
    image, mask = inpaint_inputs(image, mask)
    problem = inpaint_problem_of(PoissonProblem, image, mask)
    solution = solve(problem, method, iterations, tolerance, omega)
    return paste(problem, image, solution)


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
    background, foreground, corner, mask = clone_inputs(background, foreground, offset, mask)
    problem = clone_problem_of(PoissonProblem, background, foreground, corner, mask, "plain")
    # The problem's window of the foreground, which the checks put inside it.
    x, y = problem.corner[0] - corner[0], problem.corner[1] - corner[1]
    height, width = problem.region.shape
    return paste(problem, background, foreground[y : y + height, x : x + width])


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
    background, foreground, corner, _ = clone_inputs(background, foreground, offset, None)
    return _correction_boundary(background, foreground, corner)


def _correction_boundary(
    background: np.ndarray, foreground: np.ndarray, corner: tuple[int, int]
) -> np.ndarray:
    """:func:`correction_boundary` on inputs that :func:`clone_inputs` checked."""
    x, y = corner
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
    Pure Python, a few microseconds per pixel per sweep (lesson 08 times it): for small images.
    Like the lab, the result is not clipped to [0, 1].

    Examples
    --------
    >>> background = np.tile(np.linspace(0, 1, 5), (5, 1))
    >>> lab_clone(background, np.full((3, 3), 0.75), (1, 1), iterations=30)[2]
    array([0.  , 0.25, 0.5 , 0.75, 1.  ])
    """
    background, foreground, (x0, y0), _ = clone_inputs(background, foreground, offset, None)
    iterations = as_int(iterations, "iterations", minimum=0, maximum=limits.MAX_ITERATIONS)
    g = _correction_boundary(background, foreground, (x0, y0))
    height, width = foreground.shape[:2]
    for _ in range(iterations):
        for y in range(1, height - 1):
            for x in range(1, width - 1):
                g[y, x] = (g[y - 1, x] + g[y + 1, x] + g[y, x - 1] + g[y, x + 1]) * 0.25
    result = background.copy()
    result[y0 : y0 + height, x0 : x0 + width] = foreground + g
    return result
