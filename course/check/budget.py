"""A call under a time and a memory budget: a watchdog, and the operating system's limits.

The student's code runs in the calling thread (in a notebook, the kernel's
own), so their globals, prints and breakpoints behave as usual. A watchdog
thread looks at the clock (the case's own thread's CPU clock, and the wall
clock for a case that waits) and, past the budget, raises
:class:`_BudgetExceeded` inside the student's code, raising it again every
:data:`_REPEAT` seconds in case the code catches it. The kernel survives;
the caller gets :class:`CaseStopped`. The raise is delivered by a signal
where the platform has one (POSIX, in the main thread, which is where a
kernel runs its cells): the watchdog sends the thread ``SIGALRM`` with
``pthread_kill``, whose handler raises at once, so a ``time.sleep(60)``, a
lock or a socket that waits is interrupted too. Elsewhere, or when a signal
goes unreceived, the raise is ``PyThreadState_SetAsyncExc``'s, which CPython
offers on every operating system and which lands at the next line of Python.

Memory is capped by the operating system where a running kernel can use
its limit without dying: on Linux, the address space is capped for the
case (``RLIMIT_AS``'s soft limit, set to what the process holds plus the
budget, and put back after), so any allocation past the budget fails with
``MemoryError``, numpy's and ``mmap``'s included, at no cost to a case that
stays inside it. Elsewhere (macOS does not enforce ``RLIMIT_AS``; Windows
has no rlimits) the watchdog reads ``tracemalloc``'s count of what the case
allocated (numpy reports its buffers there too), which slows code that
allocates many small objects.

``RLIMIT_CPU`` is not used: past its soft limit the process gets
``SIGXCPU``, which the watchdog's per-thread clock already does better, and
its hard limit ends the kernel. So what no in-process checker can stop is
one long C call that neither allocates past the cap nor returns to Python
(a regex that backtracks, an ``svd`` of a huge matrix), nor a loop whose
bare ``except:`` catches every raise: a grader runs the student's code in a
child process for that (:mod:`course.check.outside`).

Unchecked: this is the checkers' kernel (``UNCHECKED = True``). It runs whatever it is
given; ``course.check.base`` validates what reaches it.
"""

from __future__ import annotations

import _thread
import ctypes
import errno
import os
import signal
import sys
import threading
import time
import tracemalloc
from collections.abc import Callable
from contextlib import AbstractContextManager, nullcontext
from typing import Any

from course.i18n import _

try:
    import resource
except ImportError:  # Windows: no rlimits
    resource = None  # type: ignore[assignment]

UNCHECKED = True  # see the module docstring

__all__ = ["MEMORY_BUDGET", "TIME_BUDGET", "CaseStopped", "run_bounded"]

#: Seconds of computing one case may take before it is stopped as a loop that does not end.
#: Counted on the case's own thread's CPU clock where the system has one (Linux, macOS), so a
#: busy machine (a class on one server, a test run beside others) never stops a right answer;
#: on the wall clock elsewhere.
TIME_BUDGET = 3.0
#: A case that waits rather than computes (``time.sleep``, ``input``) is stopped after this many
#: times the budget on the wall clock.
_WALL_FACTOR = 10
#: Bytes one case may allocate (and keep) before it is stopped as memory that keeps growing.
MEMORY_BUDGET = 512 * 2**20
#: How often the watchdog looks, and how long it waits before raising again if it is caught.
_POLL = 0.01
_REPEAT = 0.2
#: Seconds a signal sent to stop a case may go unreceived before an asynchronous raise follows.
_PATIENCE = 1.0

# What the watchdog and the budget use, held from import: a cell that patches time.monotonic
# or threading.get_ident does not switch the budget off.
_monotonic, _sleep, _get_ident = time.monotonic, time.sleep, threading.get_ident
_getprofile, _setprofile = sys.getprofile, sys.setprofile
_set_async_exc = ctypes.pythonapi.PyThreadState_SetAsyncExc
_tracing, _trace_start, _trace_stop = (
    tracemalloc.is_tracing,
    tracemalloc.start,
    tracemalloc.stop,
)
_traced_memory = tracemalloc.get_traced_memory
_os_open, _os_read, _os_close = os.open, os.read, os.close
_signal, _getsignal = signal.signal, signal.getsignal
_pthread_kill = getattr(signal, "pthread_kill", None)
_main_thread = threading.main_thread()

#: The address-space cap is used only where the kernel enforces it.
_CAPS_MEMORY = resource is not None and sys.platform.startswith("linux")
#: The signal sent to a stopped case's thread to interrupt a system call it waits in.
_INTERRUPT = signal.SIGALRM if _pthread_kill is not None and hasattr(signal, "SIGALRM") else None


class CaseStopped(Exception):
    """A case the watchdog stopped: ``reason`` says why, in the student's terms."""

    def __init__(self, reason: str, kind: str) -> None:
        super().__init__(reason)
        self.reason = reason
        self.kind = kind


class _BudgetExceeded(BaseException):
    """Raised inside the student's code; a BaseException, so ``except Exception`` lets it by."""


#: The watchdogs allowed to raise: a case's, and an outer case's for a case run inside it; a
#: watchdog left over from an earlier case never does.
_ACTIVE: list[Any] = []


class _Watchdog(threading.Thread):
    """Raises in the target thread past a budget. It shares no lock with it that the target
    waits for: an exception delivered inside a ``with lock`` could leave the lock held, so the
    two talk through plain attributes, each written in one step (``wake`` is only released by
    the target, to end the watchdog's wait early)."""

    def __init__(
        self, target: int, seconds: float, memory: int, baseline: int, interrupt: bool
    ) -> None:
        super().__init__(name="course-check-watchdog", daemon=True)
        self.target, self.seconds, self.memory, self.baseline = target, seconds, memory, baseline
        self.interrupt = interrupt  # also send the target _INTERRUPT when raising
        self.done = False  # set by the target thread: raise no more
        self.exited = False  # set here: no raise will follow
        self.signalled = False  # set here before _INTERRUPT is sent
        self.received = False  # set by the handler of _INTERRUPT, first thing
        self.signal_time = 0.0
        self.raised = False  # set here before an asynchronous raise
        self.kind: str | None = None
        self.wake = _thread.allocate_lock()
        self.wake.acquire()

    def run(self) -> None:
        try:
            self._watch()
        finally:
            self.exited = True

    def _watch(self) -> None:
        computing = _cpu_clock(self.target)
        start, start_computing = _monotonic(), computing()
        next_raise = 0.0
        while not self.done and self in _ACTIVE:
            try:
                self.wake.acquire(timeout=_POLL)  # released by stop(): no wait for the poll
                now = _monotonic()
                kind = None
                if (
                    computing() - start_computing > self.seconds
                    or now - start > self.seconds * _WALL_FACTOR
                ):
                    kind = "time"
                elif self.baseline >= 0 and _tracing():
                    current, _ = _traced_memory()
                    if current - self.baseline > self.memory:
                        kind = "memory"
                if kind is None or now < next_raise or self.done or self not in _ACTIVE:
                    continue
                self.kind = self.kind or kind
                self._stop_case(now)
                next_raise = now + _REPEAT
            except MemoryError:  # the case holds all the memory it may: look again
                continue

    def _stop_case(self, now: float) -> None:
        """Raise in the target: by a signal where it can have one, whose handler raises at once,
        a wait in a system call included; else, or when a signal has not been received for
        :data:`_PATIENCE` s (a long C call), asynchronously. Never both at first: a pending
        asynchronous raise would land inside the signal's handler before it says it ran."""
        if self.interrupt and not self.raised:
            if not self.signalled or self.received:
                self.received, self.signalled, self.signal_time = False, True, now
                _pthread_kill(self.target, _INTERRUPT)
                return
            if now - self.signal_time < _PATIENCE:
                return
        self.raised = True
        _raise_in(self.target, _BudgetExceeded)

    def stop(self) -> None:
        self.done = True
        if self in _ACTIVE:
            _ACTIVE.remove(self)
        try:
            self.wake.release()
        except RuntimeError:  # released already
            pass
        deadline = _monotonic() + 1.0
        while not self.exited and _monotonic() < deadline:
            _sleep(_POLL / 10)
        if self.raised:
            _drain(self.target)


def _cpu_clock(thread_id: int) -> Callable[[], float]:
    """The CPU time of thread ``thread_id`` as a function, or the wall clock where there is none."""
    try:
        clock = time.pthread_getcpuclockid(thread_id)
        time.clock_gettime(clock)
    except (AttributeError, OSError, OverflowError):
        return _monotonic
    gettime = time.clock_gettime
    return lambda: gettime(clock)


class _Drained(BaseException):
    """Replaces a raise not yet delivered, and is caught at once by :func:`_drain`."""


def _drain(thread_id: int) -> None:
    """Take delivery here of any raise still pending, so none reaches the checker's code.

    Cancelling a pending raise (``PyThreadState_SetAsyncExc`` with NULL) leaves
    CPython's "asynchronous exception" flag set with nothing to deliver: a
    profile hook (``call_budget``) then spins forever at the next function
    entry. So the pending raise is replaced by one that is delivered, which
    clears the flag, and caught here, in a loop that gives it a place to land.
    """
    try:
        _raise_in(thread_id, _Drained)
        for _ in range(10**8):
            pass
    except _Drained:
        return


def _raise_in(thread_id: int, exception: type[BaseException] | None) -> None:
    _set_async_exc(ctypes.c_ulong(thread_id), ctypes.py_object(exception) if exception else None)


def _reason(kind: str, seconds: float, memory: int) -> str:
    if kind == "memory":
        return _("memory kept growing (past {mebibytes} MiB)").format(
            mebibytes=f"{memory / 2**20:g}"
        )
    return _("the loop did not stop within {seconds} s").format(seconds=f"{seconds:g}")


def _address_space() -> int | None:
    """The bytes of address space the process holds (Linux's ``/proc/self/statm``), or None."""
    try:
        handle = _os_open("/proc/self/statm", os.O_RDONLY)
        try:
            pages = int(_os_read(handle, 200).split()[0])
        finally:
            _os_close(handle)
        return pages * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return None


def _cap_memory(memory: int) -> tuple[int, int] | None:
    """Cap the address space at what the process holds plus ``memory``; the limits it replaced,
    to put back, or None where there is no cap (not Linux, or a tighter one already set)."""
    if not _CAPS_MEMORY:
        return None
    held = _address_space()
    if held is None:
        return None
    try:
        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        cap = held + memory
        if hard != resource.RLIM_INFINITY:
            cap = min(cap, hard)
        if soft != resource.RLIM_INFINITY and soft <= cap:
            return None  # a tighter limit is already set: leave it
        resource.setrlimit(resource.RLIMIT_AS, (cap, hard))
    except (OSError, ValueError):
        return None
    return soft, hard


def _uncap_memory(limits: tuple[int, int] | None) -> None:
    if limits is not None:
        resource.setrlimit(resource.RLIMIT_AS, limits)


def _interrupt_handler(watchdog: _Watchdog) -> Any:
    """Install the handler of :data:`_INTERRUPT` for ``watchdog``'s case and return the handler
    to put back after, or None where the case cannot be interrupted by a signal: not on POSIX,
    not in the main thread (only it runs Python's signal handlers), or a handler set by someone
    else (a student's own ``signal.alarm``)."""
    if _INTERRUPT is None or threading.current_thread() is not _main_thread:
        return None
    try:
        previous = _getsignal(_INTERRUPT)
        ours = getattr(previous, "course_watchdog", None)
        if ours is not None:
            if not ours.done:
                return None  # a case run inside another's: the outer case keeps the signal
            previous = previous.course_restores  # one of ours, left installed: silent
        if previous not in (signal.SIG_DFL, signal.SIG_IGN):
            return None

        def handler(number: int, frame: Any) -> None:
            watchdog.received = True
            if not watchdog.done:
                raise _BudgetExceeded

        handler.course_restores = previous  # type: ignore[attr-defined]
        handler.course_watchdog = watchdog  # type: ignore[attr-defined]
        _signal(_INTERRUPT, handler)
    except (OSError, ValueError, RuntimeError):
        return None
    return previous


def _uninstall_interrupt(watchdog: _Watchdog, previous: Any) -> None:
    """Put back the handler :func:`_interrupt_handler` replaced, unless a signal sent may not
    have been received yet: delivered under the default handler, it would end the kernel. The
    handler then stays, silent (its case is done), until the next case replaces it."""
    if previous is None or not watchdog.exited:
        return
    if watchdog.signalled and not watchdog.received:
        return
    _signal(_INTERRUPT, previous)


def run_bounded(
    call: Callable[[], Any],
    seconds: float | None = None,
    memory: int | None = None,
    watch: Callable[[], AbstractContextManager[Any]] | None = None,
) -> Any:
    """``call()`` under a time and a memory budget; past one, :class:`CaseStopped`.

    ``watch()``, if given, makes a context manager ``call`` runs inside (a
    :func:`~course.check.base.call_budget`). Memory is capped by the
    operating system on Linux; elsewhere ``tracemalloc`` is started for the
    call and stopped after it unless it was already running. A
    ``MemoryError`` (or an ``mmap`` refused for want of memory under the
    cap) counts as memory that kept growing.

    Examples
    --------
    >>> run_bounded(lambda: sum(range(10)))
    45
    >>> def forever():
    ...     while True:
    ...         pass
    >>> run_bounded(forever, seconds=0.05)
    Traceback (most recent call last):
    ...
    course.check.budget.CaseStopped: the loop did not stop within 0.05 s
    """
    seconds = TIME_BUDGET if seconds is None else float(seconds)
    memory = MEMORY_BUDGET if memory is None else int(memory)
    was_tracing = _tracing()
    profile = _getprofile()
    watchdog = _Watchdog(_get_ident(), seconds, memory, -1, interrupt=False)
    interrupted = _interrupt_handler(watchdog)
    watchdog.interrupt = interrupted is not None
    _ACTIVE.append(watchdog)
    limits = None
    try:
        try:
            watchdog.start()  # before the cap: a new thread's stack is address space too
            limits = _cap_memory(memory)
            if limits is None:
                if not _tracing():
                    _trace_start()
                watchdog.baseline = _traced_memory()[0]
            with watch() if watch is not None else nullcontext():
                return call()
        finally:
            _uncap_memory(limits)  # first: what follows may need memory
            _stop(watchdog)
    except _BudgetExceeded:
        _uncap_memory(limits)
        _stop(watchdog)
        kind = watchdog.kind or "time"
        raise CaseStopped(_reason(kind, seconds, memory), kind) from None
    except MemoryError:
        _uncap_memory(limits)
        raise CaseStopped(_reason("memory", seconds, memory), "memory") from None
    except OSError as error:
        _uncap_memory(limits)
        if limits is None or error.errno != errno.ENOMEM:
            raise
        raise CaseStopped(_reason("memory", seconds, memory), "memory") from None
    finally:
        _restore(profile, was_tracing, watchdog, limits, interrupted)


def _stop(watchdog: _Watchdog) -> None:
    """Stop the watchdog, even if its last raise arrives while this runs."""
    for _attempt in range(100):
        try:
            watchdog.stop()
            return
        except _BudgetExceeded:
            continue
    watchdog.stop()


def _restore(
    profile: Any,
    was_tracing: bool,
    watchdog: _Watchdog,
    limits: tuple[int, int] | None,
    interrupted: Any,
) -> None:
    while True:
        try:
            _uncap_memory(limits)
            _stop(watchdog)
            _uninstall_interrupt(watchdog, interrupted)
            interrupted = None
            _setprofile(profile)
            if not was_tracing and _tracing():
                _trace_stop()
            return
        except _BudgetExceeded:
            continue
