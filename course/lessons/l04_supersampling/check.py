"""Checker for lesson 04: the lab's supersampling (Task 6).

The student's ``supersample(image, out_shape, rate)`` returns the shrunk
image: for each output pixel, the mean of rate x rate bilinear samples at
the sub-pixel centres, with pixel centres at +0.5 (:mod:`course.sampling.resample`).
The student's ``bilinear_sample(image, x, y)`` is checked on its own first,
its clamp at every edge included. An answer that calls the library's own
lookup or supersampling is told to write it.

Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("bilinear_sample")`` says more at once and
``check.hint("bilinear_sample", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.check.base import CheckResult, Mistake, close, hint, run_cases
from course.check.exercises import exercise
from course.check.hints import Hints
from course.check.pictures import image_picture, side_by_side
from course.i18n import N_, _
from course.lessons.graded_cases import drawn_in_order
from course.sampling import resample
from course.sampling.resample import (
    bilinear,
    supersample_shifted,
    supersample_without_offset,
)

__all__ = ["bilinear_sample", "hint", "supersample"]

_LIBRARY_FUNCTIONS = (
    resample.bilinear,
    resample.supersample,
    resample.supersample_shifted,
    resample.supersample_without_offset,
)


def _as_image(value: Any) -> np.ndarray:
    return np.asarray(value, dtype=float)


def _variant(
    image: Any,
    out_shape: Any,
    rate: int,
    whole_scale: bool = False,
    divide: str = "square",
    unscaled_offsets: bool = False,
    swapped_scales: bool = False,
) -> np.ndarray:
    """Supersampling with one of the slips: a whole-number scale, / rate for / rate^2, the
    sub-pixel offsets left in output pixels while the pixel's corner is in input pixels, or
    x scaled by H / h and y by W / w."""
    image = np.asarray(image, dtype=float)
    (height, width), (in_height, in_width) = out_shape, image.shape[:2]
    sx = in_width // width if whole_scale else in_width / width
    sy = in_height // height if whole_scale else in_height / height
    if swapped_scales:
        sx, sy = in_height / height, in_width / width
    offsets = (np.arange(rate) + 0.5) / rate
    offset_x, offset_y = (offsets, offsets) if unscaled_offsets else (offsets * sx, offsets * sy)
    xs = np.arange(width)[:, None] * sx + offset_x[None, :]  # (w, rate)
    ys = np.arange(height)[:, None] * sy + offset_y[None, :]  # (h, rate)
    grid_y = ys[:, None, :, None] + 0 * xs[None, :, None, :]
    grid_x = xs[None, :, None, :] + 0 * ys[:, None, :, None]
    samples = bilinear(image, grid_x.reshape(-1), grid_y.reshape(-1))
    samples = samples.reshape(height, width, rate * rate, *image.shape[2:])
    total = samples.sum(axis=2)
    return total / (rate if divide == "rate" else rate * rate)


def _cases() -> list[dict[str, Any]]:
    rng = np.random.default_rng(5)
    stripes = np.tile([0.0, 1.0], (6, 6))  # 6 x 12, one-pixel stripes
    return [
        # First a case where every named slip gives its own answer, none the right one: at
        # rate 1, offsets left unscaled and the report's two shifts agree, at 12 / 4 = 3 = rate
        # the report's two shifts cancel, and with H / h = 2 = 12 // 5 swapped scales look whole.
        {"image": stripes, "out_shape": (4, 5), "rate": 2},
        {"image": stripes, "out_shape": (2, 4), "rate": 1},
        {"image": stripes, "out_shape": (2, 4), "rate": 3},
        {"image": rng.random((8, 8)), "out_shape": (2, 2), "rate": 4},
        {"image": rng.random((25, 25)), "out_shape": (3, 3), "rate": 5},  # 25 / 3: not whole
        {"image": rng.random((9, 12, 3)), "out_shape": (4, 5), "rate": 2},  # colour
        {"image": rng.random((5, 7)), "out_shape": (5, 7), "rate": 2},  # same size
        {"image": rng.random((3, 4)), "out_shape": (6, 8), "rate": 3},  # enlarging: clamped edges
        {"image": rng.random((4, 4)), "out_shape": (2, 2), "rate": 2},  # 4 x 4: each slip shows
    ]


def _drawn_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``supersample``, drawn from ``rng``: the fixed cases' sizes, out_shapes
    and rates, in their order, with drawn pixels.

    One-pixel stripes of two drawn levels (one in [0, 0.4], the other in [0.6, 1], either
    first), 6 x 12, shrunk to 4 x 5 at rate 2, then to 2 x 4 at rates 1 and 3; then uniform
    noise: 8 x 8 to 2 x 2 at rate 4, 25 x 25 to 3 x 3 at rate 5 (a scale that is not whole),
    colour 9 x 12 to 4 x 5, 5 x 7 at its own size, 3 x 4 enlarged to 6 x 8 (clamped edges) and
    4 x 4 to 2 x 2.
    """
    levels = [rng.uniform(0.0, 0.4), rng.uniform(0.6, 1.0)]
    stripes = np.tile(rng.permutation(levels), (6, 6))
    return [
        {"image": stripes, "out_shape": (4, 5), "rate": 2},
        {"image": stripes, "out_shape": (2, 4), "rate": 1},
        {"image": stripes, "out_shape": (2, 4), "rate": 3},
        {"image": rng.random((8, 8)), "out_shape": (2, 2), "rate": 4},
        {"image": rng.random((25, 25)), "out_shape": (3, 3), "rate": 5},
        {"image": rng.random((9, 12, 3)), "out_shape": (4, 5), "rate": 2},
        {"image": rng.random((5, 7)), "out_shape": (5, 7), "rate": 2},
        {"image": rng.random((3, 4)), "out_shape": (6, 8), "rate": 3},
        {"image": rng.random((4, 4)), "out_shape": (2, 2), "rate": 2},
    ]


SUPERSAMPLE_HINTS = Hints(
    where=N_(
        "look at where your samples sit inside each output pixel's square, and at "
        "what you divide the sum by."
    ),
    more=N_(
        "output pixel (r, c) covers the input from c W / w to (c + 1) W / w (a float "
        "scale); its rate x rate samples sit at the centres of a rate x rate grid on that "
        "square, each read with your bilinear_sample, and the pixel is their mean."
    ),
    recipe=N_(
        "for each output pixel and i, j in range(rate): x = (c + (i + 0.5) / rate) "
        "W / w, y = (r + (j + 0.5) / rate) H / h; add bilinear_sample(image, x, y) / rate**2."
    ),
)


@exercise(
    hints=SUPERSAMPLE_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    handout_names=("supersampling",),
    draw=_drawn_cases,
)
def supersample(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(image, out_shape, rate)`` against
    :func:`course.sampling.resample.supersample`.

    Cases: stripes that alias at rate 1, sizes that do not divide, colour,
    enlarging (which samples beyond the outer pixel centres, where the image
    is clamped). Values must agree within 1e-9. A failure shows the expected
    and given images and their difference, and names the lab report's
    shifts: samples at the sub-pixel corners, pixel centres at integers, or
    both.

    Examples
    --------
    >>> supersample(lambda image, out_shape, rate: image).passed
    False
    """
    mistakes = [
        Mistake(
            _("the scale made whole"),
            _(
                "you divided the sizes with //, which drops the scale's fraction: W // w for "
                "W / w, H // h for H / h. Your samples then stop short of the input's right or "
                "bottom edge, wherever w does not divide W or h does not divide H. The scale is "
                "a float: W / w and H / h."
            ),
            lambda image, out_shape, rate: _variant(image, out_shape, rate, whole_scale=True),
        ),
        Mistake(
            _("divided by the rate, not its square"),
            _(
                "your pixels are rate times too bright: there are rate x rate samples per output "
                "pixel, so their mean divides by rate squared."
            ),
            lambda image, out_shape, rate: _variant(image, out_shape, rate, divide="rate"),
        ),
        Mistake(
            _("the two scales swapped"),
            _(
                "you scaled x by H / h and y by W / w: x runs along the width, so x = (c + (i + "
                "0.5) / rate) W / w and y = (r + (j + 0.5) / rate) H / h; out_shape is (h, w), "
                "rows first."
            ),
            lambda image, out_shape, rate: _variant(image, out_shape, rate, swapped_scales=True),
        ),
        Mistake(
            _("the sub-pixel offsets not scaled"),
            _(
                "your samples crowd into the first input pixels of each output pixel's square: "
                "you scaled the output pixel's corner by W / w but not the offset "
                "(i + 0.5) / rate, which is in output pixels too. Scale the whole position: "
                "x = (c + (i + 0.5) / rate) W / w."
            ),
            lambda image, out_shape, rate: _variant(image, out_shape, rate, unscaled_offsets=True),
        ),
        Mistake(
            _("the report's two shifts"),
            _(
                "your samples start at each sub-pixel's corner, i / rate, and your lookup takes "
                "pixel centres at whole numbers (ix = int(fx)), as the lab report does: the "
                "picture moves by (1/s - 1/rate) / 2 output pixels. Sample at (i + 0.5) / rate, "
                "and read pixel k as centred at k + 0.5."
            ),
            supersample_without_offset,
        ),
        Mistake(
            _("samples at the sub-pixel corners"),
            _(
                "your samples sit at (c + i / rate), each sub-pixel's corner, so the picture moves "
                "half a sample spacing up and left. Sample at (c + (i + 0.5) / rate)."
            ),
            lambda image, out_shape, rate: supersample_shifted(
                image, out_shape, rate, sample_offset=0.0
            ),
        ),
        Mistake(
            _("pixel centres at whole numbers"),
            _(
                "your bilinear lookup takes pixel k to sit at x = k (ix = int(fx), weight fx - "
                "ix): its centre is at k + 0.5, so subtract 0.5 before splitting x into ix and "
                "the weight."
            ),
            lambda image, out_shape, rate: supersample_shifted(
                image, out_shape, rate, pixel_centre=0.0
            ),
        ),
    ]

    def picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
        return image_picture(
            expected, given, title=_("case: rate {rate}").format(rate=case["rate"])
        )

    def pass_picture(results: list[tuple[dict[str, Any], Any, Any]]) -> bytes:
        _case, expected, given = results[3]  # the 25 x 25 noise shrunk to 3 x 3
        return side_by_side(expected, given, (_("expected"), _("your supersample")))

    return run_cases(
        "supersample",
        student,
        _cases(),
        resample.supersample,
        close(atol=1e-9),
        _as_image,
        mistakes=mistakes,
        picture=picture,
        pass_picture=pass_picture,
    )


def _lookup_cases() -> list[dict[str, Any]]:
    gray = np.array([[0.0, 0.25, 1.0, 0.5], [1.0, 0.0, 0.75, 0.25], [0.5, 0.5, 0.0, 1.0]])
    colour = np.random.default_rng(3).random((2, 3, 3))
    points = [
        # Between four centres, all four weights matter; here, unlike at (1.3, 0.8), reading
        # image[x, y] and weighting each centre by its distance give different values.
        (2.2, 1.3),
        (1.3, 0.8),
        (0.5, 0.5),  # on a centre: that pixel alone
        (2.0, 1.5),  # midway between two centres in x, on a row of centres
        (3.2, 2.8),  # beyond the last centres: clamped to the corner pixel
        (-0.4, 1.1),  # left of the first centre: clamped in x only
        (2.75, 0.25),
        (3.9, 1.2),  # right of the last centres: clamped in x
        (1.3, 2.9),  # below the last centres: clamped in y
        (3.8, 2.95),  # beyond the bottom-right centre
    ]
    cases = [{"image": gray, "x": x, "y": y} for x, y in points]
    cases += [{"image": colour, "x": x, "y": y} for x, y in ((1.9, 1.2), (0.2, 1.9))]
    return cases


def _lookup_mistakes() -> list[Mistake]:
    """The mistakes ``bilinear_sample``'s checker names, in the current language."""
    return [
        Mistake(
            _("no blending: the nearest pixel"),
            _(
                "you returned the pixel the point falls in; blend the four nearest centres, each "
                "weighted by how near the point is to it along x and along y."
            ),
            lambda image, x, y: image[
                int(np.clip(np.floor(y), 0, image.shape[0] - 1)),
                int(np.clip(np.floor(x), 0, image.shape[1] - 1)),
            ],
        ),
        Mistake(
            _("no clamp at the right or bottom edge"),
            _(
                "beyond the last pixel centres your blend reaches past the image (or "
                "extrapolates): a point right of the last centre, or below it, takes the edge "
                "value."
            ),
            _unclamped,
        ),
        Mistake(
            _("pixel centres at whole numbers"),
            _(
                "you read pixel k as sitting at x = k, as the lab report's ix = int(fx) does: its "
                "centre is at k + 0.5. Subtract 0.5 from x and y before taking the whole and the "
                "fractional parts."
            ),
            lambda image, x, y: bilinear(image, x + 0.5, y + 0.5),
        ),
        Mistake(
            _("int() where floor belongs"),
            _(
                "left of the first centres or above them, your blend reaches outside the four "
                "centres around the point: int() rounds toward zero, so for x - 0.5 = -0.9 it "
                "gives c = 0, not -1, and u = x - 1/2 - c comes out -0.9. Take "
                "math.floor(x - 0.5), or clamp x - 0.5 to [0, W - 1] first, as for the right and "
                "bottom edges."
            ),
            _truncated,
        ),
        Mistake(
            _("the weights flipped"),
            _(
                "you weighted each centre by its distance from the point, not by its nearness: "
                "the farther centre gets the larger share. With u = x - 1/2 - c the point's "
                "distance past the left centre, that centre gets 1 - u and the one right of it "
                "u; the same along y with v."
            ),
            _flipped,
        ),
        Mistake(
            _("x and y swapped"),
            _("you read image[x, y]: an image is indexed by row first, image[y, x]."),
            lambda image, x, y: bilinear(image, y, x),
        ),
    ]


def _drawn_lookup_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``bilinear_sample``, drawn from ``rng``, in the fixed cases' order.

    A gray 3 x 4 image of levels to 0.05 at ten points (to 0.01): two between four centres,
    one on a centre, one midway between two centres on a row of centres; beyond the
    bottom-right centre, left of the first centres (x - 1/2 in (-1, 0), where int() and
    floor differ), above the first centres, right of the last, below the last, and beyond
    the bottom-right centre again; then a colour 2 x 3 image at a point between four centres
    and one left of and below the outer centres. Each named mistake is caught, and named, at
    the case where the fixed cases catch it (:func:`~course.lessons.graded_cases.drawn_in_order`).
    """
    gray = rng.integers(0, 21, (3, 4)) / 20
    colour = rng.random((2, 3, 3))

    def at(low: float, high: float) -> float:
        return round(float(rng.uniform(low, high)), 2)

    def centre(size: int) -> float:
        return int(rng.integers(0, size)) + 0.5

    points = [
        lambda: (at(0.6, 3.4), at(0.6, 2.4)),
        lambda: (at(0.6, 3.4), at(0.6, 2.4)),
        lambda: (centre(4), centre(3)),
        lambda: (float(rng.integers(1, 4)), centre(3)),
        lambda: (at(3.55, 3.95), at(2.55, 2.95)),
        lambda: (at(-0.45, 0.45), at(0.6, 2.4)),
        lambda: (at(0.6, 3.4), at(0.05, 0.45)),
        lambda: (at(3.55, 3.95), at(0.6, 2.4)),
        lambda: (at(0.6, 3.4), at(2.55, 2.95)),
        lambda: (at(3.55, 3.95), at(2.55, 2.95)),
        lambda: (at(0.6, 2.4), at(0.6, 1.4)),
        lambda: (at(0.05, 0.45), at(1.55, 1.95)),
    ]
    fixed = _lookup_cases()

    def family(
        image: np.ndarray, point: Callable[[], tuple[float, float]]
    ) -> Callable[[], list[dict[str, Any]]]:
        return lambda: [dict(zip(("image", "x", "y"), (image, *point()), strict=True))]

    families = [
        family(gray if like["image"].ndim == 2 else colour, point)
        for like, point in zip(fixed, points, strict=True)
    ]
    return drawn_in_order(
        fixed, families, bilinear, close(atol=1e-9), _lookup_mistakes(), _as_image
    )


BILINEAR_HINTS = Hints(
    where=N_("look at where your code puts pixel centres, and at points near the image's edges."),
    more=N_(
        "pixel (r, c) is centred at (c + 0.5, r + 0.5); the point lies between four "
        "such centres and is their blend, each weighted by nearness along x and along y. A "
        "point beyond the outer centres, on any side, takes the edge value."
    ),
    recipe=N_(
        "X = x - 0.5 and Y = y - 0.5, clamped to [0, W - 1] and [0, H - 1]; the top-left "
        "centre is c = floor(X), r = floor(Y), with c + 1 and r + 1 kept inside the image; "
        "u = X - c and v = Y - r weigh them as the lesson says."
    ),
)


def _graded_bilinear_sample(image: Any, x: float, y: float) -> Any:
    """The grader's answer to ``bilinear_sample``: centres at half pixels, edges clamped."""
    pixels = np.asarray(image, dtype=float)
    height, width = pixels.shape[:2]

    def taps(position: float, size: int) -> tuple[int, int, float]:
        clamped = min(max(position, 0.0), size - 1)
        first = min(int(np.floor(clamped)), max(size - 2, 0))
        return first, min(first + 1, size - 1), clamped - first

    left, right, fx = taps(float(x) - 0.5, width)
    top, bottom, fy = taps(float(y) - 0.5, height)
    upper = pixels[top, left] * (1 - fx) + pixels[top, right] * fx
    lower = pixels[bottom, left] * (1 - fx) + pixels[bottom, right] * fx
    return upper * (1 - fy) + lower * fy


@exercise(
    hints=BILINEAR_HINTS,
    refuses=_LIBRARY_FUNCTIONS,
    handout_names=("bilinear",),
    grader_reference=_graded_bilinear_sample,
    draw=_drawn_lookup_cases,
)
def bilinear_sample(student: Callable[..., Any]) -> CheckResult:
    """Check ``student(image, x, y)``: the image at one point, blended from four centres.

    Pixel (r, c) is centred at (c + 0.5, r + 0.5); a point beyond the outer
    centres takes the edge value (clamped). Compared with
    :func:`course.sampling.resample.bilinear` to 1e-9, gray and colour.

    Examples
    --------
    >>> bilinear_sample(lambda image, x, y: image[int(y), int(x)]).mistake
    'no blending: the nearest pixel'
    """
    return run_cases(
        "bilinear_sample",
        student,
        _lookup_cases(),
        bilinear,
        close(atol=1e-9),
        _as_image,
        mistakes=_lookup_mistakes(),
    )


def _flipped(image: Any, x: float, y: float) -> np.ndarray:
    """The blend with each centre weighted by its distance: 1 - fx where fx belongs."""
    image = np.asarray(image, dtype=float)
    height, width = image.shape[:2]
    u = float(np.clip(x - 0.5, 0, width - 1))
    v = float(np.clip(y - 0.5, 0, height - 1))
    left, top = min(int(u), max(width - 2, 0)), min(int(v), max(height - 2, 0))
    right, bottom = min(left + 1, width - 1), min(top + 1, height - 1)
    fx, fy = u - left, v - top
    upper = image[top, left] * fx + image[top, right] * (1 - fx)
    lower = image[bottom, left] * fx + image[bottom, right] * (1 - fx)
    return upper * fy + lower * (1 - fy)


def _truncated(image: Any, x: float, y: float) -> np.ndarray:
    """The blend with int() for floor, clamping the centres' indices but not u and v.

    For u in (-1, 0), int(u) is 0: the weight u - 0 is negative and the blend extrapolates.
    """
    image = np.asarray(image, dtype=float)
    height, width = image.shape[:2]
    u, v = x - 0.5, y - 0.5
    left, top = int(u), int(v)
    fx, fy = u - left, v - top

    def at(row: int, column: int) -> np.ndarray:
        return image[min(max(row, 0), height - 1), min(max(column, 0), width - 1)]

    upper = at(top, left) * (1 - fx) + at(top, left + 1) * fx
    lower = at(top + 1, left) * (1 - fx) + at(top + 1, left + 1) * fx
    return upper * (1 - fy) + lower * fy


def _unclamped(image: Any, x: float, y: float) -> np.ndarray:
    """A blend clamped at the left and top only: past the last centres it extrapolates."""
    image = np.asarray(image, dtype=float)
    height, width = image.shape[:2]
    u, v = max(x - 0.5, 0.0), max(y - 0.5, 0.0)
    left, top = min(int(u), width - 2), min(int(v), height - 2)
    fx, fy = u - left, v - top
    upper = image[top, left] * (1 - fx) + image[top, left + 1] * fx
    lower = image[top + 1, left] * (1 - fx) + image[top + 1, left + 1] * fx
    return upper * (1 - fy) + lower * fy
