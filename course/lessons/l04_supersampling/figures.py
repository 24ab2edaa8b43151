"""Lesson 04's still pictures: folding in one dimension, the box filter's response, the
zone plate shrunk, the error at every rate, the report's shift and the photograph.

Each function returns a :class:`~course.widgets.picture.Still` whose caption
states the numbers it shows; pixel views are at 1:1 or a whole zoom
(:func:`~course.widgets.picture.pixel_figure`).
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cache

import numpy as np
from matplotlib.figure import Figure

from course._validate import as_int, as_point
from course.i18n import N_, _
from course.images import photograph, zone_plate, zone_plate_box
from course.metrics import rmse
from course.sampling import alias_frequency, box_response, cosine_samples
from course.sampling.resample import bilinear, supersample, supersample_without_offset
from course.widgets.picture import Still, pixel_axes, pixel_figure

__all__ = [
    "bilinear_figure",
    "box_response_figure",
    "error_by_rate_figure",
    "folding_figure",
    "photograph_figure",
    "shift_figure",
    "zone_plate_figure",
]

BLUE, VERMILLION, GREEN = "#0072B2", "#D55E00", "#009E73"
LAB_SIZE, LAB_OUT = 2500, 320


def folding_figure(frequency: float = 0.8, rate: float = 1.0, length: int = 10) -> Still:
    """A cosine sampled below its Nyquist rate, the coarser cosine its samples also fit,
    and the spectrum folding at ``rate / 2``.

    Examples
    --------
    >>> folding_figure()  # doctest: +NORMALIZE_WHITESPACE
    0.8 cycles per sample is seen as 0.2: the two cosines' samples differ by rounding alone
    (below 1e-12)
    """
    length = as_int(length, "length", minimum=1, maximum=1000)
    alias = alias_frequency(frequency, rate)
    fine_x = np.linspace(0, length, 2000)
    samples_x = np.arange(length + 1) / rate
    samples = cosine_samples(frequency, rate, len(samples_x))
    gap = np.abs(samples - cosine_samples(alias, rate, len(samples_x))).max()
    figure = Figure(figsize=(8.0, 4.6), dpi=100)
    signal, spectrum = figure.add_subplot(2, 1, 1), figure.add_subplot(2, 1, 2)
    signal.plot(
        fine_x,
        np.cos(2 * np.pi * frequency * fine_x),
        color=BLUE,
        lw=1.2,
        label=_("cos(2π {frequency:g} x)").format(frequency=frequency),
    )
    signal.plot(
        fine_x,
        np.cos(2 * np.pi * alias * fine_x),
        "--",
        color=VERMILLION,
        lw=1.5,
        label=_("cos(2π {alias:g} x): the same samples").format(alias=alias),
    )
    signal.plot(
        samples_x,
        samples,
        "o",
        color="0.1",
        ms=6,
        label=_("{rate:g} sample per unit").format(rate=rate),
    )
    signal.set_xlabel(_("x (samples)"), fontsize=8)
    signal.legend(fontsize=7, loc="upper right", ncols=3)
    signal.set_ylim(-1.25, 1.6)
    nyquist = rate / 2
    spectrum.axvspan(0, nyquist, color="0.93")
    spectrum.axvline(nyquist, color="0.3", lw=1, ls=":")
    spectrum.annotate(
        _("Nyquist: rate / 2"),
        (nyquist, 1.05),
        xytext=(4, 0),
        textcoords="offset points",
        fontsize=8,
    )
    spectrum.vlines(frequency, 0, 1, color=BLUE, lw=3, label=_("the signal"))
    spectrum.vlines(alias, 0, 1, color=VERMILLION, lw=3, label=_("where the samples put it"))
    spectrum.annotate(
        "",
        xy=(alias, 0.6),
        xytext=(frequency, 0.6),
        arrowprops={"arrowstyle": "->", "color": "0.3", "connectionstyle": "arc3,rad=0.4"},
    )
    spectrum.set_xlim(0, max(1.5 * rate, frequency + 0.2))
    spectrum.set_ylim(0, 1.3)
    spectrum.set_yticks([])
    spectrum.set_xlabel(_("frequency (cycles per unit)"), fontsize=8)
    spectrum.legend(fontsize=7, loc="upper right")
    figure.tight_layout()
    caption = (
        _(
            "{frequency:g} cycles per sample is seen as {alias:g}: "
            "the two cosines' samples differ by rounding alone (below 1e-12)"
        ).format(frequency=frequency, alias=alias)
        if gap < 1e-12
        else _(
            "{frequency:g} cycles per sample is seen as {alias:g}: "
            "the two cosines' samples differ by up to {gap:.1e}"
        ).format(frequency=frequency, alias=alias, gap=gap)
    )
    return Still.of(figure, caption)


def box_response_figure(width: float = 1.0) -> Still:
    """How much of each frequency survives averaging over one pixel (a box of ``width``).

    Examples
    --------
    >>> box_response_figure()
    at the Nyquist frequency 0.5 the box keeps 0.637; zero at 1, 2 and 3 cycles per pixel
    """
    frequencies = np.linspace(0, 3.2, 800)
    response = box_response(frequencies, width)
    figure = Figure(figsize=(6.4, 3.0), dpi=100)
    axes = figure.add_subplot()
    axes.axhline(0, color="0.6", lw=0.8)
    axes.plot(frequencies, response, color=BLUE, lw=1.5, label=_("box of one pixel: sinc(f)"))
    nyquist = 0.5 / width
    axes.axvline(nyquist, color="0.3", lw=1, ls=":", label=_("Nyquist frequency of the pixel grid"))
    axes.plot([nyquist], [box_response(nyquist, width)], "o", color=VERMILLION)
    axes.set_xlabel(_("frequency (cycles per pixel)"), fontsize=8)
    axes.set_ylabel(_("kept"), fontsize=8)
    axes.legend(fontsize=7)
    figure.tight_layout()
    caption = _(
        "at the Nyquist frequency {nyquist:g} the box keeps {kept:.3f}; "
        "zero at {first:g}, {second:g} and {third:g} cycles per pixel"
    ).format(
        nyquist=nyquist,
        kept=box_response(nyquist, width),
        first=1 / width,
        second=2 / width,
        third=3 / width,
    )
    return Still.of(figure, caption)


def bilinear_figure(x: float = 1.3, y: float = 0.9) -> Still:
    """A bilinear lookup at one point: the four nearest pixel centres and their weights.

    Examples
    --------
    >>> print(bilinear_figure().caption.replace(": ", ":\\n").replace(", the", ",\\nthe"))
    (1.3, 0.9) reads 0.2000:
    0.12 x 0 + 0.48 x 0.25 + 0.08 x 1 + 0.32 x 0,
    the weights of pixels (0, 0), (1, 0), (0, 1), (1, 1)
    """
    image = np.array([[0.0, 0.25, 1.0, 0.5], [1.0, 0.0, 0.75, 0.25], [0.5, 0.5, 0.0, 1.0]])
    height, width = image.shape
    x, y = as_point((x, y), "(x, y)", dim=2)
    if not (0 <= x <= width and 0 <= y <= height):
        raise ValueError(
            _("x and y must lie on the {width} x {height} image; got ({x:g}, {y:g})").format(
                width=width, height=height, x=x, y=y
            )
        )
    figure, (axes,) = pixel_figure(
        [
            (
                np.clip(image, 0.15, 0.85),
                (0, width, height, 0),
                _("pixel values and centres; ({x:g}, {y:g}) and its weights").format(x=x, y=y),
            )
        ],
        zoom=90,
    )
    centres = np.array([(c + 0.5, r + 0.5) for r in range(height) for c in range(width)])
    axes.plot(*centres.T, "o", color=BLUE, ms=5)
    for row in range(height):
        for column in range(width):
            # Each pixel's value, so that the blend can be checked by hand.
            axes.annotate(
                f"{image[row, column]:g}",
                (column + 0.5, row + 0.12),
                ha="center",
                va="top",
                fontsize=9,
                color="white" if image[row, column] < 0.5 else "black",
            )
    left, top = int(np.floor(x - 0.5)), int(np.floor(y - 0.5))
    fx, fy = x - 0.5 - left, y - 0.5 - top
    weights = {
        (left, top): (1 - fx) * (1 - fy),
        (left + 1, top): fx * (1 - fy),
        (left, top + 1): (1 - fx) * fy,
        (left + 1, top + 1): fx * fy,
    }
    for (column, row), weight in weights.items():
        centre = (column + 0.5, row + 0.5)
        axes.plot([x, centre[0]], [y, centre[1]], color=VERMILLION, lw=1)
        axes.annotate(
            f"{weight:.2f}",
            centre,
            xytext=(6, -14),
            textcoords="offset points",
            color=VERMILLION,
            fontsize=10,
            weight="bold",
        )
    axes.plot([x], [y], "X", color=VERMILLION, ms=10)
    value = float(bilinear(image, x, y))
    terms = " + ".join(
        _("{weight:.2f} x {value:g}").format(weight=w, value=image[r, c])
        for (c, r), w in weights.items()
    )
    owners = _(", ").join(f"({c}, {r})" for c, r in weights)
    caption = _("({x:g}, {y:g}) reads {value:.4f}: {terms}, the weights of pixels {owners}").format(
        x=x, y=y, value=value, terms=terms, owners=owners
    )
    return Still.of(figure, caption)


@cache
def _lab_zone_plate() -> tuple[np.ndarray, np.ndarray]:
    """The lab's 2500 x 2500 zone plate and its exact 320 x 320 box downsample."""
    plate = zone_plate((LAB_SIZE, LAB_SIZE))
    exact = zone_plate_box((LAB_SIZE, LAB_SIZE), (LAB_OUT, LAB_OUT))
    plate.flags.writeable = exact.flags.writeable = False
    return plate, exact


def zone_plate_figure() -> Still:
    """The zone plate's corner at 1:1, shrunk at rate 1 (false rings), and its exact box mean.

    Examples
    --------
    >>> zone_plate_figure()
    320 x 320 at rate 1: RMS 0.2998 against the exact box filter
    """
    plate, exact = _lab_zone_plate()
    rate_one = supersample(plate, (LAB_OUT, LAB_OUT), 1)
    windows = [
        (
            plate[:LAB_OUT, :LAB_OUT],
            (0, LAB_OUT, LAB_OUT, 0),
            _("the input's top-left corner, 1:1"),
        ),
        (rate_one, (0, LAB_OUT, LAB_OUT, 0), _("shrunk to 320, rate 1")),
        (exact, (0, LAB_OUT, LAB_OUT, 0), _("shrunk to 320, exact box filter")),
    ]
    figure, _axes = pixel_figure(windows, zoom=1)
    caption = _("320 x 320 at rate 1: RMS {error:.4f} against the exact box filter").format(
        error=rmse(rate_one, exact)
    )
    return Still.of(figure, caption)


def error_by_rate_figure(rates: Sequence[int] = tuple(range(1, 13)), floor_rate: int = 32) -> Still:
    """RMS error against the exact box filter at each rate, centred samples and the report's.

    The caption adds the centred error at ``floor_rate``: what many samples
    leave, the bilinear input's own distance from the exact box mean.

    Examples
    --------
    >>> print(error_by_rate_figure((1, 2, 3)).caption.replace("; ", "\\n"))
    RMS at rates 1, 2, 3: centred 0.2998, 0.1015, 0.0155
    the report's 0.3300, 0.1471, 0.0503
    centred at rate 32: 0.0034
    """
    floor_rate = as_int(floor_rate, "floor_rate", minimum=1, maximum=32)
    plate, exact = _lab_zone_plate()
    errors = {
        N_("centred"): [rmse(supersample(plate, (LAB_OUT, LAB_OUT), r), exact) for r in rates],
        N_("the report's"): [
            rmse(supersample_without_offset(plate, (LAB_OUT, LAB_OUT), r), exact) for r in rates
        ],
    }
    figure = Figure(figsize=(5.6, 3.4), dpi=100)
    axes = figure.add_subplot()
    for (name, values), (style, colour) in zip(
        errors.items(), (("o-", BLUE), ("s--", VERMILLION)), strict=True
    ):
        axes.semilogy(rates, values, style, color=colour, ms=4, label=_(name))
    axes.set_xticks(list(rates))
    axes.set_xlabel(_("rate (samples per output pixel along each axis)"), fontsize=8)
    axes.set_ylabel(_("RMS error"), fontsize=8)
    axes.grid(True, which="both", color="0.92")
    axes.legend(fontsize=8)
    figure.tight_layout()
    shown = list(rates)[:3]
    caption = _(
        "RMS at rates {rates}: centred {centred}; the report's {report}; "
        "centred at rate {floor_rate}: {floor:.4f}"
    ).format(
        rates=_(", ").join(map(str, shown)),
        centred=_(", ").join(f"{v:.4f}" for v in errors["centred"][:3]),
        report=_(", ").join(f"{v:.4f}" for v in errors["the report's"][:3]),
        floor_rate=floor_rate,
        floor=rmse(supersample(plate, (LAB_OUT, LAB_OUT), floor_rate), exact),
    )
    return Still.of(figure, caption)


def shift_figure(rate: int = 4, corner: int = 40, zoom: int = 6) -> Still:
    """Near the rings' centre at ``rate``: the exact mean, and each version minus it.

    Examples
    --------
    >>> shift_figure()
    rate 4, top-left 40 x 40: RMS centred 0.0008, the report's 0.0326
    """
    # Two supersamplings of the lab's whole plate: their cost grows with rate**2.
    rate = as_int(rate, "rate", minimum=1, maximum=16)
    corner = as_int(corner, "corner", minimum=1, maximum=LAB_OUT)
    plate, exact = _lab_zone_plate()
    window = (slice(0, corner), slice(0, corner))
    centred = supersample(plate, (LAB_OUT, LAB_OUT), rate)[window]
    shifted = supersample_without_offset(plate, (LAB_OUT, LAB_OUT), rate)[window]
    truth = exact[window]
    limit = 0.1
    extent = (0, corner, corner, 0)
    figure, axes_list = pixel_figure(
        [
            (truth, extent, _("exact box mean")),
            (np.zeros_like(truth), extent, _("centred minus exact")),
            (np.zeros_like(truth), extent, _("the report's minus exact")),
        ],
        zoom=zoom,
        reserve_right=70,
    )
    shown = None
    for axes, difference in zip(axes_list[1:], (centred - truth, shifted - truth), strict=True):
        axes.images[0].remove()
        shown = axes.imshow(
            difference,
            cmap="RdBu_r",
            vmin=-limit,
            vmax=limit,
            interpolation="nearest",
            extent=extent,
        )
    last = axes_list[-1].get_window_extent()
    bar = pixel_axes(figure, round(last.x1) + 8, round(last.y0), 12, round(last.height))
    figure.colorbar(shown, cax=bar)
    bar.set_ylabel(_("too bright (+) / too dark (−)"), fontsize=7)
    bar.tick_params(labelsize=7)
    caption = _(
        "rate {rate}, top-left {corner} x {corner}: RMS centred {centred:.4f}, "
        "the report's {shifted:.4f}"
    ).format(rate=rate, corner=corner, centred=rmse(centred, truth), shifted=rmse(shifted, truth))
    return Still.of(figure, caption)


def photograph_figure(rates: Sequence[int] = (1, 2, 3, 12), reference_rate: int = 32) -> Still:
    """A 500 x 500 crop of the photograph shrunk to 64 x 64 at several rates, 3 x zoomed.

    Examples
    --------
    >>> photograph_figure((1, 3))
    RMS against rate 32: rate 1 0.0674, rate 3 0.0084
    """
    photo = photograph()[50:550, 6:506]
    reference = supersample(photo, (64, 64), reference_rate)
    windows, parts = [], []
    for rate in rates:
        image = supersample(photo, (64, 64), rate)
        error = rmse(image, reference)
        windows.append(
            (
                image,
                (0, 64, 64, 0),
                _("rate {rate}: RMS {error:.4f}").format(rate=rate, error=error),
            )
        )
        parts.append(_("rate {rate} {error:.4f}").format(rate=rate, error=error))
    figure, _axes = pixel_figure(windows, zoom=3)
    caption = _("RMS against rate {reference_rate}: {parts}").format(
        reference_rate=reference_rate, parts=_(", ").join(parts)
    )
    return Still.of(figure, caption)
