"""Lesson 08's exercises: the lab's boundary ring for the correction ``g``, and its sweep.

The lab's skeleton solves for ``g = result - foreground``, starting from an
array of zeros whose outer ring the student fills with ``background -
foreground`` (:func:`poisson_boundary`); Jacobi sweeps then make ``g``
harmonic inside, each pixel the mean of its four neighbours, until the
residual is small (:func:`jacobi_sweep`). Failures draw the difference and
recognise the sign flipped, x and y swapped, the sweep done in place (the
lab's loop: Gauss-Seidel), the ring swept too and a stop one sweep late.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course import poisson
from course.check.base import CheckResult, Mistake, close, run_cases
from course.check.pictures import image_picture
from course.poisson_problem import image_of, planes_of
from course.poisson_solvers import jacobi_sweeps, residual

__all__ = ["jacobi_sweep", "poisson_boundary"]


def _cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(8)

    def image(*shape: int) -> np.ndarray:
        # Multiples of 1/16: every difference is exact, so equality is too.
        return rng.integers(0, 17, shape) / 16

    return [
        # Gray, square, one pixel in: the smallest case.
        {"background": image(5, 5), "foreground": image(3, 3), "offset": (1, 1)},
        # x and y differ, and so do width and height: swapping them shows.
        {"background": image(6, 9), "foreground": image(3, 5), "offset": (3, 1)},
        # RGB, in the background's bottom-right corner: the far edges count.
        {"background": image(7, 8, 3), "foreground": image(4, 6, 3), "offset": (2, 3)},
        # At the origin.
        {"background": image(6, 6, 3), "foreground": image(5, 4, 3), "offset": (0, 0)},
    ]


def poisson_boundary(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(background, foreground, offset)`` against the lab's boundary setup.

    It must return ``g``, of the foreground's shape: ``background - foreground``
    on the foreground's outer ring (``offset = (x, y)`` places the
    foreground's top-left pixel at ``background[y, x]``), and 0 inside.

    Examples
    --------
    >>> from course.poisson import correction_boundary
    >>> poisson_boundary(correction_boundary)
    PASS poisson_boundary: all 4 cases pass
    >>> zeros = lambda background, foreground, offset: foreground * 0
    >>> print(poisson_boundary(zeros))  # doctest: +ELLIPSIS
    FAIL poisson_boundary: case 1 is wrong
    ...
    """
    return run_cases(
        "poisson_boundary",
        student,
        _cases(),
        poisson.correction_boundary,
        close(atol=1e-12, rtol=0),
        convert=lambda g: np.asarray(g, dtype=float),
        hint="the correction is zero inside and, on the region's border, the difference "
        "between the background and the pasted image there.",
        mistakes=BOUNDARY_MISTAKES,
        picture=_boundary_picture,
    )


def _boundary_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
    # g lies in [-1, 1]: shown as (g + 1) / 2, so 0 is mid-gray.
    return image_picture(
        (np.asarray(expected, dtype=float) + 1) / 2,
        (np.asarray(given, dtype=float) + 1) / 2,
        title="g, shown as (g + 1) / 2: 0 is mid-gray",
    )


def _swapped_offset(background: Any, foreground: Any, offset: Any) -> np.ndarray:
    return poisson.correction_boundary(background, foreground, (offset[1], offset[0]))


BOUNDARY_MISTAKES = (
    Mistake(
        "the sign flipped",
        "your ring holds foreground - background. The report's formula is right: "
        "g = background - foreground, so that foreground + g is the background on the ring.",
        lambda background, foreground, offset: (
            -poisson.correction_boundary(background, foreground, offset)
        ),
    ),
    Mistake(
        "the background alone",
        "your ring holds the background, without subtracting the foreground: the result "
        "foreground + g is then the background plus the foreground on the ring.",
        lambda background, foreground, offset: poisson.correction_boundary(
            background, np.zeros_like(foreground), offset
        ),
    ),
    Mistake(
        "x and y swapped",
        "you read the background at (offset[1], offset[0]): offset is (x, y), the column "
        "first, and background[y, x] is row y.",
        _swapped_offset,
    ),
)


def _sweep_cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(18)

    def ring(*shape: int) -> np.ndarray:
        g = np.zeros(shape)
        edge = rng.integers(-16, 17, shape) / 16  # multiples of 1/16, as the ring's differences
        g[0], g[-1], g[:, 0], g[:, -1] = edge[0], edge[-1], edge[:, 0], edge[:, -1]
        return g

    return [
        {"g": ring(4, 5), "tolerance": 1e-3},
        {"g": ring(7, 12), "tolerance": 1e-6},
        {"g": ring(6, 9, 3), "tolerance": 1e-4},
        {"g": np.zeros((5, 5)), "tolerance": 1e-6},  # already harmonic: no sweep at all
    ]


def _jacobi_until(g: Any, tolerance: float, late: int = 0) -> tuple[np.ndarray, int]:
    """Jacobi sweeps on ``g``'s inside until the residual is below ``tolerance``, then
    ``late`` more (a loop that tests after it sweeps)."""
    image = np.asarray(g, dtype=float)
    planes = planes_of(image)
    region = np.zeros(planes.shape[1:], dtype=bool)
    region[1:-1, 1:-1] = True
    source = np.zeros_like(planes)
    count, u = 0, planes
    sweeps = jacobi_sweeps(planes, region, source)
    while residual(u, region, source) >= tolerance:
        u, count = next(sweeps), count + 1
    for _ in range(late):
        u, count = next(sweeps), count + 1
    return image_of(u, image), count


def _gauss_seidel_until(g: Any, tolerance: float) -> tuple[np.ndarray, int]:
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


def _same_sweeps(expected: Any, given: Any) -> bool:
    try:
        g, sweeps = given
    except (TypeError, ValueError):
        return False
    want_g, want_sweeps = expected
    g = np.asarray(g, dtype=float)
    return (
        int(sweeps) == want_sweeps
        and g.shape == want_g.shape
        and bool(np.allclose(g, want_g, atol=1e-12, rtol=0.0))
    )


def _sweep_difference(expected: Any, given: Any) -> str:
    want_g, want_sweeps = expected
    try:
        g, sweeps = given
        g = np.asarray(g, dtype=float)
    except (TypeError, ValueError):
        return "return two things: the array g and the number of sweeps"
    parts = [f"sweeps: expected {want_sweeps}, given {sweeps}"]
    if g.shape != want_g.shape:
        parts.append(f"g: expected shape {want_g.shape}, given {g.shape}")
    else:
        worst = np.unravel_index(np.abs(g - want_g).argmax(), g.shape)
        parts.append(
            f"largest difference in g at [row, column] {list(map(int, worst[:2]))}: "
            f"expected {want_g[worst]:.6g}, given {g[worst]:.6g}"
        )
    return "; ".join(parts)


def _sweep_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes | None:
    try:
        g = np.asarray(given[0], dtype=float)
    except (TypeError, ValueError, IndexError):
        return None
    return image_picture(
        (expected[0] + 1) / 2, (g + 1) / 2, title="g after the sweeps, shown as (g + 1) / 2"
    )


def _show_sweeps(answer: Any) -> str:
    try:
        g, sweeps = answer
        return f"g of shape {np.shape(g)} after {sweeps} sweeps"
    except (TypeError, ValueError):
        return f"{type(answer).__name__} (expected a pair: g and the number of sweeps)"


SWEEP_MISTAKES = (
    Mistake(
        "in place: Gauss-Seidel",
        "your sweep writes g as it goes, so each pixel already sees its new upper and left "
        "neighbours: that is Gauss-Seidel, and so is the lab's loop, whatever its comment "
        "says. Jacobi computes every new value from the old array (a copy, or all four "
        "shifted slices at once).",
        _gauss_seidel_until,
    ),
    Mistake(
        "one sweep late",
        "you sweep before you test: the loop must stop as soon as the residual is below the "
        "tolerance, so an array already within it gets no sweep at all.",
        lambda g, tolerance: _jacobi_until(g, tolerance, late=1),
    ),
)


def jacobi_sweep(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(g, tolerance) -> (g, sweeps)``: Jacobi sweeps until the residual is small.

    The outer ring of ``g`` (gray ``(H, W)`` or RGB ``(H, W, 3)``) is fixed;
    each sweep replaces every inside pixel by the mean of its four
    neighbours in the previous array. Before each sweep, the residual
    ``max |g_up + g_down + g_left + g_right - 4 g|`` over the inside is
    compared with ``tolerance``: below it, stop and return the array and the
    number of sweeps done. The input is not changed.

    Examples
    --------
    >>> jacobi_sweep(_jacobi_until)
    PASS jacobi_sweep: all 4 cases pass
    """
    return run_cases(
        "jacobi_sweep",
        student,
        _sweep_cases(),
        _jacobi_until,
        _same_sweeps,
        hint="loop: compute the residual from the four shifted slices; stop if it is below "
        "the tolerance; else set the inside to their sum / 4 (all from the old values) and "
        "count the sweep.",
        mistakes=SWEEP_MISTAKES,
        difference=_sweep_difference,
        picture=_sweep_picture,
        show=_show_sweeps,
    )
