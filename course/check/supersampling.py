"""Checker for lesson 04: the lab's supersampling (Task 6).

The student's ``supersample(image, out_shape, rate)`` returns the shrunk
image: for each output pixel, the mean of rate x rate bilinear samples at
the sub-pixel centres, with pixel centres at +0.5 (:mod:`course.resample`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.check.base import CheckResult, close, run_cases
from course.resample import supersample

__all__ = ["image_supersampling"]


def _cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(5)
    stripes = np.tile([0.0, 1.0], (6, 6))  # 6 x 12, one-pixel stripes
    return [
        {"image": stripes, "out_shape": (2, 4), "rate": 1},
        {"image": stripes, "out_shape": (2, 4), "rate": 3},
        {"image": rng.random((8, 8)), "out_shape": (2, 2), "rate": 4},
        {"image": rng.random((25, 25)), "out_shape": (3, 3), "rate": 5},  # 25 / 3: not whole
        {"image": rng.random((9, 12, 3)), "out_shape": (4, 5), "rate": 2},  # colour
        {"image": rng.random((5, 7)), "out_shape": (5, 7), "rate": 2},  # same size
        {"image": rng.random((3, 4)), "out_shape": (6, 8), "rate": 3},  # enlarging: clamped edges
    ]


def image_supersampling(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(image, out_shape, rate)`` against :func:`course.resample.supersample`.

    Cases: stripes that alias at rate 1, sizes that do not divide, colour,
    enlarging (which samples beyond the outer pixel centres, where the image
    is clamped). Values must agree within 1e-9.
    """
    return run_cases(
        "Supersampling",
        student,
        _cases(),
        supersample,
        close(atol=1e-9),
        np.asarray,
        hint="each output pixel averages rate x rate bilinear samples, spread evenly over the "
        "pixel's square: their positions are the pixel's corner plus (i + 0.5) / rate.",
    )
