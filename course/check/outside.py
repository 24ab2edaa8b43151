"""A student's function run outside the grader's process: a fresh interpreter, the OS's limits.

:func:`outside_function` starts a child Python in a temporary folder (``python -I -S``: no
site packages but numpy's folder, so no ``course`` and none of the grader's objects), runs a
student's answer cells there (:mod:`course.check._outside_child`) and returns a stand-in
for the student's function. A checker calls the stand-in as it would the function itself:
the arguments cross to the child, the student's function runs there under the operating
system's limits (an address space, a processor-time alarm, a processor-time cap for the
child; on Windows, the grader's kill), and what it returned comes back as plain numbers,
text, lists and arrays. The expected answers, the comparisons and the verdict never leave
the grader's process, so nothing the student's code does (patching the checker, walking up
the frames, switching off a watch) can change them.

The stand-in behaves as the function for the checker: it has the function's parameters, it
raises what the function raised (the student's line attached), an argument the function
changed comes back changed, a case past its budget raises
:class:`~course.check.sandbox.CaseStopped`, and inside a
:func:`~course.check.references.call_budget` the child counts the calls and stops at the
same limit. What the student's code printed or warned is kept (:attr:`Outside.printed`),
never mixed with the grader's output.

Unchecked: the grader, not a student, calls these (``UNCHECKED = True``).
"""

from __future__ import annotations

import atexit
import builtins
import contextlib
import importlib.util
import inspect
import os
import queue
import shutil
import signal
import site
import subprocess
import sys
import sysconfig
import tempfile
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from course.check._outside_child import CHANGE, EVENT, LOAD, MEMORY_EXIT, READ, UP
from course.check._wire import (
    ARRAY,
    BYTES,
    ITERATOR,
    LIST,
    NESTED,
    Unreadable,
    decode,
    encode,
    read_message,
    write_message,
)
from course.check.references import CallBudget, call_limits, known_mistake
from course.check.sandbox import MEMORY_BUDGET, TIME_BUDGET, CaseStopped
from course.i18n import N_, _

__all__ = ["PRELUDE", "Outside", "outside_function"]

UNCHECKED = True  # see the module docstring

#: What every child has before the student's cells: the lessons' own imports.
PRELUDE = "import itertools\nimport math\n\nimport numpy as np\n"
#: Seconds of processor time the whole child may use (every case, and loading the cells).
CHILD_CPU_SECONDS = 120
#: The child's address space beyond the cells' memory budget: numpy's own, and the cells'.
_CHILD_OWN_MEMORY = 256 * 2**20
#: The wall-clock grace beyond a call's budget before the grader kills the child: a call
#: that waits (``time.sleep``) or sits in one long C call uses no processor time.
_WALL_FACTOR, _WALL_EXTRA = 4, 5.0


def _numpy_folders() -> list[Path]:
    """numpy's package folder and its bundled libraries' (``numpy.libs``, ``.dylibs``)."""
    spec = importlib.util.find_spec("numpy")
    if spec is None or not spec.submodule_search_locations:
        raise RuntimeError(_("numpy is not installed: the grader's child needs it"))
    package = Path(next(iter(spec.submodule_search_locations))).resolve()
    found = [package.parent / name for name in ("numpy", "numpy.libs", ".dylibs")]
    return [folder for folder in found if folder.exists()]


def _numpy_site() -> Path:
    """A folder holding only numpy (and its bundled libraries): the child's site packages.
    Removed when the grader's process ends."""
    folder = Path(tempfile.mkdtemp(prefix="course-numpy-"))
    for source in _numpy_folders():
        (folder / source.name).symlink_to(source, target_is_directory=True)
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    return folder


def _confinement(folder: Path, paths: Sequence[str]) -> dict[str, Any]:
    """Where the child may open files (:func:`course.check._outside_child.confine`): the
    standard library, but not the site packages inside it or beside it; numpy, the grader's
    ``paths`` and the folder linking numpy; and ``folder``, its working folder, to write.
    ``ctypes`` only where the grader grants ``paths`` (the course's own tests)."""
    stdlib = {sysconfig.get_paths()[key] for key in ("stdlib", "platstdlib")}
    refused = {sysconfig.get_paths()[key] for key in ("purelib", "platlib")}
    refused.update(site.getsitepackages())
    refused.add(site.getusersitepackages())
    granted = [*map(str, _numpy_folders()), str(_site()), *paths]

    def real(folders: Any) -> list[str]:
        return sorted(
            {os.path.realpath(path) for path in folders} | {str(path) for path in folders}
        )

    return {
        "granted": real(granted),
        "reads": real(stdlib),
        "refused": real(refused),
        "writes": real([folder]),
        "with_ctypes": bool(paths),
    }


_SITE: list[Path] = []
#: The child's program, run as text (importing it would bring the course along): how values
#: cross, then the child itself.
_CHILD_PROGRAM = [
    str(importlib.util.find_spec(f"course.check.{name}").origin)
    for name in ("_wire", "_outside_child")
]


def _site() -> Path:
    if not _SITE or not _SITE[0].exists():
        _SITE[:] = [_numpy_site()]
    return _SITE[0]


class Outside:
    """A child process holding a student's cells, and their function called there.

    ``cells`` run in order in the child (after :data:`PRELUDE` and the ``given`` names: the
    lesson's constants); an error in the last one is the student's, reported when the
    function is first called; errors in the others are ignored. ``paths`` are folders the
    child may import from besides numpy's (none by default; the course's own tests plant
    mistakes with the library's help).
    """

    def __init__(
        self,
        cells: Sequence[str],
        function: str,
        given: Mapping[str, Any] | None = None,
        *,
        prelude: str = PRELUDE,
        seconds: float = TIME_BUDGET,
        memory: int = MEMORY_BUDGET,
        paths: Sequence[str] = (),
    ) -> None:
        self.cells = list(cells)
        self.paths = [str(path) for path in paths]
        self.function = function
        self.given = dict(given or {})
        self.prelude = prelude
        self.seconds = float(seconds)
        self.memory = int(memory)
        self.printed: list[str] = []
        self.warned: list[str] = []
        self._process: subprocess.Popen[bytes] | None = None
        self._answers: queue.Queue[tuple[dict[str, Any], list[bytearray]] | None] | None = None
        self._asked = 0
        self._folder: Path | None = None
        self.loaded: dict[str, Any] = {}

    # --- the child ---------------------------------------------------------------------

    def _start(self) -> dict[str, Any]:
        self.close()
        self._folder = Path(tempfile.mkdtemp(prefix="course-outside-"))
        source = "\n".join(Path(part).read_text(encoding="utf-8") for part in _CHILD_PROGRAM)
        environment = {
            "PATH": os.environ.get("PATH", ""),
            "HOME": str(self._folder),
            "TMPDIR": str(self._folder),
            "OPENBLAS_NUM_THREADS": "1",
            "OMP_NUM_THREADS": "1",
            "MKL_NUM_THREADS": "1",
        }
        if sys.platform == "win32":
            environment["SYSTEMROOT"] = os.environ.get("SYSTEMROOT", "")
        self._process = subprocess.Popen(
            [sys.executable, "-I", "-S", "-c", source, str(_site()), *self.paths],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            cwd=self._folder,
            env=environment,
            start_new_session=sys.platform != "win32",  # its own group: close() ends them all
        )
        self._answers = queue.Queue()
        # No answer holds more than the child's address space could.
        most = self.memory + _CHILD_OWN_MEMORY
        threading.Thread(
            target=_read_answers, args=(self._process.stdout, self._answers, most), daemon=True
        ).start()
        buffers: list[Any] = []
        message = {
            "op": "load",
            "prelude": self.prelude,
            "given": {name: encode(value, buffers) for name, value in self.given.items()},
            "cells": [
                [cell, index == len(self.cells) - 1] for index, cell in enumerate(self.cells)
            ],
            "function": self.function,
            "confine": _confinement(self._folder, self.paths),
            "memory": self.memory + _CHILD_OWN_MEMORY,
            "cpu_seconds": CHILD_CPU_SECONDS,
            "seconds": max(self.seconds, 10.0),  # importing numpy takes a while
        }
        answer = self._ask(message, buffers, max(self.seconds, 10.0))
        self.loaded = answer[0] if answer is not None else {"stopped": "time"}
        return self.loaded

    def _ask(
        self, message: dict[str, Any], buffers: list[Any], seconds: float
    ) -> tuple[dict[str, Any], list[bytearray]] | None:
        """Send ``message`` and the bytes of its arrays; the child's answer and the bytes of
        its arrays, or None (the child killed) past the wall time.

        Each message carries a number the answer repeats: a line the student's code wrote to
        the grader's channel itself is skipped, never taken for the answer.
        """
        process, answers = self._process, self._answers
        if process is None or process.stdin is None or answers is None:
            return None
        self._asked += 1
        try:
            write_message(process.stdin, {**message, "asked": self._asked}, buffers)
        except OSError:
            return self._died(), []
        deadline = time.monotonic() + seconds * _WALL_FACTOR + _WALL_EXTRA
        while True:
            try:
                received = answers.get(timeout=max(deadline - time.monotonic(), 0.0))
            except queue.Empty:
                self.close()
                return None
            if received is None:  # the child's output ended: it died
                return self._died(), []
            answer, answer_buffers = received
            if answer.get("asked") == self._asked:
                break
        if answer.get("printed"):
            self.printed.append(str(answer["printed"]))
        self.warned.extend(str(warning) for warning in answer.get("warnings", []))
        return answer, answer_buffers

    def _died(self) -> dict[str, Any]:
        code = None
        if self._process is not None:
            try:
                code = self._process.wait(timeout=2)
            except subprocess.TimeoutExpired:  # it closed the grader's channel and runs on
                code = 0
        self.close()
        if code is not None and code >= 0 and code != MEMORY_EXIT:  # os._exit, a closed channel
            return {"stopped": "ended", "died": code}
        # Killed by the processor-time cap (SIGXCPU, SIGKILL), else by the address space.
        return {"stopped": "time" if code in (-24, -9) else "memory", "died": code}

    def close(self) -> None:
        """Stop the child, and any process left in its group, and remove its folder."""
        if self._process is not None:
            if sys.platform != "win32":
                with contextlib.suppress(OSError):  # the group is gone already
                    os.killpg(self._process.pid, signal.SIGKILL)
            if self._process.poll() is None:
                self._process.kill()
            self._process.wait()
            for stream in (self._process.stdin, self._process.stdout):
                if stream is not None:
                    stream.close()
            self._process = None
        if self._folder is not None:
            shutil.rmtree(self._folder, ignore_errors=True)
            self._folder = None

    # --- the function ------------------------------------------------------------------

    def signature(self) -> inspect.Signature | None:
        """The student's function's parameters, as the child read them (None if unknown)."""
        loaded = self.loaded or self._start()
        parameters = loaded.get("parameters")
        if not parameters:
            return None if parameters is None else inspect.Signature([])
        return inspect.Signature(
            [
                inspect.Parameter(
                    name,
                    getattr(inspect.Parameter, kind),
                    default=None if has_default else inspect.Parameter.empty,
                )
                for name, kind, has_default in parameters
            ]
        )

    def call(self, *arguments: Any) -> Any:
        """The student's function called with ``arguments`` in the child: what it returned.

        Arrays and lists among ``arguments`` are updated in place with what the function
        left in them. Raises what the function raised, :class:`CaseStopped` past a budget,
        :class:`CallBudget` past the innermost call budget's calls.
        """
        loaded = self.loaded if self._process is not None else self._start()
        self._raise_for(loaded)
        max_calls, too_many = call_limits()
        buffers: list[Any] = []
        message = {
            "op": "call",
            "function": self.function,
            "arguments": [encode(value, buffers) for value in arguments],
            "seconds": self.seconds,
            "max_calls": max_calls,
        }
        answer, buffers = self._ask(message, buffers, self.seconds) or ({"stopped": "time"}, [])
        if answer.get("stopped") == "calls" and max_calls is not None:
            text = _("more than {count:,} Python function calls").format(count=max_calls)
            if too_many is None:
                raise CallBudget(text)
            raise CallBudget(f"{text}\n{known_mistake(too_many)}", too_many.name)
        self._raise_for(answer)
        try:
            for given, left in zip(arguments, answer.get("arguments", ()), strict=False):
                _write_back(given, decode(left, buffers))
            return decode(answer["returned"], buffers)
        except Unreadable as unreadable:
            raise _unreadable(*unreadable.args) from None

    def _raise_for(self, answer: Mapping[str, Any]) -> None:
        if "stopped" in answer:
            self.close()  # a fresh child for the next case
            if answer["stopped"] == "memory":
                reason = _("memory kept growing (past {mebibytes} MiB)").format(
                    mebibytes=f"{self.memory / 2**20:g}"
                )
                raise CaseStopped(reason, "memory")
            if answer["stopped"] == "ended":
                reason = _(
                    "your code ended the process it ran in, or closed its channel to the grader"
                )
                raise CaseStopped(reason, "ended")
            reason = _("the loop did not stop within {seconds} s").format(
                seconds=f"{self.seconds:g}"
            )
            raise CaseStopped(reason, "time")
        if "unreadable" in answer:
            raise _unreadable(*[*list(answer["unreadable"]), 0, 0][:2])
        if "missing" in answer:
            raise NameError(
                _("your cell does not define {function}").format(function=answer["missing"])
            )
        if "error" in answer:
            rebuilt = _rebuilt(answer["error"])  # the student's own message, as they wrote it
            raise rebuilt


def _read_answers(
    stream: Any, answers: queue.Queue[tuple[dict[str, Any], list[bytearray]] | None], most: int
) -> None:
    """The child's answers (:func:`~course.check._wire.read_message`, each at most
    ``most`` bytes), then None: a thread's job, so that the grader waits with a timeout on
    any system (select cannot wait on a pipe on Windows)."""
    try:
        while (received := read_message(stream, most)) is not None:
            answers.put(received)
    except (OSError, ValueError):
        pass
    answers.put(None)


def _unreadable(kind: Any, count: Any) -> CaseStopped:
    """Why an answer could not be read (an :class:`Unreadable`'s kind and count), in the
    student's language."""
    why = _(_UNREADABLE.get(kind, _UNREADABLE[ITERATOR]))
    unreadable = _("your answer cannot be read: {reason}")
    return CaseStopped(unreadable.format(reason=why.format(count=int(count))), "answer")


def _write_back(given: Any, left: Any) -> None:
    """Put into ``given`` (an argument) what the student's function left in its copy."""
    if isinstance(given, np.ndarray) and isinstance(left, np.ndarray):
        if given.shape == left.shape and given.flags.writeable:
            np.copyto(given, left, casting="unsafe")
    elif isinstance(given, list) and isinstance(left, list):
        given[:] = left


def _rebuilt(error: Mapping[str, Any]) -> Exception:
    """An exception like the student's: the same type for Python's own exceptions (so a
    NotImplementedError is still "not written yet"), a look-alike for their own, and never a
    BaseException (a SystemExit stays in the report)."""
    name, message = str(error.get("type", "Exception")), str(error.get("message", ""))
    if isinstance(error.get("refused"), list) and len(error["refused"]) == 2:
        message = _refusal(*map(str, error["refused"]))
    kind = getattr(builtins, name, None) if error.get("builtin") else None
    if not (isinstance(kind, type) and issubclass(kind, Exception)):
        kind = type(name, (Exception,), {"__module__": "student"})
    try:
        rebuilt = kind(message)
    except Exception:  # a builtin that wants other arguments (UnicodeDecodeError)
        rebuilt = type(name, (Exception,), {"__module__": "student"})(message)
    line = error.get("line")
    if isinstance(line, str):
        rebuilt.course_student_line = _("in your cell: {line}").format(line=line)
    return rebuilt


#: Why an answer could not cross, by the child's code for it (:class:`Unreadable`'s kinds).
_UNREADABLE = {
    NESTED: N_("lists nested more than {count} deep"),
    ARRAY: N_("an array of {count:,} numbers"),
    LIST: N_("a list of {count:,} items"),
    ITERATOR: N_("an iterator of more than {count:,} items"),
    BYTES: N_("an array whose bytes do not match its shape and type"),
}
#: What the confined child refused, by its code; any other code is a refused audit event.
_REFUSALS = {
    READ: N_("the grading process reads no file outside Python's and numpy's own: {subject}"),
    CHANGE: N_("the grading process writes only in its own working folder: {subject}"),
    UP: N_("the grading process opens no path that climbs with '..': {subject}"),
    LOAD: N_("the grading process does not load {subject}: numpy and Python's own modules only"),
    EVENT: N_(
        "the grading process does not allow {subject} (no processes, signals, sockets or ctypes)"
    ),
}


def _refusal(kind: str, subject: str) -> str:
    """What the grader's confined child refused to do, in the student's language."""
    return _(_REFUSALS.get(kind, _REFUSALS[EVENT])).format(subject=subject)


def outside_function(
    cells: Sequence[str],
    function: str,
    given: Mapping[str, Any] | None = None,
    **options: Any,
) -> Callable[..., Any]:
    """A stand-in for the student's ``function``, defined by ``cells``, run in a child process.

    Call ``.close()`` on it when done (the child is also stopped when it is collected).

    Examples
    --------
    >>> double = outside_function(["def double(x):\\n    return 2 * x"], "double")
    >>> double(21), inspect.signature(double)
    (42, <Signature (x)>)
    >>> double.close()
    """
    outside = Outside(cells, function, given, **options)

    def stand_in(*arguments: Any) -> Any:
        return outside.call(*arguments)

    stand_in.__name__ = stand_in.__qualname__ = function
    stand_in.__signature__ = outside.signature()  # type: ignore[attr-defined]
    stand_in.outside = outside  # type: ignore[attr-defined]
    stand_in.close = outside.close  # type: ignore[attr-defined]
    return stand_in
