"""Lesson 02's app: the Bernstein basis polynomials of one degree, and their values at t.

Every B_{i,n} is drawn on [0, 1] in its own colour and named at its peak,
with a marker at its value at t; the dashed line is their sum, which is 1 everywhere (partition of
unity). The bar chart beside shows the weights at t that the curve gives its
control points.
"""

from __future__ import annotations

import ipywidgets as widgets
import matplotlib
import numpy as np

from course import limits
from course._validate import as_int, as_shape, as_unit
from course.curves.bezier import bernstein_basis
from course.i18n import _
from course.widgets.base import SliderApp

__all__ = ["BernsteinBasisApp"]

MAX_DEGREE = 20
_SAMPLES = np.linspace(0.0, 1.0, 201)


class BernsteinBasisApp(SliderApp):
    """The degree-n Bernstein basis with a marker at t; controls ``degree`` and ``t``."""

    def __init__(
        self, degree: int = 3, t: float = 0.3, shape: tuple[int, int] = (350, 700)
    ) -> None:
        degree = as_int(degree, "degree", minimum=0, maximum=MAX_DEGREE)
        t = as_unit(t, "t")
        shape = as_shape(shape, max_pixels=limits.MAX_FIGURE_PIXELS)
        controls = {
            "degree": widgets.IntSlider(
                value=degree, min=0, max=MAX_DEGREE, description=_("degree n")
            ),
            "t": widgets.FloatSlider(value=t, min=0.0, max=1.0, step=0.01, description="t"),
        }
        super().__init__(controls, shape)
        self.axes = self.figure.add_axes((0.07, 0.12, 0.6, 0.78))
        self.bars_axes = self.figure.add_axes((0.74, 0.12, 0.24, 0.78))
        self.axes.set_xlim(0, 1)
        self.axes.set_ylim(-0.02, 1.22)
        self.axes.set_xlabel("t")
        self.bars_axes.set_ylim(0, 1.0)
        self.bars_axes.set_xlabel("i")
        self.bars_axes.set_title(_("weights $B_{i,n}(t)$ at t"), fontsize=9)
        self.basis_lines = [self.axes.plot([], [], linewidth=1.5)[0] for _ in range(MAX_DEGREE + 1)]
        # Each curve named at its peak, in its colour: the key to the colours, bars included.
        self.curve_labels = [
            self.axes.text(0, 0, "", ha="center", va="bottom", fontsize=9)
            for _ in range(MAX_DEGREE + 1)
        ]
        (self.sum_line,) = self.axes.plot([], [], "k--", linewidth=1, label=_("sum of the weights"))
        self.t_line = self.axes.axvline(t, color="crimson", linewidth=1)
        (self.markers,) = self.axes.plot(
            [], [], "o", color="crimson", markersize=4, label=_("the weights at t")
        )
        self.axes.legend(
            handles=[self.sum_line, self.markers],
            loc="upper center",
            ncols=2,
            fontsize=8,
            frameon=False,
        )
        self.bars = self.bars_axes.bar(np.arange(MAX_DEGREE + 1), np.zeros(MAX_DEGREE + 1))
        self.title = self.axes.set_title("", fontsize=10)

    def update(self) -> None:
        degree, t = int(self.value("degree")), float(self.value("t"))
        curves = bernstein_basis(degree, _SAMPLES)
        colors = matplotlib.colormaps["viridis"](np.linspace(0.0, 0.9, degree + 1))
        for i, line in enumerate(self.basis_lines):
            if i <= degree:
                line.set_data(_SAMPLES, curves[:, i])
                line.set_color(colors[i])
            else:
                line.set_data([], [])
        # Every curve named up to degree 8; beyond, the ends and every fifth, to stay legible.
        named = set(range(degree + 1)) if degree <= 8 else {0, degree, *range(0, degree, 5)}
        peaks = bernstein_basis(degree, np.arange(degree + 1) / max(degree, 1))
        for i, label in enumerate(self.curve_labels):
            if i in named:
                peak = i / degree if degree else 0.0
                label.set_position((min(max(peak, 0.03), 0.97), peaks[i, i] + 0.01))
                label.set_text(f"$B_{{{i},{degree}}}$")
                label.set_color(colors[i])
            else:
                label.set_text("")
        self.sum_line.set_data(_SAMPLES, curves.sum(axis=1))
        weights = bernstein_basis(degree, t)[0]
        self.t_line.set_xdata([t, t])
        self.markers.set_data(np.full(degree + 1, t), weights)
        for i, bar in enumerate(self.bars):
            bar.set_height(weights[i] if i <= degree else 0.0)
            bar.set_color(colors[min(i, degree)])
        self.bars_axes.set_xlim(-0.6, degree + 0.6)
        step = 1 if degree <= 8 else 2 if degree <= 12 else 5
        self.bars_axes.set_xticks(range(0, degree + 1, step))
        self.title.set_text(
            _("n = {degree}, t = {t:.2f}: weights sum to {total:.12f}").format(
                degree=degree, t=t, total=weights.sum()
            )
        )
