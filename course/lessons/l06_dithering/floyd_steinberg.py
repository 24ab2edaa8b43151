"""Lesson 06's Floyd-Steinberg, one pixel at a time: where a pixel's error goes, and a
3 x 3 ramp diffused by hand, every value written.

Each function returns a :class:`~course.widgets.picture.Still` whose caption
states the numbers it shows, as those of :mod:`.figures` do.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle

from course import limits
from course._validate import as_gray, as_int
from course.halftone.diffusion import diffusion_offsets
from course.i18n import _
from course.lessons.l06_dithering.figures import BLUE, VERMILLION
from course.widgets.picture import GRAY_PIXELS, Still, bare_axes, pixel_axes, pixel_figure

__all__ = ["BY_HAND", "by_hand_figure", "diffusion_figure"]


def diffusion_figure() -> Still:
    """Where Floyd-Steinberg sends a pixel's error, on the pixels not yet visited.

    Examples
    --------
    >>> diffusion_figure()
    the error goes 7/16 right, 3/16 below left, 5/16 below, 1/16 below right: 16/16 in all
    """
    shades = np.array([[0.55, 0.55, 1.0, 1.0, 1.0], [1.0, 1.0, 1.0, 1.0, 1.0]])
    shades[0, 2] = 0.8
    figure, (axes,) = pixel_figure(
        [
            (
                shades,
                (0, 5, 2, 0),
                _("visited (gray), this pixel (x), the four that get its error"),
            )
        ],
        zoom=70,
    )
    shares = {(3, 0): 7, (1, 1): 3, (2, 1): 5, (3, 1): 1}
    axes.text(2.5, 0.5, "x", ha="center", va="center", fontsize=16, weight="bold")
    for (column, row), share in shares.items():
        axes.text(
            column + 0.5,
            row + 0.5,
            f"{share}/16",
            ha="center",
            va="center",
            fontsize=13,
            color=BLUE,
        )
    for k in range(6):
        axes.axvline(k, color="0.7", lw=0.8)
    axes.axhline(1, color="0.7", lw=0.8)
    caption = _(
        "the error goes 7/16 right, 3/16 below left, 5/16 below, 1/16 below right: "
        "{total}/16 in all"
    ).format(total=sum(shares.values()))
    return Still.of(figure, caption)


#: The 3 x 3 image lesson 06 diffuses by hand: a ramp from 0.2 to 1.
BY_HAND = np.array([[0.2, 0.4, 0.6], [0.4, 0.6, 0.8], [0.6, 0.8, 1.0]])


def _diffusion_steps(gray: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """Floyd-Steinberg one pixel at a time: (values so far, dots so far) after each pixel.

    Values start as the image; after pixel k its dot is decided and its error
    has reached the pixels not yet visited. Unvisited dots are NaN.

    Examples
    --------
    >>> values, dots = _diffusion_steps(BY_HAND)[0]
    >>> values[0].round(4).tolist(), dots[0].tolist()
    ([0.2, 0.4875, 0.6], [0.0, nan, nan])
    """
    gray = as_gray(gray, "gray")
    height, width = gray.shape
    values, dots = gray.copy(), np.full(gray.shape, np.nan)
    steps = []
    for y in range(height):
        for x in range(width):
            dots[y, x] = 1.0 if values[y, x] > 0.5 else 0.0
            error = values[y, x] - dots[y, x]
            for dx, dy, weight in diffusion_offsets("floyd-steinberg"):
                if 0 <= x + dx < width and y + dy < height:
                    values[y + dy, x + dx] += error * weight
            steps.append((values.copy(), dots.copy()))
    return steps


#: The most pixels a by-hand figure draws, one panel per pixel visited.
_BY_HAND_PIXELS = 16


def by_hand_figure(gray: np.ndarray = BY_HAND, zoom: int = 52) -> Still:
    """Floyd-Steinberg on a 3 x 3 image, one panel per pixel visited, every value written.

    Examples
    --------
    >>> by_hand_figure()  # doctest: +NORMALIZE_WHITESPACE
    6 of 9 dots lit: mean 0.667 against the image's 0.600; the last pixel saw 0.709
    """
    gray = as_gray(gray, "gray")
    height, width = gray.shape
    if height * width > _BY_HAND_PIXELS:
        raise ValueError(
            _(
                "gray must be small enough to work by hand, at most {most} pixels; got {height} x "
                "{width}"
            ).format(most=_BY_HAND_PIXELS, height=height, width=width)
        )
    zoom = as_int(zoom, "zoom", minimum=8, maximum=limits.MAX_ZOOM)
    steps = _diffusion_steps(gray)
    side, gap, title, top = width * zoom, 24, 40, 58
    columns = width
    rows = -(-len(steps) // columns)
    figure = Figure(
        figsize=(
            (columns * (side + gap) + gap) / 100,
            (top + rows * (height * zoom + title)) / 100,
        ),
        dpi=100,
    )
    figure_height = top + rows * (height * zoom + title)
    for index, (values, dots) in enumerate(steps):
        row, column = divmod(index, columns)
        bottom = figure_height - top - (row + 1) * (height * zoom + title) + 6
        axes = bare_axes(
            pixel_axes(figure, gap + column * (side + gap), bottom, side, height * zoom)
        )
        shown = np.where(np.isnan(dots), 0.25 + 0.5 * np.clip(values, 0, 1), dots)
        axes.imshow(shown, extent=(0, width, height, 0), **GRAY_PIXELS)
        y, x = divmod(index, width)
        seen = values[y, x] if index == 0 else steps[index - 1][0][y, x]
        axes.add_patch(Rectangle((x, y), 1, 1, fill=False, edgecolor=VERMILLION, lw=3))
        for (r, c), value in np.ndenumerate(values):
            decided = not np.isnan(dots[r, c])
            text = f"{dots[r, c]:.0f}" if decided else f"{value:.3f}"
            dark = shown[r, c] < 0.5
            axes.text(
                c + 0.5,
                r + 0.5,
                text,
                ha="center",
                va="center",
                fontsize=9,
                color="white" if dark else "black",
            )
        error = seen - dots[y, x]
        axes.set_title(
            _("pixel ({x}, {y}): {seen:.3f} -> {dot:.0f}\nerror {error:+.3f}").format(
                x=x, y=y, seen=seen, dot=dots[y, x], error=error
            ),
            fontsize=8,
        )
    figure.legend(
        handles=[
            Line2D([], [], color=VERMILLION, lw=3, label=_("the pixel visited")),
            Patch(facecolor="white", edgecolor="0.5", label=_("its dot, 1 or 0")),
            Patch(facecolor="0.55", edgecolor="0.5", label=_("grey: value so far")),
        ],
        loc="upper center",
        ncols=3,
        fontsize=8,
        frameon=False,
    )
    final = steps[-1][1]
    lit = _("{lit} of {count} dots lit: mean {mean:.3f} against the image's {image:.3f}").format(
        lit=int(final.sum()), count=final.size, mean=final.mean(), image=gray.mean()
    )
    figure.text(0.5, 1 - 30 / figure_height, lit, ha="center", va="top", fontsize=9)
    last = steps[-2][0][-1, -1]
    caption = _("{lit}; the last pixel saw {last:.3f}").format(lit=lit, last=last)
    return Still.of(figure, caption)
