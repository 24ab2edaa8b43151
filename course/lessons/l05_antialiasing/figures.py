"""Lesson 05's still pictures: a curve with and without anti-aliasing, a pixel as a small
area, one splat, the brightness along the curve, the report's half-pixel offset, stroked text.

Each picture is a :class:`~course.widgets.picture.Still` whose caption states
the numbers it shows; pixel views are at a whole zoom
(:func:`~course.widgets.picture.pixel_figure`). The handouts' curve and its
variants, rendered once, come from :mod:`.measurements`, whose tables and
variants chart are listed here too: the notebook calls them as
``figures.<name>()``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Polygon

from course import limits
from course._validate import as_positive_float, describe
from course.antialias import bilinear_centres, render
from course.antialias.coverage import agg_render, curve_polyline, reference
from course.antialias.curve_quality import intensity_along, position_error
from course.curves.bezier import de_casteljau
from course.curves.paths import canvas_for, text_curves
from course.i18n import _
from course.images import SEED_000_CUBIC, SEED_000_SHAPE
from course.lessons.l05_antialiasing.measurements import seed_000_renderings
from course.metrics import rmse
from course.raster.canvas import crop
from course.widgets.picture import Still, pixel_figure

__all__ = [
    "brightness_figure",
    "offset_figure",
    "opening_figure",
    "pixel_area_figure",
    "splat_figure",
    "text_figure",
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
    step 0.0002: counted 1.24..2.00, by length 1.00
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
            _("step {step:g}: counted {counted}, by length {weighted}").format(
                step=step, counted=_spread(c0, c1), weighted=_spread(a0, a1)
            )
        )
    caption = _("ink per px of length, {parts}").format(parts=_("; ").join(parts))
    return Still.of(figure, caption)


def _spread(low: float, high: float) -> str:
    """``low..high`` to two decimals, or one value where both print alike.

    >>> _spread(0.5, 1.094), _spread(0.999, 1.001)
    ('0.50..1.09', '1.00')
    """
    low_text, high_text = f"{low:.2f}", f"{high:.2f}"
    if low_text == high_text:
        return low_text
    return _("{low}..{high}").format(low=low_text, high=high_text)


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
