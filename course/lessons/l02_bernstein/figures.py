"""Lesson 02's still pictures: end tangents, the hodograph, the binomials' cost, accuracy.

Each function draws one picture of the lesson and returns it as a
:class:`~course.widgets.picture.Still`, with a caption that states the
numbers the picture shows, so the notebook holds no plotting code.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from course import limits
from course._validate import as_figure_curve, as_int
from course.curves.bezier import binomial, de_casteljau, derivative
from course.curves.bezier_accuracy import accuracy_by_degree
from course.curves.bezier_handouts import comb_recursive_calls
from course.i18n import N_, _
from course.lessons.printed import degree_numeral
from course.widgets.picture import Still, rounding_level

__all__ = [
    "accuracy_figure",
    "comb_calls_figure",
    "hodograph_figure",
    "pascal_figure",
    "tangents_figure",
]

BLUE, VERMILLION, GREEN, PURPLE = "#0072B2", "#D55E00", "#009E73", "#CC79A7"


def _label_points(axes: Any, points: np.ndarray, name: str = "P") -> None:
    for index, point in enumerate(points):
        axes.annotate(
            f"{name}{index}", point, xytext=(5, 5), textcoords="offset points", fontsize=8
        )


def _arrow(axes: Any, start: Any, vector: Any, colour: str, label: str | None = None) -> None:
    axes.annotate(
        "",
        xy=tuple(np.add(start, vector)),
        xytext=tuple(start),
        arrowprops={"arrowstyle": "-|>", "color": colour, "linewidth": 2},
    )
    if label:
        axes.plot([], [], color=colour, linewidth=2, label=label)


def tangents_figure(points: Any) -> Still:
    """A curve leaves P0 along P0P1 and arrives at Pn along Pn-1Pn: B'(0), B'(1) drawn.

    Each tangent is drawn at a third of its length (``B'(t) / 3`` for a cubic
    is the edge itself), so it lies on the polygon's first or last edge.

    Examples
    --------
    >>> tangents_figure([[90, 610], [170, 130], [540, 80], [620, 470]])
    B'(0) = (240, -1440) = 3 (P1 - P0); B'(1) = (240, 1170) = 3 (P3 - P2)
    """
    control = as_figure_curve(points)
    degree = len(control) - 1
    hodograph = derivative(control)
    start, end = de_casteljau(hodograph, 0.0), de_casteljau(hodograph, 1.0)
    curve = de_casteljau(control, np.linspace(0.0, 1.0, 201))
    figure = Figure(figsize=(5.0, 4.4), dpi=100)
    axes = figure.add_subplot()
    axes.plot(
        *control.T, "o--", color="0.55", linewidth=1, markersize=6, label=_("control polygon")
    )
    _label_points(axes, control)
    axes.plot(*curve.T, color="0.15", linewidth=2, label="B(t)")
    _arrow(axes, control[0], start / degree, BLUE, f"B'(0) / {degree}")
    _arrow(axes, control[-1] - end / degree, end / degree, VERMILLION, f"B'(1) / {degree}")
    axes.set_aspect("equal")
    axes.invert_yaxis()
    axes.margins(0.12)
    axes.legend(fontsize=8, loc="lower center")
    axes.tick_params(labelsize=7)
    axes.set_title(_("the end tangents lie along the first and last edges"), fontsize=9)
    figure.tight_layout()

    def vector(value: np.ndarray) -> str:
        return "(" + ", ".join(f"{v:g}" for v in value) + ")"

    # Formulas only: the joiner is the language's (Chinese ；).
    caption = _("; ").join(
        (
            f"B'(0) = {vector(start)} = {degree} (P1 - P0)",
            f"B'(1) = {vector(end)} = {degree} (P{degree} - P{degree - 1})",
        )
    )
    return Still.of(figure, caption)


def hodograph_figure(points: Any, ts: Sequence[float] = (0.0, 0.25, 0.5, 0.75, 1.0)) -> Still:
    """Velocities along the curve, and the same vectors as points of the hodograph.

    Left, the curve with its velocity B'(t) at each t of ``ts`` (scaled to
    fit); right, the derivative's own Bézier curve, of degree n - 1 with the
    control points ``n (P[i+1] - P[i])``, on which each velocity is a point.

    The speed |B'(t)| is the hodograph's distance from the origin: the
    caption names where the curve is slowest (the hodograph's point nearest
    the origin, joined to it by a dotted line) and where it is fastest.

    Examples
    --------
    >>> still = hodograph_figure([[90, 610], [170, 130], [540, 80], [620, 470]])
    >>> print(still.caption.replace("; ", "\\n"))
    the hodograph's control points n (P[i+1] - P[i]): (240, -1440), (1110, -150), (240, 1170)
    slowest at t = 0.582, 667 px per unit of t
    fastest at t = 0, 1460
    """
    control = as_figure_curve(points)
    if np.size(ts) > limits.MAX_FIGURE_POINTS:  # one arrow and label each
        raise ValueError(
            _("ts must hold at most {most} values; got {size}").format(
                most=limits.MAX_FIGURE_POINTS, size=np.size(ts)
            )
        )
    hodograph = derivative(control)
    velocities = de_casteljau(hodograph, np.asarray(ts, dtype=float))
    curve = de_casteljau(control, np.linspace(0.0, 1.0, 201))
    trace = de_casteljau(hodograph, np.linspace(0.0, 1.0, 201))
    figure = Figure(figsize=(9.0, 4.2), dpi=100)
    left, right = figure.add_subplot(1, 2, 1), figure.add_subplot(1, 2, 2)
    left.plot(*curve.T, color="0.15", linewidth=2, label="B(t)")
    left.plot(*control.T, "o--", color="0.6", linewidth=1, markersize=5)
    _label_points(left, control)
    scale = 0.15 * np.ptp(control, axis=0).max() / np.abs(velocities).max()
    colours = [BLUE, GREEN, PURPLE, VERMILLION, "#E69F00"]
    for index, (t, velocity) in enumerate(zip(ts, velocities, strict=True)):
        colour = colours[index % len(colours)]
        _arrow(left, de_casteljau(control, t), velocity * scale, colour, f"t = {t:g}")
        right.plot(*velocity, "o", color=colour, markersize=8)
        _arrow(right, (0.0, 0.0), velocity, colour)
        right.annotate(
            f"t = {t:g}", velocity, xytext=(7, -10), textcoords="offset points", fontsize=7
        )
    left.set_title(_("B(t) and its velocity B'(t) (scaled)"), fontsize=9)
    right.plot(*trace.T, color="0.15", linewidth=1.5, label="B'(t)")
    right.plot(
        *hodograph.T, "s--", color="0.55", linewidth=1, markersize=5, label=_("its control points")
    )
    _label_points(right, hodograph, "D")
    right.plot(0, 0, "+", color="0.2", markersize=12)
    right.annotate(
        _("origin"), (0, 0), xytext=(-3, -16), textcoords="offset points", fontsize=7, ha="left"
    )
    fine = np.linspace(0.0, 1.0, 1001)
    speeds = np.hypot(*de_casteljau(hodograph, fine).T)
    slowest, fastest = int(np.argmin(speeds)), int(np.argmax(speeds))
    nearest = de_casteljau(hodograph, fine[slowest])
    right.plot(
        [0, nearest[0]],
        [0, nearest[1]],
        ":",
        color="0.2",
        linewidth=1.2,
        label=_("nearest the origin: slowest"),
    )
    right.set_title(
        _("the hodograph: a Bézier curve of degree {degree}").format(
            degree=degree_numeral(len(hodograph) - 1)
        ),
        fontsize=9,
    )
    for axes in (left, right):
        axes.set_aspect("equal")
        axes.invert_yaxis()
        axes.margins(0.1)
        axes.tick_params(labelsize=7)
    left.legend(fontsize=7, loc="lower center")
    right.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    figure.tight_layout()
    values = ", ".join("(" + ", ".join(f"{v:g}" for v in point) + ")" for point in hodograph)
    caption = _(
        "the hodograph's control points n (P[i+1] - P[i]): {values}; "
        "slowest at t = {slow_t:g}, {slow:.0f} px per unit of t; "
        "fastest at t = {fast_t:g}, {fast:.0f}"
    ).format(
        values=values,
        slow_t=fine[slowest],
        slow=speeds[slowest],
        fast_t=fine[fastest],
        fast=speeds[fastest],
    )
    return Still.of(figure, caption)


def pascal_figure(rows: int = 7, entry: tuple[int, int] = (5, 2)) -> Still:
    """Pascal's triangle to row ``rows``, one entry and the two it is the sum of marked.

    Examples
    --------
    >>> pascal_figure()
    C(5, 2) = 10 = C(4, 2) + C(4, 1) = 6 + 4
    """
    rows = as_int(rows, "rows", minimum=0, maximum=30)
    m, n = (as_int(v, f"entry[{i}]", minimum=0, maximum=rows) for i, v in enumerate(_pair(entry)))
    figure = Figure(figsize=(5.2, 0.42 * (rows + 1) + 0.3), dpi=100)
    axes = figure.add_axes((0.0, 0.0, 1.0, 1.0))
    parents = {(m - 1, n), (m - 1, n - 1)}
    for row in range(rows + 1):
        for column in range(row + 1):
            value = binomial(row, column)
            colour = (
                VERMILLION
                if (row, column) == entry
                else BLUE
                if (row, column) in parents
                else "0.2"
            )
            weight = "bold" if colour != "0.2" else "normal"
            axes.text(
                column - row / 2,
                -row,
                str(value),
                ha="center",
                va="center",
                fontsize=10,
                color=colour,
                weight=weight,
            )
        axes.text(
            -rows / 2 - 1.2,
            -row,
            _("row {row}").format(row=row),
            ha="right",
            va="center",
            fontsize=8,
            color="0.5",
        )
    for parent in parents:
        axes.annotate(
            "",
            xy=(n - m / 2, -m + 0.25),
            xytext=(parent[1] - parent[0] / 2, -parent[0] - 0.25),
            arrowprops={"arrowstyle": "->", "color": BLUE},
        )
    axes.set_xlim(-rows / 2 - 2.4, rows / 2 + 0.8)
    axes.set_ylim(-rows - 0.7, 0.7)
    axes.set_axis_off()
    values = [binomial(*entry), binomial(m - 1, n), binomial(m - 1, n - 1)]
    caption = (
        f"C({m}, {n}) = {values[0]} = C({m - 1}, {n}) + C({m - 1}, {n - 1}) "
        f"= {values[1]} + {values[2]}"
    )
    return Still.of(figure, caption)


def comb_calls_figure(sizes: Sequence[int] = tuple(range(4, 41, 2))) -> Still:
    """Calls the handout's recursive ``comb(m, m // 2)`` makes, against 2^m.

    Examples
    --------
    >>> comb_calls_figure((10, 20))
    comb(20, 10) makes 184,755 calls; 2^20 = 1,048,576
    """
    sizes = [as_int(m, "sizes", minimum=2, maximum=400) for m in _as_list(sizes, "sizes")]
    calls = [comb_recursive_calls(m, m // 2) for m in sizes]
    figure = Figure(figsize=(5.2, 3.4), dpi=100)
    axes = figure.add_subplot()
    axes.semilogy(sizes, calls, "o-", color=VERMILLION, label=_("calls of comb(m, m/2)"))
    axes.semilogy(sizes, [2.0**m for m in sizes], "--", color="0.5", label="2^m")
    axes.set_xlabel("m")
    axes.set_ylabel(_("calls"))
    axes.set_title(
        _("the report's recursive comb: its calls grow almost as fast as 2^m"), fontsize=9
    )
    axes.legend(fontsize=8)
    figure.tight_layout()
    last = sizes[-1]
    caption = _("comb({last}, {half}) makes {calls:,} calls; 2^{last} = {power:,}").format(
        last=last, half=last // 2, calls=calls[-1], power=2**last
    )
    return Still.of(figure, caption)


_LABELS = {
    "de_casteljau": (N_("de Casteljau"), BLUE, "o-"),
    "bernstein_loop": (N_("Bernstein, the handout's sum"), VERMILLION, "s--"),
    "bernstein_horner": (N_("Bernstein, Horner (library default)"), GREEN, "^:"),
    "power": (N_("power basis"), PURPLE, "D-"),
}


def accuracy_figure(degrees: Sequence[int] = tuple(range(1, 61)), samples: int = 17) -> Still:
    """Worst error of four evaluations of the same curve, against the exact value, by degree.

    Random control points in [-1, 1]^2 for each degree (seeded), each way
    evaluated at ``samples`` parameters and compared with
    :func:`course.curves.bezier_accuracy.bezier_exact`; errors relative to the
    polygon's size, exact results drawn at the bottom.

    Examples
    --------
    >>> accuracy_figure(range(1, 31), samples=5).caption.split("; ")[-1]
    'power basis above 1e-6 from degree 25'
    """
    errors = accuracy_by_degree(degrees, samples=samples, rng=np.random.default_rng(2))
    floor = 1e-18
    figure = Figure(figsize=(7.0, 3.8), dpi=100)
    axes = figure.add_subplot()
    for method, (label, colour, style) in _LABELS.items():
        axes.semilogy(
            errors["degree"],
            np.maximum(errors[method], floor),
            style,
            color=colour,
            markersize=3,
            label=_(label),
        )
    axes.axhline(2.0**-52, color="0.6", linestyle=":", label=_("float64 epsilon"))
    axes.set_xlabel(_("degree n"))
    axes.set_ylabel(_("worst error / polygon size"))
    axes.set_ylim(floor / 2, 1e12)
    axes.legend(fontsize=7)
    figure.tight_layout()
    worst = {method: float(errors[method].max()) for method in _LABELS}
    power = errors["power"]
    parts = [
        _("{method} worst {error}").format(
            method=_(_LABELS[m][0]), error=rounding_level(worst[m], spec=".0e")
        )
        for m in ("de_casteljau", "bernstein_loop")
    ]
    if (power > 1e-6).any():
        parts.append(
            _("power basis above 1e-6 from degree {degree}").format(
                degree=degree_numeral(int(errors["degree"][np.argmax(power > 1e-6)]))
            )
        )
    if (power > 1).any():
        parts.append(
            _("above 1 from degree {degree}").format(
                degree=degree_numeral(int(errors["degree"][np.argmax(power > 1)]))
            )
        )
    return Still.of(figure, _("; ").join(parts))


def _as_list(values: Any, name: str) -> list[Any]:
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        raise TypeError(
            _("{name} must be a sequence of integers; got {values_type}").format(
                name=name, values_type=type(values).__name__
            )
        )
    listed = list(values)
    if not listed:
        raise ValueError(_("{name} must not be empty").format(name=name))
    return listed


def _pair(entry: Any) -> list[Any]:
    listed = _as_list(entry, "entry")
    if len(listed) != 2:
        raise ValueError(
            _("entry must be a pair (row, column); got {entry}").format(entry=repr(entry))
        )
    return listed
