"""Running a student's function safely: a time and memory budget, its inputs kept, its errors read.

The student's code runs in the calling thread (in a notebook, the kernel's
own), so their globals, prints and breakpoints behave as usual. A watchdog
thread looks at the clock and at ``tracemalloc``'s count of the memory
allocated since the case began (numpy reports its buffers there too); past
either budget it raises :class:`_BudgetExceeded` inside the student's code
with ``PyThreadState_SetAsyncExc``, which CPython offers on every operating
system, and raises it again every :data:`_REPEAT` seconds in case the code
catches it. The kernel survives; the caller gets :class:`CaseStopped`.

A call that stays inside one long C function (a single ``time.sleep(60)``)
cannot be interrupted this way, nor a loop whose bare ``except:`` catches
every raise; every other loop written in Python can.

Unchecked: this is the checkers' kernel (``UNCHECKED = True``). It runs and
copies whatever it is given, NaN included; ``course.check.base`` validates
what reaches it.
"""

from __future__ import annotations

import ast
import copy
import ctypes
import inspect
import os
import sys
import textwrap
import threading
import time
import traceback
import tracemalloc
from collections.abc import Callable, Mapping
from contextlib import AbstractContextManager, nullcontext
from typing import Any

import numpy as np

from course.i18n import _

UNCHECKED = True  # see the module docstring

__all__ = [
    "MEMORY_BUDGET",
    "TIME_BUDGET",
    "CaseStopped",
    "arity_problem",
    "case_inputs",
    "changed_argument",
    "copies",
    "describe_function",
    "is_stub",
    "run_bounded",
    "student_line",
]

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
_COURSE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Frames in these folders are the course's, Python's or a library's, never the student's.
_NOT_THEIRS = tuple(
    {_COURSE, *(os.path.abspath(p) for p in (sys.prefix, sys.base_prefix, sys.exec_prefix))}
)


class CaseStopped(Exception):
    """A case the watchdog stopped: ``reason`` says why, in the student's terms."""

    def __init__(self, reason: str, kind: str) -> None:
        super().__init__(reason)
        self.reason = reason
        self.kind = kind


class _BudgetExceeded(BaseException):
    """Raised inside the student's code; a BaseException, so ``except Exception`` lets it by."""


#: The one watchdog allowed to raise: a watchdog left over from an earlier case never does.
_ACTIVE: list[Any] = [None]


class _Watchdog(threading.Thread):
    """Raises in the target thread past a budget. It shares no lock with it: an exception
    delivered inside a ``with lock`` could leave the lock held, so the two talk through
    plain attributes, each written in one step."""

    def __init__(self, target: int, seconds: float, memory: int, baseline: int) -> None:
        super().__init__(name="course-check-watchdog", daemon=True)
        self.target, self.seconds, self.memory, self.baseline = target, seconds, memory, baseline
        self.done = False  # set by the target thread: raise no more
        self.exited = False  # set here: no raise will follow
        self.kind: str | None = None

    def run(self) -> None:
        try:
            self._watch()
        finally:
            self.exited = True

    def _watch(self) -> None:
        computing = _cpu_clock(self.target)
        start, start_computing = time.monotonic(), computing()
        next_raise = 0.0
        while not self.done and _ACTIVE[0] is self:
            time.sleep(_POLL)
            now = time.monotonic()
            kind = None
            if (
                computing() - start_computing > self.seconds
                or now - start > self.seconds * _WALL_FACTOR
            ):
                kind = "time"
            elif tracemalloc.is_tracing():
                current, _ = tracemalloc.get_traced_memory()
                if current - self.baseline > self.memory:
                    kind = "memory"
            if kind is None or now < next_raise or self.done or _ACTIVE[0] is not self:
                continue
            self.kind = self.kind or kind
            _raise_in(self.target, _BudgetExceeded)
            next_raise = now + _REPEAT

    def stop(self) -> None:
        self.done = True
        if _ACTIVE[0] is self:
            _ACTIVE[0] = None
        deadline = time.monotonic() + 1.0
        while not self.exited and time.monotonic() < deadline:
            time.sleep(_POLL / 10)
        if self.kind is not None:
            _drain(self.target)


def _cpu_clock(thread_id: int) -> Callable[[], float]:
    """The CPU time of thread ``thread_id`` as a function, or the wall clock where there is none."""
    try:
        clock = time.pthread_getcpuclockid(thread_id)
        time.clock_gettime(clock)
    except (AttributeError, OSError, OverflowError):
        return time.monotonic
    return lambda: time.clock_gettime(clock)


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
    ctypes.pythonapi.PyThreadState_SetAsyncExc(
        ctypes.c_ulong(thread_id), ctypes.py_object(exception) if exception else None
    )


def _reason(kind: str, seconds: float, memory: int) -> str:
    if kind == "memory":
        return _("memory kept growing (past {mebibytes} MiB)").format(
            mebibytes=f"{memory / 2**20:g}"
        )
    return _("the loop did not stop within {seconds} s").format(seconds=f"{seconds:g}")


def run_bounded(
    call: Callable[[], Any],
    seconds: float | None = None,
    memory: int | None = None,
    watch: Callable[[], AbstractContextManager[Any]] | None = None,
) -> Any:
    """``call()`` under a time and a memory budget; past one, :class:`CaseStopped`.

    ``watch()``, if given, makes a context manager ``call`` runs inside (a
    :func:`~course.check.base.call_budget`). ``tracemalloc`` is started for
    the call and stopped after it unless it was already running. A
    ``MemoryError`` counts as memory that kept growing.

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
    course.check.sandbox.CaseStopped: the loop did not stop within 0.05 s
    """
    seconds = TIME_BUDGET if seconds is None else float(seconds)
    memory = MEMORY_BUDGET if memory is None else int(memory)
    was_tracing = tracemalloc.is_tracing()
    if not was_tracing:
        tracemalloc.start()
    watchdog = _Watchdog(threading.get_ident(), seconds, memory, tracemalloc.get_traced_memory()[0])
    profile = sys.getprofile()
    _ACTIVE[0] = watchdog
    try:
        try:
            watchdog.start()
            with watch() if watch is not None else nullcontext():
                return call()
        finally:
            _stop(watchdog)
    except _BudgetExceeded:
        _stop(watchdog)
        kind = watchdog.kind or "time"
        raise CaseStopped(_reason(kind, seconds, memory), kind) from None
    except MemoryError:
        raise CaseStopped(_reason("memory", seconds, memory), "memory") from None
    finally:
        _restore(profile, was_tracing, watchdog)


def _stop(watchdog: _Watchdog) -> None:
    """Stop the watchdog, even if its last raise arrives while this runs."""
    for _attempt in range(100):
        try:
            watchdog.stop()
            return
        except _BudgetExceeded:
            continue
    watchdog.stop()


def _restore(profile: Any, was_tracing: bool, watchdog: _Watchdog) -> None:
    while True:
        try:
            _stop(watchdog)
            sys.setprofile(profile)
            if not was_tracing and tracemalloc.is_tracing():
                tracemalloc.stop()
            return
        except _BudgetExceeded:
            continue


def copies(values: tuple[Any, ...]) -> tuple[Any, ...]:
    """Deep copies of a case's inputs, so the student's code cannot change the checker's."""
    return tuple(copy.deepcopy(value) for value in values)


def changed_argument(
    names: tuple[str, ...], before: tuple[Any, ...], after: tuple[Any, ...]
) -> str | None:
    """The first argument the call changed, and where, in words; None if none changed.

    Examples
    --------
    >>> changed_argument(("a", "b"), (1, np.zeros(3)), (1, np.array([0.0, 2.0, 0.0])))
    'b: element [1] was 0, is now 2'
    >>> changed_argument(("a",), ([1, 2],), ([1, 2, 3],)) is None
    False
    """
    for name, old, new in zip(names, before, after, strict=True):
        where = _first_change(old, new)
        if where is not None:
            return _("{name}: {where}").format(name=name, where=where)
    return None


def _first_change(old: Any, new: Any) -> str | None:
    if isinstance(old, np.ndarray):
        if not isinstance(new, np.ndarray) or new.shape != old.shape:
            return _("its shape was {old}, is now {new}").format(old=old.shape, new=np.shape(new))
        if old.dtype.kind in "fc":
            differ = ~((old == new) | (np.isnan(old) & np.isnan(new)))
        else:
            differ = old != new
        if not differ.any():
            return None
        index = tuple(int(i) for i in np.argwhere(differ)[0])
        where = "[" + ", ".join(map(str, index)) + "]"
        return _("element {where} was {old}, is now {new}").format(
            where=where, old=f"{old[index]:.6g}", new=f"{new[index]:.6g}"
        )
    if isinstance(old, (list, tuple)):
        if not isinstance(new, type(old)) or len(new) != len(old):
            return _("it was {old}, is now {new}").format(old=_short(old), new=_short(new))
        for index, (a, b) in enumerate(zip(old, new, strict=True)):
            inner = _first_change(a, b)
            if inner is not None:
                return _("item [{index}]: {inner}").format(index=index, inner=inner)
        return None
    try:
        same = bool(old == new)
    except Exception:
        return None
    if same:
        return None
    return _("it was {old}, is now {new}").format(old=_short(old), new=_short(new))


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def arity_problem(function: Callable[..., Any], parameters: tuple[str, ...]) -> str | None:
    """Why ``function`` cannot be called with the handout's parameters by position, or None.

    Examples
    --------
    >>> arity_problem(lambda p: p, ("control_points", "t"))
    'expected 2 parameters, (control_points, t); your function takes 1, (p)'
    >>> arity_problem(lambda a, b, c=0: a, ("control_points", "t")) is None
    True
    """
    try:
        signature = inspect.signature(function)
    except (TypeError, ValueError):
        return None  # a builtin without a signature: the call will tell
    try:
        signature.bind(*parameters)
        return None
    except TypeError:
        pass
    names = [
        p.name
        for p in signature.parameters.values()
        if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
    ]
    count = len(parameters)
    if count == 1:
        text = _("expected {count} parameter, ({expected}); your function takes {taken}, ({names})")
    else:
        text = _(
            "expected {count} parameters, ({expected}); your function takes {taken}, ({names})"
        )
    return text.format(
        count=count, expected=", ".join(parameters), taken=len(names), names=", ".join(names)
    )


def is_stub(function: Callable[..., Any]) -> bool:
    """Whether ``function``'s body does nothing yet: a docstring, ``pass``, ``...`` or a raise."""
    try:
        source = textwrap.dedent(inspect.getsource(function))
        tree = ast.parse(source)
    except (OSError, TypeError, SyntaxError, IndentationError):
        return False
    definitions = [n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)]
    if not definitions:
        return False
    body = list(definitions[0].body)
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
        body = body[1:]  # the docstring
    for statement in body:
        if isinstance(statement, (ast.Pass, ast.Raise)):
            continue
        if isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Constant):
            continue  # `...`
        if isinstance(statement, ast.Return) and statement.value is None:
            continue
        return False
    return True


def student_line(error: BaseException) -> str | None:
    """The line of the student's code that raised ``error``: the last frame outside the course.

    Examples
    --------
    >>> def mine():
    ...     return 1 / 0
    >>> try:
    ...     mine()
    ... except ZeroDivisionError as error:
    ...     print(student_line(error))
    line 2 of mine: return 1 / 0
    """
    frames = traceback.extract_tb(error.__traceback__)
    own = [
        f
        for f in frames
        if not os.path.abspath(f.filename).startswith(tuple(p + os.sep for p in _NOT_THEIRS))
    ]
    if not own:
        return None
    frame = own[-1]
    text = (frame.line or "").strip()
    if _is_cell(frame.filename):
        # IPython compiles each cell on its own, so the line number counts from the cell's top.
        where = _("line {line} of your cell, in {function}").format(
            line=frame.lineno, function=frame.name
        )
    else:
        where = _("line {line} of {function}").format(line=frame.lineno, function=frame.name)
    return f"{where}: {text}" if text else where


def _is_cell(filename: str) -> bool:
    """Whether ``filename`` is a notebook cell's: ipykernel's ``.../ipykernel_N/M.py``, or older
    IPython's ``<ipython-input-N-...>``."""
    if filename.startswith("<ipython-input-"):
        return True
    folder = os.path.basename(os.path.dirname(filename))
    return folder.startswith("ipykernel_") and filename.endswith(".py")


def describe_function(function: Any) -> str:
    """A short name for what the student passed in place of a function."""
    return getattr(function, "__name__", type(function).__name__)


def case_inputs(case: Mapping[str, Any], show: Callable[[Any], str]) -> str:
    """A case's inputs in one line, as the handout names them."""
    return ", ".join(f"{name}={show(value)}" for name, value in case.items())
