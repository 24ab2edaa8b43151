"""course.classroom.serving: the kernel's websocket sends each message at once."""

from jupyter_server.services.kernels.connection.channels import ZMQChannelsWebsocketConnection
from traitlets.utils.importstring import import_item

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
