"""Building and pasting a Poisson problem from inputs checked already.

Kernels shared by :mod:`course.poisson.problem` (:func:`~course.poisson.problem.clone_problem`,
:func:`~course.poisson.problem.inpaint_problem`, the paste) and :mod:`course.poisson.editing`
(the clone, the naive paste and the inpainting), whose callers validated every input with
:mod:`course.poisson.inputs`. A problem built here is valid by construction, so it skips
:class:`~course.poisson.problem.PoissonProblem`'s own checks of its fields, but for its size,
which the fast path of the inputs' check leaves to it.

Unchecked kernels: this module trusts its callers and checks no input
(``UNCHECKED = True``, which the fuzz test reads).
"""

from __future__ import annotations

from typing import Any, TypeVar

import numpy as np

from course import limits
from course.i18n import _
from course.poisson import solvers
from course.poisson._layout import clipped_window

__all__ = ["clone_problem_of", "guidance_sum", "inpaint_problem_of", "paste", "problem_of"]

UNCHECKED = True  # kernels for checked callers; see the module docstring

Problem = TypeVar("Problem")


def problem_of(
    kind: type[Problem],
    values: np.ndarray,
    region: np.ndarray,
    source: np.ndarray,
    corner: tuple[int, int],
) -> Problem:
    """A ``kind`` (a frozen :class:`~course.poisson.problem.PoissonProblem`) of these fields,
    built from checked inputs: finite, the region a mask's box with a ring of False around it.

    Only the size is checked, as the problem's own check does: an image the inputs' fast
    path took unchecked may be larger than the solvers allow.
    """
    if values.size > limits.MAX_PIXELS * 3:
        raise ValueError(
            _(
                "values must be at least 3 x 3 and at most {most} pixels; got shape {values_shape}"
            ).format(most=limits.MAX_PIXELS, values_shape=values.shape)
        )
    problem = object.__new__(kind)
    for name, value in (("values", values), ("region", region), ("source", source)):
        object.__setattr__(problem, name, value)
    object.__setattr__(problem, "corner", corner)
    return problem


def clone_problem_of(
    kind: type[Problem],
    background: np.ndarray,
    foreground: np.ndarray,
    corner: tuple[int, int],
    mask: np.ndarray | None,
    guidance: str,
) -> Problem:
    """The clone's problem, on inputs that :func:`course.poisson.inputs.clone_inputs` checked."""
    height, width = foreground.shape[:2]
    if mask is None:
        mask = np.zeros((height, width), bool)
        mask[1:-1, 1:-1] = True
    # The masked rows and columns, from two reductions: np.nonzero of a 2-D mask is slow.
    rows, columns = np.flatnonzero(mask.any(axis=1)), np.flatnonzero(mask.any(axis=0))
    top, bottom = rows[0] - 1, rows[-1] + 2
    left, right = columns[0] - 1, columns[-1] + 2
    region = mask[top:bottom, left:right].copy()
    crop = (corner[0] + left, corner[1] + top)
    f = foreground[top:bottom, left:right]
    b = clipped_window(background, crop, region.shape)
    values = b.copy()
    _copy_where(values, f, region)
    source = guidance_sum(f, b, region, guidance)
    return problem_of(kind, values, region, source, (int(crop[0]), int(crop[1])))


def inpaint_problem_of(kind: type[Problem], image: np.ndarray, mask: np.ndarray) -> Problem:
    """The inpainting's problem, on inputs that :func:`course.poisson.inputs.inpaint_inputs`
    checked: the hole, cropped with a ring around it."""
    rows, columns = np.nonzero(mask)
    top, left = rows.min() - 1, columns.min() - 1
    window = (slice(top, rows.max() + 2), slice(left, columns.max() + 2))
    values = image[window].copy()
    return problem_of(
        kind, values, mask[window].copy(), np.zeros_like(values), (int(left), int(top))
    )


def guidance_sum(f: np.ndarray, b: np.ndarray, region: np.ndarray, guidance: str) -> np.ndarray:
    """``sum_q v_pq`` over the four neighbours of each region pixel, in the images' layout.

    Plain guidance sums to ``4 f_p - sum_q f_q``, written in place: with an
    array for every step, this was one of the clone's larger costs beside the
    solve.
    """
    height, width = region.shape
    total = np.zeros(f.shape)
    inner = total[1:-1, 1:-1]
    if guidance == "plain":
        np.multiply(f[1:-1, 1:-1], 4.0, out=inner)
    for dy, dx in solvers.NEIGHBOURS:
        neighbour = (slice(1 + dy, height - 1 + dy), slice(1 + dx, width - 1 + dx))
        if guidance == "plain":
            inner -= f[neighbour]
            continue
        step = f[1:-1, 1:-1] - f[neighbour]
        background_step = b[1:-1, 1:-1] - b[neighbour]
        inner += np.where(np.abs(step) > np.abs(background_step), step, background_step)
    inner[~region[1:-1, 1:-1]] = 0.0
    return total


def paste(problem: Any, image: np.ndarray, window: np.ndarray) -> np.ndarray:
    """A copy of ``image`` (float) whose ``problem``'s region pixels are those of ``window``."""
    x, y = problem.corner
    height, width = problem.region.shape
    result = np.array(image, dtype=float)
    target = result[y : y + height, x : x + width]
    if problem.rectangular:  # a slice copies several times faster than a mask
        target[1:-1, 1:-1] = window[1:-1, 1:-1]
    else:
        _copy_where(target, window, problem.region)
    return result


def _copy_where(target: np.ndarray, source: np.ndarray, mask: np.ndarray) -> None:
    """``source``'s pixels where the ``(h, w)`` ``mask`` is True into ``target``, in place.

    A channel at a time: with the mask broadcast over the channels
    (:func:`~course.poisson._layout.mask_for`), numpy copies three values per
    inner loop, and the clone spent a twentieth of its time in two such copies.

    Examples
    --------
    >>> target = np.zeros((1, 2, 3))
    >>> _copy_where(target, np.ones((1, 2, 3)), np.array([[False, True]]))
    >>> target[0]
    array([[0., 0., 0.],
           [1., 1., 1.]])
    """
    if source.ndim == 2:
        np.copyto(target, source, where=mask)
        return
    for channel in range(source.shape[-1]):
        np.copyto(target[..., channel], source[..., channel], where=mask)
