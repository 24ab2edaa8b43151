"""Lesson 05's measurements of the handouts' curve (seed 000's cubic on its 700 x 700 canvas).

:func:`seed_000_renderings` renders every variant and the exact reference
once, and :data:`ROLES` names each variant by who draws the curve that way
and what its splat does. On them: :func:`variants_table` and
:func:`variants_figure` (each variant's error against the exact coverage and
its brightness variation along the curve, counted and weighted by length),
:func:`claims` (the GAMES101 report's three conclusions, measured),
:func:`speeds` (how far apart the handouts' samples fall) and
:func:`step_study` (the step app's questions answered). Numbers come as a
:class:`Table`, text a notebook shows as it is.

:mod:`.figures` draws the lesson's pictures from the same renderings; the notebook calls
these as ``measurements.claims()``.
"""

from __future__ import annotations

import functools

import numpy as np
from matplotlib.figure import Figure

from course._validate import as_positive_float, describe
from course.antialias import DEFAULT_STEP, arc_length_step, render
from course.antialias.coverage import reference
from course.antialias.curve_quality import (
    AGG,
    ARC_LENGTH,
    intensity_along,
    position_error,
    quality_table,
    variants,
)
from course.i18n import N_, _
from course.images import SEED_000_CUBIC, SEED_000_SHAPE
from course.lessons.printed import display_width
from course.limits import require_step_samples
from course.metrics import rmse
from course.widgets.base import pad
from course.widgets.picture import Still

__all__ = [
    "ROLES",
    "WEIGHTING_LABELS",
    "Table",
    "claims",
    "seed_000_renderings",
    "speeds",
    "step_study",
    "variants_figure",
    "variants_table",
]

BLUE, GREEN = "#0072B2", "#009E73"  # Okabe and Ito's, as figures.py draws them


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
#: The two ways a sample's ink is weighted, by the name :func:`course.antialias.render` takes,
#: as the step app's toggle, its title and :func:`step_study` show them (``_`` of the value).
WEIGHTING_LABELS = {"count": N_("count"), "arc_length": N_("arc length")}


@functools.cache
def seed_000_renderings() -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Every variant of the GAMES101 test (700 x 700) and the exact reference (k = 64), once."""
    renderings = variants(SEED_000_CUBIC, SEED_000_SHAPE)
    exact = reference(SEED_000_CUBIC, SEED_000_SHAPE, width=1.0, k=64)
    for image in (*renderings.values(), exact):
        image.flags.writeable = False
    return renderings, exact


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
    # The number columns are 7 wide, or as wide as their heading in the current language.
    e, c = (max(7, display_width(_(heading))) for heading in ("RMSE", "CV"))
    none_e, none_c = pad("—", e, ">"), pad("—", c, ">")
    variant, what_it_does = pad(_("variant"), 34), pad(_("what it does"), 40)
    counted_, by_length_ = pad(_("counted"), e + c + 1, ">"), pad(_("by length"), e + c + 1, ">")
    area_ = pad(_("area, once"), e + c + 1, ">")
    rmse_, cv = pad(_("RMSE"), e, ">"), pad(_("CV"), c, ">")

    def numbers(row: dict) -> str:
        return f"{row['rmse']:{e}.4f} {100 * row['cv']:{c - 1}.1f}%"

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
            f"{pad(who, 34)} {pad(what, 40)} {numbers(count)} {numbers(length)} {none_e} {none_c}"
        )
    for row in others:
        who, what = (_(text) for text in ROLES[row["name"]])
        lines.append(
            f"{pad(who, 34)} {pad(what, 40)} {none_e} {none_c} {none_e} {none_c} {numbers(row)}"
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
    # 19 columns hold the English names; a longer translation widens the column for all four.
    width = max(19, *(display_width(name) + 3 for name, _image in shown))
    return Table(
        "\n".join(
            _(
                "{name} pixels differing from it: {count:5d}  "
                "RMSE {error:.4f}  position error {position:.3f} px"
            ).format(
                name=pad(name, width),
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
    # The CV column is 6 wide, or as wide as its heading in the current language.
    c = max(6, display_width(_("CV")))
    mean, cv = pad(_("mean"), 6, ">"), pad(_("CV"), c, ">")
    lines = [
        f"{step_} {pad(weighting_, 12)} {end} {mean} {cv}   {pad(weighting_, 12)} {end} {mean} {cv}"
    ]
    for step in steps:
        parts = [f"{step:<10g}"]
        for weighting in ("count", "arc_length"):
            image = render(SEED_000_CUBIC, SEED_000_SHAPE, method, step=step, weighting=weighting)
            _positions, ink = intensity_along(image, SEED_000_CUBIC)
            # The curve leaves (10, 10) level and fast: columns 12..59, rows 5..19 hold it.
            emptiest = image[5:20, 12:60].sum(axis=0).min()
            parts.append(
                f"{pad(_(WEIGHTING_LABELS[weighting]), 12)} {emptiest:5.2f} {ink.mean():6.2f} "
                f"{100 * ink.std() / ink.mean():{c - 1}.1f}%"
            )
        lines.append(" ".join(parts[:2]) + "   " + parts[2])
    return Table("\n".join(lines))
