"""``python -m course.classroom.foreground MODULE ARGS``: ``python -m MODULE ARGS``, and Ctrl-C.

``python -m course lab`` and ``app`` start JupyterLab and Voila through this module. Ctrl-C
in a terminal reaches every process of its foreground group: the server as well as the
command that started it. A running server answers it its own way (JupyterLab asks "Shut
down this Jupyter server (y/[n])?", Voila stops); in the seconds before, while the server
still imports, Python's own answer would be a KeyboardInterrupt traceback. Here that Ctrl-C
ends the server as Ctrl-C ends a program, without a traceback: by SIGINT itself (POSIX),
which a shell and make read as interrupted; elsewhere with status 130.

Classroom tooling: its only input is the command :mod:`course.classroom.cli` writes, so it
checks none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import os
import runpy
import signal
import sys

__all__ = ["run_module"]

UNCHECKED = True  # see the module docstring


def run_module(arguments: list[str]) -> int:
    """Run ``python -m MODULE ARGS`` for ``arguments = [MODULE, *ARGS]``; 130 if interrupted.

    The module's own ``sys.exit`` ends the process as it would have; a KeyboardInterrupt
    before the module handles Ctrl-C itself ends it by SIGINT, as Python does, minus the
    traceback (as :mod:`course.classroom.cli` does).
    """
    module, *rest = arguments
    sys.argv[1:] = rest
    try:
        runpy.run_module(module, run_name="__main__", alter_sys=True)
    except KeyboardInterrupt:
        if os.name == "posix":
            signal.signal(signal.SIGINT, signal.SIG_DFL)
            os.kill(os.getpid(), signal.SIGINT)
        return 128 + signal.SIGINT
    return 0


if __name__ == "__main__":
    sys.exit(run_module(sys.argv[1:]))
