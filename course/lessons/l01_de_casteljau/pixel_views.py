"""The pieces lesson 01's pixel figures are built from, and the yellow check's overview.

:mod:`course.lessons.l01_de_casteljau.figures` draws each handout loop's
pixels at a whole zoom (:func:`course.widgets.picture.pixel_figure`); these
add what its panels share: the pixel grid (:func:`pixel_grid`), a legend whose
handles show shape and dash (:func:`replace_legend`), a canvas painted with a
loop's pixels (:func:`painted_canvas`), and, for the GAMES101 yellow check,
the overview of the whole curve coloured by how yellow its pixels are
(:func:`yellow_along`, :func:`yellow_overview`).

Only the figures call these, on input they have validated, so this module
checks none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.colors import LinearSegmentedColormap, Normalize
from matplotlib.figure import Figure
from matplotlib.legend_handler import HandlerTuple
from matplotlib.patches import Rectangle
from matplotlib.ticker import PercentFormatter
from scipy.spatial import cKDTree

from course.curves.handout_loops import YellowCheck
from course.i18n import _
from course.raster.canvas import paint
from course.widgets.picture import pixel_axes

__all__ = [
    "CANVAS",
    "YELLOW",
    "YELLOW_SHARE",
    "painted_canvas",
    "pixel_grid",
    "replace_legend",
    "yellow_along",
    "yellow_overview",
]

UNCHECKED = True  # see the module docstring

#: The yellow of the check's picture, where both curves paint a pixel.
YELLOW = (0.95, 0.85, 0.0)
#: The overview's scale: dark blue where no pixel is yellow, the check's yellow where all are.
YELLOW_SHARE = LinearSegmentedColormap.from_list("yellow_share", [(0.0, 0.13, 0.3), YELLOW])
#: The handouts' window, (H, W): the canvas the loops paint and the overview shows.
CANVAS = (700, 700)
#: The least width of the box that marks the zoom on the overview, in canvas pixels.
_ZOOM_BOX = 60


def pixel_grid(axes: Any, extent: tuple[int, ...]) -> None:
    """Thin lines on the pixel edges of a crop, so that unpainted pixels show as squares."""
    left, right, bottom, top = extent
    lines = [[(x, top), (x, bottom)] for x in range(left, right + 1)]
    lines += [[(left, y), (right, y)] for y in range(top, bottom + 1)]
    axes.add_collection(LineCollection(lines, colors="0.8", linewidths=0.6))


def replace_legend(figure: Figure, handles: list, labels: list[str], ncols: int = 0) -> None:
    """Swap ``pixel_figure``'s colour patches for handles that also show shape and dash."""
    for legend in list(figure.legends):
        legend.remove()
    figure.legend(
        handles=handles,
        labels=labels,
        loc="upper center",
        ncols=ncols or len(handles),
        fontsize=8,
        frameon=False,
        handler_map={tuple: HandlerTuple(ndivide=1)},
    )


def painted_canvas(pixels: np.ndarray, colour: Any, shape: tuple[int, int] = CANVAS) -> np.ndarray:
    """A white canvas with ``pixels`` painted in ``colour`` over it."""
    image = np.ones((*shape, 3))
    paint(image, pixels, colour, mode="over")
    return image


def yellow_along(curve: np.ndarray, yellow: np.ndarray, odd: np.ndarray) -> np.ndarray:
    """The share of yellow pixels among the painted ones nearest each of 50 stretches of curve.

    ``curve`` holds 401 points; each painted pixel (its centre) counts for the
    curve point nearest it, and the points are taken eight at a time. A
    stretch no pixel is nearest to takes its neighbour's share.
    """
    painted = np.vstack([yellow, odd]) + 0.5
    is_yellow = np.arange(len(painted)) < len(yellow)
    _distance, nearest = cKDTree(curve).query(painted)
    stretch = np.minimum(nearest // 8, 49)
    counts = np.bincount(stretch, minlength=50)
    shares = np.bincount(stretch, weights=is_yellow, minlength=50) / np.maximum(counts, 1)
    seen = np.flatnonzero(counts)
    if len(seen) == 0:
        return np.ones(50)
    # A stretch with no pixel of its own (the curve sped past) borrows its nearest neighbour's.
    return shares[seen[np.abs(np.arange(50)[:, None] - seen).argmin(axis=1)]]


def yellow_overview(
    figure: Figure,
    check: YellowCheck,
    curve: np.ndarray,
    extent: tuple[int, ...],
    side: int,
    circle_colour: Any,
) -> bool:
    """The yellow check's overview, left of its zoom: the whole canvas, ``side`` px square.

    The curve (its points ``curve``) is coloured by the share of its painted
    pixels that are yellow, stretch by stretch (:func:`yellow_along`), with a
    colour bar beside it; the pixels that are not yellow are circled in
    ``circle_colour`` when there are at most 40; and a box marks the zoomed
    window ``extent``. Returns whether any pixel was circled.
    """
    left, right, bottom, top = extent
    odd = np.vstack([check.red_only, check.green_only])
    yellow = check.image[..., 0] * check.image[..., 1]
    overview = pixel_axes(figure, 18, 9, side, side)
    shares = yellow_along(curve, np.argwhere(yellow > 0)[:, ::-1], odd)
    pieces = LineCollection(
        np.stack([curve[:-1], curve[1:]], axis=1),
        array=np.repeat(shares, (len(curve) - 1) // len(shares)),
        cmap=YELLOW_SHARE,
        norm=Normalize(0.0, 1.0),
        linewidths=4,
        capstyle="round",
    )
    overview.add_collection(pieces)
    scale = pixel_axes(figure, 18 + side + 8, 9, 10, side)
    bar = figure.colorbar(
        pieces, cax=scale, ticks=[0.0, 0.5, 1.0], format=PercentFormatter(1.0, decimals=0)
    )
    bar.set_label(_("share of nearby pixels yellow"), fontsize=8, labelpad=-2)
    scale.tick_params(labelsize=7)
    circled = len(odd) <= 40 and len(odd) > 0
    if circled:
        overview.plot(
            *(odd + 0.5).T, "o", markersize=9, fillstyle="none", color=circle_colour, linestyle=""
        )
    # The zoom is a few canvas pixels: at 192 screen pixels for 700 its own box would hide under
    # the curve's stroke, so the box drawn around it is at least _ZOOM_BOX wide, kept on the canvas.
    half = max(right - left, bottom - top, _ZOOM_BOX) / 2
    centre_x = np.clip((left + right) / 2, half, CANVAS[1] - half)
    centre_y = np.clip((top + bottom) / 2, half, CANVAS[0] - half)
    overview.add_patch(
        Rectangle(
            (centre_x - half, centre_y - half),
            2 * half,
            2 * half,
            fill=False,
            edgecolor="black",
            linewidth=1.5,
            zorder=3,
        )
    )
    overview.set_xlim(0, CANVAS[1])
    overview.set_ylim(CANVAS[0], 0)
    overview.set_aspect("equal")
    overview.set_xticks([])
    overview.set_yticks([])
    painted = np.count_nonzero(check.image.sum(axis=2) > 0)
    overview.set_title(
        _("{odd} of {painted} pixels not yellow").format(odd=len(odd), painted=painted),
        fontsize=9,
    )
    return circled
