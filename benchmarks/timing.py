"""Timing for the benchmarks: the fastest of interleaved batches.

A ratio against an anchor means something only when both are timed alike.
Each function runs in batches of about 20 ms; the batches of all functions
take turns, round after round, so that load from other processes falls on
all of them alike; and the fastest batch counts, the least disturbed
estimate of what a call costs.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

BATCH_SECONDS = 0.02


def batch_size(function: Callable[[], object], seconds: float = BATCH_SECONDS) -> int:
    """Calls per batch for batches of about ``seconds``, from one timed warm-up call."""
    start = time.perf_counter()
    function()
    return max(1, int(seconds / max(time.perf_counter() - start, 1e-7)))


def best_times(
    *functions: Callable[[], object], rounds: int = 7, batch_seconds: float = BATCH_SECONDS
) -> list[float]:
    """Seconds per call of each function: the fastest of its batches, interleaved.

    Under load, give batches that span many of the scheduler's time slices
    (``batch_seconds`` of a few tenths): a batch shorter than a slice can run
    undisturbed, one longer cannot, and the fastest of short batches would
    then favour the quicker function.
    """
    sizes = [batch_size(function, batch_seconds) for function in functions]
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


# Load as a student's laptop has it: a browser beside the kernel keeps the cores busy.
BUSY_PROCESSES = 2

# A busy process: a tight Python loop, which stops by itself once its parent is
# gone, so that not even a killed benchmark leaves it running.
BUSY_LOOP = """
import os, sys
parent = int(sys.argv[1])
while os.getppid() == parent:
    for _ in range(200_000):
        pass
"""


@contextmanager
def busy_processes(count: int = BUSY_PROCESSES) -> Iterator[list[subprocess.Popen]]:
    """``count`` processes keeping the cores busy for the duration of the block."""
    started = []
    try:
        for _ in range(count):
            started.append(
                subprocess.Popen(
                    [sys.executable, "-c", BUSY_LOOP, str(os.getpid())],
                    stdin=subprocess.DEVNULL,
                    stdout=subprocess.DEVNULL,
                    stderr=subprocess.DEVNULL,
                )
            )
        time.sleep(1.0)  # long enough for them to start and for the scheduler to see them
        yield started
    finally:
        for process in started:
            process.terminate()
        for process in started:
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
