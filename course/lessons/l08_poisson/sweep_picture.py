"""The picture of a wrong sweep: when Jacobi stops and when the student's loop did, and where
the student's ``g`` differs from Jacobi's.

A wrong sweep is often a wrong count with a ``g`` a hundred-thousandth off (Gauss-Seidel
stops at 10 sweeps where Jacobi needs 16): two pictures of ``g`` side by side then look the
same. So the left panel is the count: Jacobi's residual before each sweep, on a log scale,
the tolerance across it, and a line at each loop's stop, the student's residual marked at
theirs. The right panel is the difference, the student's ``g`` minus Jacobi's, in its
own scale (for RGB, the channel where it is largest), each pixel a square at a whole
zoom. :func:`.check.jacobi_solve` draws it; the checker's own cases and the student's
answer as it has read it come in, so this module checks none (``UNCHECKED = True``).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from course.check.pictures import EXPECTED, GIVEN, figure_png
from course.i18n import _
from course.lessons.l08_poisson.mistakes import count_of, g_residual, jacobi_residuals

UNCHECKED = True  # see the module docstring

__all__ = ["sweep_picture"]

#: The figure's size in screen pixels (at 100 dpi), and the difference panel's largest side.
WIDTH, HEIGHT, PANEL = 660, 270, 150
#: The log scale reaches this far below the tolerance; a smaller residual (0, say) is drawn there.
DECADES_BELOW = 4


def sweep_picture(case: dict[str, Any], expected: Any, given: Any) -> bytes | None:
    """Jacobi's residual sweep by sweep with both stops, and the student's ``g`` minus Jacobi's.

    ``case`` holds ``g`` and ``tolerance``; ``expected`` is Jacobi's ``(g, sweeps)``,
    ``given`` the student's. None when ``given`` holds no count to draw.
    """
    want_g, want_count = expected
    try:
        g, sweeps = given
        g = np.asarray(g, dtype=float)
    except (TypeError, ValueError):
        return None
    count = count_of(sweeps)
    if count is None:
        return None
    figure = Figure(figsize=(WIDTH / 100, HEIGHT / 100), dpi=100)
    if count == want_count:
        title = _("both loops stop after {count} sweeps; g differs").format(count=count)
    else:
        title = _("Jacobi stops after {expected} sweeps, yours after {given}").format(
            expected=want_count, given=count
        )
    figure.suptitle(title, fontsize=10, y=1 - 6 / HEIGHT, va="top")
    same_shape = g.shape == want_g.shape
    _draw_stops(figure, case, want_count, count, g_residual(g) if same_shape else None)
    _draw_difference(figure, want_g, g)
    return figure_png(figure)


def _draw_stops(
    figure: Figure, case: dict[str, Any], want_count: int, count: int, theirs: float | None
) -> None:
    """Jacobi's residual before each sweep, the tolerance, and the two loops' stops."""
    axes = figure.add_axes((56 / WIDTH, 44 / HEIGHT, 300 / WIDTH, 176 / HEIGHT))
    last = 2 * want_count + 20  # past it, a count is told, not drawn: a fixed 8000 says little
    shown = 0 <= count <= last
    sweeps = max(want_count, count if shown else 0) + 2
    floor = case["tolerance"] / 10**DECADES_BELOW
    residuals = np.maximum(jacobi_residuals(case["g"], sweeps), floor)
    axes.semilogy(range(sweeps + 1), residuals, "o-", color=EXPECTED, markersize=3, lw=1.2)
    axes.axhline(case["tolerance"], color="0.4", ls="--", lw=1)
    axes.annotate(
        _("tolerance"),
        (0, case["tolerance"]),
        xytext=(2, 3),
        textcoords="offset points",
        ha="left",
        fontsize=7,
        color="0.3",
    )
    axes.axvline(
        want_count,
        color=EXPECTED,
        lw=1.5,
        label=_("Jacobi stops: {count}").format(count=want_count),
    )
    if shown:
        axes.axvline(
            count,
            color=GIVEN,
            ls="--",
            lw=1.5,
            label=_("your loop stops: {count}").format(count=count),
        )
        if theirs is not None:
            axes.plot(
                count,
                max(theirs, floor),
                "X",
                color=GIVEN,
                markersize=8,
                label=_("your g's residual: {residual:.2g}").format(residual=theirs),
            )
    else:
        axes.text(
            0.98,
            0.5,
            _("your loop: {count} sweeps,\noff this axis").format(count=count),
            transform=axes.transAxes,
            ha="right",
            fontsize=8,
            color=GIVEN,
        )
    lowest = min(float(residuals.min()), case["tolerance"], *(() if theirs is None else (theirs,)))
    axes.set_ylim(max(lowest, floor) / 3, max(float(residuals.max()), case["tolerance"]) * 4)
    axes.set_xlabel(_("sweeps"), fontsize=8)
    axes.set_title(_("Jacobi's residual before each sweep"), fontsize=8)
    axes.tick_params(labelsize=7)
    axes.xaxis.set_major_locator(MaxNLocator(integer=True))
    axes.legend(fontsize=7, loc="upper right")


def _draw_difference(figure: Figure, want_g: np.ndarray, g: np.ndarray) -> None:
    """The student's g minus Jacobi's at a whole zoom, in its own colour scale."""
    left, bottom, top = 420, 44, 220
    if g.shape != want_g.shape:
        figure.text(
            (left + 60) / WIDTH,
            (bottom + top) / 2 / HEIGHT,
            _("your g has shape {given},\nexpected {expected}").format(
                given=g.shape, expected=want_g.shape
            ),
            ha="center",
            fontsize=8,
        )
        return
    difference = g - want_g
    same = bool(np.allclose(g, want_g, atol=1e-12, rtol=0.0))
    title = _("your g is Jacobi's") if same else _("your g minus Jacobi's")
    if difference.ndim == 3 and not same:
        channel = int(np.unravel_index(np.abs(difference).argmax(), difference.shape)[2])
        difference = difference[..., channel]
        title = _("your g minus Jacobi's, channel {channel}").format(channel=channel)
    height, width = difference.shape
    zoom = max(1, min(24, PANEL // max(height, width)))
    side_w, side_h = width * zoom, height * zoom
    limit = max(float(np.abs(difference).max()), 1e-12)
    axes = figure.add_axes((left / WIDTH, (top - side_h) / HEIGHT, side_w / WIDTH, side_h / HEIGHT))
    shown = axes.imshow(difference, cmap="RdBu_r", vmin=-limit, vmax=limit, interpolation="nearest")
    axes.set_xticks([])
    axes.set_yticks([])
    axes.set_title(title, fontsize=8)
    if same:
        return
    bar = figure.add_axes(
        ((left + side_w + 8) / WIDTH, (top - side_h) / HEIGHT, 10 / WIDTH, side_h / HEIGHT)
    )
    # The scale written on each tick: no "1e-5" above the bar, where the title is.
    figure.colorbar(shown, cax=bar, ticks=[-limit, 0, limit], format="{x:.1e}")
    bar.tick_params(labelsize=7)
