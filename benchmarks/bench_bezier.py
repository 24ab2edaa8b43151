"""Curve evaluation against the compiled ``bezier`` package (dhermes/bezier).

Prints one line per measurement: the best of several runs of ours divided by
the best of the anchor's, ``bezier.Curve(nodes, degree).evaluate_multi(t)``
(Fortran, O(n) per parameter), measured in the same run, with the goal beside
it. Our output is (M, d) by the package's convention; the anchor's is (d, M).
"""

from __future__ import annotations

import time
from collections.abc import Callable

import bezier
import numpy as np

from course.bezier import bezier_bernstein, de_casteljau

GOALS = {"bezier_bernstein": 2.0, "de_casteljau": 4.0}


def best_time(function: Callable[[], object], repeats: int = 7) -> float:
    """The fastest of ``repeats`` runs, after one warm-up (the least noisy estimate)."""
    function()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    rng = np.random.default_rng(0)
    for degree in (3, 9):
        points = rng.uniform(0, 700, (degree + 1, 2))
        curve = bezier.Curve(np.asfortranarray(points.T), degree=degree)
        for count in (10**5, 10**6):
            t = np.linspace(0.0, 1.0, count)
            anchor = best_time(lambda t=t, curve=curve: curve.evaluate_multi(t))
            ours = {
                "bezier_bernstein": lambda t=t, p=points: bezier_bernstein(p, t),
                "de_casteljau": lambda t=t, p=points: de_casteljau(p, t),
            }
            for name, function in ours.items():
                ratio = best_time(function) / anchor
                verdict = "met" if ratio <= GOALS[name] else "NOT met"
                print(
                    f"{name} degree {degree}, 10^{round(np.log10(count))} t: "
                    f"{ratio:.2f}x bezier.Curve.evaluate_multi "
                    f"({anchor * 1e3:.2f} ms) (goal <= {GOALS[name]:g}x, {verdict})"
                )
            naive = best_time(lambda t=t, p=points: bezier_bernstein(p, t, method="naive"), 3)
            print(
                f"bezier_bernstein(method='naive') degree {degree}, "
                f"10^{round(np.log10(count))} t: {naive / anchor:.2f}x "
                f"bezier.Curve.evaluate_multi (readable form, no goal)"
            )


if __name__ == "__main__":
    main()
