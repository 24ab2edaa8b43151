"""Lesson 04's app: shrinking an image by supersampling, rate by rate.

The lab shrinks a 2500 x 2500 image to 320 x 320. :class:`SupersampleApp`
does that to a zone plate, whose exact box-filtered downsample is known in
closed form (:func:`course.images.zone_plate_box`), and to the photograph
(a 500 x 500 crop shrunk to 64 x 64, the same ratio), whose reference is the
same supersampling at a very high rate. It shows the result, its difference
from the reference, and the error at every rate, for the centred sampling
and for the report's.
"""

from __future__ import annotations

from typing import Any

import ipywidgets as widgets
import numpy as np

from course import limits
from course._validate import as_float_array, as_int, as_option, require_finite
from course.i18n import N_, _
from course.images import photograph, zone_plate, zone_plate_box
from course.metrics import rmse
from course.sampling.resample import supersample, supersample_without_offset
from course.widgets.base import SliderApp

__all__ = ["DIFFERENCE_SCALES", "IMAGES", "VERSIONS", "SupersampleApp", "difference_scale"]

IMAGES = (N_("zone plate"), N_("photograph"))
VERSIONS = (N_("centred"), N_("report's"))
_RESAMPLERS = {"centred": supersample, "report's": supersample_without_offset}
_PHOTO_SIDE = 500
_PANEL = 320  # pixels on screen for each picture


#: The difference panel's colour scales, +-: the smallest that holds the largest difference.
DIFFERENCE_SCALES = (0.5, 0.2, 0.1, 0.05, 0.02, 0.01)


def difference_scale(difference: Any) -> float:
    """The difference panel's colour scale, +-: the tightest of :data:`DIFFERENCE_SCALES`.

    A difference past 0.5 is clipped at 0.5.

    >>> difference_scale([[0.03, -0.08]]), difference_scale([[0.9]])
    (0.1, 0.5)
    """
    array = as_float_array(difference, "difference")
    require_finite(array, "difference")
    largest = float(np.abs(array).max()) if array.size else 0.0
    return min((step for step in DIFFERENCE_SCALES if step >= largest), default=0.5)


class SupersampleApp(SliderApp):
    """Supersampling from rate 1 to ``max_rate``, against the exact downsample.

    Controls: ``rate``, ``image`` (:data:`IMAGES`) and ``version``
    (:data:`VERSIONS`: centred sub-pixel samples, or the report's, shifted).
    ``size`` and ``out_size`` default to the lab's 2500 and 320.
    """

    def __init__(
        self,
        size: int = 2500,
        out_size: int = 320,
        rate: int = 1,
        max_rate: int = 12,
        reference_rate: int = 32,
    ) -> None:
        size = as_int(size, "size", minimum=2, maximum=int(limits.MAX_PIXELS**0.5))
        out_size = as_int(out_size, "out_size", minimum=1, maximum=size)
        max_rate = as_int(max_rate, "max_rate", minimum=1, maximum=limits.MAX_RATE)
        rate = as_int(rate, "rate", minimum=1, maximum=max_rate)
        reference_rate = as_int(
            reference_rate, "reference_rate", minimum=1, maximum=limits.MAX_RATE
        )
        if round(_PHOTO_SIDE * out_size / size) < 1:
            raise ValueError(
                _(
                    "out_size must be at least size / {divisor} so the photograph keeps a pixel; "
                    "got out_size={out_size} for size={size}"
                ).format(divisor=2 * _PHOTO_SIDE, out_size=out_size, size=size)
            )
        controls = {
            "rate": widgets.IntSlider(value=rate, min=1, max=max_rate, description=_("rate")),
            "image": widgets.ToggleButtons(
                options=[(_(name), name) for name in IMAGES], description=_("image")
            ),
            "version": widgets.ToggleButtons(
                options=[(_(name), name) for name in VERSIONS], description=_("sampling")
            ),
        }
        super().__init__(controls, shape=(420, 1080))
        self.max_rate = max_rate
        photo_out = round(_PHOTO_SIDE * out_size / size)
        photo = photograph()
        top = (photo.shape[0] - _PHOTO_SIDE) // 2
        left = (photo.shape[1] - _PHOTO_SIDE) // 2
        photo = photo[top : top + _PHOTO_SIDE, left : left + _PHOTO_SIDE]
        self.sources = {"zone plate": zone_plate((size, size)), "photograph": photo}
        self.out_shapes = {"zone plate": (out_size, out_size), "photograph": (photo_out, photo_out)}
        self.references = {
            "zone plate": zone_plate_box((size, size), (out_size, out_size)),
            "photograph": supersample(photo, (photo_out, photo_out), reference_rate),
        }
        self.reference_names = {
            "zone plate": _("exact box filter"),
            "photograph": _("rate {rate}").format(rate=reference_rate),
        }
        self.errors: dict[str, dict[str, np.ndarray]] = {}

        width, height = 1080, 420

        def box(x: float, y: float, w: float, h: float) -> tuple[float, ...]:
            return (x / width, y / height, w / width, h / height)

        self.result_axes = self.figure.add_axes(box(20, 40, _PANEL, _PANEL))
        self.difference_axes = self.figure.add_axes(box(370, 40, _PANEL, _PANEL))
        self.curve_axes = self.figure.add_axes(box(830, 60, 235, 300))
        for axes in (self.result_axes, self.difference_axes):
            axes.set_axis_off()
        self.result = self.result_axes.imshow(
            np.zeros((out_size, out_size)), cmap="gray", vmin=0, vmax=1, interpolation="nearest"
        )
        self.difference = self.difference_axes.imshow(
            np.zeros((out_size, out_size)),
            cmap="RdBu_r",
            vmin=-0.5,
            vmax=0.5,
            interpolation="nearest",
        )
        bar = self.figure.add_axes(box(696, 40, 10, _PANEL))
        self.figure.colorbar(self.difference, cax=bar)
        bar.set_ylabel(_("too bright (+), too dark (−)"), fontsize=7, labelpad=1)
        bar.tick_params(labelsize=7)
        rates = np.arange(1, max_rate + 1)
        # Told apart by marker and dash as well as colour.
        styles = dict(zip(VERSIONS, (("o-", "#0072B2"), ("s--", "#D55E00")), strict=True))
        self.curves = {
            version: self.curve_axes.semilogy(
                rates,
                np.ones(max_rate),
                styles[version][0],
                color=styles[version][1],
                markersize=3,
                label=_(version),
            )[0]
            for version in VERSIONS
        }
        (self.current,) = self.curve_axes.plot(
            [], [], "o", color="crimson", markersize=8, fillstyle="none"
        )
        self.curve_axes.set_xlabel(_("rate (samples per pixel along each axis)"), fontsize=8)
        self.curve_axes.set_ylabel(_("RMS error"), fontsize=8)
        self.curve_axes.set_xticks(rates)
        self.curve_axes.tick_params(labelsize=7)
        self.curve_axes.grid(True, which="both", color="0.9")
        self.curve_axes.legend(fontsize=8)
        self.heading = self.figure.suptitle("", fontsize=10)

    def resample(self, image: str, version: str, rate: int) -> np.ndarray:
        """The chosen image shrunk by the chosen version at this rate."""
        image = as_option(image, "image", tuple(self.sources))
        version = as_option(version, "version", VERSIONS)
        rate = as_int(rate, "rate", minimum=1, maximum=self.max_rate)
        return _RESAMPLERS[version](self.sources[image], self.out_shapes[image], rate)

    def error_curves(self, image: str) -> dict[str, np.ndarray]:
        """RMS error against the reference at every rate, per version (computed once)."""
        image = as_option(image, "image", tuple(self.sources))
        if image not in self.errors:
            reference = self.references[image]
            self.errors[image] = {
                version: np.array(
                    [
                        rmse(self.resample(image, version, rate), reference)
                        for rate in range(1, self.max_rate + 1)
                    ]
                )
                for version in VERSIONS
            }
        return self.errors[image]

    def update(self) -> None:
        rate, image, version = self.value("rate"), self.value("image"), self.value("version")
        result = self.resample(image, version, rate)
        reference = self.references[image]
        height, width = result.shape[:2]
        extent = (0, width, height, 0)
        self.result.set_data(result)
        self.result.set_extent(extent)
        difference = result - reference
        if difference.ndim == 3:
            difference = difference.mean(axis=2)
        self.difference.set_data(difference)
        self.difference.set_extent(extent)
        # The colour scale follows the error, so a small one still shows its pattern.
        scale = difference_scale(difference)
        self.difference.set_clim(-scale, scale)
        error = rmse(result, reference)
        self.result_axes.set_title(
            _("{width} x {height} at rate {rate} ({version})").format(
                width=width, height=height, rate=rate, version=_(version)
            ),
            fontsize=9,
        )
        self.difference_axes.set_title(
            _("minus the {reference}: RMS {error:.4f}").format(
                reference=self.reference_names[image], error=error
            ),
            fontsize=9,
        )
        curves = self.error_curves(image)
        for name, curve in self.curves.items():
            curve.set_ydata(curves[name])
        low = min(values.min() for values in curves.values())
        high = max(values.max() for values in curves.values())
        self.curve_axes.set_ylim(low / 1.5, high * 1.5)
        self.current.set_data([rate], [curves[version][rate - 1]])
        self.curve_axes.set_title(
            _("{image}: error at each rate").format(image=_(image)), fontsize=9
        )
        self.heading.set_text(
            _("{rate} x {rate} = {samples} bilinear samples per output pixel").format(
                rate=rate, samples=rate * rate
            )
        )
