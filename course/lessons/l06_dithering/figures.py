"""Lesson 06's still pictures: every method side by side, the blue-noise mask and its
spectrum, the wavefront order, and the left-edge slip.

Each function returns a :class:`~course.widgets.picture.Still` whose caption
states the numbers it shows. Dots are drawn as whole squares: zoomed crops at
a whole zoom, and overviews at 1:1 after a block mean (what an eye at a
distance sees), never resampled by the display. Floyd-Steinberg worked one
pixel at a time is in :mod:`.floyd_steinberg`.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle

from course._validate import as_gray, as_image, as_int, as_point
from course.halftone import dither
from course.halftone.blue_noise_masks import (
    blue_noise_mask,
    low_frequency_fraction,
    radial_power_spectrum,
)
from course.i18n import _
from course.raster.canvas import crop
from course.widgets.base import pad
from course.widgets.picture import GRAY_PIXELS, Still, bare_axes, pixel_axes, pixel_figure

__all__ = [
    "Table",
    "block_mean",
    "clumps_and_holes",
    "mask_figure",
    "methods_figure",
    "wavefront_figure",
    "wraparound_figure",
]

BLUE, VERMILLION = "#0072B2", "#D55E00"


def block_mean(image: np.ndarray, factor: int) -> np.ndarray:
    """The image shrunk by a whole ``factor``: each output pixel the mean of a factor^2 block.

    Examples
    --------
    >>> block_mean(np.array([[0.0, 1.0, 1.0, 1.0], [0.0, 1.0, 0.0, 0.0]]), 2)
    array([[0.5, 0.5]])
    """
    image = as_image(image, "image")
    factor = as_int(factor, "factor", minimum=1, maximum=min(image.shape[:2]))
    height, width = (np.array(image.shape[:2]) // factor) * factor
    trimmed = image[:height, :width]
    return trimmed.reshape(height // factor, factor, width // factor, factor).mean(axis=(1, 3))


def methods_figure(
    images: Mapping[str, np.ndarray],
    centre: tuple[float, float],
    size: int = 24,
    zoom: int = 6,
    shrink: int = 2,
    columns: int = 6,
) -> Still:
    """Each image as a whole (a block mean, 1:1) above a zoomed window, every dot a square.

    The first image sets the scale; an image three times larger (ordered
    dithering) is shrunk and zoomed three times less, so every panel shows
    the same part of the picture at the same size. ``zoom`` must be a
    multiple of 3. A name the course's catalog knows (the lab's methods,
    ``"original"``) is shown in the current language.

    Examples
    --------
    >>> gray = np.linspace(0, 1, 48 * 36).reshape(36, 48)
    >>> methods_figure({"ramp": gray, "ordered": dither.ordered(gray)}, (24, 18), 12, 6, 2)
    2 images; the window 12 x 12 around (24, 18), each pixel 6 x 6 screen pixels
    """
    size, zoom, shrink = (
        as_int(v, n, minimum=1, maximum=100)
        for v, n in ((size, "size"), (zoom, "zoom"), (shrink, "shrink"))
    )
    columns = as_int(columns, "columns", minimum=1, maximum=20)
    as_point(centre, "centre", dim=2)
    if not isinstance(images, Mapping) or not images:
        raise TypeError(
            _("images must map names to gray images; got {images_type}").format(
                images_type=type(images).__name__
            )
        )
    if zoom % 3:
        raise ValueError(
            _("zoom must be a multiple of 3 (ordered dithering is 3x); got {zoom}").format(
                zoom=zoom
            )
        )
    arrays = {name: as_gray(image, f"images[{name!r}]") for name, image in images.items()}
    reference = next(iter(arrays.values()))
    height, width = reference.shape
    over_h, over_w = height // shrink, width // shrink
    side = size * zoom
    panel_w = max(over_w, side)
    gap, title = 14, 22
    rows = -(-len(arrays) // columns)
    row_height = title + over_h + 8 + side + 6
    figure_w = gap + min(columns, len(arrays)) * (panel_w + gap)
    figure_h = rows * row_height + 8
    figure = Figure(figsize=(figure_w / 100, figure_h / 100), dpi=100)
    for index, (name, image) in enumerate(arrays.items()):
        row, column = divmod(index, columns)
        scale = image.shape[0] // height
        left = gap + column * (panel_w + gap)
        top = figure_h - row * row_height - title
        overview = bare_axes(pixel_axes(figure, left, top - over_h, over_w, over_h))
        small = block_mean(image, shrink * scale)
        overview.imshow(small, extent=(0, small.shape[1], small.shape[0], 0), **GRAY_PIXELS)
        overview.set_title(_(name), fontsize=9)
        window, (x0, x1, y1, y0) = crop(image, np.multiply(centre, scale), size * scale)
        box = Rectangle(
            (x0 / (shrink * scale), y0 / (shrink * scale)),
            (x1 - x0) / (shrink * scale),
            (y1 - y0) / (shrink * scale),
            fill=False,
            color="red",
            lw=1,
        )
        overview.add_patch(box)
        zoomed = bare_axes(pixel_axes(figure, left, top - over_h - 8 - side, side, side))
        full = np.full((size * scale, size * scale), 0.5)
        full[: window.shape[0], : window.shape[1]] = window
        zoomed.imshow(full, extent=(0, size * scale, size * scale, 0), **GRAY_PIXELS)
    caption = _(
        "{count} images; the window {size} x {size} around ({x:g}, {y:g}), "
        "each pixel {zoom} x {zoom} screen pixels"
    ).format(count=len(arrays), size=size, x=centre[0], y=centre[1], zoom=zoom)
    return Still.of(figure, caption)


def mask_figure(size: int = 64, seed: int = 0) -> Still:
    """The void-and-cluster mask and white noise, each tiled 2 x 2, and their spectra.

    Examples
    --------
    >>> mask_figure(32)  # doctest: +NORMALIZE_WHITESPACE
    share of the power below 0.125 cycles per pixel: mask 1.67e-05, white noise 0.042
    (about 2500 times less)
    """
    mask = blue_noise_mask(size, np.random.default_rng(seed))
    white = np.random.default_rng(seed + 1).random((size, size))
    zoom = max(1, 256 // (2 * size))
    side = 2 * size * zoom
    figure = Figure(figsize=((2 * side + 400) / 100, (side + 60) / 100), dpi=100)
    blue_name, white_name = _("void-and-cluster"), _("white noise")
    for index, (picture, name) in enumerate(((mask, blue_name), (white, white_name))):
        axes = bare_axes(pixel_axes(figure, 16 + index * (side + 16), 16, side, side))
        tiled = np.tile(picture, (2, 2))
        axes.imshow(tiled, extent=(0, 2 * size, 2 * size, 0), **GRAY_PIXELS)
        axes.set_title(_("{name}, tiled 2 x 2").format(name=name), fontsize=9)
    chart = figure.add_axes(
        ((2 * side + 90) / figure.bbox.width, 0.18, 280 / figure.bbox.width, 0.68)
    )
    # Each divided by its pattern's variance, as the app does: white noise sits at 1.
    frequency, blue_power = radial_power_spectrum(mask)
    blue_power = blue_power / mask.var()
    _frequency, white_power = radial_power_spectrum(white)
    white_power = white_power / white.var()
    chart.plot(frequency, blue_power, color=BLUE, label=blue_name)
    chart.plot(frequency, white_power, color=VERMILLION, ls="--", label=white_name)
    chart.axvline(0.125, color="0.5", lw=0.8, ls=":", label=_("below 0.125: the low frequencies"))
    chart.set_xlabel(_("frequency (cycles per pixel)"), fontsize=8)
    chart.set_ylabel(_("power (white noise = 1)"), fontsize=8)
    chart.tick_params(labelsize=7)
    chart.set_ylim(top=chart.get_ylim()[1] * 1.3)  # room for the legend above the lines
    chart.legend(fontsize=7, loc="upper left")
    blue_low, white_low = low_frequency_fraction(mask), low_frequency_fraction(white)
    # the ratio to two significant digits, written out: 3900, not 3.9e+03
    caption = _(
        "share of the power below 0.125 cycles per pixel: mask {mask:.2e}, white noise "
        "{white:.3f} (about {ratio:g} times less)"
    ).format(mask=blue_low, white=white_low, ratio=float(f"{white_low / blue_low:.2g}"))
    return Still.of(figure, caption)


class Table(str):
    """Text that a notebook shows as it is (a ``str`` whose repr is itself)."""

    def __repr__(self) -> str:
        return str(self)


def clumps_and_holes(patterns: Mapping[str, np.ndarray], level: float) -> Table:
    """Each method's flat patch at ``level``: share lit, dots touching a dot, largest hole.

    A clump is a dot with another among its eight neighbours; the largest
    hole is the radius of the largest disc of unlit pixels (in pixels).

    Examples
    --------
    >>> dots = np.zeros((6, 6)); dots[0, 0] = dots[0, 1] = dots[5, 5] = 1
    >>> print(clumps_and_holes({"three dots": dots}, 0.1))  # doctest: +NORMALIZE_WHITESPACE
    level 0.100      lit   dots touching a dot   largest hole (px)
    three dots      0.083                     2                5.00
    """
    from scipy import ndimage

    lines = [
        pad(_("level {level:.3f}").format(level=level), 14)
        + pad(_("lit"), 6, ">")
        + pad(_("dots touching a dot"), 22, ">")
        + pad(_("largest hole (px)"), 20, ">")
    ]
    for name, dots in patterns.items():
        lit = np.asarray(dots) > 0.5
        neighbours = ndimage.convolve(lit.astype(int), np.ones((3, 3), int), mode="constant")
        touching = int(np.count_nonzero(lit & (neighbours > 1)))
        hole = ndimage.distance_transform_edt(~lit).max() if lit.any() else float("inf")
        # No dot at all: the hole is the whole plane, "inf" in English.
        shown = f"{hole:20.2f}" if np.isfinite(hole) else pad(_("inf"), 20, ">")
        lines.append(f"{pad(_(name), 15)}{lit.mean():6.3f}{touching:22d}{shown}")
    return Table("\n".join(lines))


def wavefront_figure(height: int = 6, width: int = 10, pixel: tuple[int, int] = (5, 3)) -> Still:
    """Pixels numbered t = x + 2 y: error diffusion's pixels of one number run together.

    Examples
    --------
    >>> wavefront_figure()
    pixel (5, 3) is number 11 and waits for 4 pixels, all numbered below 11
    """
    height = as_int(height, "height", minimum=2, maximum=64)
    width = as_int(width, "width", minimum=3, maximum=64)
    if isinstance(pixel, (str, bytes)) or not hasattr(pixel, "__len__") or len(pixel) != 2:
        raise ValueError(
            _("pixel must be a pair (x, y) of integers; got {pixel:.60}").format(pixel=repr(pixel))
        )
    x = as_int(pixel[0], "pixel[0] (x)", minimum=1, maximum=width - 2)
    y = as_int(pixel[1], "pixel[1] (y)", minimum=1, maximum=height - 1)
    t = np.add.outer(2 * np.arange(height), np.arange(width))
    needs = [(x - 1, y), (x - 1, y - 1), (x, y - 1), (x + 1, y - 1)]
    shade = np.where(t == t[y, x], 0.6, 0.0)
    for nx, ny in needs:
        shade[ny, nx] = 0.3
    figure, (axes,) = pixel_figure(
        [
            (
                1 - shade,
                (0, width, height, 0),
                _("t = x + 2y: the pixels numbered {number} run together").format(number=t[y, x]),
            )
        ],
        zoom=44,
        legend=[
            ("0.4", _("numbered {number}").format(number=t[y, x])),
            ("0.7", _("what pixel ({x}, {y}) waits for").format(x=x, y=y)),
        ],
    )
    for (row, column), value in np.ndenumerate(t):
        axes.text(column + 0.5, row + 0.5, str(value), ha="center", va="center", fontsize=9)
    waits = [t[ny, nx] for nx, ny in needs]
    caption = (
        _(
            "pixel {pixel} is number {number} and waits for {count} pixels, all numbered "
            "below {number}"
        ).format(pixel=pixel, number=t[y, x], count=len(needs))
        if max(waits) < t[y, x]
        else _("the numbering is wrong")
    )
    return Still.of(figure, caption)


def wraparound_figure(
    gray: np.ndarray, centre: tuple[float, float], size: int = 32, zoom: int = 6
) -> Still:
    """Floyd-Steinberg, the same with the left-edge slip, and where they differ.

    Left, the whole image (every second pixel, 1:1) with the window marked;
    then the window: correct, with the slip, and the difference, keyed.

    Examples
    --------
    >>> flat = np.full((40, 40), 0.3)
    >>> wraparound_figure(flat, (30, 20), 16)
    the slip changes 122 pixels (7.6%), all in columns 30 to 39
    """
    gray = as_gray(gray, "gray")
    good = dither.error_diffusion(gray)
    bad = dither.error_diffusion_wraparound(gray)
    difference = 0.5 + 0.5 * (bad - good)  # gray: equal; white: lit only with the slip
    changed = good != bad
    windows = []
    for picture, name in (
        (good, _("correct")),
        (bad, _("with the slip")),
        (
            difference,
            _("difference in the window\n({count} pixels in the whole image)").format(
                count=changed.sum()
            ),
        ),
    ):
        window, extent = crop(picture, centre, size)
        windows.append((window, extent, name))
    overview = gray[::2, ::2]
    reserve = overview.shape[1] + 18
    figure, _panels = pixel_figure(
        windows,
        zoom=zoom,
        reserve_left=reserve,
        title_height=44,  # the difference's title takes two lines
        legend=[
            ("0.5", _("same dot")),
            ("white", _("lit only with the slip")),
            ("black", _("lit only without it")),
            ("red", _("the window")),
        ],
    )
    height, width = gray.shape
    panel_top = size * zoom  # pixel_figure puts the panels' bottom at gap // 2
    axes = bare_axes(
        pixel_axes(
            figure, 18, 9 + panel_top - overview.shape[0], overview.shape[1], overview.shape[0]
        )
    )
    axes.imshow(overview, extent=(0, width, height, 0), **GRAY_PIXELS)
    axes.set_title(_("the whole image"), fontsize=9)
    _window, (left, right, bottom, top) = crop(gray, centre, size)
    axes.add_patch(
        Rectangle((left, top), right - left, bottom - top, fill=False, edgecolor="red", lw=1.5)
    )
    columns = np.flatnonzero(changed.any(axis=0))
    where = (
        _("all in columns {first} to {last}").format(first=columns.min(), last=columns.max())
        if len(columns)
        else _("none")
    )
    caption = _("the slip changes {count} pixels ({share:.1%}), {where}").format(
        count=changed.sum(), share=changed.mean(), where=where
    )
    return Still.of(figure, caption)
