"""The Jupyter servers that show the lessons: each kernel message sent the moment it comes.

jupyter_server writes the kernel's messages to the browser's websocket with
Nagle's algorithm left on, so a small message that follows another waits for
the browser's acknowledgement of the first, which Linux and Chromium hold
back up to 40 ms. A drag redraws on every step and waits for each picture:
measured on this machine, a comm round trip took 47 ms at the median, and
8.4 ms with ``TCP_NODELAY`` on the websocket. ``make lab``, ``make app`` and
the browser tests start their servers with this connection class, as the
option ``--ServerApp.kernel_websocket_connection_class`` (JupyterLab) or
``--Voila.kernel_websocket_connection_class`` (Voila) set to
:data:`CONNECTION_CLASS`.

Classroom tooling for the course's authors and its browser tests: its
inputs come from the lesson registry, never from a student, so this module
checks none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

from typing import Any

from jupyter_server.services.kernels.connection.channels import ZMQChannelsWebsocketConnection

__all__ = ["CONNECTION_CLASS", "PromptConnection"]

UNCHECKED = True  # see the module docstring

#: The dotted name the servers' option takes.
CONNECTION_CLASS = "course.classroom.serving.PromptConnection"


class PromptConnection(ZMQChannelsWebsocketConnection):
    """jupyter_server's kernel websocket connection, with Nagle's algorithm off."""

    def connect(self) -> Any:
        self.websocket_handler.set_nodelay(True)
        return super().connect()
