"""Checker for lesson 04: the lab's supersampling (Task 6).

The student's ``supersample(image, out_shape, rate)`` returns the shrunk
image: for each output pixel, the mean of rate x rate bilinear samples at
the sub-pixel centres, with pixel centres at +0.5 (:mod:`course.sampling.resample`).
The student's ``bilinear_sample(image, x, y)`` is checked on its own first,
its clamp at every edge included; a failure draws the point, the four
centres it blends and both values. :mod:`.mistakes` reproduces the mistakes
each checker names. An answer that calls the library's own lookup or
supersampling is told to write it.

Hints come in steps: a failure says where to look, the next failures say
more; ``check.hint("bilinear_sample")`` says more at once and
``check.hint("bilinear_sample", recipe=True)`` gives the recipe.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from course.check.base import CheckResult, close, hint, run_cases
from course.check.exercises import exercise
from course.check.hints import Hints
from course.check.pictures import EXPECTED, GIVEN, figure_png, image_picture, side_by_side
from course.i18n import N_, _
from course.lessons.graded_cases import drawn_in_order
from course.lessons.l04_supersampling.mistakes import lookup_mistakes, supersample_mistakes
from course.sampling import resample
from course.sampling.resample import bilinear
from course.widgets.picture import pixel_axes

__all__ = ["bilinear_sample", "hint", "supersample"]

_LIBRARY_FUNCTIONS = (
    resample.bilinear,
    resample.supersample,
    resample.supersample_shifted,
    resample.supersample_without_offset,
)


def _as_image(value: Any) -> np.ndarray:
    return np.asarray(value, dtype=float)


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
        mistakes=supersample_mistakes(),
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
    return drawn_in_order(fixed, families, bilinear, close(atol=1e-9), lookup_mistakes(), _as_image)


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
        mistakes=lookup_mistakes(),
        picture=_lookup_picture,
    )


def _value_text(value: Any) -> str:
    """A lookup's value: one number to four significant digits, or three to three."""
    values = np.asarray(value, dtype=float).ravel()
    digits = 4 if values.size == 1 else 3
    shown = ", ".join(f"{v:.{digits}g}" for v in values[:3])
    return shown if values.size <= 3 else f"{shown}, ..."


def _lookup_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes:
    """The image around a wrong lookup: its pixels (gray ones with their values), the four
    centres the lesson blends for the point (clamped at the edges) joined to it, the point, and
    the expected and the given value in the title. A pixel's margin around the image shows a
    point past its edge."""
    image = np.clip(np.asarray(case["image"], dtype=float), 0, 1)
    x, y = float(case["x"]), float(case["y"])
    height, width = image.shape[:2]
    zoom, margin, top, left, bottom = 64, 1, 58, 26, 20
    side_w, side_h = (width + 2 * margin) * zoom, (height + 2 * margin) * zoom
    columns, rows = max(side_w + 2 * left, 470), side_h + top + bottom
    figure = Figure(figsize=(columns / 100, rows / 100), dpi=100)
    axes = pixel_axes(figure, (columns - side_w) // 2, bottom, side_w, side_h)
    cmap = "gray" if image.ndim == 2 else None
    axes.imshow(
        image, extent=(0, width, height, 0), interpolation="nearest", cmap=cmap, vmin=0, vmax=1
    )
    axes.set_xlim(-margin, width + margin)
    axes.set_ylim(height + margin, -margin)
    axes.set_xticks(range(width + 1))
    axes.set_yticks(range(height + 1))
    axes.tick_params(labelsize=7, length=2, pad=1)
    axes.plot([0, width, width, 0, 0], [0, 0, height, height, 0], color="0.5", lw=0.8)
    if image.ndim == 2:  # the values, so that the blend can be checked by hand
        for (row, column), value in np.ndenumerate(image):
            axes.annotate(
                f"{value:.3g}",
                (column + 0.5, row + 0.15),
                ha="center",
                va="top",
                fontsize=8,
                color="white" if value < 0.5 else "black",
            )

    def pair(position: float, size: int) -> tuple[int, int]:
        first = min(int(np.floor(min(max(position - 0.5, 0.0), size - 1))), max(size - 2, 0))
        return first, min(first + 1, size - 1)

    near = [(column, row) for column in pair(x, width) for row in pair(y, height)]
    for column, row in near:
        axes.plot([x, column + 0.5], [y, row + 0.5], color=EXPECTED, lw=1)
    centres = np.array([(column + 0.5, row + 0.5) for column, row in near])
    axes.plot(*centres.T, "o", color=EXPECTED, ms=6, label=_("the four centres blended"))
    axes.plot([x], [y], "X", color=GIVEN, ms=10, label=_("the point (x, y)"))
    figure.legend(loc="upper center", ncols=2, fontsize=8, frameon=False, bbox_to_anchor=(0.5, 1))
    figure.suptitle(
        _("({x:g}, {y:g}): expected {expected}, yours {given}").format(
            x=x, y=y, expected=_value_text(expected), given=_value_text(given)
        ),
        fontsize=9,
        y=1 - 24 / rows,
        va="top",
    )
    return figure_png(figure)
