"""The known mistakes lesson 04's checkers name, each reproduced on the checker's cases.

:func:`lookup_mistakes` are the wrong lookups :func:`.check.bilinear_sample` names: the
nearest pixel, no clamp at the right or bottom edge, the point clamped before the half-pixel
shift, pixel centres at whole numbers, int() or round() where floor belongs, the weights
flipped, x and y swapped, and a read past the image (IndexError).
:func:`supersample_mistakes` are the wrong loops :func:`.check.supersample` names: the
scale made whole, a division by the rate, the scales swapped, the sub-pixel offsets not
scaled, the report's shifts, samples spread edge to edge or 1 / (rate + 1) apart, and
the means cut to whole numbers or never stored (a result of zeros, which either leaves, has
its own explanation). Each list is built in the current language.

Only the checkers call these, with their own cases, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from course.check.base import Mistake
from course.i18n import _
from course.sampling import resample
from course.sampling.resample import bilinear, supersample_shifted, supersample_without_offset

UNCHECKED = True  # see the module docstring

__all__ = [
    "clamped_before_the_shift",
    "flipped",
    "lookup_mistakes",
    "read_past_the_edge",
    "rounded_base",
    "supersample_mistakes",
    "supersample_slip",
    "truncated",
    "unclamped",
]

#: Where :func:`supersample_slip` puts the rate samples of an output pixel along each axis,
#: in output pixels from its corner: the lesson's sub-pixel centres, and two slips.
SPACINGS = {
    "centres": lambda rate: (np.arange(rate) + 0.5) / rate,
    "edge to edge": lambda rate: np.linspace(0.0, 1.0, rate),
    "inside": lambda rate: np.linspace(0.0, 1.0, rate + 2)[1:-1],
}


def supersample_slip(
    image: Any,
    out_shape: Any,
    rate: int,
    whole_scale: bool = False,
    divide: str = "square",
    unscaled_offsets: bool = False,
    swapped_scales: bool = False,
    spacing: str = "centres",
) -> np.ndarray:
    """Supersampling with one of the slips: a whole-number scale, / rate for / rate^2, the
    sub-pixel offsets left in output pixels while the pixel's corner is in input pixels, x
    scaled by H / h and y by W / w, or the samples spaced otherwise (:data:`SPACINGS`).

    Examples
    --------
    >>> stripes = np.tile([0.0, 1.0], (2, 2))
    >>> supersample_slip(stripes, (1, 1), 2).tolist()
    [[0.5]]
    >>> supersample_slip(stripes, (1, 1), 2, spacing="edge to edge").tolist()
    [[0.5]]
    """
    image = np.asarray(image, dtype=float)
    (height, width), (in_height, in_width) = out_shape, image.shape[:2]
    sx = in_width // width if whole_scale else in_width / width
    sy = in_height // height if whole_scale else in_height / height
    if swapped_scales:
        sx, sy = in_height / height, in_width / width
    offsets = SPACINGS[spacing](rate)
    offset_x, offset_y = (offsets, offsets) if unscaled_offsets else (offsets * sx, offsets * sy)
    xs = np.arange(width)[:, None] * sx + offset_x[None, :]  # (w, rate)
    ys = np.arange(height)[:, None] * sy + offset_y[None, :]  # (h, rate)
    grid_y = ys[:, None, :, None] + 0 * xs[None, :, None, :]
    grid_x = xs[None, :, None, :] + 0 * ys[:, None, :, None]
    samples = bilinear(image, grid_x.reshape(-1), grid_y.reshape(-1))
    samples = samples.reshape(height, width, rate * rate, *image.shape[2:])
    total = samples.sum(axis=2)
    return total / (rate if divide == "rate" else rate * rate)


def _whole(cut: Any) -> Any:
    """The right means, each cut to a whole number by ``cut`` (as an integer array keeps them)."""
    return lambda image, out_shape, rate: cut(resample.supersample(image, out_shape, rate))


def _zeros(image: np.ndarray, out_shape: tuple[int, int], rate: int) -> np.ndarray:
    """The result as it was made, every mean lost: np.zeros of the answer's shape."""
    return np.zeros((*out_shape, *image.shape[2:]))


def supersample_mistakes() -> list[Mistake]:
    """The mistakes ``supersample``'s checker names, in the current language."""
    whole_numbers = _(
        "every value you returned is a whole number, where the means are fractions: your "
        "result holds integers (np.zeros(..., dtype=int), np.zeros_like of an integer image, "
        "or .astype(np.uint8) at the end), which turn each mean into 0 or 1. Make the result a "
        "float array, np.zeros((h, w)) or np.zeros((h, w, 3)), and return the means as they "
        "are."
    )
    whole_or_none = _("means cut to whole numbers, or never stored")
    # Means below 1 cut to integers are 0, as a result nothing was stored into is: the
    # values cannot tell the two apart, so the explanation names both.
    all_zero = _(
        "every pixel you returned is 0: no mean reached your result. Either nothing was "
        "stored into it, or it holds integers (np.zeros(..., dtype=int), np.zeros_like of an "
        "integer image, or .astype(np.uint8) at the end), which cut every mean below 1, and "
        "every sample's share added with +=, to 0. Make the result a float array, "
        "np.zeros((h, w)) or np.zeros((h, w, 3)), and store each pixel's mean in it."
    )
    return [
        Mistake(
            _("the scale made whole"),
            _(
                "you divided the sizes with //, which drops the scale's fraction: W // w for "
                "W / w, H // h for H / h. Your samples then stop short of the input's right or "
                "bottom edge, wherever w does not divide W or h does not divide H. The scale is "
                "a float: W / w and H / h."
            ),
            lambda image, out_shape, rate: supersample_slip(image, out_shape, rate, True),
        ),
        Mistake(
            _("divided by the rate, not its square"),
            _(
                "your pixels are rate times too bright: there are rate x rate samples per output "
                "pixel, so their mean divides by rate squared."
            ),
            lambda image, out_shape, rate: supersample_slip(image, out_shape, rate, divide="rate"),
        ),
        Mistake(
            _("the two scales swapped"),
            _(
                "you scaled x by H / h and y by W / w: x runs along the width, so x = (c + (i + "
                "0.5) / rate) W / w and y = (r + (j + 0.5) / rate) H / h; out_shape is (h, w), "
                "rows first."
            ),
            lambda image, out_shape, rate: supersample_slip(
                image, out_shape, rate, swapped_scales=True
            ),
        ),
        Mistake(
            _("the sub-pixel offsets not scaled"),
            _(
                "your samples crowd into the first input pixels of each output pixel's square: "
                "you scaled the output pixel's corner by W / w but not the offset "
                "(i + 0.5) / rate, which is in output pixels too. Scale the whole position: "
                "x = (c + (i + 0.5) / rate) W / w."
            ),
            lambda image, out_shape, rate: supersample_slip(
                image, out_shape, rate, unscaled_offsets=True
            ),
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
        Mistake(
            _("samples from edge to edge"),
            _(
                "your samples run from the square's left edge to its right edge, both included "
                "(i / (rate - 1), or np.linspace(0, 1, rate)): they are 1 / (rate - 1) apart, "
                "and the outer ones sit on the edges, shared with the neighbouring pixels. Split "
                "the square into rate sub-pixels and sample each one's centre: (i + 0.5) / rate, "
                "1 / rate apart and half of that from each edge."
            ),
            lambda image, out_shape, rate: supersample_slip(
                image, out_shape, rate, spacing="edge to edge"
            ),
        ),
        Mistake(
            _("samples 1 / (rate + 1) apart"),
            _(
                "your samples sit at (i + 1) / (rate + 1) (np.linspace(0, 1, rate + 2)[1:-1]): "
                "1 / (rate + 1) apart and a whole spacing from each edge, so the middle of the "
                "pixel counts more than its sides. Sample the centres of rate equal sub-pixels: "
                "(i + 0.5) / rate, 1 / rate apart and half of that from each edge."
            ),
            lambda image, out_shape, rate: supersample_slip(
                image, out_shape, rate, spacing="inside"
            ),
        ),
        # One mistake as the class sees it; all zeros first, for its own explanation.
        Mistake(whole_or_none, all_zero, _zeros),
        Mistake(whole_or_none, whole_numbers, _whole(np.trunc)),
        Mistake(whole_or_none, whole_numbers, _whole(np.round)),
    ]


def lookup_mistakes() -> list[Mistake]:
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
                "beyond the last pixel centres your blend reaches past them and extrapolates: a "
                "point right of the last centre, or below it, takes the edge value. Keeping the "
                "point on the image, x <= W, is not enough: the last centre is at W - 0.5, so "
                "clamp x - 0.5 to [0, W - 1] and y - 0.5 to [0, H - 1]."
            ),
            unclamped,
        ),
        Mistake(
            _("clamped before the half-pixel shift"),
            _(
                "you clamped the point itself to [0, W - 1] x [0, H - 1], then subtracted 0.5: "
                "past x = W - 1 your point stops half a pixel short of the last centre and "
                "blends the last two columns, where the edge value belongs. Clamp after the "
                "shift: x - 0.5 to [0, W - 1] and y - 0.5 to [0, H - 1]."
            ),
            clamped_before_the_shift,
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
            truncated,
        ),
        Mistake(
            _("round() where floor belongs"),
            _(
                "you took the top-left centre with round(): for x - 0.5 = 1.7 it gives c = 2, "
                "right of the point, so u = x - 1/2 - c comes out -0.3 and your blend "
                "extrapolates from the wrong pair. The top-left centre is the one at or left of "
                "the point: c = math.floor(x - 0.5) (and r likewise), so that u and v lie in "
                "[0, 1)."
            ),
            rounded_base,
        ),
        Mistake(
            _("the weights flipped"),
            _(
                "you weighted each centre by its distance from the point, not by its nearness: "
                "the farther centre gets the larger share. With u = x - 1/2 - c the point's "
                "distance past the left centre, that centre gets 1 - u and the one right of it "
                "u; the same along y with v."
            ),
            flipped,
        ),
        Mistake(
            _("x and y swapped"),
            _("you read image[x, y]: an image is indexed by row first, image[y, x]."),
            lambda image, x, y: bilinear(image, y, x),
        ),
        Mistake(
            _("a read past the image"),
            _(
                "your code read past the image's last column or row (IndexError): beyond the "
                "outer centres, c + 1 is W (or r + 1 is H). Clamp x - 0.5 to [0, W - 1] and "
                "y - 0.5 to [0, H - 1], and keep c + 1 inside (c at most W - 2), so that a point "
                "past the outer centres takes the edge value. Clamp the left and top too: there "
                "c = -1 raises nothing, Python reads the last column instead."
            ),
            read_past_the_edge,
            raises=IndexError,
        ),
    ]


def flipped(image: Any, x: float, y: float) -> np.ndarray:
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


def truncated(image: Any, x: float, y: float) -> np.ndarray:
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


def rounded_base(image: Any, x: float, y: float) -> np.ndarray:
    """The lesson's blend with round() for floor: the top-left centre c = round(x - 1/2), so
    u = x - 1/2 - c lies in [-1/2, 1/2] and, below zero, the blend extrapolates."""
    image = np.asarray(image, dtype=float)
    height, width = image.shape[:2]
    u = min(max(x - 0.5, 0.0), width - 1.0)
    v = min(max(y - 0.5, 0.0), height - 1.0)
    left, top = min(round(u), max(width - 2, 0)), min(round(v), max(height - 2, 0))
    right, bottom = min(left + 1, width - 1), min(top + 1, height - 1)
    fx, fy = u - left, v - top
    upper = image[top, left] * (1 - fx) + image[top, right] * fx
    lower = image[bottom, left] * (1 - fx) + image[bottom, right] * fx
    return upper * (1 - fy) + lower * fy


def clamped_before_the_shift(image: Any, x: float, y: float) -> np.ndarray:
    """The point clamped to [0, W - 1] x [0, H - 1] before the half-pixel shift: past x = W - 1
    it blends the last two columns at u = 1/2 instead of taking the last one."""
    height, width = np.shape(image)[:2]
    return bilinear(image, min(max(x, 0.0), width - 1.0), min(max(y, 0.0), height - 1.0))


def unclamped(image: Any, x: float, y: float) -> np.ndarray:
    """A blend clamped at the left and top only: past the last centres it extrapolates."""
    image = np.asarray(image, dtype=float)
    height, width = image.shape[:2]
    u, v = max(x - 0.5, 0.0), max(y - 0.5, 0.0)
    left, top = min(int(u), width - 2), min(int(v), height - 2)
    fx, fy = u - left, v - top
    upper = image[top, left] * (1 - fx) + image[top, left + 1] * fx
    lower = image[top + 1, left] * (1 - fx) + image[top + 1, left + 1] * fx
    return upper * (1 - fy) + lower * fy


def read_past_the_edge(image: Any, x: float, y: float) -> np.ndarray:
    """The blend with no clamp at all: c = floor(x - 1/2) and c + 1 read as they are. Past the
    last centres c + 1 is W (or r + 1 is H), and the read raises IndexError; before the first,
    c = -1 reads the last column (Python's negative index)."""
    image = np.asarray(image, dtype=float)
    u, v = x - 0.5, y - 0.5
    left, top = math.floor(u), math.floor(v)
    fx, fy = u - left, v - top
    upper = image[top, left] * (1 - fx) + image[top, left + 1] * fx
    lower = image[top + 1, left] * (1 - fx) + image[top + 1, left + 1] * fx
    return upper * (1 - fy) + lower * fy
