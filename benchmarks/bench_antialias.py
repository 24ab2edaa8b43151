"""Lesson 05: drawing seed 000's curve on 700 x 700, against matplotlib's Agg.

The anchor is a new ``RendererAgg`` of 700 x 700 at 72 dpi and one
``draw_path`` of the cubic (``CURVE4`` codes, width 1, round caps): Agg's
whole pipeline from a Bézier to a fresh canvas, compiled C++. Ours is
``course.antialias.render``: sampling (or flattening), splatting (or
coverage), painting into a fresh float image. Each line is the fastest batch
of ours over the fastest of the anchor, the batches alternating so that the
load of a shared machine falls on both alike.
"""

from __future__ import annotations

from collections.abc import Callable

from timing import best_times

from course.antialias import SPLATS, STROKES, arc_length_step, render
from course.coverage import agg_draw, agg_path
from course.images import SEED_000_CUBIC

POINTS = SEED_000_CUBIC
SHAPE = (700, 700)
GOALS = {"splat": 3.0, "stroke": 10.0}


def main() -> None:
    path = agg_path(POINTS)

    def agg() -> object:
        return agg_draw(path, SHAPE, 1.0)

    cases: list[tuple[str, Callable[[], object], float | None]] = []
    for method in SPLATS:
        cases.append((method, lambda m=method: render(POINTS, SHAPE, m), GOALS["splat"]))
    default_samples = round(1 / arc_length_step(POINTS)) + 1
    for method in ("nearest_truncate", "bilinear_centres"):
        cases.append(
            (
                f"{method} + arc length, step 0.001",
                lambda m=method: render(POINTS, SHAPE, m, step=0.001, weighting="arc_length"),
                GOALS["splat"],
            )
        )
        cases.append(
            (
                f"{method} + arc length, default step ({default_samples} samples, not 1001)",
                lambda m=method: render(POINTS, SHAPE, m, weighting="arc_length"),
                None,
            )
        )
    for method in STROKES:
        cases.append((method, lambda m=method: render(POINTS, SHAPE, m), GOALS["stroke"]))

    for name, function, goal in cases:
        anchor, ours = best_times(agg, function)
        ratio = ours / anchor
        verdict = (
            f"goal <= {goal:g}x, {'met' if ratio <= goal else 'NOT met'}" if goal else "no goal"
        )
        print(
            f"{name} 700x700: {ratio:.1f}x RendererAgg.draw_path "
            f"({ours * 1e3:.2f} ms vs {anchor * 1e3:.2f} ms) ({verdict})"
        )


if __name__ == "__main__":
    main()
