"""The Poisson problem of an edit: a window, its region, its boundary values and guidance.

:func:`clone_problem` and :func:`inpaint_problem` validate their inputs once
(:mod:`course.poisson.inputs`; every message names the parameter) and cut out the
window the solvers work on: the region's bounding box and one more ring of pixels,
its boundary. The solvers in :mod:`course.poisson.solvers` take the window's arrays
channels first (:meth:`PoissonProblem.planes`); :mod:`course.poisson` solves and
pastes (:func:`paste_window`). The checked helpers that cut windows and change the
channel order are in :mod:`course.poisson.windows`.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

from course import limits
from course._validate import as_choice, as_finite_array, as_int, describe, require_finite
from course.i18n import _
from course.poisson import solvers
from course.poisson._build import clone_problem_of, inpaint_problem_of, paste
from course.poisson._layout import channels_first
from course.poisson.inputs import clone_inputs, inpaint_inputs

__all__ = [
    "GUIDANCE",
    "PoissonProblem",
    "as_problem",
    "build_clone_problem",
    "clone_problem",
    "inpaint_problem",
    "paste_window",
]

GUIDANCE = ("plain", "mixed")


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

    def __post_init__(self) -> None:
        """Check the four fields once, so that the unchecked solvers get what they need."""
        for name in ("values", "source"):
            array = getattr(self, name)
            if not isinstance(array, np.ndarray) or array.dtype.kind not in "fiu":
                raise TypeError(
                    _("{name} must be a numpy array of real numbers; got {array}").format(
                        name=name, array=describe(array)
                    )
                )
            require_finite(array, name)
        values, region, source = self.values, self.region, self.source
        if not (values.ndim == 2 or (values.ndim == 3 and values.shape[2] == 3)):
            raise ValueError(
                _("values must have shape (h, w) or (h, w, 3); got {values_shape}").format(
                    values_shape=values.shape
                )
            )
        if min(values.shape[:2]) < 3 or values.size > limits.MAX_PIXELS * 3:
            raise ValueError(
                _(
                    "values must be at least 3 x 3 and at most {most} pixels; got shape "
                    "{values_shape}"
                ).format(most=limits.MAX_PIXELS, values_shape=values.shape)
            )
        if source.shape != values.shape:
            raise ValueError(
                _(
                    "source must have the shape of values, {values_shape}; got {source_shape}"
                ).format(values_shape=values.shape, source_shape=source.shape)
            )
        if not isinstance(region, np.ndarray) or region.dtype != bool:
            raise TypeError(
                _("region must be a boolean numpy array; got {region}").format(
                    region=describe(region)
                )
            )
        if region.shape != values.shape[:2]:
            raise ValueError(
                _("region must have shape {values_size}; got {region_shape}").format(
                    values_size=values.shape[:2], region_shape=region.shape
                )
            )
        ring = np.concatenate([region[0], region[-1], region[:, 0], region[:, -1]])
        if ring.any():
            raise ValueError(
                _("region must be False on the outer ring, so each pixel has 4 neighbours")
            )
        if not region.any():
            raise ValueError(_("region selects no pixel: there is nothing to solve"))
        if not isinstance(self.corner, tuple) or len(self.corner) != 2:
            raise ValueError(
                _("corner must be a pair (x, y) of integers; got {corner}").format(
                    corner=describe(self.corner)
                )
            )
        as_int(self.corner[0], "corner[0] (x)")
        as_int(self.corner[1], "corner[1] (y)")

    @property
    def rectangular(self) -> bool:
        """True when the region is every pixel inside the outer ring."""
        return bool(self.region[1:-1, 1:-1].all())

    def planes(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(values, region, source)`` as :mod:`course.poisson.solvers` takes them.

        Channels first, ``(C, h, w)``, so that each channel is one plane; copies.

        Examples
        --------
        >>> problem = clone_problem(np.zeros((5, 5, 3)), np.ones((3, 4, 3)), (0, 1))
        >>> [array.shape for array in problem.planes()]
        [(3, 3, 4), (3, 4), (3, 3, 4)]
        """
        return channels_first(self.values), self.region.copy(), channels_first(self.source)

    def residual(self, solution: Any) -> float:
        """Largest ``|b_p + sum_q u_q - 4 u_p|`` over the region: 0 for the exact solution."""
        return solvers.residual(
            channels_first(self._as_solution(solution)), self.region, channels_first(self.source)
        )

    def paste(self, image: np.ndarray, solution: Any) -> np.ndarray:
        """A copy of ``image`` whose region pixels are ``solution``'s.

        Examples
        --------
        >>> problem = clone_problem(np.zeros((4, 4)), np.zeros((3, 3)), (1, 0))
        >>> problem.paste(np.zeros((4, 4)), np.ones((3, 3)))[1]
        array([0., 0., 1., 0.])
        """
        return paste(self, self._as_image(image, "image"), self._as_solution(solution))

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
        window = self._as_image(image, "image")[y : y + height, x : x + width]
        steps = []
        for dy, dx in solvers.NEIGHBOURS:
            neighbour = (slice(1 + dy, height - 1 + dy), slice(1 + dx, width - 1 + dx))
            other = self.region[neighbour]
            pairs = self.region[1:-1, 1:-1] & (~other if across_border else other)
            steps.append(np.abs(window[1:-1, 1:-1][pairs] - window[neighbour][pairs]).reshape(-1))
        steps = np.concatenate(steps)
        return float(steps.mean()) if steps.size else float("nan")

    def _as_image(self, image: Any, name: str) -> np.ndarray:
        """``image`` as finite floats, the problem's kind, holding the problem's window.

        A float64 array is checked where it lies (the callers only read it).
        """
        if isinstance(image, np.ndarray) and image.dtype == np.float64:
            self._require_window(image, name)
            require_finite(image, name)
            return image
        return as_finite_array(
            image, name, shape=functools.partial(self._require_window, name=name)
        )

    def _require_window(self, array: np.ndarray, name: str) -> None:
        """ValueError unless ``array`` is an image of the problem's kind holding its window."""
        kind = "(H, W)" if self.values.ndim == 2 else "(H, W, 3)"
        if array.ndim != self.values.ndim or array.shape[2:] != self.values.shape[2:]:
            raise ValueError(
                _(
                    "{name} must be an image of shape {kind}, like the problem's values "
                    "{values_shape}; got shape {array_shape}"
                ).format(
                    name=name, kind=kind, values_shape=self.values.shape, array_shape=array.shape
                )
            )
        x, y = self.corner
        height, width = self.region.shape
        if not (0 <= x and x + width <= array.shape[1] and 0 <= y and y + height <= array.shape[0]):
            raise ValueError(
                _(
                    "{name} of shape {array_size} must hold the problem's window, {height} x "
                    "{width} pixels at (x, y) = ({x}, {y})"
                ).format(
                    name=name, array_size=array.shape[:2], height=height, width=width, x=x, y=y
                )
            )

    def _as_solution(self, solution: Any) -> np.ndarray:
        return as_finite_array(solution, "solution", shape=self._require_solution_shape)

    def _require_solution_shape(self, array: np.ndarray) -> None:
        if array.shape != self.values.shape:
            raise ValueError(
                _(
                    "solution must have the problem's shape {values_shape}; got {array_shape}"
                ).format(values_shape=self.values.shape, array_shape=array.shape)
            )


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
    background, foreground, corner, mask = clone_inputs(background, foreground, offset, mask)
    guidance = as_choice(guidance, "guidance", GUIDANCE)
    return clone_problem_of(PoissonProblem, background, foreground, corner, mask, guidance)


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
    image, mask = inpaint_inputs(image, mask)
    return inpaint_problem_of(PoissonProblem, image, mask)


def build_clone_problem(
    background: Any,
    foreground: Any,
    corner: tuple[int, int],
    mask: Any,
    guidance: str,
) -> PoissonProblem:
    """:func:`clone_problem` with every argument given: ``corner`` is the offset.

    Examples
    --------
    >>> build_clone_problem(np.zeros((5, 5)), np.ones((3, 3)), (1, 1), None, "plain").corner
    (1, 1)
    """
    background, foreground, corner, mask = clone_inputs(background, foreground, corner, mask)
    guidance = as_choice(guidance, "guidance", GUIDANCE)
    return clone_problem_of(PoissonProblem, background, foreground, corner, mask, guidance)


def paste_window(problem: PoissonProblem, image: Any, window: Any) -> np.ndarray:
    """A copy of ``image`` (float) whose region pixels are those of ``window``.

    ``window`` has the shape of ``problem.values``; ``image`` holds the
    problem's window at ``problem.corner``. Both are checked (finite, their
    shapes); see :func:`course.poisson._build.paste` for arrays checked already.

    Examples
    --------
    >>> problem = clone_problem(np.zeros((4, 4)), np.zeros((3, 3)), (0, 1))
    >>> paste_window(problem, np.zeros((4, 4)), np.ones((3, 3)))[:, 1]
    array([0., 0., 1., 0.])
    """
    problem = as_problem(problem)
    image = problem._as_image(image, "image")

    def require_problem_shape(array: np.ndarray) -> None:
        if array.shape != problem.values.shape:
            raise ValueError(
                _("window must have the problem's shape {values_shape}; got {window_shape}").format(
                    values_shape=problem.values.shape, window_shape=array.shape
                )
            )

    return paste(problem, image, as_finite_array(window, "window", shape=require_problem_shape))


def as_problem(problem: Any) -> PoissonProblem:
    """``problem`` itself, if it is a :class:`PoissonProblem`; else TypeError."""
    if not isinstance(problem, PoissonProblem):
        raise TypeError(
            _(
                "problem must be a PoissonProblem, e.g. from clone_problem or inpaint_problem; got "
                "{problem}"
            ).format(problem=describe(problem))
        )
    return problem
