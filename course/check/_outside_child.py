"""The child's side of :mod:`course.check.outside`: a student's cells, run in a fresh interpreter.

The grader starts ``python -I -S -c <program>``, the program being the text of
:mod:`course.check._wire` and then this file's: no site packages but numpy's folder, no
``course``, a temporary working folder. The grader's messages come on standard input and
the answers go out on the standard output it held at start (file descriptors 0 and 1,
duplicated; the student's ``print``, ``input`` and C-level output go elsewhere), as
:mod:`course.check._wire` frames them.

Every step of a call runs under the operating system's limits where it has them (an
address space, ``RLIMIT_AS``; a processor-time alarm, ``ITIMER_PROF``; ``RLIMIT_CPU`` for the
whole child), turning the returned value into JSON included: an endless iterator or a lying
object stops with the call. The grader also kills a child that stops answering.

Before the first line of the student's, the child confines itself (:func:`confine`, an audit
hook, PEP 578, which no Python code can remove): it opens files only in the folders the
grader names (the standard library, numpy, its own working folder, which alone it may
write), never in the site packages (where ``course`` is); it starts no process, sends no
signal, opens no socket, loads no ``ctypes``, and cannot list the objects (``gc``) that
would reach the hook. So the library's answers, the teacher's notebooks and the grader's
files are out of reach, however the student's code looks for them.

Standard library and numpy only, and no ``from __future__`` import: in the child this text
follows :mod:`course.check._wire`'s. The grader imports this module for its codes
(``UNCHECKED = True``: it trusts its caller).
"""

import contextlib
import io
import os
import sys
import traceback
import warnings
from typing import Any

if __name__ != "__main__":  # the grader's import; in the child, _wire's text came first
    from course.check._wire import Unreadable, decode, encode, read_message, write_message

UNCHECKED = True  # see the module docstring

#: Characters of printed output or of an error message kept.
MAX_TEXT = 4000


class _TimeUp(BaseException):
    """The processor-time alarm: a BaseException, so ``except Exception`` lets it by."""


class _TooManyCalls(BaseException):
    """More Python calls than the exercise allows (an exponential recursion)."""


def _student_line(error: BaseException) -> str | None:
    """The student's line where ``error`` was raised: the last frame in one of their cells."""
    found = None
    for frame, line in traceback.walk_tb(error.__traceback__):
        if frame.f_code.co_filename.startswith("<cell"):
            found = (frame.f_code.co_filename, line)
    if found is None:
        return None
    cell, line = found
    lines = _CELLS.get(cell, "").splitlines()
    return lines[line - 1].strip() if 0 < line <= len(lines) else None


_CELLS: dict[str, str] = {}


def _limits(memory: int, cpu_seconds: int) -> None:
    """The operating system's limits on this process: its address space grows by at most
    ``memory`` bytes, it computes for at most ``cpu_seconds``, its files stay small."""
    try:
        import resource
    except ImportError:  # Windows: the grader's kill is the limit
        return
    used = 0
    with contextlib.suppress(OSError, ValueError):  # no /proc on macOS: counted from 0
        with open("/proc/self/statm") as statm:
            used = int(statm.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    for limit, wanted in (
        (resource.RLIMIT_AS, used + memory),
        (resource.RLIMIT_CPU, cpu_seconds),
        (resource.RLIMIT_FSIZE, 64 * 2**20),
    ):
        _, hard = resource.getrlimit(limit)
        if hard == resource.RLIM_INFINITY or wanted < hard:
            with contextlib.suppress(ValueError, OSError):
                resource.setrlimit(limit, (wanted, hard))


def _alarm(seconds: float) -> None:
    import signal

    if hasattr(signal, "setitimer"):
        signal.setitimer(signal.ITIMER_PROF, max(seconds, 0.0))


def _on_alarm(signum: int, frame: Any) -> None:
    raise _TimeUp()


def _error(error: BaseException) -> dict[str, Any]:
    if isinstance(error, (Refused, RefusedImport)) and len(error.args) == 2:
        refused = [str(part)[:MAX_TEXT] for part in error.args]
        return {
            "type": type(error).__mro__[1].__name__,
            "builtin": True,
            "refused": refused,
            "message": "",
            "line": _student_line(error),
        }
    return {
        "type": type(error).__name__,
        "builtin": type(error).__module__ == "builtins",
        "message": str(error)[:MAX_TEXT],
        "line": _student_line(error),
    }


def _run(
    namespace: dict[str, Any], message: dict[str, Any], buffers: list[bytearray]
) -> tuple[dict[str, Any], list[Any]]:
    """One call of the student's function, its arguments in ``buffers``: the answer turned
    into JSON, under the alarm, and the bytes of its arrays."""
    function = namespace[message["function"]]
    arguments = [decode(value, buffers) for value in message["arguments"]]
    max_calls = message.get("max_calls")
    calls = [0]

    def count(frame: Any, event: str, argument: Any) -> None:
        if event == "call":
            calls[0] += 1
            if calls[0] > max_calls:
                raise _TooManyCalls()

    answer: dict[str, Any] = {}
    sent: list[Any] = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _alarm(message["seconds"])
        try:
            if max_calls is not None:
                sys.setprofile(count)
            try:
                returned = function(*arguments)
            finally:
                sys.setprofile(None)
            answer["returned"] = encode(returned, sent)
            answer["arguments"] = [encode(value, sent) for value in arguments]
        except _TimeUp:
            answer = {"stopped": "time"}
        except _TooManyCalls:
            answer = {"stopped": "calls", "calls": calls[0]}
        except MemoryError:
            answer = {"stopped": "memory"}
        except Unreadable as unreadable:
            answer = {"unreadable": list(unreadable.args)}
        except RecursionError as error:
            answer = {"error": _error(error)}
        except Exception as error:  # the student's bug, reported by the grader
            answer = {"error": _error(error)}
        except BaseException as error:  # SystemExit, KeyboardInterrupt: a bug too
            answer = {"error": _error(error)}
        finally:
            _alarm(0)
    answer["warnings"] = [str(w.message)[:MAX_TEXT] for w in caught[:20]]
    answer["calls"] = calls[0]
    return answer, (sent if "returned" in answer else [])


def main() -> None:
    # The folder that holds numpy, and nothing of the grader's; then any the grader allows.
    sys.path[:0] = sys.argv[1:]
    channel_in = os.fdopen(os.dup(0), "rb")
    channel_out = os.fdopen(os.dup(1), "wb")
    null = os.open(os.devnull, os.O_RDWR)
    for descriptor in (0, 1, 2):  # the student's input, prints and C-level output: nowhere
        os.dup2(null, descriptor)
    import signal

    signal.signal(signal.SIGPROF, _on_alarm)
    namespace: dict[str, Any] = {"__name__": "__main__"}
    # The grader's own messages: no bound on their size.
    while (received := read_message(channel_in, sys.maxsize - 1)) is not None:
        message, buffers = received
        printed = io.StringIO()
        sent: list[Any] = []
        with contextlib.redirect_stdout(printed), contextlib.redirect_stderr(printed):
            if message["op"] == "load":
                _limits(message["memory"], message["cpu_seconds"])
                answer = _load(namespace, message, buffers)
            else:
                answer, sent = _run(namespace, message, buffers)
        answer["printed"] = printed.getvalue()[-MAX_TEXT:]
        answer["asked"] = message.get("asked")
        write_message(channel_out, answer, sent)


#: Modules the confined child may not load: each reaches memory, processes or the hook.
_REFUSED_MODULES = frozenset(
    {"ctypes", "_ctypes", "_posixsubprocess", "_testcapi", "_testinternalcapi", "cffi"}
)
#: Audit events the confined child refuses outright.
_REFUSED_EVENTS = frozenset(
    {
        "subprocess.Popen",
        "os.system",
        "os.exec",
        "os.spawn",
        "os.posix_spawn",
        "os.fork",
        "os.forkpty",
        "os.startfile",
        "os.kill",
        "os.killpg",
        "signal.pthread_kill",
        "socket.__new__",
        "os.symlink",
        "os.link",
        "gc.get_objects",
        "gc.get_referrers",
        "gc.get_referents",
        "sys._current_frames",
    }
)
#: Audit events that change a file by its path: allowed in the working folder only.
_WRITES = frozenset(
    {
        "os.remove",
        "os.rmdir",
        "os.rename",
        "os.mkdir",
        "os.chmod",
        "os.chown",
        "os.utime",
        "os.truncate",
        "os.chflags",
        "os.lchflags",
        "shutil.rmtree",
    }
)


#: What the confined child refused (:class:`Refused`), worded by the grader.
READ, CHANGE, UP, LOAD, EVENT = "read", "change", "up", "load", "event"


class Refused(PermissionError):
    """A step the confined child does not take: what (:data:`READ`, :data:`CHANGE`,
    :data:`UP`, :data:`EVENT`) and on what (a path, an audit event's name)."""


class RefusedImport(ImportError):
    """A module the confined child does not load (:data:`LOAD`): an ImportError, so that a
    library that can do without it (numpy without ``ctypes``) does."""


def confine(
    granted: list[str],
    reads: list[str],
    refused: list[str],
    writes: list[str],
    with_ctypes: bool = False,
) -> None:
    """From now on this process opens a file only under ``granted`` or ``writes``, or under
    ``reads`` outside ``refused``; it writes only under ``writes``; it starts no process and
    loads none of :data:`_REFUSED_MODULES`. Paths with ``..`` are refused: a link the
    grader placed (numpy's) must not lead back up into the site packages.

    ``with_ctypes`` lets it load and use ``ctypes``: for a grader that grants folders of its
    own (the course's tests plant mistakes with the library, whose in-notebook checker
    uses ``ctypes``), never for a class."""
    normpath, join, fsdecode, getcwd, sep = (
        os.path.normpath,
        os.path.join,
        os.fsdecode,
        os.getcwd,
        os.sep,
    )
    granted_, reads_, refused_, writes_ = (
        tuple(granted),
        tuple(reads),
        tuple(refused),
        tuple(writes),
    )
    writing = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_TRUNC | os.O_APPEND
    refused_events, refused_modules, write_events = _REFUSED_EVENTS, _REFUSED_MODULES, _WRITES
    if with_ctypes:
        refused_modules = refused_modules - {"ctypes", "_ctypes"}

    def under(path: str, roots: tuple[str, ...]) -> bool:
        return any(path == root or path.startswith(root + sep) for root in roots)

    def where(path: Any) -> str:
        text = fsdecode(path)
        if ".." in text.replace("\\", "/").split("/"):
            raise Refused(UP, text)
        return normpath(join(getcwd(), text))

    def opens(path: Any, changes: bool) -> None:
        if isinstance(path, int):  # a descriptor already open: the channels, /dev/null
            return
        place = where(path)
        if under(place, writes_):
            return
        if not changes and (
            under(place, granted_) or (under(place, reads_) and not under(place, refused_))
        ):
            return
        raise Refused(CHANGE if changes else READ, place)

    def hook(event: str, arguments: tuple) -> None:
        if event == "open":
            path, mode, flags = arguments
            changes = (
                any(c in mode for c in "wax+") if isinstance(mode, str) else bool(flags & writing)
            )
            opens(path, changes)
        elif event == "import":
            if arguments[0] in refused_modules:
                raise RefusedImport(LOAD, arguments[0])
        elif event in refused_events or (event.startswith("ctypes.") and not with_ctypes):
            raise Refused(EVENT, event)
        elif event in write_events:
            for path in arguments[:2]:
                if isinstance(path, (str, bytes, os.PathLike)):
                    opens(path, changes=True)

    # ``subprocess`` imports it at import time (and matplotlib imports ``subprocess``): a
    # stand-in whose one function refuses, so the imports work and no process starts.
    stand_in = type(sys)("_posixsubprocess")
    stand_in.fork_exec = _refuse_fork_exec  # type: ignore[attr-defined]
    sys.modules["_posixsubprocess"] = stand_in
    sys.addaudithook(hook)


def _refuse_fork_exec(*arguments: Any) -> None:
    raise Refused(EVENT, "subprocess")


def _load(
    namespace: dict[str, Any], message: dict[str, Any], buffers: list[bytearray]
) -> dict[str, Any]:
    """Confine the process, then run the prelude, the given values (their arrays in
    ``buffers``) and the cells; the function's parameters."""
    if message.get("confine"):
        confine(**message["confine"])
    _alarm(message["seconds"])
    try:
        exec(compile(message["prelude"], "<prelude>", "exec"), namespace)
        namespace.update({name: decode(value, buffers) for name, value in message["given"].items()})
        for index, (source, last) in enumerate(message["cells"]):
            name = f"<cell {index}>"
            _CELLS[name] = source
            try:
                exec(compile(source, name, "exec"), namespace)
            except Exception as error:
                if last:
                    return {"error": _error(error)}
        function = namespace.get(message["function"])
        if not callable(function):
            return {"missing": message["function"]}
        import inspect

        try:
            parameters = [
                [p.name, p.kind.name, p.default is not p.empty]
                for p in inspect.signature(function).parameters.values()
            ]
        except (TypeError, ValueError):
            parameters = None
        return {"parameters": parameters}
    except _TimeUp:
        return {"stopped": "time"}
    except MemoryError:
        return {"stopped": "memory"}
    except BaseException as error:
        return {"error": _error(error)}
    finally:
        _alarm(0)


#: The child's exit status when memory ran out outside a call (printing, answering).
MEMORY_EXIT = 75

if __name__ == "__main__":
    try:
        main()
    except MemoryError:
        os._exit(MEMORY_EXIT)
