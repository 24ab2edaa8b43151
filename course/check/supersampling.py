"""Checker for lesson 04: the lab's supersampling (Task 6).

The student's ``supersample(image, out_shape, rate)`` returns the shrunk
image: for each output pixel, the mean of rate x rate bilinear samples at
the sub-pixel centres, with pixel centres at +0.5 (:mod:`course.resample`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.check.base import CheckResult, Mistake, close, run_cases
from course.check.pictures import image_picture
from course.resample import (
    bilinear,
    supersample,
    supersample_shifted,
    supersample_without_offset,
)

__all__ = ["bilinear_lookup", "image_supersampling"]


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
    is clamped). Values must agree within 1e-9. A failure shows the expected
    and given images and their difference, and names the lab report's
    shifts: samples at the sub-pixel corners, pixel centres at integers, or
    both.

    Examples
    --------
    >>> image_supersampling(supersample)
    PASS Supersampling: all 7 cases pass
    >>> image_supersampling(supersample_without_offset).mistake
    "the report's two shifts"
    """
    mistakes = [
        Mistake(
            "the report's two shifts",
            "your samples start at each sub-pixel's corner, i / rate, and your lookup takes "
            "pixel centres at whole numbers (ix = int(fx)), as the lab report does: the picture "
            "moves by (1/s - 1/rate) / 2 output pixels. Sample at (i + 0.5) / rate, and read "
            "pixel k as centred at k + 0.5.",
            supersample_without_offset,
        ),
        Mistake(
            "samples at the sub-pixel corners",
            "your samples sit at (c + i / rate), each sub-pixel's corner, so the picture moves "
            "half a sample spacing up and left. Sample at (c + (i + 0.5) / rate).",
            lambda image, out_shape, rate: supersample_shifted(
                image, out_shape, rate, sample_offset=0.0
            ),
        ),
        Mistake(
            "pixel centres at whole numbers",
            "your bilinear lookup takes pixel k to sit at x = k (ix = int(fx), weight fx - ix): "
            "its centre is at k + 0.5, so subtract 0.5 before splitting x into ix and the weight.",
            lambda image, out_shape, rate: supersample_shifted(
                image, out_shape, rate, pixel_centre=0.0
            ),
        ),
    ]

    def picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
        return image_picture(expected, given, title=f"case: rate {case['rate']}")

    return run_cases(
        "Supersampling",
        student,
        _cases(),
        supersample,
        close(atol=1e-9),
        np.asarray,
        hint="each output pixel averages rate x rate bilinear samples, spread evenly over the "
        "pixel's square: their positions are the pixel's corner plus (i + 0.5) / rate.",
        mistakes=mistakes,
        picture=picture,
    )


def _lookup_cases() -> list[dict[str, Any]]:
    gray = np.array([[0.0, 0.25, 1.0, 0.5], [1.0, 0.0, 0.75, 0.25], [0.5, 0.5, 0.0, 1.0]])
    colour = np.random.default_rng(3).random((2, 3, 3))
    points = [
        (1.3, 0.9),  # between four centres: all four weights matter
        (0.5, 0.5),  # on a centre: that pixel alone
        (2.0, 1.5),  # midway between two centres in x, on a row of centres
        (3.2, 2.8),  # beyond the last centres: clamped to the corner pixel
        (-0.4, 1.1),  # left of the first centre: clamped in x only
        (2.75, 0.25),
    ]
    cases = [{"image": gray, "x": x, "y": y} for x, y in points]
    cases += [{"image": colour, "x": x, "y": y} for x, y in ((1.9, 1.2), (0.2, 1.9))]
    return cases


def bilinear_lookup(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(image, x, y)``: the image at one point, blended from four centres.

    Pixel (r, c) is centred at (c + 0.5, r + 0.5); a point beyond the outer
    centres takes the edge value (clamped). Compared with
    :func:`course.resample.bilinear` to 1e-9, gray and colour.

    Examples
    --------
    >>> bilinear_lookup(bilinear)
    PASS bilinear: all 8 cases pass
    >>> bilinear_lookup(lambda image, x, y: bilinear(image, x + 0.5, y + 0.5)).mistake
    'pixel centres at whole numbers'
    """
    mistakes = [
        Mistake(
            "pixel centres at whole numbers",
            "you read pixel k as sitting at x = k, as the lab report's ix = int(fx) does: its "
            "centre is at k + 0.5. Subtract 0.5 from x and y before taking the whole and the "
            "fractional parts.",
            lambda image, x, y: bilinear(image, x + 0.5, y + 0.5),
        ),
        Mistake(
            "x and y swapped",
            "you read image[x, y]: an image is indexed by row first, image[y, x].",
            lambda image, x, y: bilinear(np.swapaxes(image, 0, 1), y, x),
        ),
        Mistake(
            "no blending: the nearest pixel",
            "you returned the pixel the point falls in; blend the four nearest centres, each "
            "weighted by how near the point is to it along x and along y.",
            lambda image, x, y: image[
                int(np.clip(np.floor(y), 0, image.shape[0] - 1)),
                int(np.clip(np.floor(x), 0, image.shape[1] - 1)),
            ],
        ),
    ]
    return run_cases(
        "bilinear",
        student,
        _lookup_cases(),
        bilinear,
        close(atol=1e-9),
        np.asarray,
        hint="with u = x - 0.5 and v = y - 0.5, the four centres around the point are at "
        "floor(u), floor(u) + 1 and floor(v), floor(v) + 1 (clamped to the image); blend "
        "them with the weights u - floor(u) and v - floor(v).",
        mistakes=mistakes,
    )
