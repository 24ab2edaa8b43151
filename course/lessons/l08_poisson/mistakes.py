"""The known mistakes lesson 08's checkers name, each reproduced on the checker's cases.

:func:`boundary_mistakes` are the wrong rings :func:`.check.boundary_ring` names: the
sign flipped, the background alone, x and y swapped, the offset ignored (the foreground
read at the background's corner), the ring read one pixel outside the foreground, and the
ring one pixel in. :func:`sweep_mistakes` are the
wrong loops :func:`.check.jacobi_solve` names: the sweep done in place (the lab's loop:
Gauss-Seidel), the lab's fixed count of sweeps, a stop one sweep late, a stop on the
change between sweeps, on the residual's mean, at a residual equal to the tolerance, on
a quarter of the residual or on its first channel alone, each channel of an RGB ``g``
swept until its own residual is small, the pair returned as ``(sweeps, g)``, and a sweep
that moves the fixed ring. Beside
them, :func:`jacobi_until`, the sweep checker's own answer, which the "one sweep late"
mistake runs a sweep longer, and :func:`same_sweeps`, its comparison. Both lists are
built in the current language, at each check.

Only the checkers call these, with their own cases and the student's answer as
:mod:`.check` has read it, so this module checks none (``UNCHECKED = True``; the fuzz
test skips it).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from course import poisson
from course.check.base import Mistake
from course.i18n import _
from course.poisson.solvers import jacobi_sweeps, residual
from course.poisson.windows import image_of, planes_of

UNCHECKED = True  # see the module docstring

__all__ = [
    "BOUNDARY_MISTAKES",
    "SWEEP_MISTAKES",
    "boundary_mistakes",
    "count_first",
    "count_of",
    "each_channel_alone",
    "first_channel",
    "fixed_count",
    "g_residual",
    "gauss_seidel_until",
    "jacobi_residuals",
    "jacobi_until",
    "ring_moved",
    "ring_one_in",
    "ring_one_out",
    "ring_swept",
    "same_but_corners",
    "same_count_first",
    "same_each_channel",
    "same_sweeps",
    "swapped_offset",
    "sweep_mistakes",
    "until_change",
    "until_residual_measure",
]


def swapped_offset(background: Any, foreground: Any, offset: Any) -> np.ndarray:
    """The lab's ring with the background read at ``(offset[1], offset[0])``."""
    return poisson.correction_boundary(background, foreground, (offset[1], offset[0]))


def ring_one_out(background: Any, foreground: Any, offset: Any) -> np.ndarray:
    """g's ring read from the background one pixel outside the foreground (the row above
    it, the row below, the columns beside; a corner from its column), minus the
    foreground's ring; 0 inside. Past the background's edge, its nearest pixel."""
    back, fore = np.asarray(background, dtype=float), np.asarray(foreground, dtype=float)
    x, y = offset
    height, width = fore.shape[:2]
    padded = np.pad(back, [(1, 1), (1, 1)] + [(0, 0)] * (back.ndim - 2), mode="edge")
    around = padded[y : y + height + 2, x : x + width + 2]  # background[y - 1 : y + height + 1]
    g = np.zeros_like(fore)
    g[0], g[-1] = around[0, 1:-1] - fore[0], around[-1, 1:-1] - fore[-1]
    g[:, 0], g[:, -1] = around[1:-1, 0] - fore[:, 0], around[1:-1, -1] - fore[:, -1]
    return g


def same_but_corners(expected: Any, given: Any) -> bool:
    """``given`` is ``expected`` to 1e-12 but at the four corners, which a ring read from
    outside takes from the row or the column, as the student's order of writing has it."""
    want, have = np.asarray(expected, dtype=float), np.asarray(given, dtype=float)
    if want.shape != have.shape or want.ndim < 2 or min(want.shape[:2]) < 2:
        return False
    near = np.isclose(want, have, atol=1e-12, rtol=0.0)
    near[[0, 0, -1, -1], [0, -1, 0, -1]] = True
    return bool(near.all())


def ring_one_in(background: Any, foreground: Any, offset: Any) -> np.ndarray:
    """background - foreground on the ring one pixel inside the outer ring, 0 elsewhere (the
    outer ring too)."""
    back, fore = np.asarray(background, dtype=float), np.asarray(foreground, dtype=float)
    x, y = offset
    height, width = fore.shape[:2]
    difference = back[y : y + height, x : x + width] - fore
    g = np.zeros_like(fore)
    g[1:-1, 1:-1] = difference[1:-1, 1:-1]
    g[2:-2, 2:-2] = 0
    return g


def boundary_mistakes() -> tuple[Mistake, ...]:
    """The known mistakes, in the current language."""
    return (
        Mistake(
            _("the sign flipped"),
            _(
                "your ring holds foreground - background. The report's formula is right: "
                "g = background - foreground, so that foreground + g is the background on the ring."
            ),
            lambda background, foreground, offset: (
                -poisson.correction_boundary(background, foreground, offset)
            ),
        ),
        Mistake(
            _("the background alone"),
            _(
                "your ring holds the background, without subtracting the foreground: the result "
                "foreground + g is then the background plus the foreground on the ring."
            ),
            lambda background, foreground, offset: poisson.correction_boundary(
                background, np.zeros_like(foreground), offset
            ),
        ),
        Mistake(
            _("x and y swapped"),
            _(
                "you read the background at (offset[1], offset[0]): offset is (x, y), the column "
                "first, and background[y, x] is row y."
            ),
            swapped_offset,
        ),
        Mistake(
            _("the offset ignored"),
            _(
                "you read the background at its top-left corner, background[0 : height, "
                "0 : width], whatever the offset: offset = (x, y) puts the foreground's top-left "
                "pixel at background[y, x], so read background[y : y + height, x : x + width]."
            ),
            lambda background, foreground, offset: poisson.correction_boundary(
                background, foreground, (0, 0)
            ),
        ),
        Mistake(
            _("the ring one pixel out"),
            _(
                "your ring reads the background one pixel outside the foreground (the row above "
                "it, the row below, the columns beside). The ring is the foreground's own "
                "outermost pixels: g[0] is background[y, x : x + width] - foreground[0], the "
                "row under the foreground's top row."
            ),
            ring_one_out,
            matches=same_but_corners,
        ),
        Mistake(
            _("the ring one pixel in"),
            _(
                "you filled the pixels one inside the outer ring and left the outer ring at 0. "
                "The ring is the foreground's own outermost pixels, g[0], g[-1], g[:, 0] and "
                "g[:, -1]; everything inside it is 0."
            ),
            ring_one_in,
        ),
    )


BOUNDARY_MISTAKES = boundary_mistakes()


def _inside(image: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``image`` as channel planes, its inside as the region, and no source: g's problem."""
    planes = planes_of(image)
    region = np.zeros(planes.shape[1:], dtype=bool)
    region[1:-1, 1:-1] = True
    return planes, region, np.zeros_like(planes)


def jacobi_until(g: Any, tolerance: float, late: int = 0) -> tuple[np.ndarray, int]:
    """Jacobi sweeps on ``g``'s inside until the residual is below ``tolerance``, then
    ``late`` more (a loop that tests after it sweeps)."""
    image = np.asarray(g, dtype=float)
    planes, region, source = _inside(image)
    count, u = 0, planes
    sweeps = jacobi_sweeps(planes, region, source)
    while residual(u, region, source) >= tolerance:
        u, count = next(sweeps), count + 1
    for _late in range(late):
        u, count = next(sweeps), count + 1
    return image_of(u, image), count


def jacobi_residuals(g: Any, sweeps: int) -> np.ndarray:
    """The residual of ``g`` (the largest over the inside and every channel) before the first
    sweep and after each of ``sweeps`` Jacobi sweeps: ``sweeps + 1`` values."""
    planes, region, source = _inside(np.asarray(g, dtype=float))
    iterates = jacobi_sweeps(planes, region, source)
    after = (residual(next(iterates), region, source) for _sweep in range(sweeps))
    return np.array([residual(planes, region, source), *after])


def g_residual(g: Any) -> float:
    """The residual of ``g`` itself: the largest |up + down + left + right - 4 g| inside."""
    planes, region, source = _inside(np.asarray(g, dtype=float))
    return residual(planes, region, source)


def count_of(sweeps: Any) -> int | None:
    """A returned count as an int, or None when it is not one whole number."""
    try:
        count = float(sweeps) if np.ndim(sweeps) == 0 else math.nan
    except (TypeError, ValueError, OverflowError):
        return None
    return int(count) if math.isfinite(count) and count == int(count) else None


def same_sweeps(expected: Any, given: Any) -> bool:
    """Whether ``given`` is the pair ``expected`` is: g to 1e-12, and the same count."""
    try:
        g, sweeps = given
    except (TypeError, ValueError):
        return False
    want_g, want_sweeps = expected
    g = np.asarray(g, dtype=float)
    return (
        count_of(sweeps) == want_sweeps
        and g.shape == want_g.shape
        and bool(np.allclose(g, want_g, atol=1e-12, rtol=0.0))
    )


class _ChannelByChannel(tuple):
    """``(g, sweeps)`` of a loop that sweeps each channel apart; ``counts``: each channel's."""

    counts: tuple[int, ...]


def each_channel_alone(g: Any, tolerance: float) -> tuple[np.ndarray, int]:
    """Each channel of an RGB ``g`` swept on its own until its own residual is below
    ``tolerance``: the largest of the channels' counts is the count returned."""
    image = np.asarray(g, dtype=float)
    if image.ndim != 3:
        return jacobi_until(image, tolerance)
    swept = [jacobi_until(image[..., channel], tolerance) for channel in range(image.shape[2])]
    counts = tuple(count for _plane, count in swept)
    answer = _ChannelByChannel((np.stack([plane for plane, _count in swept], axis=-1), max(counts)))
    answer.counts = counts
    return answer


def same_each_channel(theirs: Any, given: Any) -> bool:
    """``given`` is :func:`each_channel_alone`'s g, with the largest of its channels' counts,
    their sum or the last channel's (when the channels' counts differ)."""
    counts = getattr(theirs, "counts", (theirs[1],))
    allowed = {max(counts)} | ({sum(counts), counts[-1]} if len(set(counts)) > 1 else set())
    try:
        g, sweeps = given
    except (TypeError, ValueError):
        return False
    count = count_of(sweeps)
    return count in allowed and same_sweeps((theirs[0], count), (g, count))


def count_first(g: Any, tolerance: float) -> tuple[int, np.ndarray]:
    """The right sweeps, returned in the wrong order: ``(sweeps, g)``."""
    swept, sweeps = jacobi_until(g, tolerance)
    return sweeps, swept


def same_count_first(theirs: Any, given: Any) -> bool:
    """``given`` is ``(sweeps, g)`` as :func:`count_first` returns it."""
    try:
        sweeps, g = given
    except (TypeError, ValueError):
        return False
    return same_sweeps((theirs[1], theirs[0]), (g, sweeps))


def gauss_seidel_until(g: Any, tolerance: float) -> tuple[np.ndarray, int]:
    """The lab's loop, which writes g in place: Gauss-Seidel."""
    u = np.array(g, dtype=float)
    height, width = u.shape[:2]
    count = 0
    while True:
        inner = u[:-2, 1:-1] + u[2:, 1:-1] + u[1:-1, :-2] + u[1:-1, 2:] - 4 * u[1:-1, 1:-1]
        if np.abs(inner).max() < tolerance:
            return u, count
        for y in range(1, height - 1):
            for x in range(1, width - 1):
                u[y, x] = (u[y - 1, x] + u[y + 1, x] + u[y, x - 1] + u[y, x + 1]) * 0.25
        count += 1


def until_change(g: Any, tolerance: float) -> tuple[np.ndarray, int]:
    """Jacobi sweeps until the largest change of one sweep is below ``tolerance``."""
    u = np.array(g, dtype=float)
    count = 0
    while True:
        new = u.copy()
        new[1:-1, 1:-1] = (u[:-2, 1:-1] + u[2:, 1:-1] + u[1:-1, :-2] + u[1:-1, 2:]) / 4
        count += 1
        if u.size == 0 or np.abs(new - u).max() < tolerance:
            return new, count
        u = new


def until_residual_measure(
    g: Any, tolerance: float, measure: Callable[[np.ndarray], float]
) -> tuple[np.ndarray, int]:
    """Jacobi sweeps until ``measure(|residual|)`` (over the inside, every channel) is below
    ``tolerance``: the residual's mean, a quarter of its max, or its first channel's."""
    u = np.array(g, dtype=float)
    count = 0
    while True:
        neighbours = u[:-2, 1:-1] + u[2:, 1:-1] + u[1:-1, :-2] + u[1:-1, 2:]
        if neighbours.size == 0 or measure(np.abs(neighbours - 4 * u[1:-1, 1:-1])) < tolerance:
            return u, count
        u = u.copy()
        u[1:-1, 1:-1] = neighbours / 4
        count += 1


def first_channel(size: np.ndarray) -> float:
    """The largest of ``size`` in channel 0 alone (all of it, for a gray ``g``)."""
    return float((size[..., 0] if size.ndim == 3 else size).max())


def fixed_count(expected: Any, given: Any) -> bool:
    """A sweep count far past what the tolerance needs: the lab's fixed loop of 8000."""
    try:
        _, sweeps = given
        return int(sweeps) >= 1000 and int(sweeps) != int(expected[1])
    except (TypeError, ValueError):
        return False


class _RingMoved(tuple):
    """``(g, sweeps)`` of a sweep that moved the ring; ``before``: the g it was given."""

    before: np.ndarray


def ring_swept(g: Any, tolerance: float) -> tuple[np.ndarray, int]:
    """Sweeps of every pixel, the ring too, each the mean of its four neighbours (the edge
    repeated past the array), until the residual inside is below ``tolerance``."""
    u = np.array(g, dtype=float)
    count = 0
    while count < 10_000:  # the ring drifts to one level, and the residual with it to 0
        padded = np.pad(u, [(1, 1), (1, 1)] + [(0, 0)] * (u.ndim - 2), mode="edge")
        neighbours = padded[:-2, 1:-1] + padded[2:, 1:-1] + padded[1:-1, :-2] + padded[1:-1, 2:]
        if u.size == 0 or np.abs(neighbours - 4 * u)[1:-1, 1:-1].max() < tolerance:
            break
        u, count = neighbours / 4, count + 1
    answer = _RingMoved((u, count))
    answer.before = np.asarray(g, dtype=float)
    return answer


def ring_moved(theirs: Any, given: Any) -> bool:
    """``given``'s g has the input's shape and a ring that is not the input's."""
    try:
        g, _sweeps = given
        g = np.asarray(g, dtype=float)
    except (TypeError, ValueError):
        return False
    before = getattr(theirs, "before", None)
    if before is None or g.shape != before.shape or min(g.shape[:2]) < 2:
        return False
    ring = np.ones(g.shape[:2], dtype=bool)
    ring[1:-1, 1:-1] = False
    return not np.allclose(g[ring], before[ring], atol=1e-12, rtol=0.0)


def sweep_mistakes() -> tuple[Mistake, ...]:
    """The known mistakes, in the current language."""
    return (
        Mistake(
            _("in place: Gauss-Seidel"),
            _(
                "your sweep writes g as it goes, so each pixel already sees its new upper and left "
                "neighbours: that is Gauss-Seidel, and so is the lab's loop, whatever its comment "
                "says. Jacobi computes every new value from the old array (a copy, or all four "
                "shifted slices at once)."
            ),
            gauss_seidel_until,
        ),
        Mistake(
            _("a fixed number of sweeps"),
            _(
                "you ran a fixed count of sweeps, as the lab's loop runs 8000: the exercise "
                "stops as soon as the residual is below the tolerance, and returns how many "
                "sweeps that took."
            ),
            lambda g, tolerance: (np.asarray(g, dtype=float), 0),
            matches=fixed_count,
        ),
        # Before the stop on the change: on an array already harmonic both give one sweep, and
        # only a loop that sweeps before it tests fails nothing else.
        Mistake(
            _("one sweep late"),
            _(
                "you sweep before you test: the loop must stop as soon as the residual is below "
                "the tolerance, so an array already within it gets no sweep at all."
            ),
            lambda g, tolerance: jacobi_until(g, tolerance, late=1),
        ),
        Mistake(
            _("a stop on the change between sweeps"),
            _(
                "you stopped when one sweep changed g by less than the tolerance: that change is "
                "a quarter of the residual, so your loop stops while the residual is still up to "
                "four times the tolerance. Test the residual, max |up + down + left + right - 4 "
                "g| over the inside, before each sweep."
            ),
            until_change,
        ),
        Mistake(
            _("the mean of the residual instead of its largest value"),
            _(
                "you compared the mean of |up + down + left + right - 4 g| over the inside with "
                "the tolerance: the exercise compares its largest value, so the loop goes on "
                "while any one pixel is still far from the mean of its neighbours."
            ),
            lambda g, tolerance: until_residual_measure(g, tolerance, np.mean),
        ),
        # Before the quarter: on the residual equal to the tolerance (case 5) both stop at once.
        Mistake(
            _("a stop at a residual equal to the tolerance"),
            _(
                "your loop stops when the residual is at or below the tolerance (<=): it stops "
                "only below it (<), so a residual equal to the tolerance still gets a sweep."
            ),
            lambda g, tolerance: until_residual_measure(
                g, tolerance, lambda size: float(np.nextafter(size.max(), -np.inf))
            ),
        ),
        Mistake(
            _("a quarter of the residual"),
            _(
                "you compared the residual divided by 4 (the mean of the four neighbours minus "
                "g, which is the change the next sweep makes) with the tolerance: your loop "
                "stops while the residual is still up to four times the tolerance. Compare the "
                "residual itself, max |up + down + left + right - 4 g|."
            ),
            lambda g, tolerance: until_residual_measure(
                g, tolerance, lambda size: float(size.max()) / 4
            ),
        ),
        Mistake(
            _("the residual of the first channel only"),
            _(
                "your residual looks at channel 0 only: on an RGB g the loop goes on until the "
                "residual of every channel is below the tolerance, the largest value over the "
                "inside and all three channels."
            ),
            lambda g, tolerance: until_residual_measure(g, tolerance, first_channel),
        ),
        Mistake(
            _("each channel stopped on its own"),
            _(
                "you swept each channel until its own residual was below the tolerance, so a "
                "channel that settles early stops while the others go on. The exercise sweeps "
                "the three channels together, all of them at each sweep, and stops when the "
                "largest residual over every pixel and every channel is below the tolerance: "
                "the sweep of the whole (H, W, 3) array at once does it."
            ),
            each_channel_alone,
            matches=same_each_channel,
        ),
        Mistake(
            _("the number of sweeps first"),
            _(
                "you returned (sweeps, g): the exercise returns the array first, then the "
                "number of sweeps, as return g, sweeps."
            ),
            count_first,
            matches=same_count_first,
        ),
        Mistake(
            _("the ring changed"),
            _(
                "your sweep moves the outer ring too (g[0], g[-1], g[:, 0] and g[:, -1]): those "
                "are the boundary values b - f, fixed, and once they move the clone no longer "
                "meets the background at its edge. Sweep the inside only, g[1:-1, 1:-1], from "
                "the four shifted slices."
            ),
            ring_swept,
            matches=ring_moved,
        ),
    )


SWEEP_MISTAKES = sweep_mistakes()
