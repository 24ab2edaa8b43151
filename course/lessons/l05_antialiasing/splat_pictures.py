"""The splat checker's pictures: a wrong splat beside the right one, its pixels numbered.

:func:`failure_picture` draws the expected splat, the student's and their difference
around the point, on axes in the lesson's coordinates: pixel (c, r) is the square from
(c, r) to (c + 1, r + 1), numbered c and r at its centre, so a pixel the report names,
"(2, 1)", is the square the axes number (2, 1), and the point sits where it lies among the
pixel centres. :func:`pass_picture` shows a passing splat beside the expected one.

Only :func:`.check.splat` calls these, with splat tables it made
(:mod:`.splat_tables`), so this module checks none (``UNCHECKED = True``; the fuzz test
skips it).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from course.check.pictures import figure_png, side_by_side
from course.i18n import _

UNCHECKED = True  # see the module docstring

__all__ = ["failure_picture", "painted", "pass_picture", "splat_window"]

# The picture shows at least this many pixels on each side of the point's own pixel.
_AROUND = 2
# ... and at most this many pixels across, however far a wrong splat strays.
_LARGEST_WINDOW = 16
# A panel is about this many screen pixels across, each pixel a whole number of them.
_PANEL = 192


def splat_window(case: dict[str, Any], tables: list[np.ndarray]) -> tuple[int, int, int, int]:
    """(left, top, width, height): the point's pixel and every lit pixel, within limits.

    Examples
    --------
    >>> splat_window({"x": 2.5, "y": 1.5}, [np.array([[2.0, 1.0, 1.0]])])
    (0, -1, 5, 5)
    """
    px, py = math.floor(case["x"]), math.floor(case["y"])
    xs = [px - _AROUND, px + _AROUND] + [int(x) for t in tables for x in t[:, 0]]
    ys = [py - _AROUND, py + _AROUND] + [int(y) for t in tables for y in t[:, 1]]
    left = max(min(xs), px - _LARGEST_WINDOW // 2)
    top = max(min(ys), py - _LARGEST_WINDOW // 2)
    right = min(max(xs), left + _LARGEST_WINDOW - 1)
    bottom = min(max(ys), top + _LARGEST_WINDOW - 1)
    return left, top, right - left + 1, bottom - top + 1


def painted(table: np.ndarray, window: tuple[int, int, int, int]) -> np.ndarray:
    """The splat table's weights as an image of the window; pixels outside it are left out.

    Examples
    --------
    >>> painted(np.array([[2.0, 1.0, 0.75], [9.0, 9.0, 0.25]]), (1, 0, 3, 2))
    array([[0.  , 0.  , 0.  ],
           [0.  , 0.75, 0.  ]])
    """
    left, top, width, height = window
    image = np.zeros((height, width))
    for x, y, weight in table:
        column, row = int(x) - left, int(y) - top
        if 0 <= row < height and 0 <= column < width:
            image[row, column] += weight
    return image


def failure_picture(case: dict[str, Any], expected: np.ndarray, given: np.ndarray) -> bytes:
    """The expected splat, the student's and their difference, every pixel numbered.

    Each panel's axes number the pixels at their centres, in the report's (x, y); the point
    is marked, and the difference is red where the student's weight is too large, blue where
    too small, with a colour bar in weights.
    """
    window = splat_window(case, [expected, given])
    left, top, width, height = window
    want, have = painted(expected, window), painted(given, window)
    difference = have - want
    limit = max(float(np.abs(difference).max(initial=0.0)), 1e-12)
    zoom = max(1, _PANEL // max(width, height))
    side_w, side_h = width * zoom, height * zoom
    # Screen pixels: room for the y numbers left of each panel, the x numbers below.
    margin, gap, bar, above, below = 30, 34, 14, 70, 24
    columns = margin + 3 * side_w + 2 * gap + 10 + bar + 44
    rows = above + side_h + below
    figure = Figure(figsize=(columns / 100, rows / 100), dpi=100)
    extent = (left, left + width, top + height, top)
    panels = (
        (want, _("expected"), {"cmap": "gray", "vmin": 0.0, "vmax": 1.0}),
        (have, _("your result"), {"cmap": "gray", "vmin": 0.0, "vmax": 1.0}),
        (
            difference,
            _("your result minus expected"),
            {"cmap": "RdBu_r", "vmin": -limit, "vmax": limit},
        ),
    )
    step = 1 if max(width, height) <= 8 else 2
    edges = [[(c, top), (c, top + height)] for c in range(left, left + width + 1)]
    edges += [[(left, r), (left + width, r)] for r in range(top, top + height + 1)]
    shown = None
    for index, (image, title, style) in enumerate(panels):
        position = margin + index * (side_w + gap)
        axes = figure.add_axes((position / columns, below / rows, side_w / columns, side_h / rows))
        shown = axes.imshow(image, extent=extent, interpolation="nearest", **style)
        axes.set_xlim(extent[0], extent[1])
        axes.set_ylim(extent[2], extent[3])
        axes.add_collection(LineCollection(edges, colors="0.55", linewidths=0.5))
        axes.plot([case["x"]], [case["y"]], "o", ms=6, mfc="white", mec="black", mew=1.2)
        # A pixel's number at its centre: (c + 0.5, r + 0.5) is pixel (c, r).
        xs, ys = range(left, left + width, step), range(top, top + height, step)
        axes.set_xticks([c + 0.5 for c in xs], [str(c) for c in xs])
        axes.set_yticks([r + 0.5 for r in ys], [str(r) for r in ys])
        axes.tick_params(labelsize=7, length=2, pad=1)
        axes.set_title(title, fontsize=8)
    bar_left = margin + 3 * side_w + 2 * gap + 10
    colour_bar = figure.add_axes((bar_left / columns, below / rows, bar / columns, side_h / rows))
    figure.colorbar(shown, cax=colour_bar)
    colour_bar.tick_params(labelsize=7)
    figure.suptitle(
        _("the splat of ({x}, {y}): pixels x {left}..{right}, y {top}..{bottom}").format(
            x=case["x"],
            y=case["y"],
            left=left,
            right=left + width - 1,
            top=top,
            bottom=top + height - 1,
        ),
        fontsize=9,
        y=1 - 4 / rows,
        va="top",
    )
    figure.legend(
        handles=[
            Line2D([], [], ls="", marker="o", mfc="white", mec="black", label=_("the curve point")),
            Line2D([], [], color="0.55", lw=0.8, label=_("pixel edges")),
        ],
        loc="upper center",
        bbox_to_anchor=(0.5, 1 - 20 / rows),
        ncols=2,
        fontsize=7,
        frameon=False,
    )
    return figure_png(figure)


def pass_picture(case: dict[str, Any], expected: np.ndarray, given: np.ndarray) -> bytes:
    """The expected splat of ``case`` beside the student's, which matches it."""
    window = splat_window(case, [expected, given])
    return side_by_side(
        painted(expected, window),
        painted(given, window),
        (_("expected"), _("your splat of ({x}, {y})").format(x=case["x"], y=case["y"])),
    )
