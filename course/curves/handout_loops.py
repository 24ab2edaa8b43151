"""The handouts' drawing loops, and the GAMES101 check that compares them.

Each report's ``bezier()`` walks t in its own way and turns a curve point
into a pixel in its own way: :class:`HandoutLoop` records both (the ``float``
or ``double`` t of its ``t += 0.001``, OpenCV's rounding or a truncation),
and :data:`HANDOUT_LOOPS` holds the seeds' loops as written, with
:data:`NAIVE_LOOP`, the framework's ``naive_bezier``. :func:`loop_pixels`
gives the pixels a loop paints; :func:`yellow_check` paints ``naive_bezier``
red and a loop green, as the GAMES101 homework checks its answer, and
measures how yellow the picture is.

Lesson 01 uses them (its notebook, its figures of the curve's end and of the
yellow check); the handouts' other code is in :mod:`course.curves.bezier_handouts`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from course import limits
from course._validate import as_choice, as_points, as_shape
from course.curves._bernstein import bernstein_loop, require_bernstein_degree
from course.curves._bezier_fast import de_casteljau_chunked
from course.curves._handouts import de_casteljau_swapped
from course.curves._uniform import uniform_steps
from course.i18n import N_, _
from course.raster import ROUNDING
from course.raster._lines import pixels_of, require_image_space
from course.raster._paint import on_canvas

__all__ = [
    "HANDOUT_LOOPS",
    "NAIVE_LOOP",
    "HandoutLoop",
    "YellowCheck",
    "loop_pixels",
    "yellow_check",
]


@dataclass(frozen=True)
class HandoutLoop:
    """How one handout's ``bezier()`` walks t and turns a point into a pixel.

    ``accumulate`` is the :func:`course.curves.flattening.uniform_parameters` mode of
    its ``t += 0.001`` (``"float32"`` for a ``float t``, ``"float64"`` for
    a ``double``); ``rounding`` the :func:`course.raster.nearest_pixels`
    mode of its pixel write (``"round"`` for ``window.at<cv::Vec3b>(point)``,
    which converts through ``cv::Point``; ``"trunc"`` for ``(point.y,
    point.x)``); ``reversed`` whether its step is ``t P[i] + (1 - t) P[i+1]``.
    The points themselves are computed here in double precision. ``name`` is the English
    a catalog translates (its report's role); :attr:`label` shows it.
    """

    name: str
    code: str
    accumulate: str
    rounding: str
    reversed: bool = False

    @property
    def label(self) -> str:
        """The loop's name in the current language, as figures and captions show it.

        Examples
        --------
        >>> from course.i18n import language
        >>> with language("zh-CN"):
        ...     HANDOUT_LOOPS["003"].label
        'VS2022 作业报告'
        """
        return _(self.name)


#: The seeds' drawing loops, as written, each named for its report's role.
HANDOUT_LOOPS = {
    "000": HandoutLoop(
        N_("the GAMES101 report"),
        "for (float t = 0; t <= 1; t += 0.001f) window.at<cv::Vec3b>(point) = ...",
        "float32",
        "round",
    ),
    "002": HandoutLoop(
        N_("the any-degree report"),
        "float dt = 0.001; for (t = 0; t <= 1; t += dt) window.at<cv::Vec3b>(point.y, point.x)",
        "float32",
        "trunc",
        reversed=True,
    ),
    "003": HandoutLoop(
        N_("the VS2022 report"),
        "for (double t = 0.0; t <= 1.0; t += 0.001) window.at<cv::Vec3b>(point.y, point.x)",
        "float64",
        "trunc",
    ),
    "004": HandoutLoop(
        N_("the lab 6 report"),
        "for (float t = 0; t <= 1; t += 0.001) window.at<cv::Vec3b>(point.y, point.x)",
        "float32",
        "trunc",
        reversed=True,
    ),
}
#: The GAMES101 framework's ``naive_bezier``: the red curve of the yellow check.
NAIVE_LOOP = HandoutLoop(
    "naive_bezier",
    "for (double t = 0.0; t <= 1.0; t += 0.001) window.at<cv::Vec3b>(point.y, point.x)",
    "float64",
    "trunc",
)


def loop_pixels(points: Any, loop: HandoutLoop, shape: Any = None) -> np.ndarray:
    """The pixels ``loop`` paints for the curve: (K, 2) (x, y), one per t, repeats kept.

    Examples
    --------
    >>> loop_pixels([[0.5, 0.5], [4.5, 0.5]], HANDOUT_LOOPS["003"])[[0, -1]].tolist()
    [[0, 0], [4, 0]]
    """
    control = as_points(points, bound=limits.MAX_COORDINATE)
    _require_loop(loop)
    pixels = _loop_pixels(control, loop)
    if shape is not None:
        pixels = pixels[on_canvas(pixels, as_shape(shape))]
    return pixels


# The modes of course.curves.flattening.uniform_parameters' accumulate.
_ACCUMULATE = ("exact", "float32", "float64")


def _loop_pixels(control: np.ndarray, loop: HandoutLoop) -> np.ndarray:
    """:func:`loop_pixels` of a checked curve and loop, on no canvas.

    The loop's ``accumulate`` and ``rounding`` are checked where they are first used, as
    they always were; :func:`course._validate.as_choice` words a refusal.
    """
    if not _is_one_of(loop.accumulate, _ACCUMULATE):
        as_choice(loop.accumulate, "accumulate", _ACCUMULATE)
    t = uniform_steps(0.001, loop.accumulate)
    if loop is NAIVE_LOOP:
        require_bernstein_degree(control)
        curve = bernstein_loop(control, t)
    elif loop.reversed:
        curve = de_casteljau_swapped(control, t)
    else:
        curve = de_casteljau_chunked(control, t)
    require_image_space(curve)
    if not _is_one_of(loop.rounding, ROUNDING):
        as_choice(loop.rounding, "rounding", ROUNDING)
    return pixels_of(curve, loop.rounding)


def _is_one_of(value: Any, choices: tuple[str, ...]) -> bool:
    return isinstance(value, str) and value in choices


def _require_loop(loop: Any) -> None:
    if not isinstance(loop, HandoutLoop):
        raise TypeError(
            _(
                "loop must be a HandoutLoop, e.g. HANDOUT_LOOPS['003'] or NAIVE_LOOP; got "
                "{loop_type} {loop:.60}"
            ).format(loop_type=type(loop).__name__, loop=repr(loop))
        )


@dataclass(frozen=True)
class YellowCheck:
    """The GAMES101 check of one handout loop: red ``naive_bezier``, green the loop.

    ``image`` is the (H, W, 3) picture; ``fraction`` the share of painted
    pixels that are yellow (both); ``red_only`` and ``green_only`` the
    (K, 2) pixels only one curve lights, in reading order.
    """

    image: np.ndarray
    fraction: float
    red_only: np.ndarray
    green_only: np.ndarray


def yellow_check(points: Any, loop: HandoutLoop, shape: Any = (700, 700)) -> YellowCheck:
    """Paint ``naive_bezier`` red and ``loop`` green, as the GAMES101 homework does.

    Examples
    --------
    >>> check = yellow_check([[0.5, 0.5], [9.5, 0.5]], HANDOUT_LOOPS["003"], (2, 10))
    >>> check.fraction, len(check.red_only), len(check.green_only)
    (1.0, 0, 0)
    """
    height, width = as_shape(shape)
    _require_loop(loop)
    control = as_points(points, bound=limits.MAX_COORDINATE)
    red = np.zeros((height, width), dtype=bool)
    green = np.zeros((height, width), dtype=bool)
    for mask, each in ((red, NAIVE_LOOP), (green, loop)):
        pixels = _loop_pixels(control, each)
        pixels = pixels[on_canvas(pixels, (height, width))]
        mask[pixels[:, 1], pixels[:, 0]] = True
    image = np.zeros((height, width, 3))
    image[..., 0], image[..., 1] = red, green
    painted = np.count_nonzero(red | green)
    fraction = float(np.count_nonzero(red & green) / painted) if painted else 1.0

    def listed(mask: np.ndarray) -> np.ndarray:
        rows, columns = np.nonzero(mask)
        return np.column_stack([columns, rows])

    return YellowCheck(image, fraction, listed(red & ~green), listed(green & ~red))
