"""Lesson 06 apps: dithering methods side by side, a gray-level slider, void-and-cluster.

- :class:`DitherComparisonApp`: every method on one image, zoomed crops
  (nearest interpolation) at a window the sliders move.
- :class:`GrayLevelApp`: a flat patch at the slider's level: the ten
  patterns of the lab's 3 x 3 matrix, and what each method makes of it.
- :class:`VoidAndClusterApp`: the blue-noise mask being built, dot by dot,
  over the energy that chooses each dot, with the pattern's spectrum.

The lesson's still pictures are in :mod:`course.lessons.l06_dithering.figures`.
"""

from __future__ import annotations

from typing import Any, ClassVar

import ipywidgets as widgets
import numpy as np
from matplotlib.patches import Rectangle

from course import limits
from course._validate import as_gray, as_int, as_positive_float, as_unit
from course.halftone import dither
from course.halftone.blue_noise_masks import blue_noise_mask, cluster_energy, radial_power_spectrum
from course.halftone.blue_noise_masks import void_and_cluster as rank_pixels
from course.i18n import N_, _
from course.raster.canvas import crop
from course.widgets.base import Handle, SliderApp, format_points
from course.widgets.picture import GRAY_PIXELS, PixelPanel, bare_axes, pixel_axes

# The names of course.halftone.dither.all_methods as the apps title them: marked here, where
# they are
# shown, for the catalog (the library keys its results by the English names).
_METHOD_TITLES = (
    N_("original"),
    N_("Floyd-Steinberg serpentine"),
    N_("Jarvis-Judice-Ninke"),
    N_("Stucki"),
    N_("Atkinson"),
)

__all__ = ["DitherComparisonApp", "GrayLevelApp", "VoidAndClusterApp"]


def _zoom_window(image: np.ndarray, scale: int, centre: tuple[float, float], size: int) -> Any:
    """The same window as ``crop`` on the reference image, of an image ``scale`` times larger."""
    _, (left, right, bottom, top) = crop(image[::scale, ::scale], centre, size)
    window = image[scale * top : scale * bottom, scale * left : scale * right]
    return window, (scale * left, scale * right, scale * bottom, scale * top)


class DitherComparisonApp(SliderApp):
    """Every dithering method on one gray image; drag the window to zoom elsewhere.

    The red window on the original (shown 1:1) is the part every other panel
    shows, each pixel a ``zoom`` x ``zoom`` square (ordered dithering's
    three times larger output at a third of the zoom), so the dots are drawn
    as they are, with nothing resampled. Drag the window, or type its centre
    pixel in ``window`` (``x, y``).

    Parameters
    ----------
    gray : array_like, (H, W), values in [0, 1]
    size : int
        Side of the zoomed window, in input pixels.
    zoom : int
        Screen pixels per input pixel in the zoomed panels; a multiple of 3.
    """

    BLIT = True
    COLUMNS = 4
    # Titles wider than a panel, shortened so that nothing is cut off.
    SHORT_TITLES: ClassVar[dict[str, str]] = {"Floyd-Steinberg serpentine": N_("F-S serpentine")}

    def __init__(self, gray: Any, size: int = 24, zoom: int = 6) -> None:
        self.gray = as_gray(gray, "gray")
        self.size = as_int(size, "size", minimum=4, maximum=min(self.gray.shape))
        self.zoom = as_int(zoom, "zoom", minimum=3, maximum=30)
        if self.zoom % 3:
            raise ValueError(
                _("zoom must be a multiple of 3 (ordered dithering is 3x); got {zoom}").format(
                    zoom=zoom
                )
            )
        height, width = self.gray.shape
        self.results = {"original": self.gray, **dither.all_methods(self.gray)}
        self.at = np.array([width // 2, height // 2])
        controls = {
            "window": widgets.Text(
                value=format_points([self.at]), description="x, y", continuous_update=False
            )
        }
        side, gap, title = self.size * self.zoom, 12, 24
        rows = -(-len(self.results) // self.COLUMNS)
        figure_height = max(height + title + 10, rows * (side + title) + 10)
        figure_width = 12 + width + 24 + self.COLUMNS * (side + gap)
        super().__init__(controls, shape=(figure_height, figure_width))
        overview = pixel_axes(self.figure, 12, figure_height - title - height, width, height)
        bare_axes(overview).imshow(self.gray, extent=(0, width, height, 0), **GRAY_PIXELS)
        overview.set_title(_("original, 1:1 (drag the red window)"), fontsize=9)
        self.window = Rectangle((0, 0), 1, 1, fill=False, color="red", lw=1.5)
        overview.add_patch(self.window)
        self.overview = overview
        self.crops = {}
        for index, (name, result) in enumerate(self.results.items()):
            row, column = divmod(index, self.COLUMNS)
            left = 12 + width + 24 + column * (side + gap)
            bottom = figure_height - (row + 1) * (side + title)
            axes = bare_axes(pixel_axes(self.figure, left, bottom, side, side))
            axes.set_title(_(self.SHORT_TITLES.get(name, name)), fontsize=9)
            scale = result.shape[0] // height
            shape = (self.size * scale, self.size * scale)
            self.crops[name] = PixelPanel(self, axes, shape, self.zoom // scale)
        self.animate(self.window)
        self.highlight_ring(overview)

    def centre(self) -> tuple[float, float]:
        """The window's centre: the middle of the pixel the text names."""
        height, width = self.gray.shape
        (at,) = self.typed_points("window", [self.at], 1, 0, (width - 1, height - 1), whole=True)
        self.at = at.astype(int)
        return (self.at[0] + 0.5, self.at[1] + 0.5)

    def update(self) -> None:
        centre = self.centre()
        for name, result in self.results.items():
            scale = result.shape[0] // self.gray.shape[0]
            window, _extent = _zoom_window(result, scale, centre, self.size)
            self.crops[name].set_data(_padded(window, self.size * scale))
        _, (left, right, bottom, top) = crop(self.gray, centre, self.size)
        self.window.set_bounds(left, top, right - left, bottom - top)

    def handles(self) -> list[Handle]:
        _, (left, right, bottom, top) = crop(self.gray, self.centre(), self.size)
        return [
            Handle("window", self.overview, tuple(self.at + 0.5), box=(left, top, right, bottom))
        ]

    def drag(self, name: str, point: np.ndarray) -> None:
        height, width = self.gray.shape
        at = np.clip(np.floor(point), 0, (width - 1, height - 1))
        self.controls["window"].value = format_points([at])


def _padded(window: np.ndarray, side: int) -> np.ndarray:
    """A crop made square by gray: near the image's edge a window has fewer pixels."""
    if window.shape == (side, side):
        return window
    square = np.full((side, side), 0.5)
    square[: window.shape[0], : window.shape[1]] = window
    return square


class GrayLevelApp(SliderApp):
    """A flat patch at one gray level: the lab's ten ordered patterns and each method.

    Every panel draws each pixel as a whole square (the patch at ``zoom``,
    ordered dithering's three times larger output at a third of it).

    Parameters
    ----------
    level : float
        Initial slider value in [0, 1], rounded to the slider's steps of 1/360
        (forty per ninth), as the browser rounds it when it shows the slider.
    size : int
        Side of the flat patch in pixels (ordered dithering shows 3 times more).
    """

    BLIT = True
    # 360 steps: both the tenths (0.1 = 36/360) and the ninths (1/9 = 40/360) can be set.
    DIVISIONS = 360
    STEP = 1 / DIVISIONS
    ZOOM = 6
    # The methods side by side under the strip, in the order of :meth:`outputs`.
    PANELS = (
        N_("threshold"),
        N_("uniform random"),
        N_("blue noise"),
        N_("ordered 3x3"),
        N_("Bayer 8x8"),
        N_("Floyd-Steinberg"),
    )

    def __init__(self, level: float = 0.3, size: int = 24) -> None:
        self.size = as_int(size, "size", minimum=3, maximum=64)
        level = as_unit(level, "level")
        self.mask = blue_noise_mask(32, np.random.default_rng(0))
        controls = {
            "level": widgets.FloatSlider(
                value=self.snapped(float(level)),
                min=0.0,
                max=1.0,
                step=self.STEP,
                description=_("level"),
                readout_format=".3f",
            )
        }
        side, gap = self.size * self.ZOOM, 14
        strip_zoom = 20
        width = 16 + len(self.PANELS) * (side + gap)
        height = 10 + side + 60 + 3 * strip_zoom + 40
        super().__init__(controls, shape=(height, width))
        strip = bare_axes(pixel_axes(self.figure, 16, side + 80, 39 * strip_zoom, 3 * strip_zoom))
        strip.imshow(self.ordered_patterns(), extent=(0, 39, 3, 0), **GRAY_PIXELS)
        strip.set_title(
            _(
                "the ten patterns of M = [[6, 8, 4], [1, 0, 3], [5, 2, 7]]: k sub-pixels "
                "lit for levels in ((k - 1)/9, k/9]"
            ),
            fontsize=9,
        )
        for k in range(10):
            strip.text(4 * k + 1.5, 3.15, f"k={k}", ha="center", va="top", fontsize=8)
        self.highlight = Rectangle((-0.1, -0.1), 3.2, 3.2, fill=False, color="red", lw=2)
        strip.add_patch(self.highlight)
        self.panels, self.titles = {}, {}
        for index, name in enumerate(self.PANELS):
            axes = bare_axes(pixel_axes(self.figure, 16 + index * (side + gap), 10, side, side))
            scale = 3 if name == "ordered 3x3" else 1
            shape = (self.size * scale, self.size * scale)
            self.panels[name] = PixelPanel(self, axes, shape, self.ZOOM // scale)
            self.titles[name] = axes.set_title(_(name), fontsize=9)
        self.animate(self.highlight, *self.titles.values())
        self.update()

    @classmethod
    def snapped(cls, level: float) -> float:
        """``level`` on the slider's grid, as the nearest float to n / 360.

        ``n * (1 / 360)`` can land just above a ninth, ``40 * (1 / 360) >
        1 / 9``, which would light the next ordered pattern at the ninth itself.
        """
        level = as_unit(level, "level")
        return round(level * cls.DIVISIONS) / cls.DIVISIONS

    @staticmethod
    def ordered_patterns() -> np.ndarray:
        """The ten 3 x 3 patterns in a strip, one gray column between them."""
        strip = np.full((3, 39), 0.5)
        for k in range(10):
            strip[:, 4 * k : 4 * k + 3] = dither.ordered([[k / 9]])
        return strip

    def outputs(self, level: float) -> dict[str, np.ndarray]:
        """Each method on the flat patch at ``level``, as the panels show them."""
        patch = np.full((self.size, self.size), level)
        return {
            "threshold": dither.threshold(patch),
            "uniform random": dither.uniform_random(patch, np.random.default_rng(0)),
            "blue noise": dither.blue_noise(patch, self.mask),
            "ordered 3x3": dither.ordered(patch),
            "Bayer 8x8": dither.bayer(patch, 8),
            "Floyd-Steinberg": dither.error_diffusion(patch),
        }

    def update(self) -> None:
        level = self.snapped(float(self.value("level")))
        for name, result in self.outputs(level).items():
            self.panels[name].set_data(result)
            self.titles[name].set_text(
                _("{name}\nlit {lit:.3f} (level {level:.3f})").format(
                    name=_(name), lit=result.mean(), level=level
                )
            )
        lit = int(dither.ordered([[level]]).sum())
        self.highlight.set_x(4 * lit - 0.1)


class VoidAndClusterApp(SliderApp):
    """The blue-noise mask built dot by dot: the first k dots over their energy.

    At k dots the picture shows the pixels ranked below k over the energy
    of that pattern (the Gaussian-blurred dots on a torus), the next dot
    (rank k) circled, and beside it the radial power spectrum of the k dots
    against k white-noise dots.

    Parameters
    ----------
    size : int
        Side of the mask.
    sigma : float
        Width of the energy's Gaussian.
    """

    def __init__(self, size: int = 32, sigma: float = 1.5, dots: int = 60) -> None:
        self.size = as_int(size, "size", minimum=4, maximum=limits.MAX_MASK_SIZE)
        sigma = as_positive_float(sigma, "sigma")
        dots = as_int(dots, "dots", minimum=1, maximum=self.size**2 - 1)
        self.sigma = sigma
        self.ranks = rank_pixels(self.size, np.random.default_rng(0), sigma)
        self.initial = round(0.1 * self.size**2)
        self.white_order = np.random.default_rng(1).permutation(self.size**2)
        controls = {
            "dots": widgets.IntSlider(
                value=dots, min=1, max=self.size**2 - 1, description=_("dots")
            )
        }
        super().__init__(controls, shape=(460, 1000))
        zoom = 380 // self.size  # each pixel of the mask a whole square
        left = bare_axes(pixel_axes(self.figure, 20, 20, zoom * self.size, zoom * self.size))
        self.energy = left.imshow(
            np.zeros((self.size, self.size)), cmap="viridis", interpolation="nearest"
        )
        bar = pixel_axes(self.figure, 30 + zoom * self.size, 20, 12, zoom * self.size)
        self.figure.colorbar(self.energy, cax=bar).set_label(
            _("energy: the dots blurred by a Gaussian (sigma {sigma:g} px)").format(sigma=sigma),
            fontsize=8,
        )
        bar.tick_params(labelsize=7)
        self.dots = left.imshow(np.zeros((self.size, self.size, 4)), interpolation="nearest")
        (self.next_dot,) = left.plot([], [], "o", ms=14, mfc="none", mec="red", mew=2)
        self.heading = left.set_title("", fontsize=9)
        right = self.figure.add_axes((0.57, 0.12, 0.41, 0.72))
        frequency, _power = radial_power_spectrum(np.eye(self.size))
        (self.blue_line,) = right.plot(
            frequency, np.ones_like(frequency), label=_("void-and-cluster")
        )
        (self.white_line,) = right.plot(
            frequency, np.ones_like(frequency), ls="--", label=_("white noise")
        )
        right.set_xlim(0, 0.72)
        right.set_ylim(0, 3)
        right.set_xlabel(_("frequency (cycles per pixel)"))
        # A pattern with a share p of dots has variance p (1 - p): dividing by it puts white
        # noise at 1 on average, whatever the number of dots.
        right.set_ylabel(_("power (white noise = 1)"))
        right.legend(loc="upper left", fontsize=9)
        self.ratio = right.set_title("", fontsize=9)
        self.update()

    def pattern(self, dots: int) -> np.ndarray:
        """The first ``dots`` pixels of the ranking, as a boolean image."""
        return self.ranks < dots

    def update(self) -> None:
        count = int(self.value("dots"))
        pattern = self.pattern(count)
        energy = cluster_energy(pattern, self.sigma)
        self.energy.set_data(energy)
        self.energy.set_clim(energy.min(), energy.max())
        overlay = np.zeros((self.size, self.size, 4))
        overlay[pattern] = (1.0, 1.0, 1.0, 1.0)
        self.dots.set_data(overlay)
        y, x = np.unravel_index(int(np.flatnonzero(self.ranks.ravel() == count)[0]), pattern.shape)
        self.next_dot.set_data([x], [y])
        if count < self.initial:
            # Phase 1 ranks backwards: the circled dot is the one taken out when it and these
            # dots were left, so among these alone its place looks like a void.
            phase = _(
                "phase 1: ranks a random start, tightest cluster out first;\n"
                "circled: the dot taken out when it and these were left"
            )
        else:
            phase = _("phase 2: each new dot into the largest void (lowest energy)")
        self.heading.set_text(
            _("{count} dots (white), the next circled\n{phase}").format(count=count, phase=phase)
        )
        white = np.zeros(self.size**2, dtype=bool)
        white[self.white_order[:count]] = True
        share = count / self.size**2
        scale = share * (1 - share)
        _frequency, blue_power = radial_power_spectrum(pattern)
        _frequency, white_power = radial_power_spectrum(white.reshape(self.size, self.size))
        self.blue_line.set_ydata(blue_power / scale)
        self.white_line.set_ydata(white_power / scale)
        low = (0 < self.blue_line.get_xdata()) & (self.blue_line.get_xdata() < 0.125)
        ratio = blue_power[low].mean() / white_power[low].mean()
        self.ratio.set_text(
            _("power below 0.125 cycles/pixel: {ratio:.3f} x white noise").format(ratio=ratio)
        )
