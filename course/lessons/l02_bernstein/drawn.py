"""Lesson 02's graded cases: the families of the fixed cases, drawn per submission.

:func:`drawn_comb_cases` and :func:`drawn_naive_cases` draw the cases ``comb`` and
``naive_bezier`` are graded on, as :mod:`course.check.grading` asks. Unchecked: only the
grader calls them, with its own generator.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from course.curves.bezier import binomial
from course.curves.bezier_handouts import comb_recursive_calls
from course.lessons.l01_de_casteljau.drawn import draw_curve_cases

__all__ = ["drawn_comb_cases", "drawn_naive_cases"]

UNCHECKED = True  # the grader draws with its own generator; no student calls these


def drawn_comb_cases(rng: np.random.Generator, max_calls: int) -> list[dict[str, int]]:
    """Graded cases of :data:`COMB_CASES`' families, in their order, drawn from ``rng``.

    Rows 0 and 1 whole, (0, 0), (1, 0), (1, 1); inner entries of two small rows (m of 4 to 7);
    the ends of a row, (m, 0) and (m, m), m of 8 to 12; two with n > m (two m of 1 to 4); one
    where the handout's recursion makes more than twice ``max_calls`` calls, the checker's
    budget (m of 19 to 24); two past 32 bits and within 2^53 (m of 34 to 37, then 38 to
    45); one past 64 bits (m of 67 to 72); and one near C(100, 50) (m of 92 to 100),
    which only Pascal's rule computes in time. The big ones lie near the middle of their rows.
    """

    def middle(low: int, high: int, within: Callable[[int, int], bool]) -> tuple[int, int]:
        while True:
            m = int(rng.integers(low, high + 1))
            n = m // 2 + int(rng.integers(-3, 4))
            if within(m, n):
                return m, n

    small = [(int(m), int(rng.integers(1, m))) for m in rng.choice(range(4, 8), 2, replace=False)]
    ends = [(int(rng.integers(8, 13)), 0)]
    ends.append((int(rng.integers(8, 13)),) * 2)
    above = [
        (int(m), int(m + rng.integers(1, 6))) for m in rng.choice(range(1, 5), 2, replace=False)
    ]
    pairs = [
        (0, 0),
        (1, 0),
        (1, 1),
        *small,
        *ends,
        *above,
        middle(19, 24, lambda m, n: comb_recursive_calls(m, n) > 2 * max_calls),
        middle(34, 37, lambda m, n: 2**31 < binomial(m, n) < 2**53),
        middle(38, 45, lambda m, n: 2**31 < binomial(m, n) < 2**53),
        middle(67, 72, lambda m, n: binomial(m, n) > 2**64),
        middle(92, 100, lambda m, n: True),
    ]
    return [{"m": m, "n": n} for m, n in pairs]


def drawn_naive_cases(rng: np.random.Generator) -> list[dict[str, Any]]:
    """Graded cases of ``naive_bezier``, drawn from ``rng``: :func:`draw_curve_cases`' families
    for curves of 2 to 12 control points, then a curve of 39 to 43 control points across the
    700 x 700 window (C(38, 19) > 2^31 already), at a t in [0.15, 0.4) and at 0.5."""
    points = rng.uniform(0, 700, (int(rng.integers(39, 44)), 2)).round(1)
    high = [{"control_points": points, "t": t} for t in (rng.integers(150, 400) / 1000, 0.5)]
    return draw_curve_cases(rng, max_points=12) + high
