"""Lesson 03: Bresenham lines and filled triangles against scikit-image.

Each line is the best of several runs of ours divided by the best of the
anchor's, measured in the same run, with the goal beside it.
``skimage.draw.line`` and ``skimage.draw.polygon`` are compiled (Cython);
ours are numpy. The readable loop forms are timed too, without a goal.
"""

from __future__ import annotations

import numpy as np
from skimage.draw import line as skimage_line
from skimage.draw import polygon as skimage_polygon
from timing import best_times

from course.raster import line, triangle, triangle_coverage

GOAL = 3.0  # for line and triangle, the fast forms


def report(
    name: str, ours: float, anchor: float, anchor_name: str, goal: float | None = None
) -> None:
    ratio = ours / anchor
    verdict = f"goal <= {goal:g}x, {'met' if ratio <= goal else 'NOT met'}" if goal else "no goal"
    print(f"{name}: {ratio:.2f}x {anchor_name} ({anchor * 1e6:.1f} us) ({verdict})")


def main() -> None:
    # A 1000-pixel line in the first octant, from the lab's DrawLine.
    p0, p1 = (0, 0), (999, 700)
    assert len(line(p0, p1)) == 1000
    anchor, ours, loop = best_times(
        lambda: skimage_line(p0[1], p0[0], p1[1], p1[0]),
        lambda: line(p0, p1),
        lambda: line(p0, p1, method="loop"),
    )
    report("line 1000 px", ours, anchor, "skimage.draw.line", GOAL)
    report("line 1000 px, method='loop'", loop, anchor, "skimage.draw.line")

    # A triangle covering about half of a 512 x 512 canvas.
    shape = (512, 512)
    vertices = np.array([[0.3, 0.6], [511.4, 0.2], [0.8, 511.7]])
    pixels = triangle(*vertices, shape=shape)
    rows, columns = vertices[:, 1], vertices[:, 0]
    anchor_pixels = skimage_polygon(rows, columns, shape)
    print(
        f"triangle 512 x 512: {len(pixels)} pixels ({len(pixels) / 512**2:.0%} of the canvas); "
        f"skimage.draw.polygon gives {len(anchor_pixels[0])}"
    )
    anchor, ours, loop, coverage = best_times(
        lambda: skimage_polygon(rows, columns, shape),
        lambda: triangle(*vertices, shape=shape),
        lambda: triangle(*vertices, shape=shape, method="loop"),
        lambda: triangle_coverage(*vertices, shape, 4),
        rounds=3,
    )
    name = "triangle half of 512 x 512"
    report(name, ours, anchor, "skimage.draw.polygon", GOAL)
    report(f"{name}, method='loop'", loop, anchor, "skimage.draw.polygon")
    report(f"triangle_coverage {name[9:]}, rate 4", coverage, anchor, "skimage.draw.polygon")


if __name__ == "__main__":
    main()
