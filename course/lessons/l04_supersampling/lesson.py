"""Lesson 04, sampling and supersampling: its registry entry, pictures, landmarks and printed lines.

A lesson's registry entry: the classroom tools call these with the registry's
own arguments, never with a student's input, so this module checks none
(``UNCHECKED = True``; the fuzz test skips it). The apps and functions they
build validate their own input.
"""

from __future__ import annotations

import functools

import numpy as np

from course import images
from course._validate import as_int
from course.classroom.pictures import (
    app_picture,
    colormap_color,
    gray_color,
    landmark_at,
    panel_picture,
    read_only,
    still_picture,
)
from course.classroom.registry import Landmark, Lesson, Picture, SliderMove
from course.i18n import N_, _
from course.lessons.l04_supersampling import figures
from course.lessons.l04_supersampling.apps import SupersampleApp, difference_scale
from course.lessons.printed import padded
from course.sampling.resample import supersample, supersample_without_offset
from course.widgets.base import SliderApp
from course.widgets.picture import rounding_level

UNCHECKED = True  # see the module docstring

#: The zone plates whose error the lesson prints rate by rate, as the notebook names them.
ZONE_PLATE_NAMES = (N_("the lab's"), N_("half as fine"))


def print_largest_difference(difference: float) -> None:
    """Print the largest difference between two forms of a computation, as a rounding level.

    Examples
    --------
    >>> print_largest_difference(4e-16)
    largest difference: below 1e-12
    """
    print(_("largest difference: {difference}").format(difference=rounding_level(difference)))


def print_supersampled_row(rate: int, image: np.ndarray) -> None:
    """Print an image supersampled at ``rate``, its values rounded to 4 decimals, as lists.

    Examples
    --------
    >>> print_supersampled_row(3, np.array([[1 / 3, 2 / 3]]))
    rate  3: [[0.3333, 0.6667]]
    """
    values = np.asarray(image).round(4).tolist()
    print(_("rate {rate:>2}: {values}").format(rate=rate, values=values))


def print_errors_by_rate(name: str, errors: list[float]) -> None:
    """Print a zone plate's error against its exact downsample at each rate, 4 decimals.

    ``name`` is one of :data:`ZONE_PLATE_NAMES`, shown in the current language.

    Examples
    --------
    >>> print_errors_by_rate("the lab's", [0.29981, 0.1015])
       the lab's: 0.2998 0.1015
    """
    print(
        _("{name}: {errors}").format(
            name=padded(_(name), 12, ">"), errors=" ".join(f"{error:.4f}" for error in errors)
        )
    )


def print_measured_shift(rate: int, shift: float, predicted: float) -> None:
    """Print the picture's shift measured at ``rate`` beside the formula's prediction.

    Examples
    --------
    >>> print_measured_shift(8, 0.0015, 0.0015)
    rate  8: measured +0.0015, (1/s - 1/rate)/2 = +0.0015
    """
    print(
        _("rate {rate:>2}: measured {shift:+.4f}, (1/s - 1/rate)/2 = {predicted:+.4f}").format(
            rate=rate, shift=shift, predicted=predicted
        )
    )


def print_centred_against_report(rate: int, centred: float, shifted: float) -> None:
    """Print the RMS error of centred supersampling at ``rate`` and of the report's shifted one.

    Examples
    --------
    >>> print_centred_against_report(4, 0.0043, 0.0275)
    rate 4: RMS centred 0.0043, the report's 0.0275
    """
    print(
        _("rate {rate}: RMS centred {centred:.4f}, the report's {shifted:.4f}").format(
            rate=rate, centred=centred, shifted=shifted
        )
    )


def print_rate_against_rate(low: int, high: int, rms: float) -> None:
    """Print the RMS difference of the zone plate supersampled at ``low`` and at ``high``.

    Examples
    --------
    >>> print_rate_against_rate(1, 32, 0.29853)
    zone plate, rate 1 against rate 32: RMS 0.2985
    """
    print(
        _("zone plate, rate {low} against rate {high}: RMS {rms:.4f}").format(
            low=low, high=high, rms=rms
        )
    )


@functools.cache
def zone_plate_lab() -> tuple[np.ndarray, np.ndarray]:
    """The lab's 2500 x 2500 zone plate and its exact 320 x 320 box downsample."""
    plate = images.zone_plate((2500, 2500))
    return read_only(plate), read_only(images.zone_plate_box((2500, 2500), (320, 320)))


def supersample_app(rate: int = 1) -> SupersampleApp:
    rate = as_int(rate, "rate", minimum=1, maximum=12)
    app = SupersampleApp()
    app.controls["rate"].value = rate
    return app


def supersample_landmarks(app: SliderApp) -> list[Landmark]:
    """Result and difference pixels: ``supersample`` of the zone plate, minus ``zone_plate_box``.

    The landmarks are the 200 pixels where this rate differs most from the
    rates beside it.
    """
    if app.value("image") != "zone plate":
        raise ValueError("supersample_landmarks: the browser test moves the zone plate's rate")
    plate, exact = zone_plate_lab()
    rate = int(app.value("rate"))
    resample = supersample if app.value("version") == "centred" else supersample_without_offset
    result = resample(plate, (320, 320), rate)
    difference = result - exact
    # Where this rate differs most from both neighbouring rates: the false
    # rings that move. The result is shown pixel for pixel, 1 px per pixel.
    changes = [
        np.abs(result - resample(plate, (320, 320), other))
        for other in (rate - 1, rate + 1)
        if 1 <= other <= 12
    ]
    telling = np.min(changes, axis=0)
    scale = difference_scale(difference)
    landmarks = []
    for flat_index in np.argsort(telling, axis=None)[::-1][:200]:
        row, column = (int(i) for i in np.unravel_index(flat_index, telling.shape))
        centre = (column + 0.5, row + 0.5)
        value = float(result[row, column])
        what = f"supersample(zone plate, rate {rate}) pixel ({column}, {row})"
        landmarks.append(landmark_at(app, app.result_axes, centre, gray_color(value), what, 3))
        color = colormap_color("RdBu_r", float(difference[row, column]), -scale, scale)
        landmarks.append(
            landmark_at(app, app.difference_axes, centre, color, f"{what} - zone_plate_box", 3)
        )
    return landmarks


def preview() -> bytes:
    """The course map's preview: the zone plate shrunk with supersampling."""
    app = SupersampleApp()
    return panel_picture(app, app.result_axes)


LESSON = Lesson(
    outcomes=(
        N_("explain aliasing as detail folding back at half the sampling rate"),
        N_("write a bilinear lookup and the lab's supersampling loop"),
        N_("measure the error at every rate, and the lab report's half-sample shift"),
    ),
    minutes=45,
    preview=Picture("04_preview", "a zone plate shrunk by supersampling", preview),
    handout=N_(
        "the lab report (Lab01 Report), Task 6: shrink a 2500 x 2500 image to 320 x 320 "
        "by supersampling"
    ),
    teaches=N_(
        "aliasing as folding, in one dimension and on a zone plate; the box filter's "
        "response; bilinear lookup and the supersampling loop, written and checked; the error at "
        "every rate against the exact box mean; the report's half-sample shift measured"
    ),
    pictures=(
        still_picture(
            "04_folding",
            "a cosine of 0.8 cycles per sample seen as 0.2: the spectrum folds at rate / 2",
            figures.folding_figure,
        ),
        still_picture(
            "04_box_response",
            "how much of each frequency a one-pixel box keeps",
            figures.box_response_figure,
        ),
        still_picture(
            "04_report_shift",
            "the report's half-sample shift at rate 4, against the exact box mean",
            figures.shift_figure,
        ),
        Picture(
            "04_zone_plate_rate1",
            "the zone plate shrunk to 320 x 320 with one sample per pixel: false rings, "
            "their difference from the exact box filter, and the error at every rate",
            lambda: app_picture(supersample_app(1)),
        ),
        Picture(
            "04_zone_plate_rate4",
            "the same at rate 4 (16 samples per pixel): the false rings are gone",
            lambda: app_picture(supersample_app(4)),
        ),
    ),
    sliders=(
        SliderMove(
            build=SupersampleApp,
            control="rate",
            moves=(("ArrowRight", "ArrowRight"), ("End",)),
            landmarks=supersample_landmarks,
        ),
    ),
)
