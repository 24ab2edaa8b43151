"""Lesson 01's still pictures: the construction by hand, and each handout pitfall.

Each function draws one picture of the lesson and returns it as a
:class:`~course.widgets.picture.Still` (shown as PNG in a notebook), so the
notebook holds no plotting code. Pixel views are drawn at a whole zoom
(:func:`~course.widgets.picture.pixel_figure`); colours are Okabe and Ito's,
and every colour has a legend entry or a label. The pieces the pixel views
share, and the yellow check's overview, are in
:mod:`~course.lessons.l01_de_casteljau.pixel_views`.
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction
from typing import Any

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle

from course._validate import as_choice, as_figure_curve, as_int
from course.curves.bezier import de_casteljau, de_casteljau_levels, derivative
from course.curves.bezier_handouts import de_casteljau_reversed, trace_iterative, trace_recursive
from course.curves.flattening import flatten, uniform_parameters
from course.curves.handout_loops import HANDOUT_LOOPS, loop_pixels, yellow_check
from course.i18n import _
from course.lessons.l01_de_casteljau.pixel_views import (
    YELLOW,
    painted_canvas,
    pixel_grid,
    replace_legend,
    yellow_overview,
)
from course.raster import nearest_pixels
from course.raster.canvas import crop
from course.widgets.picture import Still, pixel_figure

__all__ = [
    "end_of_curve_figure",
    "gaps_figure",
    "points_held_figure",
    "reversed_figure",
    "three_points_figure",
    "yellow_check_figure",
]

BLUE, VERMILLION, GREEN, ORANGE = "#0072B2", "#D55E00", "#009E73", "#E69F00"
#: The end-of-curve figure's zoom: a 10-pixel window is 280 px, a pixel's outline readable.
END_ZOOM = 28


def _fraction(value: float) -> str:
    """A coordinate as the student computes it by hand: 9/4 rather than 2.25 when short."""
    exact = Fraction(value).limit_denominator(64)
    if float(exact) == value and exact.denominator > 1:
        return f"{exact.numerator}/{exact.denominator}"
    return f"{value:g}"


def three_points_figure(points: Any, t: float) -> Still:
    """De Casteljau by hand on three points: both levels, each point labelled with its value.

    Examples
    --------
    >>> three_points_figure([[0, 0], [2, 4], [8, 0]], 0.25)
    de Casteljau on three points at t = 0.25: B(t) = (5/4, 3/2)
    """
    control = as_figure_curve(points)
    levels = de_casteljau_levels(control, t)
    curve = de_casteljau(control, np.linspace(0.0, 1.0, 101))
    figure = Figure(figsize=(5.2, 3.6), dpi=100)
    axes = figure.add_subplot()
    axes.plot(*curve.T, color="0.8", linewidth=1, label=_("the curve"))
    names = [["P"], ["Q"], ["B(t)"]]
    styles = [("o-", "0.35"), ("s--", BLUE), ("D", VERMILLION)]
    for level, (points_at, (style, colour)) in enumerate(zip(levels, styles, strict=False)):
        label = (_("control polygon"), _("level 1"), _("level 2: B(t)"))[min(level, 2)]
        axes.plot(*points_at.T, style, color=colour, markersize=7, label=label)
        for index, point in enumerate(points_at):
            name = names[min(level, 2)][0]
            text = name if name == "B(t)" else f"{name}{index}"
            coordinates = ", ".join(_fraction(float(v)) for v in point)
            # Level 1 labelled outside the triangle, B(t) beside its point: nothing overlaps.
            first = level == 1 and index == 0
            axes.annotate(
                f"{text} = ({coordinates})",
                point,
                xytext=(-9, 0) if first else (9, -3) if level == 1 else (7, 7),
                textcoords="offset points",
                ha="right" if first else "left",
                va="center" if level == 1 else "bottom",
                fontsize=8,
                color=colour,
            )
    axes.set_aspect("equal")
    axes.invert_yaxis()
    axes.margins(x=0.3, y=0.18)
    axes.legend(fontsize=7, loc="lower right")
    axes.set_title(
        _("t = {t}: a quarter of the way along each segment").format(t=_fraction(t)), fontsize=9
    )
    figure.tight_layout()
    point = levels[-1][0]
    value = ", ".join(_fraction(float(v)) for v in point)
    caption = _("de Casteljau on three points at t = {t:g}: B(t) = ({value})").format(
        t=t, value=value
    )
    return Still.of(figure, caption)


def points_held_figure(counts: Sequence[int] = (4, 10, 20, 50, 100, 200)) -> Still:
    """Points held at once by the recursion and by the loop, counted by running both.

    Examples
    --------
    >>> points_held_figure((4, 10))
    points held at N = 10: recursion 55, loop 19
    """
    counts = [as_int(count, "counts", minimum=1, maximum=300) for count in counts]
    if not counts:
        raise ValueError(_("counts must not be empty"))
    rng = np.random.default_rng(1)
    recursive, iterative = [], []
    for count in counts:
        points = rng.uniform(0, 700, (count, 2))
        recursive.append(trace_recursive(points, 0.3).peak_points_held)
        iterative.append(trace_iterative(points, 0.3).peak_points_held)
    figure = Figure(figsize=(4.6, 3.2), dpi=100)
    axes = figure.add_subplot()
    axes.loglog(counts, recursive, "o-", color=VERMILLION, label=_("recursion: N(N+1)/2"))
    axes.loglog(counts, iterative, "s--", color=BLUE, label=_("loop: 2N - 1"))
    axes.set_xlabel(_("control points N"))
    axes.set_ylabel(_("points held at once"))
    axes.legend(fontsize=8)
    figure.tight_layout()
    caption = _("points held at N = {count}: recursion {recursive}, loop {loop}").format(
        count=counts[-1], recursive=recursive[-1], loop=iterative[-1]
    )
    return Still.of(figure, caption)


def reversed_figure(points: Any, t: float = 0.25) -> Still:
    """The textbook step and the handouts' reversed step: one curve, run opposite ways.

    Examples
    --------
    >>> reversed_figure([[10, 10], [690, 10], [10, 690], [690, 690]])
    at t = 0.25: textbook (307.5, 116.25), reversed (392.5, 583.75) = textbook at t = 0.75
    """
    control = as_figure_curve(points)
    ts = np.linspace(0.0, 1.0, 21)
    figure = Figure(figsize=(8.4, 4.4), dpi=100)
    pairs = (
        (_("textbook: (1 - t) P[i] + t P[i+1]"), de_casteljau),
        (_("two reports: t P[i] + (1 - t) P[i+1]"), de_casteljau_reversed),
    )
    centre = control.mean(axis=0)
    marks = []
    for index, (title, curve_of) in enumerate(pairs):
        axes = figure.add_subplot(1, 2, index + 1)
        curve = curve_of(control, ts)
        axes.plot(*control.T, "o--", color="0.6", linewidth=1, markersize=5)
        for number, point in enumerate(control):
            axes.annotate(
                f"P{number}", point, xytext=(5, 5), textcoords="offset points", fontsize=8
            )
        dots = axes.scatter(*curve.T, c=ts, cmap="viridis", s=18, zorder=3)
        mark = curve_of(control, t)
        marks.append(mark)
        axes.plot(*mark, "D", color=VERMILLION, markersize=8, zorder=4)
        axes.annotate(
            f"t = {t:g}",
            mark,
            xytext=(10, -4) if mark[0] <= centre[0] else (-10, 10),
            ha="left" if mark[0] <= centre[0] else "right",
            textcoords="offset points",
            color=VERMILLION,
        )
        # "t = 0" towards the polygon's middle, clear of the point labels at the corners.
        inward = np.sign(centre - curve[0]) * (1, -1)  # y down in data, up in offsets
        axes.annotate(
            "t = 0",
            curve[0],
            xytext=tuple(28 * inward + (-12, 0)),
            textcoords="offset points",
            fontsize=9,
            arrowprops={"arrowstyle": "-", "color": "0.3"},
        )
        axes.set_title(title, fontsize=9, pad=12)
        axes.set_aspect("equal")
        axes.invert_yaxis()
        axes.margins(0.08)
        axes.tick_params(labelsize=7)
    figure.colorbar(dots, ax=figure.axes, shrink=0.6, fraction=0.03, label="t")
    textbook, backwards = ((f"{v:g}" for v in mark) for mark in marks)
    caption = _(
        "at t = {t:g}: textbook ({textbook}), reversed ({reversed}) = textbook at t = {mirror:g}"
    ).format(t=t, textbook=", ".join(textbook), reversed=", ".join(backwards), mirror=1 - t)
    return Still.of(figure, caption)


def end_of_curve_figure(
    points: Any, seeds: Sequence[str] = ("000", "003"), size: int = 10
) -> Still:
    """The last pixels each handout loop paints, beside the pixel that holds B(1).

    Examples
    --------
    >>> still = end_of_curve_figure([[10, 10], [690, 10], [10, 690], [690, 690]])
    >>> print(still.caption.replace("; ", "\\n"))
    B(1) = (690, 690) in pixel (690, 690)
    the GAMES101 report paints it (last t 0.9999907)
    the VS2022 report does not (last t 0.999)
    """
    control = as_figure_curve(points)
    if isinstance(seeds, str) or not hasattr(seeds, "__iter__"):
        raise TypeError(
            _("seeds must be a sequence of handout seeds; got {seeds_type}").format(
                seeds_type=type(seeds).__name__
            )
        )
    seeds = [as_choice(seed, "seeds", tuple(HANDOUT_LOOPS)) for seed in seeds]
    size = as_int(size, "size", minimum=2, maximum=100)
    end = de_casteljau(control, 1.0)
    home = tuple(int(v) for v in np.floor(end))
    windows, verdicts = [], []
    for seed in seeds:
        loop = HANDOUT_LOOPS[seed]
        pixels = loop_pixels(control, loop)
        last_t = uniform_parameters(0.001, loop.accumulate)[-1]
        lit = bool((pixels == home).all(axis=1).any())
        window, extent = crop(painted_canvas(pixels, (0.0, 0.62, 0.45)), end, size)
        rounding = _("rounded") if loop.rounding == "round" else _("truncated")
        windows.append(
            (
                window,
                extent,
                _("{loop}\nlast t {last_t:.7g}, {rounding}").format(
                    loop=loop.label, last_t=last_t, rounding=rounding
                ),
            )
        )
        verdict = (
            _("{loop} paints it (last t {last_t:.7g})")
            if lit
            else _("{loop} does not (last t {last_t:.7g})")
        )
        verdicts.append(verdict.format(loop=loop.label, last_t=last_t))
    legend = [
        (GREEN, _("painted")),
        ("white", _("not painted")),
        ("white", _("B(1)'s pixel")),
        ("white", "B(1)"),
    ]
    figure, axes_list = pixel_figure(windows, zoom=END_ZOOM, legend=legend, title_height=44)
    for axes, (_window, extent, _title) in zip(axes_list, windows, strict=True):
        pixel_grid(axes, extent)
        # B(1) often sits on a pixel corner: a "+" there would lie along the outline's edges.
        axes.plot(*end, "x", color="black", markersize=12, markeredgewidth=2, zorder=4)
        # The outline goes over the painted square and the cross: dashes on a white line,
        # so that they read on green, on white and across the cross alike.
        for colour, dashes, width in (("white", "-", 3.5), (VERMILLION, (0, (3, 2)), 2.0)):
            axes.add_patch(
                Rectangle(
                    home,
                    1,
                    1,
                    fill=False,
                    edgecolor=colour,
                    linewidth=width,
                    linestyle=dashes,
                    zorder=5,
                )
            )
    handles = [
        Patch(facecolor=GREEN, edgecolor="0.5"),
        Patch(facecolor="white", edgecolor="0.5"),
        Patch(facecolor="white", edgecolor=VERMILLION, linestyle=(0, (3, 2)), linewidth=2),
        Line2D([], [], marker="x", color="black", linestyle="", markersize=8, mew=2),
    ]
    replace_legend(figure, handles, [label for _colour, label in legend])
    caption = _("B(1) = ({x:g}, {y:g}) in pixel {pixel}; {verdicts}").format(
        x=end[0], y=end[1], pixel=home, verdicts=_("; ").join(verdicts)
    )
    return Still.of(figure, caption)


def gaps_figure(points: Any, near_t: float = 0.012, size: int = 16) -> Still:
    """Near the curve's fastest part: a 0.001 step, a 0.0001 step, and ``flatten(max_step=1)``.

    Examples
    --------
    >>> still = gaps_figure([[10, 10], [690, 10], [10, 690], [690, 690]])
    >>> print(still.caption.replace("; ", "\\n"))
    speed 2040 px per unit of t at t = 0, 1020 at t = 0.5
    whole curve: step 0.001 leaves 147 gaps, 1.05 points per painted pixel
    step 0.0001 0 gaps, 7.55
    flatten 0 gaps, 1.21
    """
    control = as_figure_curve(points)
    # Three panels zoomed 12 times: a window of 100 pixels is a 3600-pixel-wide picture.
    size = as_int(size, "size", minimum=1, maximum=100)
    centre = de_casteljau(control, near_t)
    polyline = flatten(control, 0.25, max_step=1.0)
    drawings = [
        (
            _("step 0.001 (the handouts)"),
            nearest_pixels(de_casteljau(control, uniform_parameters(0.001, "float32"))),
        ),
        (
            _("step 0.0001"),
            nearest_pixels(de_casteljau(control, uniform_parameters(0.0001, "float32"))),
        ),
        ("flatten(max_step=1)", nearest_pixels(polyline)),
    ]
    windows, gaps, overdraw = [], [], []
    for title, pixels in drawings:
        jumps = np.abs(np.diff(pixels, axis=0)).max(axis=1)
        gaps.append(int(np.count_nonzero(jumps > 1)))
        overdraw.append(len(pixels) / len(np.unique(pixels, axis=0)))
        window, extent = crop(painted_canvas(pixels, (0.0, 0.45, 0.7)), centre, size)
        windows.append((window, extent, title))
    figure, axes_list = pixel_figure(windows, zoom=12, legend=[(BLUE, _("painted"))])
    for axes, (_window, extent, _title) in zip(axes_list, windows, strict=True):
        pixel_grid(axes, extent)
    speed = np.hypot(*de_casteljau(derivative(control), [0.0, 0.5]).T)
    caption = _(
        "speed {start:g} px per unit of t at t = 0, {middle:g} at t = 0.5; "
        "whole curve: step 0.001 leaves {gaps0} gaps, {over0:.2f} points per painted "
        "pixel; step 0.0001 {gaps1} gaps, {over1:.2f}; flatten {gaps2} gaps, {over2:.2f}"
    ).format(
        start=speed[0],
        middle=speed[1],
        gaps0=gaps[0],
        over0=overdraw[0],
        gaps1=gaps[1],
        over1=overdraw[1],
        gaps2=gaps[2],
        over2=overdraw[2],
    )
    return Still.of(figure, caption)


def yellow_check_figure(points: Any, seed: str, size: int = 12) -> Still:
    """The GAMES101 check for one handout loop: where the red and green curves part.

    Left, the whole curve coloured by the share of its painted pixels that
    are yellow, stretch by stretch (:func:`~.pixel_views.yellow_along`; at 700 pixels in
    192, a mark per pixel would merge into one band), the pixels that are not
    yellow circled when there are at most 40, and the zoomed window boxed;
    right, the pixels around the first of them at a whole zoom, on the pixel
    grid. Red-only and green-only pixels also carry a
    mark of their own (a ring, a cross), so they are told apart without
    colour.

    Examples
    --------
    >>> yellow_check_figure([[10, 10], [690, 10], [10, 690], [690, 690]], "002")
    the any-degree report against naive_bezier: 99.2% yellow, 4 pixels only red, 4 only green
    """
    control = as_figure_curve(points)
    seed = as_choice(seed, "seed", tuple(HANDOUT_LOOPS))
    size = as_int(size, "size", minimum=2, maximum=100)
    check = yellow_check(control, HANDOUT_LOOPS[seed])
    odd = np.vstack([check.red_only, check.green_only])
    curve = de_casteljau(control, np.linspace(0.0, 1.0, 401))
    first = odd[np.lexsort((odd[:, 0], odd[:, 1]))][0] if len(odd) else np.floor(curve[0])
    yellow = check.image[..., 0] * check.image[..., 1]
    # Red, green and yellow on white: unpainted pixels white, as in the zoom panels.
    shown = np.where((check.image.sum(axis=2) > 0)[..., None], check.image, 1.0)
    shown[yellow > 0] = YELLOW
    window, extent = crop(shown, first + 0.5, size)
    side = size * 16  # the overview is as tall as the zoomed panel
    scale_room = 60  # the overview's colour bar and its label
    colours = [
        (YELLOW, _("both")),
        ((1, 0, 0), _("only red (ring)")),
        ((0, 1, 0), _("only green (cross)")),
    ]
    figure, (zoomed,) = pixel_figure(
        [(window, extent, _("around pixel {pixel}").format(pixel=tuple(int(v) for v in first)))],
        zoom=16,
        legend=[*colours, ("white", _("not yellow"))],
        legend_height=44,
        reserve_left=side + 18 + scale_room,
    )
    pixel_grid(zoomed, extent)
    left, right, bottom, top = extent
    for listed, marker in ((check.red_only, "o"), (check.green_only, "x")):
        inside = listed[
            (listed[:, 0] >= left)
            & (listed[:, 0] < right)
            & (listed[:, 1] >= top)
            & (listed[:, 1] < bottom)
        ]
        zoomed.plot(*(inside + 0.5).T, marker, color="black", markersize=6, fillstyle="none")
    circled = yellow_overview(figure, check, curve, extent, side, VERMILLION)
    handles = [
        Patch(facecolor=YELLOW, edgecolor="0.5"),
        (
            Patch(facecolor=(1, 0, 0), edgecolor="0.5"),
            Line2D([], [], marker="o", color="black", fillstyle="none", linestyle=""),
        ),
        (
            Patch(facecolor=(0, 1, 0), edgecolor="0.5"),
            Line2D([], [], marker="x", color="black", linestyle=""),
        ),
        Patch(facecolor="none", edgecolor="black", linewidth=1.5),
    ]
    labels = [label for _colour, label in colours]
    labels.append(_("box: around the zoom"))
    if circled:
        handles.append(Line2D([], [], marker="o", color=VERMILLION, fillstyle="none", linestyle=""))
        labels.append(_("not yellow, circled"))
    replace_legend(figure, handles, labels, ncols=2)
    caption = _(
        "{loop} against naive_bezier: {yellow:.1%} yellow, "
        "{red} pixels only red, {green} only green"
    ).format(
        loop=HANDOUT_LOOPS[seed].label,
        yellow=check.fraction,
        red=len(check.red_only),
        green=len(check.green_only),
    )
    return Still.of(figure, caption)
