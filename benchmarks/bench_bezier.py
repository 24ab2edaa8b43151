"""Lessons 01-02: curve evaluation and the de Casteljau app.

Curves: the best of several runs of ours divided by the best of the anchor's,
``bezier.Curve(nodes, degree).evaluate_multi(t)`` of the compiled ``bezier``
package (Fortran, O(n) per parameter), measured in the same run, with the goal
beside it. Our output is (M, d) by the design's convention; the anchor's is
(d, M).

The app: the median time of one t-slider step of ``DeCasteljauApp`` (500 x 500
px, update and PNG included) against rebuilding the figure on every step, as
``ipywidgets.interact`` with the inline backend does (new pyplot figure,
``savefig(..., bbox_inches="tight")``).

Flattening (lessons 03-05): ``flatten``'s segment count and error on real
curves, the quadratics of DejaVu Sans glyphs and the cubics of matplotlib's
SVG icons (:mod:`outlines`), at 0.1, 0.25 and 1 px, against Levien's count
(the best achievable, written out from kurbo one curve at a time) and the
best uniform t step of each curve. Errors are measured, not estimated: the
largest distance from 256 points of each piece of the curve to its chord.
"""

from __future__ import annotations

import io
import time
from collections.abc import Callable

import bezier
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from outlines import (
    fewest_uniform_segments,
    glyph_quadratics,
    icon_cubics,
    levien_segments,
    piece_errors,
)
from timing import best_time, best_times

from course.curves.bezier import bezier_bernstein, de_casteljau, de_casteljau_levels
from course.curves.flattening import flatten
from course.lessons.l01_de_casteljau.apps import DeCasteljauApp

GOALS = {"bezier_bernstein": 2.0, "de_casteljau": 4.0}
FLATTEN_TOLERANCES = (0.1, 0.25, 1.0)
# flatten's total segment count over Levien's, at most.
FLATTEN_GOAL = 1.15


def main() -> None:
    rng = np.random.default_rng(0)
    for degree in (3, 9):
        points = rng.uniform(0, 700, (degree + 1, 2))
        curve = bezier.Curve(np.asfortranarray(points.T), degree=degree)
        for count in (10**5, 10**6):
            t = np.linspace(0.0, 1.0, count)
            # Anchor and ours take turns, so that load falls on all alike.
            anchor, *ours = best_times(
                lambda t=t, curve=curve: curve.evaluate_multi(t),
                lambda t=t, p=points: bezier_bernstein(p, t),
                lambda t=t, p=points: de_casteljau(p, t),
            )
            for name, seconds in zip(GOALS, ours, strict=True):
                ratio = seconds / anchor
                verdict = "met" if ratio <= GOALS[name] else "NOT met"
                print(
                    f"{name} degree {degree}, 10^{round(np.log10(count))} t: "
                    f"{ratio:.2f}x bezier.Curve.evaluate_multi "
                    f"({anchor * 1e3:.2f} ms) (goal <= {GOALS[name]:g}x, {verdict})"
                )
            loop = best_time(lambda t=t, p=points: bezier_bernstein(p, t, method="loop"), 3)
            print(
                f"bezier_bernstein(method='loop') degree {degree}, "
                f"10^{round(np.log10(count))} t: {loop / anchor:.2f}x "
                f"bezier.Curve.evaluate_multi (readable form, no goal)"
            )


def median_time(function: Callable[[], object], values: np.ndarray) -> float:
    times = []
    for value in values:
        start = time.perf_counter()
        function(value)
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def rebuild_picture(points: np.ndarray, t: float) -> bytes:
    """What an ``interact`` callback does: a new figure per step, shown as PNG."""
    figure, axes = plt.subplots(figsize=(5, 5), dpi=100)
    axes.invert_yaxis()
    curve = de_casteljau(points, np.linspace(0, 1, 201))
    axes.plot(curve[:, 0], curve[:, 1], color="0.8")
    for level in de_casteljau_levels(points, t)[:-1]:
        axes.plot(level[:, 0], level[:, 1], "o-")
    traced = de_casteljau(points, np.linspace(0, t, 201))
    axes.plot(traced[:, 0], traced[:, 1], color="crimson", linewidth=2.5)
    point = de_casteljau(points, t)
    axes.plot([point[0]], [point[1]], "o", color="crimson", markersize=9)
    axes.set_title(f"t = {t:.2f}: B(t) = ({point[0]:.1f}, {point[1]:.1f})")
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", bbox_inches="tight")
    plt.close(figure)
    return buffer.getvalue()


def bench_app() -> None:
    steps = np.linspace(0.0, 1.0, 41)
    for count in (4, 10):
        app = DeCasteljauApp(size=500)
        app.controls["count"].value = count
        app.refresh()

        def step(t: float, app: DeCasteljauApp = app) -> None:
            app.controls["t"].value = float(t)

        ours = median_time(step, steps)
        points = app.points
        rebuild = median_time(lambda t, points=points: rebuild_picture(points, t), steps[::2])
        verdict = "met" if ours <= 0.030 and rebuild / ours >= 3 else "NOT met"
        print(
            f"DeCasteljauApp t step, {count} points, 500x500 px: {ours * 1e3:.1f} ms median "
            f"(goal <= 30 ms); {rebuild / ours:.1f}x faster than rebuilding per step "
            f"({rebuild * 1e3:.1f} ms) (goal >= 3x, {verdict})"
        )


def verdict(met: bool) -> str:
    return "met" if met else "NOT met"


def bench_flatten() -> None:
    """flatten against Levien's count and the best uniform step, curve by curve."""
    curve_sets = {
        "DejaVu Sans glyph quadratics (200 px)": glyph_quadratics(),
        "matplotlib icon cubics (400 px)": icon_cubics(),
    }
    totals = {"ours": 0, "levien": 0, "uniform": 0, "curves": 0, "more": 0, "worst": 0.0}
    for name, curves in curve_sets.items():
        for tolerance in FLATTEN_TOLERANCES:
            ours = levien = uniform = more = 0
            worst = 0.0
            for points in curves:
                vertices, t = flatten(points, tolerance, return_parameters=True)
                best_uniform = fewest_uniform_segments(points, tolerance)
                ours += len(t) - 1
                levien += levien_segments(points, tolerance)
                uniform += best_uniform
                more += len(t) - 1 > best_uniform
                worst = max(worst, float(piece_errors(points, t, vertices).max()) / tolerance)
            print(
                f"flatten, {len(curves)} {name}, tolerance {tolerance:g} px: {ours} segments, "
                f"{ours / levien:.3f}x Levien's {levien} (goal <= {FLATTEN_GOAL:g}x, "
                f"{verdict(ours <= FLATTEN_GOAL * levien)}), {ours / uniform:.3f}x the best "
                f"uniform steps' {uniform}; more than the best uniform step on {more} curves "
                f"(goal 0, {verdict(more == 0)}); worst error {worst:.5f} x tolerance "
                f"(goal <= 1, {verdict(worst <= 1)})"
            )
            for key, value in zip(
                ("ours", "levien", "uniform", "curves", "more"),
                (ours, levien, uniform, len(curves), more),
                strict=True,
            ):
                totals[key] += value
            totals["worst"] = max(totals["worst"], worst)
    ours, levien, uniform, more, worst = (
        totals[key] for key in ("ours", "levien", "uniform", "more", "worst")
    )
    met = ours <= FLATTEN_GOAL * levien and more == 0 and worst <= 1
    print(
        f"flatten in total ({totals['curves']} curve-tolerance pairs): {ours} segments, "
        f"{ours / levien:.3f}x Levien's {levien}, {ours / uniform:.3f}x the best uniform "
        f"steps' {uniform}; more than the best uniform step on {more}; worst error "
        f"{worst:.5f} x tolerance (goals <= {FLATTEN_GOAL:g}x, never more, <= 1: {verdict(met)})"
    )


if __name__ == "__main__":
    main()
    bench_flatten()
    bench_app()
