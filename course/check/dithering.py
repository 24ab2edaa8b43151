"""Lesson 06 exercise: the lab's ``DitheringErrorDiffuse``."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.check.base import CheckResult, close, run_cases
from course.error_diffusion import error_diffusion
from course.images import ramp

__all__ = ["dithering_error_diffuse"]


def _cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(6)
    return [
        {"gray": np.full((4, 6), 0.5)},
        {"gray": ramp((4, 16))},
        {"gray": rng.random((1, 10))},
        {"gray": np.full((8, 1), 0.3)},
        {"gray": rng.random((9, 13))},
        {"gray": rng.random((16, 16))},
    ]


def dithering_error_diffuse(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(gray)`` against Floyd-Steinberg as the lab specifies it.

    The function takes a gray float image ``gray`` (H, W) in [0, 1] and
    returns an (H, W) array of 0s and 1s: pixels in raster order (row by
    row, left to right), each 1 where its value plus the errors received is
    > 0.5, the error pushed 7/16 right, 3/16 below left, 5/16 below, 1/16
    below right, pushes off the image dropped. Compared exactly with
    ``course.dither.error_diffusion(gray, method="loop")``.

    Examples
    --------
    >>> from course.dither import error_diffusion
    >>> dithering_error_diffuse(lambda gray: error_diffusion(gray, method="loop"))
    PASS DitheringErrorDiffuse: all 6 cases pass
    >>> dithering_error_diffuse(lambda gray: (gray > 0.5).astype(float)).passed
    False
    """
    return run_cases(
        "DitheringErrorDiffuse",
        student,
        _cases(),
        reference=lambda gray: error_diffusion(gray, method="loop"),
        compare=close(atol=0, rtol=0),
        convert=lambda value: np.asarray(value, dtype=float),
        hint="visit the pixels row by row, left to right; threshold each at 0.5, and pass its "
        "error (value - output) on to the four neighbours not yet visited, 7/16 to the right, "
        "3/16, 5/16, 1/16 below.",
    )
