"""Lesson 07's still pictures: blur and edges on the photograph, one output pixel's window,
the border after many blurs, and the false edges zero padding draws.

Each function returns a :class:`~course.widgets.picture.Still` whose caption
states the numbers it shows; pixel views are at a whole zoom
(:func:`~course.widgets.picture.pixel_figure`).
"""

from __future__ import annotations

import functools

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

from course import filters, images
from course._validate import as_int
from course.i18n import _
from course.lessons.l07_filtering.apps import (
    blurred,
    right_column_mean,
)
from course.lessons.l07_filtering.border_names import BORDER_LABELS, BORDER_NAMES
from course.widgets.picture import Still, pixel_figure

__all__ = [
    "border_figure",
    "false_edges_figure",
    "filters_figure",
    "frame_depth",
    "ratios_at_edge",
    "window_figure",
]

BLUE, VERMILLION, GREEN = "#0072B2", "#D55E00", "#009E73"


@functools.cache
def _face() -> np.ndarray:
    """:func:`course.images.face`, read once for every figure."""
    image = images.face()
    image.flags.writeable = False
    return image


def filters_figure(zoom: int = 2) -> Still:
    """The face, blurred once and five times, and its Sobel magnitude (clipped at 1).

    Examples
    --------
    >>> filters_figure()
    Sobel magnitude: max 4.06, 13.1% of the pixels above 1 (drawn white); each pixel 2 x 2
    """
    image = _face()
    five = image
    for _blur in range(5):
        five = filters.blur(five)
    edges = filters.sobel(image)
    extent = (0, image.shape[1], image.shape[0], 0)
    figure, _panels = pixel_figure(
        [
            (image, extent, _("original")),
            (filters.blur(image), extent, _("box blur")),
            (five, extent, _("box blur, 5 times")),
            (np.clip(edges, 0, 1), extent, _("Sobel magnitude")),
        ],
        zoom,
    )
    caption = _(
        "Sobel magnitude: max {largest:.2f}, {share:.1%} of the pixels "
        "above 1 (drawn white); each pixel {zoom} x {zoom}"
    ).format(largest=edges.max(), share=(edges > 1).mean(), zoom=zoom)
    return Still.of(figure, caption)


def window_figure(row: int = 2, column: int = 2, zoom: int = 56) -> Still:
    """One output pixel of the box blur: the mean of its 3 x 3 window, numbers shown.

    Examples
    --------
    >>> window_figure()
    the window around (x, y) = (2, 2) holds 0.19 ... 0.66; their mean, 0.418, is the output
    """
    patch = np.round(_face()[44:49, 54:59], 2)
    out = filters.blur(patch)
    extent = (0, 5, 5, 0)
    figure, axes = pixel_figure(
        [
            (patch, extent, _("input: the 3 x 3 window")),
            (out, extent, _("output: its mean\n(border pixels: the report's rule, below)")),
        ],
        zoom,
        gap=40,
        title_height=44,
    )
    for panel, values in zip(axes, (patch, out), strict=True):
        grid = [[(x, 0), (x, 5)] for x in range(6)] + [[(0, y), (5, y)] for y in range(6)]
        panel.add_collection(LineCollection(grid, colors="0.5", linewidths=0.6))
        for r, c in np.ndindex(*values.shape):
            panel.text(
                c + 0.5,
                r + 0.5,
                f"{values[r, c]:.2f}",
                ha="center",
                va="center",
                fontsize=8,
                color="black" if values[r, c] > 0.5 else "white",
            )
    axes[0].add_patch(
        Rectangle((column - 1, row - 1), 3, 3, fill=False, edgecolor=VERMILLION, lw=2.5)
    )
    axes[1].add_patch(Rectangle((column, row), 1, 1, fill=False, edgecolor=VERMILLION, lw=2.5))
    window = patch[row - 1 : row + 2, column - 1 : column + 2]
    caption = _(
        "the window around (x, y) = ({x}, {y}) holds {low:.2f} ... "
        "{high:.2f}; their mean, {mean:.3f}, is the output"
    ).format(x=column, y=row, low=window.min(), high=window.max(), mean=out[row, column])
    return Still.of(figure, caption)


def frame_depth(zero: np.ndarray, other: np.ndarray, share: float = 0.95) -> int:
    """How many columns in from the right edge ``zero`` is below ``share`` of ``other``.

    Examples
    --------
    >>> other = np.ones((2, 6))
    >>> frame_depth(np.array([[1, 1, 1, 1, 0.9, 0.5]] * 2), other)
    2
    """
    ratio = np.mean(zero, axis=(0, 2) if np.ndim(zero) == 3 else 0) / np.mean(
        other, axis=(0, 2) if np.ndim(other) == 3 else 0
    )
    return int(np.argmax(np.append(ratio[::-1], 1.0) > share))


def ratios_at_edge(results: dict[str, np.ndarray], image: np.ndarray) -> dict[str, float]:
    """Each rule's rightmost column: its mean after the blurs over its mean before (the
    repeated-blur app's titles measure the same, :func:`.apps.right_column_mean`)."""
    before = right_column_mean(image)
    return {border: right_column_mean(result) / before for border, result in results.items()}


def border_figure(passes: int = 20, depth: int = 16) -> Still:
    """The face's right edge after ``passes`` blurs under each border rule, as a profile.

    For each of the last ``depth`` columns: its mean after the blurs divided
    by its mean before, so 1 is "unchanged" and the dark frame of zero
    padding shows as a dip towards the edge.

    Examples
    --------
    >>> border_figure()  # doctest: +NORMALIZE_WHITESPACE
    after 20 blurs the face's right column is at 0.98 (handout), 0.20 (zero),
    0.99 (replicate), 0.98 (reflect) times its first brightness
    """
    passes = as_int(passes, "passes", minimum=0, maximum=200)
    depth = as_int(depth, "depth", minimum=2, maximum=64)
    image = _face()
    results = dict.fromkeys(filters.BORDERS, image)
    for _pass in range(passes):
        results = {border: blurred(result, border) for border, result in results.items()}
    columns = np.arange(depth)[::-1]  # distance from the right edge, in pixels
    before = image[:, -depth:].mean(axis=0)
    figure = Figure(figsize=(7.0, 3.0), dpi=100)
    axes = figure.subplots()
    styles = {
        "handout": ("-", "o", BLUE),
        "zero": ("--", "s", VERMILLION),
        "replicate": (":", "^", GREEN),
        "reflect": ("-.", "v", "black"),
    }
    for border, result in results.items():
        ratio = result[:, -depth:].mean(axis=0) / before
        dashes, marker, colour = styles[border]
        axes.plot(
            columns,
            ratio,
            ls=dashes,
            marker=marker,
            ms=4,
            color=colour,
            label=_(BORDER_LABELS[border]),
        )
    axes.axhline(1.0, color="0.6", lw=0.6)
    depth_of_frame = frame_depth(results["zero"], results["replicate"])
    axes.set_title(
        _(
            "'zero': the outermost column at {ratio:.2f} of its brightness, "
            "the frame {depth} px deep"
        ).format(ratio=ratios_at_edge(results, image)["zero"], depth=depth_of_frame),
        fontsize=9,
    )
    axes.set_xlim(depth - 0.5, -0.5)  # the edge on the right, as in the image
    axes.set_xlabel(_("distance from the image's right edge (px)"), fontsize=8)
    axes.set_ylabel(
        _("column brightness after {passes} blurs\n/ before").format(passes=passes), fontsize=8
    )
    axes.tick_params(labelsize=7)
    axes.legend(fontsize=8, title=_("border rule"), title_fontsize=8, loc="lower left")
    figure.tight_layout()
    ratios = _(", ").join(
        _("{ratio:.2f} ({border})").format(ratio=ratio, border=_(BORDER_NAMES[border]))
        for border, ratio in ratios_at_edge(results, image).items()
    )
    caption = _(
        "after {passes} blurs the face's right column is at {ratios} times its first brightness"
    ).format(passes=passes, ratios=ratios)
    return Still.of(figure, caption)


def false_edges_figure(zoom: int = 24) -> Still:
    """Sobel on a flat gray image: zero padding draws an edge all around it.

    Examples
    --------
    >>> false_edges_figure()
    a flat 0.5 image has no edge; zero padding gives its frame 2.00 to 2.12, replicate 0.00
    """
    flat = np.full((8, 10), 0.5)
    zero, replicate = filters.sobel(flat, "zero"), filters.sobel(flat, "replicate")
    limit = float(zero.max())
    extent = (0, 10, 8, 0)
    frame = np.ones(flat.shape, dtype=bool)
    frame[1:-1, 1:-1] = False
    figure, _panels = pixel_figure(
        [
            (flat, extent, _("flat 0.5")),
            (
                zero / limit,
                extent,
                _("Sobel, 'zero' border: frame {low:.2f}\nto {high:.2f} (white)").format(
                    low=zero[frame].min(), high=limit
                ),
            ),
            (
                replicate / limit,
                extent,
                _("Sobel, 'replicate':\n{value:.2f} everywhere").format(value=replicate.max()),
            ),
        ],
        zoom,
        title_height=44,
    )
    caption = _(
        "a flat 0.5 image has no edge; zero padding gives its frame {low:.2f} "
        "to {high:.2f}, replicate {replicate:.2f}"
    ).format(low=zero[frame].min(), high=zero[frame].max(), replicate=replicate.max())
    return Still.of(figure, caption)
