"""Lesson 08's apps: where to paste, and an iterative Poisson solve, sweep by sweep.

:class:`CloneApp`: drag the foreground over the background, and the seamless
clone follows, solved exactly at every step. :class:`PoissonIterationApp`:
the region starts as the pasted foreground (the lab's ``g = 0``); each sweep
lets the boundary's values seep further in. Beside the picture, the error
against the exact solution, in grey levels, on a fixed colour scale, so one
sees how slowly Jacobi's error leaves the middle of the region.
"""

from __future__ import annotations

from typing import Any

import ipywidgets as widgets
import numpy as np
from matplotlib.axes import Axes

from course import images, limits, poisson
from course._validate import (
    as_app_points,
    as_float_array,
    as_image,
    as_int,
    as_option,
    describe,
    require_finite,
)
from course.i18n import N_, _
from course.poisson._threads import limited_threads
from course.poisson.inputs import clone_inputs
from course.poisson.sine_transform import harmonic_fill
from course.widgets.base import Handle, SliderApp, format_points
from course.widgets.picture import ZoomedPixels, rounding_level
from course.widgets.text_cache import SteadyText

__all__ = [
    "CloneApp",
    "PoissonIterationApp",
    "as_pixels_uint8",
    "half_size",
]

# Sweeps the slider stops at, roughly three per decade up to the lab's 8000.
SWEEP_STOPS = (0, 1, 3, 10, 30, 100, 300, 1000, 3000, 8000)
MARGIN = 12  # background pixels shown around the region


#: The iterative methods' names, as the dropdown and the caption show them.
METHOD_NAMES = {"jacobi": N_("Jacobi"), "gauss_seidel": N_("Gauss-Seidel"), "sor": N_("SOR")}


class PoissonIterationApp(SliderApp):
    """Pick a method and a number of sweeps; see the iterate and its error.

    Iterates are computed on demand and kept, so moving back is instant and
    moving forward only runs the sweeps not yet done.

    Parameters
    ----------
    background, foreground, offset, mask
        As for :func:`course.poisson.seamless_clone`; by default the lab's
        scene, :func:`course.images.plane` into :func:`course.images.lake`
        at (500, 300).
    stops : sequence of int
        The sweep counts the slider offers, increasing, starting at 0.
    """

    def __init__(
        self,
        background: Any = None,
        foreground: Any = None,
        offset: Any = (500, 300),
        mask: Any = None,
        stops: tuple[int, ...] = SWEEP_STOPS,
    ) -> None:
        background = images.lake() if background is None else background
        foreground = images.plane() if foreground is None else foreground
        self.problem = poisson.clone_problem(background, foreground, offset, mask)
        self.background = np.asarray(background, dtype=float)
        self.exact = poisson.solve(self.problem)
        self.stops = _as_stops(stops)
        self._iterates: dict[str, dict[int, np.ndarray]] = {}
        self._runs: dict[str, tuple[Any, int]] = {}
        controls = {
            "method": widgets.Dropdown(
                options=[(_(name), method) for method, name in METHOD_NAMES.items()],
                value="jacobi",
                description=_("method"),
            ),
            "sweeps": widgets.SelectionSlider(
                options=self.stops, value=self.stops[0], description=_("sweeps")
            ),
        }
        super().__init__(controls, shape=(330, 900))
        x, y = self.problem.corner
        height, width = self.problem.region.shape
        self.window = (
            slice(max(y - MARGIN, 0), y + height + MARGIN),
            slice(max(x - MARGIN, 0), x + width + MARGIN),
        )
        self.initial_error = self._error(self.problem.values)
        picture_axes = self.figure.add_axes((0.01, 0.08, 0.48, 0.8))
        error_axes = self.figure.add_axes((0.51, 0.08, 0.48, 0.8))
        for axes in (picture_axes, error_axes):
            axes.set_axis_off()
        start = self.composite(self.problem.values)
        self.picture = picture_axes.imshow(start, interpolation="nearest")
        self.error_image = error_axes.imshow(
            self.error_map(self.problem.values),
            cmap="magma",
            vmin=0,
            vmax=max(self.initial_error, 1e-9),
            interpolation="nearest",
        )
        self.figure.colorbar(self.error_image, ax=error_axes, shrink=0.8, label=_("grey levels"))
        picture_axes.set_title(_("the result after the sweeps"), fontsize=10)
        error_axes.set_title(_("|iterate - exact solution|, largest channel"), fontsize=10)
        self.caption = self.figure.text(0.5, 0.96, "", ha="center", va="top", fontsize=11)

    def iterate(self, method: str, sweeps: int) -> np.ndarray:
        """The problem's window after ``sweeps`` sweeps of ``method`` (kept for next time)."""
        method = as_option(method, "method", poisson.ITERATIVE_METHODS)
        sweeps = as_option(sweeps, "sweeps", self.stops)  # the slider's stops: bounded work
        kept = self._iterates.setdefault(method, {0: self.problem.values})
        if sweeps not in kept:
            run, done = self._runs.get(method, (None, 0))
            if run is None or done > sweeps:
                run, done = poisson.iterates(self.problem, method), 0
            while done < sweeps:
                latest = next(run)
                done += 1
                if done in self.stops or done == sweeps:
                    kept[done] = latest.copy()
            self._runs[method] = (run, done)
        return kept[sweeps]

    def composite(self, solution: np.ndarray) -> np.ndarray:
        """The background with the region set to ``solution``, cut around the region."""
        return np.clip(self.problem.paste(self.background, solution)[self.window], 0.0, 1.0)

    def error_map(self, solution: np.ndarray) -> np.ndarray:
        """``|solution - exact|`` in grey levels, largest channel, 0 outside the region."""
        error = np.abs(solution - self.exact) * 255
        if error.ndim == 3:
            error = error.max(axis=2)
        full = np.zeros(self.background.shape[:2])
        x, y = self.problem.corner
        height, width = self.problem.region.shape
        full[y : y + height, x : x + width] = np.where(self.problem.region, error, 0.0)
        return full[self.window]

    def update(self) -> None:
        method, sweeps = self.value("method"), self.value("sweeps")
        solution = self.iterate(method, sweeps)
        self.picture.set_data(self.composite(solution))
        self.error_image.set_data(self.error_map(solution))
        residual = self.problem.residual(solution)
        self.caption.set_text(
            _(
                "{method}, {sweeps} sweeps: residual {residual}, "
                "error up to {error:.1f} grey levels (from {initial:.1f})"
            ).format(
                method=_(METHOD_NAMES[method]),
                sweeps=sweeps,
                residual=rounding_level(residual, spec=".2g"),
                error=self._error(solution),
                initial=self.initial_error,
            )
        )

    def _error(self, solution: np.ndarray) -> float:
        return float(np.abs(solution - self.exact)[self.problem.region].max() * 255)


class CloneApp(SliderApp):
    """Drag the pasted foreground over the background: the naive paste and the clone follow.

    Left, the foreground's pixels copied in (a seam all around); right, the
    seamless clone, solved exactly at each step (the foreground plus the
    harmonic fill of its ring, by the discrete sine transform: the values
    of :func:`course.poisson.seamless_clone`). Both are shown at half
    size, each screen pixel the mean of 2 x 2 image pixels. Drag the
    foreground in either panel, or type its top-left pixel in ``offset``.
    """

    BLIT = True

    def __init__(
        self, background: Any = None, foreground: Any = None, offset: Any = (500, 300)
    ) -> None:
        self.background = as_image(images.lake() if background is None else background)
        self.foreground = as_image(images.plane() if foreground is None else foreground)
        if self.background.ndim != self.foreground.ndim:
            raise ValueError(
                _(
                    "foreground: expected a gray foreground for a gray background and RGB for RGB; "
                    "got shapes {foreground_shape} and {background_shape}"
                ).format(
                    foreground_shape=self.foreground.shape, background_shape=self.background.shape
                )
            )
        # As seamless_clone refuses them: a foreground without an inside, or larger than
        # the background (at no offset would it fit).
        clone_inputs(self.background, self.foreground, (0, 0), None)
        self.half_background = half_size(self.background)
        # The panels' half-size pictures are the background but for the window the
        # foreground's blocks cover: only that window moves (FigureView.still_images).
        self._windows: dict[str, tuple[np.ndarray, tuple[int, int]]] = {}
        self.offset = as_app_points([offset], "offset", 1, whole=True)[0].astype(int)
        controls = {
            "offset": widgets.Text(
                value=format_points([self.offset]), description="x, y", continuous_update=False
            )
        }
        height, width = self.half_background.shape[:2]
        gap, top = 20, 26
        columns, rows = 2 * width + 3 * gap, height + top + 10
        super().__init__(controls, shape=(rows, columns), format="jpeg")
        self.panels: dict[str, Axes] = {}
        for index, name in enumerate(("naive paste", "seamless clone")):
            left = gap + index * (width + gap)
            axes = self.figure.add_axes((left / columns, 10 / rows, width / columns, height / rows))
            axes.set_axis_off()
            # Data coordinates are the full image's pixels, 0 .. 2 W across; each
            # screen pixel is one half-size pixel, pasted into the picture as is.
            axes.set_xlim(0, 2 * width)
            axes.set_ylim(2 * height, 0)
            self.panels[name] = axes
        still = _pixels_uint8(self.half_background)
        self.view.still_images.update(dict.fromkeys(self.panels.values(), still))
        # Where the axes' titles stand; their numbers change at every step of a drag.
        self.titles = {
            name: axes.add_artist(
                SteadyText(
                    0.5,
                    1.0,
                    "",
                    transform=axes.title.get_transform(),
                    ha="center",
                    va="baseline",
                    fontsize=10,
                    clip_on=False,
                )
            )
            for name, axes in self.panels.items()
        }
        self.animate(*self.titles.values())
        for axes in self.panels.values():
            self.highlight_ring(axes)

    def read_offset(self) -> np.ndarray:
        """The foreground's top-left pixel, as the text says, if it fits."""
        limit = np.array(self.background.shape[1::-1]) - self.foreground.shape[1::-1]
        (offset,) = self.typed_points("offset", [self.offset], 1, 0, limit, whole=True)
        self.offset = offset.astype(int)
        return self.offset

    def update(self) -> None:
        x, y = self.read_offset()
        # Both change the region: the foreground inside its outer ring of pixels
        # (course.poisson.naive_paste and seamless_clone).
        for name, region in (
            ("naive paste", self.foreground[1:-1, 1:-1]),
            ("seamless clone", self._cloned_region(int(x), int(y))),
        ):
            window, corner = self._pasted_window(x + 1, y + 1, region)
            self._windows[name] = window, corner
            # As imshow shows an RGB image in [0, 1]: 255 times, truncated.
            self.pixel_images[self.panels[name]] = ZoomedPixels(_pixels_uint8(window), 1, corner)
        self.titles["naive paste"].set_text(_("naive paste at ({x}, {y})").format(x=x, y=y))
        self.titles["seamless clone"].set_text(_("seamless clone at ({x}, {y})").format(x=x, y=y))

    def _cloned_region(self, x: int, y: int) -> np.ndarray:
        """The seamless clone's region with the foreground's top-left pixel at (x, y), clipped.

        :func:`course.poisson.seamless_clone`'s values, to rounding. Its plain
        guidance is the foreground's own Laplacian, so the clone is the
        foreground plus the harmonic fill of the ring's differences from the
        background (:func:`~course.poisson.sine_transform.harmonic_fill`): a
        step reads the background's ring alone, and transforms one way in 2-D
        where a whole solve builds the problem and transforms both ways.
        """
        height, width = self.foreground.shape[:2]
        window = self.background[y : y + height, x : x + width]
        planes = (window - self.foreground).reshape(height, width, -1).transpose(2, 0, 1)
        with limited_threads():  # as the solvers run their transforms
            fill = harmonic_fill(planes)
        inside = self.foreground[1:-1, 1:-1]
        # The fill's memory is channels last, as its transform leaves it: the sum runs along it.
        region = inside + fill.transpose(1, 2, 0).reshape(inside.shape)
        return np.clip(region, 0.0, 1.0, out=region)

    @property
    def shown(self) -> dict[str, np.ndarray]:
        """Each panel's half-size picture as it stands, by name: the background and the window."""
        shown = {}
        for name, (window, (left, top)) in self._windows.items():
            shown[name] = self.half_background.copy()
            shown[name][top : top + window.shape[0], left : left + window.shape[1]] = window
        return shown

    def _pasted_window(
        self, x: int, y: int, patch: np.ndarray
    ) -> tuple[np.ndarray, tuple[int, int]]:
        """The half-size blocks ``patch``, pasted at (x, y), touches, and their top-left block.

        Only these blocks differ from the half-size background; they alone are
        averaged again.
        """
        height, width = patch.shape[:2]
        left, top = x // 2 * 2, y // 2 * 2
        right, bottom = -(-(x + width) // 2) * 2, -(-(y + height) // 2) * 2
        window = self.background[top:bottom, left:right].copy()
        window[y - top : y - top + height, x - left : x - left + width] = patch
        return _half_size(window), (left // 2, top // 2)

    def handles(self) -> list[Handle]:
        x, y = self.offset
        height, width = self.foreground.shape[:2]
        return [
            Handle("foreground", axes, (x, y), box=(x, y, x + width, y + height))
            for axes in self.panels.values()
        ]

    def drag(self, name: str, point: np.ndarray) -> None:
        limit = np.array(self.background.shape[1::-1]) - self.foreground.shape[1::-1]
        offset = np.clip(np.round(point), 0, limit)
        self.controls["offset"].value = format_points([offset])


def as_pixels_uint8(image: np.ndarray) -> np.ndarray:
    """An image in [0, 1] as 8-bit RGB, as imshow draws it: 255 times, truncated; gray repeated.

    Examples
    --------
    >>> as_pixels_uint8(np.array([[0.5, 1.0]])).tolist()
    [[[127, 127, 127], [255, 255, 255]]]
    """
    return _pixels_uint8(_as_finite_image(image))


def _pixels_uint8(image: np.ndarray) -> np.ndarray:
    pixels = (np.clip(image, 0.0, 1.0) * 255).astype(np.uint8)
    return np.repeat(pixels[..., None], 3, axis=2) if pixels.ndim == 2 else pixels


def half_size(image: np.ndarray) -> np.ndarray:
    """Each 2 x 2 block of pixels replaced by its mean (a last odd row or column dropped).

    Examples
    --------
    >>> half_size(np.arange(16.0).reshape(4, 4))
    array([[ 2.5,  4.5],
           [10.5, 12.5]])
    """
    image = _as_finite_image(image)
    if min(image.shape[:2]) < 2:
        raise ValueError(
            _("image must be at least 2 x 2; got shape {image_shape}").format(
                image_shape=image.shape
            )
        )
    return _half_size(image)


def _half_size(image: np.ndarray) -> np.ndarray:
    height, width = (side // 2 * 2 for side in image.shape[:2])
    # Four strided sums, not a mean over a reshape's axes 1 and 3: a tenth of the time.
    top, bottom = image[0:height:2, :width], image[1:height:2, :width]
    return (top[:, 0::2] + top[:, 1::2] + bottom[:, 0::2] + bottom[:, 1::2]) * 0.25


def _as_finite_image(image: Any) -> np.ndarray:
    """A finite float (H, W) or (H, W, 3) array; values may stray from [0, 1]."""
    array = as_float_array(image, "image")
    if not (array.ndim == 2 or (array.ndim == 3 and array.shape[2] == 3)) or not array.size:
        raise ValueError(
            _("image must be a gray (H, W) or RGB (H, W, 3) image; got {array_shape}").format(
                array_shape=array.shape
            )
        )
    require_finite(array, "image")
    return array


def _as_stops(stops: Any) -> tuple[int, ...]:
    if not isinstance(stops, (tuple, list)) or not stops:
        raise TypeError(
            _("stops must be a tuple of sweep counts; got {stops}").format(stops=describe(stops))
        )
    counts = tuple(
        as_int(stop, f"stops[{index}]", minimum=0, maximum=limits.MAX_ITERATIONS)
        for index, stop in enumerate(stops)
    )
    if list(counts) != sorted(set(counts)):
        raise ValueError(
            _("stops must be increasing sweep counts; got {counts}").format(counts=counts)
        )
    return counts
