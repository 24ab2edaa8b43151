"""course.classroom.serving: the kernel's websocket sends each message at once."""

from pathlib import Path

from jupyter_server.services.kernels.connection.channels import ZMQChannelsWebsocketConnection
from traitlets.utils.importstring import import_item

from course.classroom.cli import app_command, lab_command
from course.classroom.serving import CONNECTION_CLASS, PromptConnection


def test_the_servers_option_names_the_connection_class():
    # What jupyter_server does with --ServerApp.kernel_websocket_connection_class.
    assert import_item(CONNECTION_CLASS) is PromptConnection
    assert issubclass(PromptConnection, ZMQChannelsWebsocketConnection)


def test_nagle_is_turned_off_before_the_kernel_is_connected(monkeypatch):
    events = []

    class Handler:
        def set_nodelay(self, value):
            events.append(("nodelay", value))

    monkeypatch.setattr(
        ZMQChannelsWebsocketConnection, "connect", lambda self: events.append("connect")
    )
    monkeypatch.setattr(PromptConnection, "websocket_handler", Handler())
    PromptConnection.__new__(PromptConnection).connect()
    assert events == [("nodelay", True), "connect"]


def test_make_lab_and_make_app_start_their_servers_with_it():
    makefile = (Path(__file__).resolve().parent.parent / "Makefile").read_text()
    assert f"PROMPT := {CONNECTION_CLASS}\n" in makefile
    # make lab and make teach start JupyterLab through python -m course lab.
    assert "$(BIN)/python -m course lab" in makefile
    command = lab_command(Path("notebooks"), False, [])
    assert f"--ServerApp.kernel_websocket_connection_class={CONNECTION_CLASS}" in command
    # make app starts Voila through python -m course app.
    assert "$(BIN)/python -m course app" in makefile
    command = app_command(Path("notebooks"), 8866, [])
    assert f"--Voila.kernel_websocket_connection_class={CONNECTION_CLASS}" in command
