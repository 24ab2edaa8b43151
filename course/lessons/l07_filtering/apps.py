"""Lesson 07's apps: any 3 x 3 kernel on the photograph, and repeated blurs at the border.

:class:`KernelApp` runs a 3 x 3 kernel the student types (or a preset: box,
Gaussian, sharpen, Sobel x and y) over the photograph, as the lab's loop
does (the dot product of the kernel with each pixel's window), and shows
the result pixel for pixel beside the original, with the top-left corner
zoomed, where the border rule decides what the window reads.

:class:`RepeatedBlurApp` blurs an image n times (the slider) with each border
rule of :mod:`course.filters` and shows the whole image above a zoomed crop
of its top-right corner, where the rules differ: zero padding darkens a frame
that grows with every pass; the other three keep the edge's brightness.
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import Any

import ipywidgets as widgets
import matplotlib
import numpy as np
from matplotlib.patches import Rectangle

from course import filters, images, limits
from course._validate import as_choice, as_float_array, as_image, as_int, as_option, describe
from course.i18n import N_, _
from course.lessons.l07_filtering.border_names import BORDER_LABELS, BORDER_NAMES
from course.widgets.base import SliderApp
from course.widgets.picture import GRAY_PIXELS, PixelPanel, bare_axes, pixel_axes

__all__ = [
    "KERNELS",
    "KernelApp",
    "RepeatedBlurApp",
    "blurred",
    "format_kernel",
    "parse_kernel",
    "right_column_mean",
]

#: The presets of :class:`KernelApp`, as the student would type them.
KERNELS = {
    "box": "1/9 1/9 1/9; 1/9 1/9 1/9; 1/9 1/9 1/9",
    "Gaussian": "1/16 2/16 1/16; 2/16 4/16 2/16; 1/16 2/16 1/16",
    "sharpen": "0 -1 0; -1 5 -1; 0 -1 0",
    "Sobel x": "-1 0 1; -2 0 2; -1 0 1",
    "Sobel y": "-1 -2 -1; 0 0 0; 1 2 1",
    "identity": "0 0 0; 0 1 0; 0 0 0",
}
#: The presets' names as the dropdown shows them, and "typed" for a kernel of the student's own.
PRESET_NAMES = {
    "box": N_("box"),
    "Gaussian": N_("Gaussian"),
    "sharpen": N_("sharpen"),
    "Sobel x": N_("Sobel x"),
    "Sobel y": N_("Sobel y"),
    "identity": N_("identity"),
    "typed": N_("typed"),
}


# A kernel entry: a decimal number or a fraction of two whole numbers, in the digits 0-9.
# Nothing Python alone would read (0x10, 1_0, inf, Arabic-Indic or full-width digits): the
# student sees the number the app uses. Each digit has one place in the pattern, so a long
# run of digits that fails is given up in one pass (the ambiguous \\d+\\.?\\d* tried every
# split of it: seconds on 16,000 digits).
_DECIMAL = re.compile(r"[-+]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")
_FRACTION = re.compile(r"[-+]?[0-9]+/[-+]?[0-9]+")


def _kernel_row(row: str) -> list[str]:
    """A row's entries: split by spaces, or by commas; refused when it could be either.

    ``0,5 1`` is three entries with commas as separators but two with a decimal
    comma: a row that uses commas must use them between every entry.
    """
    if "," not in row:
        return row.split()
    entries = [entry.strip() for entry in row.split(",")]
    if any(len(entry.split()) != 1 for entry in entries):
        raise ValueError(
            _(
                "kernel: the row {strip} mixes commas and spaces: separate its numbers by spaces "
                "or by commas, and write decimals with a point (0.5, not 0,5)"
            ).format(strip=repr(row.strip()))
        )
    return entries


def parse_kernel(text: str) -> np.ndarray:
    """Three rows of three numbers (fractions allowed), rows split by ``;`` or new lines.

    Numbers are written in the digits 0-9; text longer than
    ``course.limits.MAX_TYPED_TEXT`` characters is refused before it is read.

    Examples
    --------
    >>> parse_kernel("1/16 2/16 1/16; 2/16 4/16 2/16; 1/16 2/16 1/16").sum()
    np.float64(1.0)
    >>> try:
    ...     parse_kernel("1 2; 3 4")
    ... except ValueError as error:
    ...     print(str(error).split("; got ")[1])
    2 rows, of 2, 2 numbers
    """
    if not isinstance(text, str):
        raise TypeError(
            _("kernel: expected text such as '1 1 1; 1 1 1; 1 1 1'; got {text}").format(
                text=describe(text)
            )
        )
    if len(text) > limits.MAX_TYPED_TEXT:  # before any parsing: its work stays bounded
        raise ValueError(
            _("kernel: expected at most {most} characters; got {count}").format(
                most=limits.MAX_TYPED_TEXT, count=len(text)
            )
        )
    rows = [_kernel_row(row) for row in re.split(r"[;\n]+", text) if row.strip()]
    if len(rows) != 3 or any(len(row) != 3 for row in rows):
        lengths = ", ".join(str(len(row)) for row in rows)
        raise ValueError(
            _(
                "kernel: expected 3 rows of 3 numbers, the rows separated by ';'; got {count} "
                "rows, of {lengths} numbers"
            ).format(count=len(rows), lengths=lengths or "0")
        )
    for token in (token for row in rows for token in row):
        if not (_DECIMAL.fullmatch(token) or _FRACTION.fullmatch(token)):
            raise ValueError(
                _(
                    "kernel: every entry must be a decimal number like 2, -0.5 or 1/9; got {token}"
                ).format(token=repr(token if len(token) <= 40 else token[:37] + "..."))
            )
    try:
        # A decimal is read as a float, which rounds 1e10000000 to inf at once; the exact
        # Fraction would first build its ten million digits. A fraction's two whole numbers
        # are exact, then rounded once.
        values = [[_entry_value(token) for token in row] for row in rows]
    except (ValueError, ZeroDivisionError, OverflowError) as error:
        raise ValueError(
            _("kernel: every entry must be a number like 2, -0.5 or 1/9 ({error})").format(
                error=error
            )
        ) from None
    kernel = np.array(values)
    if not np.isfinite(kernel).all() or np.abs(kernel).max() > limits.LARGEST:
        raise ValueError(
            _("kernel: every entry must lie within +-{largest:g}").format(largest=limits.LARGEST)
        )
    return kernel


def _entry_value(token: str) -> float:
    """A checked kernel entry's value: ``float`` of a decimal, the exact quotient of a fraction."""
    if "/" in token:
        return float(Fraction(token))
    return float(token)


def format_kernel(kernel: np.ndarray) -> str:
    """The kernel as the app shows it: three rows of three numbers.

    Examples
    --------
    >>> format_kernel(filters.SOBEL_X)
    '-1 0 1; -2 0 2; -1 0 1'
    """
    return "; ".join(" ".join(f"{value:g}" for value in row) for row in np.asarray(kernel))


def right_column_mean(image: Any) -> float:
    """Mean of the image's rightmost column (every channel): lesson 07's edge brightness.

    Examples
    --------
    >>> image = np.zeros((4, 5))
    >>> image[:, -1] = 0.5
    >>> right_column_mean(image)
    0.5
    """
    return float(as_image(image, "image")[:, -1].mean())


def blurred(image: np.ndarray, border: str) -> np.ndarray:
    """One 3 x 3 box blur with the given border rule (``blur`` for the handout's)."""
    border = as_choice(border, "border", filters.BORDERS)
    if border == "handout":
        return filters.blur(image)
    return filters.convolve(image, filters.BOX, border)


#: Lesson 07's measure of the dark frame: columns below this share of 'replicate''s.
FRAME_SHARE = 0.95


def _frame_depth(image: np.ndarray, reference: np.ndarray) -> int:
    """How many columns in from the right edge have a mean below FRAME_SHARE of reference's.

    The rule of :func:`course.lessons.l07_filtering.figures.frame_depth`, without its division:
    a black column of ``reference`` (a black image) counts as not darkened, with no warning.

    Examples
    --------
    >>> _frame_depth(np.array([[1, 1, 1, 1, 0.9, 0.5]] * 2), np.ones((2, 6)))
    2
    >>> _frame_depth(np.zeros((2, 3)), np.zeros((2, 3)))
    0
    """
    axes = (0, 2) if image.ndim == 3 else 0
    dark = np.mean(image, axis=axes) < FRAME_SHARE * np.mean(reference, axis=axes)
    return int(np.argmin(np.append(dark[::-1], False)))


class RepeatedBlurApp(SliderApp):
    """Blur n times with each border rule; the corner crop shows the frame.

    Each title gives the right (last) column's brightness against the original's
    and the depth of the rule's dark frame, as lesson 07 measures it: the columns in
    from the right edge whose mean is below 95 % of the same column under
    ``'replicate'`` (:func:`course.lessons.l07_filtering.figures.frame_depth`).

    Parameters
    ----------
    image : array_like, (H, W) or (H, W, 3), values in [0, 1]
    repeats : int
        Initial number of blurs.
    corner : int
        Side of the zoomed top-right crop.
    """

    def __init__(self, image: Any, repeats: int = 5, corner: int = 32) -> None:
        self.image = as_image(image, "image")
        self.corner = as_int(corner, "corner", minimum=2)
        repeats = as_int(repeats, "repeats", minimum=0, maximum=30)
        self.original_column = right_column_mean(self.image)
        controls = {
            "repeats": widgets.IntSlider(value=repeats, min=0, max=30, description=_("blurs"))
        }
        super().__init__(controls, shape=(560, 1000))
        self.done = 0
        self.results = dict.fromkeys(filters.BORDERS, self.image)
        self.wholes, self.crops, self.titles = {}, {}, {}
        grid = self.figure.add_gridspec(2, 4, left=0.01, right=0.99, top=0.88, bottom=0.05)
        self.figure.text(
            0.5,
            0.01,
            _(
                "dark frame: the columns in from the right edge whose mean is below "
                "{share:.0%} of the same column's under 'replicate'"
            ).format(share=FRAME_SHARE),
            ha="center",
            va="bottom",
            fontsize=9,
        )
        style = GRAY_PIXELS if self.image.ndim == 2 else {"interpolation": "nearest"}
        for column, border in enumerate(filters.BORDERS):
            top = bare_axes(self.figure.add_subplot(grid[0, column]))
            self.wholes[border] = top.imshow(
                self.image, **{**style, "interpolation": "antialiased"}
            )
            self.titles[border] = top.set_title(_(BORDER_NAMES[border]), fontsize=9)
            bottom = bare_axes(self.figure.add_subplot(grid[1, column]))
            self.crops[border] = bottom.imshow(self._corner_of(self.image), **style)
        self.update()

    def _corner_of(self, image: np.ndarray) -> np.ndarray:
        """The zoomed top-right corner."""
        return image[: self.corner, -self.corner :]

    def blurred(self, repeats: int) -> dict[str, np.ndarray]:
        """The image blurred ``repeats`` times under each rule (kept for the next step)."""
        repeats = as_int(repeats, "repeats", minimum=0, maximum=30)  # the slider's range
        if repeats < self.done:
            self.done, self.results = 0, dict.fromkeys(filters.BORDERS, self.image)
        while self.done < repeats:
            self.results = {
                border: blurred(result, border) for border, result in self.results.items()
            }
            self.done += 1
        return self.results

    def update(self) -> None:
        repeats = int(self.value("repeats"))
        for border, result in self.blurred(repeats).items():
            self.wholes[border].set_data(result)
            self.crops[border].set_data(self._corner_of(result))
            column = right_column_mean(result)
            if self.original_column > 0:
                edge = _("right column at {ratio:.2f} x the original").format(
                    ratio=column / self.original_column
                )
            else:  # a black column: no ratio to show
                edge = _("right column's mean {mean:.2f} (the original's is 0)").format(mean=column)
            if border == "replicate":
                frame = _("the frames' reference")
            else:
                depth = _frame_depth(result, self.results["replicate"])
                frame = _("dark frame: {depth} px deep").format(depth=depth)
            self.titles[border].set_text(
                _("{border}, {repeats} blurs\n{edge}").format(
                    border=_(BORDER_LABELS[border]), repeats=repeats, edge=edge
                )
                + "\n"
                + frame
            )


class KernelApp(SliderApp):
    """A 3 x 3 kernel over the photograph: the original, the result, and the corner zoomed.

    Each output pixel is the dot product of the kernel with the pixel's 3 x 3
    window, as the lab's loop computes it (a correlation), with the border
    rule picked. A kernel whose weights sum to 0 (an edge detector) gives
    values of both signs: they are shown on a blue-white-red scale around 0,
    and anything else in gray from 0 to 1. Type a kernel in the text box, or
    pick a preset to fill it in. ``window`` is the (row, column) of the
    zoomed 16 x 16 window's top-left pixel.
    """

    BLIT = True
    ZOOM = 2
    CORNER, CORNER_ZOOM = 16, 12

    def __init__(
        self,
        image: Any = None,
        kernel: str = "box",
        border: str = "replicate",
        window: tuple[int, int] = (40, 112),
    ) -> None:
        if image is None:
            image = images.face()  # its right edge is the light wall, where the border shows
        self.image = as_image(image, "image")
        if self.image.ndim != 2:
            raise ValueError(
                _("image: expected a gray (H, W) image; got shape {image_shape}").format(
                    image_shape=self.image.shape
                )
            )
        kernel = as_option(kernel, "kernel", tuple(KERNELS))
        border = as_option(border, "border", filters.BORDERS)
        if not isinstance(window, (tuple, list)) or len(window) != 2:
            raise ValueError(
                _("window must be a pair (row, column) of integers; got {window}").format(
                    window=describe(window)
                )
            )
        window = (
            as_int(window[0], _("window[0] (row)")),
            as_int(window[1], _("window[1] (column)")),
        )
        controls = {
            "preset": widgets.Dropdown(
                options=[(_(PRESET_NAMES[name]), name) for name in (*KERNELS, "typed")],
                value=kernel,
                description=_("preset"),
            ),
            "kernel": widgets.Textarea(
                value=KERNELS[kernel], description=_("kernel"), continuous_update=False
            ),
            "border": widgets.Dropdown(
                options=[(_(BORDER_NAMES[name]), name) for name in filters.BORDERS],
                value=border,
                description=_("border"),
            ),
        }
        height, width = self.image.shape
        side_h, side_w = height * self.ZOOM, width * self.ZOOM
        # The zoomed window: 16 x 16 pixels, or the whole of a smaller image, 192 px wide.
        self.corner = min(self.CORNER, height, width)
        corner_zoom = self.CORNER * self.CORNER_ZOOM // self.corner
        corner = self.corner * corner_zoom
        gap, margin, top = 16, 12, 48
        columns = margin + 2 * side_w + corner + 2 * gap + margin
        tallest = max(side_h, corner)
        rows = top + tallest + margin
        super().__init__(controls, shape=(rows, columns))
        self.kernel = parse_kernel(KERNELS[kernel])
        self.result = self.image
        self.panels: dict[str, PixelPanel] = {}
        self.titles = {}
        for index, (name, size, zoom, (h, w)) in enumerate(
            (
                (N_("original"), side_w, self.ZOOM, (height, width)),
                (N_("filtered"), side_w, self.ZOOM, (height, width)),
            )
        ):
            axes = bare_axes(
                pixel_axes(
                    self.figure,
                    margin + index * (side_w + gap),
                    margin + tallest - side_h,  # the panels' tops in line
                    size,
                    side_h,
                )
            )
            self.panels[name] = PixelPanel(self, axes, (h, w), zoom)
            self.titles[name] = axes.set_title(_(name), fontsize=9)
        axes = bare_axes(
            pixel_axes(
                self.figure, margin + 2 * (side_w + gap), margin + tallest - corner, corner, corner
            )
        )
        self.panels["corner"] = PixelPanel(self, axes, (self.corner, self.corner), corner_zoom)
        self.titles["corner"] = axes.set_title("", fontsize=9)
        self.panels["original"].set_data(self.image)
        top = min(max(0, int(window[0])), height - self.corner)
        left = min(max(0, int(window[1])), width - self.corner)
        self.window = (slice(top, top + self.corner), slice(left, left + self.corner))
        # Drawn over the pasted pixels each time, so they are moving artists.
        self.marks = [
            self.panels[name].axes.add_patch(
                Rectangle(
                    (left, top), self.corner, self.corner, fill=False, color="#D55E00", lw=1.2
                )
            )
            for name in ("original", "filtered")
        ]
        self.preset = kernel
        self.animate(*self.titles.values(), *self.marks)

    def _set_quietly(self, name: str, value: Any) -> None:
        """Set a control from ``update`` without a second redraw."""
        held, self._held = self._held, True
        try:
            self.controls[name].value = value
        finally:
            self._held = held

    def _follow_preset(self) -> None:
        """A preset just picked fills in the kernel; a kernel typed over it is no preset."""
        preset = self.value("preset")
        if preset != self.preset and preset in KERNELS:
            self._set_quietly("kernel", KERNELS[preset])
        elif preset in KERNELS and self.value("kernel") != KERNELS[preset]:
            self._set_quietly("preset", "typed")
        self.preset = self.value("preset")

    def filtered(self, kernel: np.ndarray, border: str) -> np.ndarray:
        """The lab's dot product of ``kernel`` with each window, under ``border``."""
        kernel = as_float_array(kernel, "kernel")
        if kernel.shape != (3, 3):
            raise ValueError(
                _("kernel must be 3 x 3; got shape {kernel_shape}").format(
                    kernel_shape=kernel.shape
                )
            )
        return filters.convolve(self.image, kernel[::-1, ::-1], border)

    def update(self) -> None:
        self._follow_preset()
        try:
            kernel = parse_kernel(self.value("kernel"))
        except ValueError as error:
            self.status.value = _("Kept the last kernel: {error}").format(error=error)
            kernel = self.kernel
        else:
            self.status.value = ""
        border = self.value("border")
        if border == "handout" and abs(kernel.sum()) < 1e-12:
            self.status.value = _(
                "The report's border rule averages the pixels inside; a kernel whose "
                "weights sum to 0 has nothing to average, so it is read as zero padding."
            )
            border = "zero"
        self.kernel = kernel
        self.result = self.filtered(kernel, border)
        signed = abs(kernel.sum()) < 1e-12
        limit = max(float(np.abs(self.result).max()), 1e-12) if signed else 1.0
        for name in ("filtered", "corner"):
            panel = self.panels[name]
            panel.colormap = (
                matplotlib.colormaps["RdBu_r"] if signed else matplotlib.colormaps["gray"]
            )
            panel.vmin, panel.vmax = (-limit, limit) if signed else (0.0, 1.0)
        self.panels["filtered"].set_data(self.result)
        self.panels["corner"].set_data(self.result[self.window])
        scale = (
            _("blue -{limit:.2g} to red +{limit:.2g}").format(limit=limit)
            if signed
            else _("gray 0 to 1, clipped")
        )
        self.titles["filtered"].set_text(_("filtered ({scale})").format(scale=scale))
        self.titles["corner"].set_text(
            _("the orange window, {border}").format(border=_(BORDER_LABELS[border]))
        )
