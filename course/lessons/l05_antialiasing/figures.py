"""Lesson 05's still pictures and tables: a curve with and without anti-aliasing, a pixel
as a small area, one splat, the brightness along the curve, the handouts' splats measured.

Each picture is a :class:`~course.widgets.picture.Still` whose caption states
the numbers it shows; pixel views are at a whole zoom
(:func:`~course.widgets.picture.pixel_figure`). The handouts' variants are
named by role (:data:`ROLES`), not by the library's identifiers.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Polygon

from course import limits
from course._validate import as_positive_float, describe, require_step_samples
from course.antialias import DEFAULT_STEP, arc_length_step, bilinear_centres, render
from course.antialias.coverage import agg_render, curve_polyline, reference
from course.antialias.curve_quality import (
    AGG,
    ARC_LENGTH,
    intensity_along,
    position_error,
    quality_table,
    variants,
)
from course.curves.bezier import de_casteljau
from course.curves.paths import canvas_for, text_curves
from course.i18n import N_, _
from course.images import SEED_000_CUBIC, SEED_000_SHAPE
from course.metrics import rmse
from course.raster.canvas import crop
from course.widgets.base import pad
from course.widgets.picture import Still, pixel_figure

__all__ = [
    "ROLES",
    "brightness_figure",
    "claims",
    "offset_figure",
    "opening_figure",
    "pixel_area_figure",
    "seed_000_renderings",
    "speeds",
    "splat_figure",
    "step_study",
    "text_figure",
    "variants_figure",
    "variants_table",
]

BLUE, VERMILLION, GREEN = "#0072B2", "#D55E00", "#009E73"


#: Line styles for up to four curves told apart by more than colour.
_DASHES = ("-", (0, (6, 2)), (0, (1, 1.5)), (0, (6, 2, 1, 2)))
_COLOURS = (BLUE, "#E69F00", GREEN, "#CC79A7")  # Okabe and Ito's colour-blind-safe set


def _key(figure: Figure, handles: list, ncols: int | None = None) -> None:
    """A legend above the panels, one entry per mark drawn (pixel_figure leaves room for it)."""
    figure.legend(
        handles=handles,
        loc="upper center",
        ncols=ncols or len(handles),
        fontsize=8,
        frameon=False,
        handlelength=1.6,
        columnspacing=1.0,
    )


#: The variants of lesson 05 by role: (who draws the curve this way, what the splat does),
#: in English; ``_(ROLES[name][0])`` is the current language's.
ROLES = {
    "nearest_truncate": (N_("plain loop, truncated"), N_("the pixel under each sample, weight 1")),
    "nearest_round": (N_("plain loop, rounded"), N_("the nearest pixel corner, weight 1")),
    "bilinear_zero_offset": (
        N_("GAMES101 report, left addColor"),
        N_("corners made of the point: dx = dy = 0"),
    ),
    "bilinear_corners": (
        N_("GAMES101 report, middle addColor"),
        N_("bilinear, pixels at their corners"),
    ),
    "bilinear_centres": (
        N_("GAMES101 report, right addColor"),
        N_("bilinear about pixel centres"),
    ),
    "subsample_falloff": (
        N_("any-degree report's falloff"),
        N_("its own pixel, dimmed by distance"),
    ),
    "normalised_centres": (N_("VS2022 report's splat"), N_("four centres, weights sqrt(2) - d")),
    "stroke_area": (N_("the stroke's area (library)"), N_("each pixel's covered area, once")),
    AGG: (N_("Agg (matplotlib)"), N_("its outline's area, scanline by scanline")),
}
#: The two ways a sample's ink is weighted, by the name :func:`course.antialias.render` takes.
_WEIGHTINGS = {"count": N_("count"), "arc_length": N_("arc length")}


@functools.cache
def seed_000_renderings() -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Every variant of the GAMES101 test (700 x 700) and the exact reference (k = 64), once."""
    renderings = variants(SEED_000_CUBIC, SEED_000_SHAPE)
    exact = reference(SEED_000_CUBIC, SEED_000_SHAPE, width=1.0, k=64)
    for image in (*renderings.values(), exact):
        image.flags.writeable = False
    return renderings, exact


def _curve_overlay(axes, points: np.ndarray, offset: tuple[float, float] = (0.0, 0.0)) -> None:
    line = curve_polyline(points, 1e-3) - offset
    axes.plot(line[:, 0], line[:, 1], color=VERMILLION, lw=1.0)


def opening_figure(t: float = 0.06, size: int = 24, zoom: int = 12) -> Still:
    """The handouts' curve near ``t``: one pixel per sample, beside each pixel's coverage.

    Examples
    --------
    >>> opening_figure()  # doctest: +NORMALIZE_WHITESPACE
    24 x 24 pixels around t = 0.06, each 12 x 12: left 15 pixels are lit, all at 1;
    right 50 are lit, from 0.01 to 0.97
    """
    renderings, exact = seed_000_renderings()
    centre = de_casteljau(SEED_000_CUBIC, t)
    aliased, extent = crop(renderings["nearest_truncate"], centre, size)
    smooth, _extent = crop(exact, centre, size)
    figure, axes = pixel_figure(
        [
            (aliased, extent, _("the pixel under each sample")),
            (smooth, extent, _("each pixel: the area the stroke covers")),
        ],
        zoom,
        legend=[(VERMILLION, _("the true curve"))],
    )
    for panel in axes:
        _curve_overlay(panel, np.asarray(SEED_000_CUBIC, dtype=float))
    caption = _(
        "{size} x {size} pixels around t = {t:g}, each {zoom} x {zoom}: left "
        "{aliased} pixels are lit, all at 1; right "
        "{smooth} are lit, from 0.01 to {brightest:.2f}"
    ).format(
        size=size,
        t=t,
        zoom=zoom,
        aliased=np.count_nonzero(aliased),
        smooth=np.count_nonzero(smooth > 0.01),
        brightest=smooth.max(),
    )
    return Still.of(figure, caption)


def pixel_area_figure(zoom: int = 64) -> Still:
    """A stroke of width 1 across a 6 x 4 patch of pixels, each shaded by the area it covers.

    Examples
    --------
    >>> pixel_area_figure()
    pixel (2, 1) is 0.34 covered: the mean of the stroke over its square, lesson 04's box filter
    """
    line = np.array([[-0.5, 3.4], [6.5, 0.6]])
    shape = (4, 6)
    coverage = reference(line, shape, width=1.0, k=64)
    # One entry a row: the 6-pixel-wide picture is too narrow for two columns of these labels.
    figure, (axes,) = pixel_figure([(coverage, (0, 6, 4, 0), "")], zoom, title_height=60)
    _key(
        figure,
        [
            Line2D([], [], color=VERMILLION, lw=1.5, label=_("the stroke's edges (width 1)")),
            Line2D([], [], color=BLUE, lw=0.8, label=_("pixel edges")),
            Patch(
                facecolor="0.6",
                edgecolor="0.5",
                label=_("brightness and number: the area covered (black 0, white 1)"),
            ),
        ],
        ncols=1,
    )
    direction = (line[1] - line[0]) / np.linalg.norm(line[1] - line[0])
    normal = np.array([-direction[1], direction[0]]) * 0.5
    band = [line[0] + normal, line[1] + normal, line[1] - normal, line[0] - normal]
    axes.add_patch(Polygon(band, closed=True, fill=False, edgecolor=VERMILLION, lw=1.5))
    grid = [[(x, 0), (x, 4)] for x in range(7)] + [[(0, y), (6, y)] for y in range(5)]
    axes.add_collection(LineCollection(grid, colors=BLUE, linewidths=0.6, alpha=0.7))
    for row, column in np.ndindex(*shape):
        value = coverage[row, column]
        axes.text(
            column + 0.5,
            row + 0.5,
            f"{value:.2f}",
            ha="center",
            va="center",
            fontsize=9,
            color="black" if value > 0.5 else "white",
        )
    caption = _(
        "pixel (2, 1) is {covered:.2f} covered: the mean of the stroke over its "
        "square, lesson 04's box filter"
    ).format(covered=coverage[1, 2])
    return Still.of(figure, caption)


def splat_figure(x: float = 3.3, y: float = 2.8, zoom: int = 96) -> Still:
    """One curve point shared among the four pixels whose centres surround it.

    Examples
    --------
    >>> splat_figure()  # doctest: +NORMALIZE_WHITESPACE
    (3.3, 2.8) lies 0.8 right of and 0.3 below the centre (2.5, 2.5):
    weights 0.14, 0.56, 0.06 and 0.24
    """
    pixels, weights = bilinear_centres([[x, y]])
    left, top = int(pixels[:, 0].min()) - 1, int(pixels[:, 1].min()) - 1
    image = np.zeros((4, 4))
    for (column, row), weight in zip(pixels, weights, strict=True):
        image[row - top, column - left] = weight
    extent = (left, left + 4, top + 4, top)
    figure, (axes,) = pixel_figure([(image, extent, "")], zoom, title_height=44)
    _key(
        figure,
        [
            Line2D([], [], ls="", marker="o", color=VERMILLION, label=_("the curve point")),
            Line2D([], [], ls="", marker="+", color=BLUE, mew=1.5, label=_("pixel centres")),
            Line2D([], [], ls=":", color=GREEN, lw=1.5, label=_("its offset dx, dy")),
            Patch(
                facecolor="0.6", edgecolor="0.5", label=_("grey: the weight, its number written in")
            ),
        ],
        ncols=2,
    )
    grid = [[(c, top), (c, top + 4)] for c in range(left, left + 5)]
    grid += [[(left, r), (left + 4, r)] for r in range(top, top + 5)]
    axes.add_collection(LineCollection(grid, colors=BLUE, linewidths=0.6, alpha=0.7))
    first = np.array([math.floor(x - 0.5) + 0.5, math.floor(y - 0.5) + 0.5])
    centres = first + np.array([[0, 0], [1, 0], [0, 1], [1, 1]])
    axes.plot(*centres.T, "+", color=BLUE, ms=10, mew=1.5)
    axes.plot([first[0], x, x], [first[1], first[1], y], ":", color=GREEN, lw=1.5)
    axes.plot([x], [y], "o", color=VERMILLION, ms=7)
    dx, dy = x - first[0], y - first[1]
    label = {"color": GREEN, "fontsize": 9, "bbox": {"facecolor": "white", "lw": 0, "pad": 1}}
    axes.text(first[0] + dx / 2, first[1] - 0.12, f"dx = {dx:.1f}", ha="center", **label)
    axes.text(x - 0.1, first[1] + dy / 2, f"dy = {dy:.1f}", ha="right", va="center", **label)
    order = np.lexsort((pixels[:, 0], pixels[:, 1]))
    for (column, row), weight in zip(pixels[order], weights[order], strict=True):
        axes.text(  # the lower-right corner: the point and its dy sit towards the lower left
            column + 0.92,
            row + 0.9,
            f"{weight:.2f}",
            ha="right",
            fontsize=10,
            color="black" if weight > 0.5 else "white",
        )
    caption = _(
        "({x:g}, {y:g}) lies {dx:.1f} right of and {dy:.1f} below the centre "
        "({cx:g}, {cy:g}): weights {shares} and {last:.2f}"
    ).format(
        x=x,
        y=y,
        dx=dx,
        dy=dy,
        cx=first[0],
        cy=first[1],
        shares=_(", ").join(f"{w:.2f}" for w in weights[order][:-1]),
        last=weights[order][-1],
    )
    return Still.of(figure, caption)


def brightness_figure(
    method: str = "bilinear_centres", steps: tuple[float, ...] = (0.02, 0.005, 0.001, 0.0002)
) -> Still:
    """Ink per unit length along the curve at several t steps: counted, and weighted by length.

    Examples
    --------
    >>> brightness_figure()  # doctest: +NORMALIZE_WHITESPACE
    ink per px of length, step 0.001: counted 0.50..1.09, by length 0.75..1.00;
    step 0.0002: counted 1.24..2.00, by length 1.00..1.00
    """
    steps = _as_steps(steps)
    figure = Figure(figsize=(9.0, 3.0), dpi=100)
    panels = figure.subplots(1, 2, sharey=True)
    ranges = {}
    for axes, weighting, title in zip(
        panels,
        ("count", "arc_length"),
        (_("counted, as the handouts do"), _("weighted by the length each sample stands for")),
        strict=True,
    ):
        for step, dashes, colour in zip(steps, _DASHES, _COLOURS, strict=False):
            image = render(SEED_000_CUBIC, SEED_000_SHAPE, method, step=step, weighting=weighting)
            positions, density = intensity_along(image, SEED_000_CUBIC)
            label = _("step {step:g}").format(step=step)
            axes.plot(positions, density, lw=1.4, ls=dashes, color=colour, label=label)
            ranges[weighting, step] = (density.min(), density.max())
        axes.axhline(1.0, color="black", lw=0.6, ls=(0, (1, 3)), label=_("1: evenly bright"))
        axes.set_title(title, fontsize=9)
        axes.set_xlabel(_("distance along the curve (px)"), fontsize=8)
        axes.tick_params(labelsize=7)
    panels[0].set_ylabel(_("ink per px of length"), fontsize=8)
    panels[1].legend(fontsize=7)
    figure.tight_layout()
    parts = []
    for step in steps[-2:]:
        (c0, c1), (a0, a1) = ranges["count", step], ranges["arc_length", step]
        parts.append(
            _("step {step:g}: counted {c0:.2f}..{c1:.2f}, by length {a0:.2f}..{a1:.2f}").format(
                step=step, c0=c0, c1=c1, a0=a0, a1=a1
            )
        )
    caption = _("ink per px of length, {parts}").format(parts=_("; ").join(parts))
    return Still.of(figure, caption)


def _as_steps(steps: Any) -> tuple[float, ...]:
    """One to eight t steps, each drawn twice: at most MAX_STEP_SAMPLES / 4 samples in all."""
    if isinstance(steps, (str, bytes)) or not isinstance(steps, (tuple, list, np.ndarray)):
        raise TypeError(
            _("steps must be a sequence of t steps; got {steps}").format(steps=describe(steps))
        )
    if not 1 <= len(steps) <= 8:
        raise ValueError(
            _("steps must hold 1 to 8 t steps; got {steps_count}").format(steps_count=len(steps))
        )
    checked = tuple(as_positive_float(step, f"steps[{i}]") for i, step in enumerate(steps))
    samples = sum(np.floor(1 / step) + 1 for step in checked)
    if samples > limits.MAX_STEP_SAMPLES // 4:
        raise ValueError(
            _(
                "steps must give at most {most} samples in all, each drawn twice; {checked} give "
                "{samples:.3g}"
            ).format(
                most=limits.MAX_STEP_SAMPLES // 4,
                checked=list(checked),
                samples=samples,
            )
        )
    return checked


class Table(str):
    """Text that a notebook shows as it is (a ``str`` whose repr is itself)."""

    def __repr__(self) -> str:
        return str(self)


@functools.cache
def _variant_rows() -> tuple[list[str], list[dict], list[dict], list[dict]]:
    """The splats' names and their quality rows, counted and by length; the strokes' and Agg's."""
    renderings, exact = seed_000_renderings()
    names = [name for name in ROLES if name not in ("stroke_area", AGG)]
    counted = quality_table({n: renderings[n] for n in names}, SEED_000_CUBIC, exact)
    by_length = quality_table({n: renderings[n + ARC_LENGTH] for n in names}, SEED_000_CUBIC, exact)
    others = quality_table({n: renderings[n] for n in ("stroke_area", AGG)}, SEED_000_CUBIC, exact)
    return names, counted, by_length, others


def variants_table() -> Table:
    """The handouts' splats against the exact coverage: error, and brightness along the curve.

    RMSE is over the whole 700 x 700 image; CV is the coefficient of
    variation of the ink per unit length, over pieces of 8 px along the
    curve (0 for an evenly bright curve). Counted at the handouts' step
    0.001, and weighted by arc length at :func:`course.antialias.arc_length_step`'s
    step, both named in the first line. The stroke's area and Agg are not
    splats (neither counts nor weighs samples): their numbers have a column
    of their own, and "—" stands where a row has no number.

    Examples
    --------
    >>> print(variants_table().splitlines()[0])
    splats counted at step 0.001, weighted by length at step 0.000173
    """
    names, counted, by_length, others = _variant_rows()
    none = pad("—", 7, ">")
    variant, what_it_does = pad(_("variant"), 34), pad(_("what it does"), 40)
    counted_, by_length_ = pad(_("counted"), 15, ">"), pad(_("by length"), 15, ">")
    area_ = pad(_("area, once"), 15, ">")
    rmse_, cv = pad(_("RMSE"), 7, ">"), pad(_("CV"), 7, ">")
    lines = [
        _("splats counted at step {counted:g}, weighted by length at step {by_length:.3g}").format(
            counted=DEFAULT_STEP, by_length=arc_length_step(SEED_000_CUBIC)
        ),
        f"{variant} {what_it_does} {counted_} {by_length_} {area_}",
        f"{'':34s} {'':40s} {rmse_} {cv} {rmse_} {cv} {rmse_} {cv}",
    ]
    for name, count, length in zip(names, counted, by_length, strict=True):
        who, what = (_(text) for text in ROLES[name])
        lines.append(
            f"{pad(who, 34)} {pad(what, 40)} {count['rmse']:7.4f} {100 * count['cv']:6.1f}% "
            f"{length['rmse']:7.4f} {100 * length['cv']:6.1f}% {none} {none}"
        )
    for row in others:
        who, what = (_(text) for text in ROLES[row["name"]])
        lines.append(
            f"{pad(who, 34)} {pad(what, 40)} {none} {none} {none} {none} "
            f"{row['rmse']:7.4f} {100 * row['cv']:6.1f}%"
        )
    return Table("\n".join(lines))


def variants_figure() -> Still:
    """The handouts' splats' error and brightness variation, counted and weighted by length.

    Examples
    --------
    >>> variants_figure()  # doctest: +NORMALIZE_WHITESPACE
    weighted by length, the CV falls from 20.4-24.1% to 0.1-6.5%;
    the least error: the stroke's area (library), 0.0002
    """
    names, counted, by_length, others = _variant_rows()
    shown = [*names, *(row["name"] for row in others)]
    labels = [_(ROLES[name][0]) for name in shown]
    figure = Figure(figsize=(9.0, 3.4), dpi=100)
    error_axes, cv_axes = figure.subplots(1, 2, sharey=True)
    rows = np.arange(len(labels))[::-1]
    height = 0.38
    groups = (
        (rows[: len(names)] + height / 2, counted, "0.55", "o", _("counted (the handouts)")),
        (rows[: len(names)] - height / 2, by_length, BLUE, "s", _("weighted by length")),
        (rows[len(names) :], others, GREEN, "D", _("not a splat: each pixel's area")),
    )
    for places, group, colour, marker, label in groups:
        # A bar's length on a log axis depends on where the axis starts: a dot does not.
        error_axes.plot(
            [row["rmse"] for row in group], places, marker, color=colour, ms=5, ls="", label=label
        )
        cv_axes.barh(places, [100 * row["cv"] for row in group], height, color=colour, label=label)
    error_axes.legend(fontsize=7, loc="upper left")
    error_axes.grid(axis="x", which="both", color="0.9", lw=0.6)
    error_axes.set_axisbelow(True)
    for axes in (error_axes, cv_axes):
        axes.tick_params(labelsize=7)
    error_axes.set_xscale("log")
    error_axes.set_xlabel(_("RMSE against the exact coverage (log scale)"), fontsize=8)
    cv_axes.set_xlabel(_("brightness variation along the curve, CV (%)"), fontsize=8)
    error_axes.set_yticks(rows, labels, fontsize=8)
    cv_axes.legend(fontsize=7, loc="lower right")
    figure.tight_layout()
    low = min(row["cv"] for row in counted)
    high = max(row["cv"] for row in counted)
    fixed_low = min(row["cv"] for row in by_length)
    fixed_high = max(row["cv"] for row in by_length)
    best = min(counted + by_length + others, key=lambda row: row["rmse"])
    best_role = ROLES.get(best["name"], (best["name"],))[0]
    best_name = _(best_role)
    caption = _(
        "weighted by length, the CV falls from {low:.1f}-{high:.1f}% to "
        "{fixed_low:.1f}-{fixed_high:.1f}%; the least error: {best}, {error:.4f}"
    ).format(
        low=100 * low,
        high=100 * high,
        fixed_low=100 * fixed_low,
        fixed_high=100 * fixed_high,
        best=best_name,
        error=best["rmse"],
    )
    return Still.of(figure, caption)


def claims() -> Table:
    """The GAMES101 report's three conclusions about its three splats, measured.

    Examples
    --------
    >>> print(claims().splitlines()[0])
    no anti-aliasing    pixels differing from it:     0  RMSE 0.0327  position error 0.390 px
    """
    renderings, exact = seed_000_renderings()
    plain = renderings["nearest_round"]
    shown = (
        (_("no anti-aliasing"), plain),
        (_("left (Point2f)"), renderings["bilinear_zero_offset"]),
        (_("middle (Point)"), renderings["bilinear_corners"]),
        (_("right (rounded)"), renderings["bilinear_centres"]),
    )
    return Table(
        "\n".join(
            _(
                "{name} pixels differing from it: {count:5d}  "
                "RMSE {error:.4f}  position error {position:.3f} px"
            ).format(
                name=pad(name, 19),
                count=np.count_nonzero(image != plain),
                error=rmse(image, exact),
                position=position_error(image, SEED_000_CUBIC),
            )
            for name, image in shown
        )
    )


def speeds(step: float = 0.001) -> Table:
    """How fast the handouts' curve moves, in px per unit t, and how far apart its samples fall.

    Examples
    --------
    >>> print(speeds())  # doctest: +NORMALIZE_WHITESPACE
    the curve moves 2040 px per unit t at its ends, 912 at its two bends (t = 0.276 and 0.724)
    and 1020 in the middle: at step 0.001 its samples fall 2.04, 0.91 and 1.02 px apart
    """
    control = np.asarray(SEED_000_CUBIC, dtype=float)
    t = np.linspace(0.0, 1.0, 100_001)[:, None]
    legs = np.diff(control, axis=0)
    velocity = 3 * ((1 - t) ** 2 * legs[0] + 2 * t * (1 - t) * legs[1] + t**2 * legs[2])
    speed = np.hypot(*velocity.T)
    bend = int(np.argmin(speed[: len(t) // 2]))
    end, slowest, middle = speed[0], speed[bend], speed[len(t) // 2]
    return Table(
        _(
            "the curve moves {end:.0f} px per unit t at its ends, {slowest:.0f} at its two bends "
            "(t = {first:.3f} and {second:.3f}) and {middle:.0f} in the middle: at "
            "step {step:g} its samples fall {end_gap:.2f}, {slowest_gap:.2f} and "
            "{middle_gap:.2f} px apart"
        ).format(
            end=end,
            slowest=slowest,
            first=t[bend, 0],
            second=1 - t[bend, 0],
            middle=middle,
            step=step,
            end_gap=end * step,
            slowest_gap=slowest * step,
            middle_gap=middle * step,
        )
    )


#: The most t steps the step study renders (each one a whole curve, twice).
_STUDY_STEPS = 8


def step_study(
    steps: tuple[float, ...] = (0.002, 0.001, 0.0005, 0.0001), method: str = "bilinear_centres"
) -> Table:
    """The step app's three questions answered: dots at the ends, thickening, the fix.

    For each step and weighting: the ink of the emptiest of the 48 columns
    the curve crosses first (where it moves fastest), and the mean and CV of
    the ink per px of length along the whole curve.

    Examples
    --------
    >>> print(step_study(steps=(0.001,)).splitlines()[1])  # doctest: +NORMALIZE_WHITESPACE
    0.001      count       0.10   0.88  22.4%   arc length   0.19   0.98   3.7%
    """
    if not isinstance(steps, (tuple, list)) or not 1 <= len(steps) <= _STUDY_STEPS:
        raise ValueError(
            _("steps must be a tuple of 1 to {most} t steps; got {steps}").format(
                most=_STUDY_STEPS, steps=describe(steps)
            )
        )
    steps = tuple(
        as_positive_float(step, f"steps[{i}]", largest=1.0) for i, step in enumerate(steps)
    )
    for step in steps:
        require_step_samples(step, "steps")
    step_ = pad(_("step"), 10)
    weighting_, end = _("weighting"), pad(_("end"), 5, ">")
    mean, cv = pad(_("mean"), 6, ">"), pad(_("CV"), 6, ">")
    lines = [
        f"{step_} {pad(weighting_, 11)} {end} {mean} {cv}   {pad(weighting_, 12)} {end} {mean} {cv}"
    ]
    for step in steps:
        parts = [f"{step:<10g}"]
        for weighting in ("count", "arc_length"):
            image = render(SEED_000_CUBIC, SEED_000_SHAPE, method, step=step, weighting=weighting)
            _positions, ink = intensity_along(image, SEED_000_CUBIC)
            # The curve leaves (10, 10) level and fast: columns 12..59, rows 5..19 hold it.
            emptiest = image[5:20, 12:60].sum(axis=0).min()
            parts.append(
                f"{pad(_(_WEIGHTINGS[weighting]), 12)} {emptiest:5.2f} {ink.mean():6.2f} "
                f"{100 * ink.std() / ink.mean():5.1f}%"
            )
        lines.append(" ".join(parts[:2]) + "   " + parts[2])
    return Table("\n".join(lines))


def offset_figure(t: float = 0.06, size: int = 16, zoom: int = 14) -> Still:
    """The GAMES101 report's middle and right addColor near ``t``: half a pixel off, and on.

    Both share each point among four pixels; the middle one takes them at
    their corners, so its line sits half a pixel right of and below the
    curve. Each title gives the position error over the whole curve.

    Examples
    --------
    >>> offset_figure()  # doctest: +NORMALIZE_WHITESPACE
    position error over the whole curve: middle addColor 0.365 px, right addColor 0.017 px,
    exact coverage 0.005 px
    """
    renderings, exact = seed_000_renderings()
    centre = de_casteljau(SEED_000_CUBIC, t)
    shown = (
        (_("middle addColor"), renderings["bilinear_corners"]),
        (_("right addColor"), renderings["bilinear_centres"]),
        (_("exact coverage"), exact),
    )
    errors = [position_error(image, SEED_000_CUBIC) for _name, image in shown]
    windows = []
    for (name, image), error in zip(shown, errors, strict=True):
        window, extent = crop(image, centre, size)
        title = _("{name}\nposition error {error:.3f} px").format(name=name, error=error)
        windows.append((window, extent, title))
    figure, axes = pixel_figure(windows, zoom, legend=[(VERMILLION, _("the true curve"))])
    for panel in axes:
        _curve_overlay(panel, np.asarray(SEED_000_CUBIC, dtype=float))
    caption = _("position error over the whole curve: {errors}").format(
        errors=_(", ").join(
            _("{name} {error:.3f} px").format(name=name, error=error)
            for (name, _image), error in zip(shown, errors, strict=True)
        )
    )
    return Still.of(figure, caption)


def text_figure(text: str = "Bé", size: float = 40.0, zoom: int = 6) -> Still:
    """A line of text's outlines stroked at width 1: Agg, the library's exact stroke, the reference.

    Each glyph is one path of quadratic curves (``TextPath``), so the stroke
    must be exact where they join and at the glyphs' sharp corners.

    Examples
    --------
    >>> text_figure()  # doctest: +NORMALIZE_WHITESPACE
    'Bé' at 40 px, stroked at width 1, against the exact coverage: RMSE Agg 0.0333,
    stroke area 0.0028
    """
    size = as_positive_float(size, "size")
    if not isinstance(text, str) or len(text) * size > limits.MAX_STROKED_TEXT:
        raise ValueError(
            _(
                "text and size must have len(text) * size at most {most} (the exact coverage "
                "samples every pixel along the outlines); got {text} at {size:g} px"
            ).format(most=limits.MAX_STROKED_TEXT, text=describe(text), size=size)
        )
    curves = text_curves(text, size=size)
    shape = canvas_for(curves)
    exact = reference(curves, shape, width=1.0, k=64)
    agg = agg_render(curves, shape)
    ours = render(curves, shape, "stroke_area")
    extent = (0, shape[1], shape[0], 0)
    figure, _axes = pixel_figure(
        [
            (agg, extent, _("Agg (matplotlib)")),
            (ours, extent, _("stroke area")),
            (exact, extent, _("exact")),
        ],
        zoom,
    )
    caption = _(
        "{text} at {size:g} px, stroked at width 1, against the exact coverage: RMSE Agg "
        "{agg:.4f}, stroke area {ours:.4f}"
    ).format(text=repr(text), size=size, agg=rmse(agg, exact), ours=rmse(ours, exact))
    return Still.of(figure, caption)
