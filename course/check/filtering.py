"""Lesson 07 exercises: the lab's ``Blur`` and ``Edge``."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.check.base import CheckResult, close, run_cases
from course.filters import blur as reference_blur
from course.filters import sobel

__all__ = ["blur", "edge"]


def _cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(7)
    return [
        {"image": rng.random((5, 7))},
        {"image": rng.random((1, 1))},
        {"image": rng.random((1, 6))},
        {"image": rng.random((6, 1))},
        {"image": rng.random((2, 2))},
        {"image": rng.random((4, 5, 3))},
    ]


def _as_float(value: Any) -> np.ndarray:
    return np.asarray(value, dtype=float)


def blur(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(image)``: the 3 x 3 box blur with the handout's border rule.

    ``image`` is gray (H, W) or RGB (H, W, 3) in [0, 1]; each output pixel is
    the mean of the pixels of its 3 x 3 neighbourhood that lie in the image
    (9 inside, 6 on an edge, 4 in a corner), per channel. Compared with
    ``course.filters.blur`` within 1e-9.

    Examples
    --------
    >>> from course.filters import blur as library_blur
    >>> blur(library_blur)
    PASS Blur: all 6 cases pass
    """
    return run_cases(
        "Blur",
        student,
        _cases(),
        reference_blur,
        close(1e-9),
        _as_float,
        hint="each output pixel is the mean of the 3 x 3 neighbours that lie inside the image: "
        "9 inside, 6 on an edge, 4 at a corner.",
    )


def edge(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(image)``: the Sobel gradient magnitude, border replicated.

    ``Gx`` and ``Gy`` are the dot products of ``[[-1, 0, 1], [-2, 0, 2],
    [-1, 0, 1]]`` and its transpose with each 3 x 3 window, a pixel outside
    the image taking the value of the nearest one inside; the output is
    ``sqrt(Gx**2 + Gy**2)``, per channel, not clipped. Compared with
    ``course.filters.sobel(image, border="replicate")`` within 1e-9.

    Examples
    --------
    >>> from course.filters import sobel
    >>> edge(sobel)
    PASS Edge: all 6 cases pass
    """
    return run_cases(
        "Edge",
        student,
        _cases(),
        lambda image: sobel(image, border="replicate"),
        close(1e-9),
        _as_float,
        hint="read outside pixels from the nearest pixel inside (clamp the index); Gx and Gy "
        "are two 3 x 3 weighted sums, and the answer is sqrt(Gx^2 + Gy^2).",
    )
