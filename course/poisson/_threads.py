"""How many threads the solvers' BLAS and FFT calls may use: no more than there are idle cores.

numpy's and scipy's BLAS (OpenBLAS) start one thread per core for a matrix
product or a Cholesky factorisation. On an idle machine that helps a little at
the sizes the lessons solve (matrices of a few hundred rows); when other
processes keep the cores busy (a browser beside the kernel, a test run, a
second kernel) the threads wait on each other at every synchronisation, and the
same product takes several times longer: 6x and 22x the quiet time in the issue
that added this module. So every solver runs inside :func:`limited_threads`,
which lowers the BLAS thread count (with threadpoolctl) and scipy.fft's worker
count to :func:`threads_to_use`: one, plus one for each core that the load
leaves idle beside the caller's own. It only ever lowers them: a limit the
caller has set (``OPENBLAS_NUM_THREADS=1``, ``threadpoolctl``,
``scipy.fft.set_workers``) stays in force.

BLAS's thread count is one setting for the whole process, so the limit is too.
If two threads of the caller solved at once, one could restore the limit while
the other still relied on it, or record the other's limit as the one to
restore and so leave BLAS limited for good; threadpoolctl also lets only one
thread at a time change OpenBLAS's setting (the others' calls do nothing). So
limited blocks take turns: a second thread waits for the first to leave. An
exact solve is a few milliseconds, and two at once would only compete for the
same cores. A limit that another thread of the caller holds with threadpoolctl
stays in force: threadpoolctl ignores ours then.

The thread count changes how OpenBLAS splits a product, and so the order of
some sums: a solve on two threads may differ from one on one thread in its
last bits (at most 1e-12 on the lessons' problems, which
``tests/test__threads.py`` checks). Nothing printed or stored may depend on
those bits: the lessons print such differences and residuals as a bound
(:func:`course.widgets.picture.rounding_level`), and the same test checks
that what lesson 08 prints is the same on one thread and on two.
"""

from __future__ import annotations

import functools
import math
import os
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, TypeVar

import scipy.fft
import scipy.linalg  # loads scipy's own BLAS, so that the controller finds it beside numpy's
from threadpoolctl import ThreadpoolController

__all__ = [
    "MAX_THREADS",
    "available_cores",
    "limited_threads",
    "others_load",
    "threads_to_use",
    "with_limited_threads",
]

# A cap: the solvers' matrices (a few hundred rows) leave little work for each of
# many threads. Measured only on two cores, where it never binds.
MAX_THREADS = 4

Function = TypeVar("Function", bound=Callable[..., Any])

# One limited block at a time in this process (re-entrant for nested blocks of one thread).
_turn = threading.RLock()


def available_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system tells it)."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return max(1, os.cpu_count() or 1)


def others_load() -> float:
    """How many cores other work keeps busy: the larger of two views of the run queue.

    The one-minute load average remembers bursts (a browser repainting) but
    takes a minute to see a job that has just started; Linux's count of tasks
    running at this instant sees it at once. Infinite where the system tells
    neither (Windows): then the solvers keep to one thread.
    """
    try:
        load = os.getloadavg()[0]
    except (AttributeError, OSError):
        return math.inf
    try:
        with open("/proc/loadavg") as file:
            running = int(file.read().split()[3].split("/")[0])
    except (OSError, IndexError, ValueError):
        return load
    return max(load, running - 1.0)  # the running count includes this process


def threads_to_use(cores: int | None = None, load: float | None = None) -> int:
    """Threads worth starting now: 1 for this process, plus one per core the load leaves idle.

    ``cores`` and ``load`` default to :func:`available_cores` and
    :func:`others_load`. A core counts as idle when the load leaves at least
    half of it (a load average of 0.05 on two cores leaves one idle, of 0.6
    none). At least 1, at most :data:`MAX_THREADS`.

    Examples
    --------
    >>> threads_to_use(cores=2, load=0.0), threads_to_use(cores=2, load=1.3)
    (2, 1)
    >>> threads_to_use(cores=8, load=2.5), threads_to_use(cores=8, load=float("inf"))
    (4, 1)
    """
    cores = available_cores() if cores is None else cores
    load = others_load() if load is None else load
    if not math.isfinite(load):
        return 1
    idle = math.floor(cores - 1 - max(load, 0.0) + 0.5)
    return int(min(MAX_THREADS, max(1, 1 + idle)))


@functools.cache
def _blas() -> ThreadpoolController:
    return ThreadpoolController().select(user_api="blas")


@contextmanager
def limited_threads(threads: int | None = None) -> Iterator[int]:
    """Within the block, BLAS and scipy.fft use at most ``threads`` (:func:`threads_to_use`).

    Yields the FFT worker count in force, for calls that take ``workers=``.
    Never raises a limit the caller has set, and restores the caller's limits
    on leaving, also after an exception. Blocks of different threads of the
    caller take turns (see the module's description). Costs about 30
    microseconds.

    Examples
    --------
    >>> import numpy as np
    >>> with limited_threads(1) as workers:
    ...     product = np.ones((300, 300)) @ np.ones((300, 300))   # on one BLAS thread
    >>> workers, float(product[0, 0])
    (1, 300.0)
    """
    threads = threads_to_use() if threads is None else max(1, int(threads))
    with _turn:
        blas = _blas()
        limits = {
            library["filepath"]: min(threads, library["num_threads"]) for library in blas.info()
        }
        workers = min(threads, scipy.fft.get_workers())
        with blas.limit(limits=limits), scipy.fft.set_workers(workers):
            yield workers


def with_limited_threads(function: Function) -> Function:
    """Decorate a solver to run inside :func:`limited_threads`."""

    @functools.wraps(function)
    def limited(*args: Any, **kwargs: Any) -> Any:
        with limited_threads():
            return function(*args, **kwargs)

    return limited  # type: ignore[return-value]
