"""Timing for the benchmarks: the fastest of interleaved batches.

A ratio against an anchor means something only when both are timed alike.
Each function runs in batches of about 20 ms; the batches of all functions
take turns, round after round, so that load from other processes falls on
all of them alike; and the fastest batch counts, the least disturbed
estimate of what a call costs.
"""

from __future__ import annotations

import time
from collections.abc import Callable

BATCH_SECONDS = 0.02


def batch_size(function: Callable[[], object]) -> int:
    """Calls per batch for batches of about 20 ms, from one timed warm-up call."""
    start = time.perf_counter()
    function()
    return max(1, int(BATCH_SECONDS / max(time.perf_counter() - start, 1e-7)))


def best_times(*functions: Callable[[], object], rounds: int = 7) -> list[float]:
    """Seconds per call of each function: the fastest of its batches, interleaved."""
    sizes = [batch_size(function) for function in functions]
    best = [float("inf")] * len(functions)
    for _ in range(rounds):
        for index, (function, number) in enumerate(zip(functions, sizes, strict=True)):
            start = time.perf_counter()
            for _ in range(number):
                function()
            best[index] = min(best[index], (time.perf_counter() - start) / number)
    return best


def best_time(function: Callable[[], object], rounds: int = 7) -> float:
    """Seconds per call of one function: the fastest of its batches."""
    return best_times(function, rounds=rounds)[0]


def named_best_times(
    functions: dict[str, Callable[[], object]], rounds: int = 7
) -> dict[str, float]:
    """:func:`best_times` for functions given by name."""
    return dict(zip(functions, best_times(*functions.values(), rounds=rounds), strict=True))
