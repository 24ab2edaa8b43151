"""Lesson 08's exercise: the lab's boundary condition for the correction ``g``.

The lab's skeleton solves for ``g = result - foreground``, starting from an
array of zeros whose outer ring the student fills with ``background -
foreground``; the iterations then make ``g`` harmonic inside.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course import poisson
from course.check.base import CheckResult, close, run_cases

__all__ = ["poisson_boundary"]


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
    )
