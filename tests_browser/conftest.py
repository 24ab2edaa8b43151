"""Servers and a browser for the lessons as students use them.

A JupyterLab server and a Voila server, each started on 127.0.0.1 on a free
port with no token, serving a copy of the notebooks (so that nothing a test
does, autosave included, can touch the committed files), and stopped at the
end of the session. The browser is Debian's Chromium (``/usr/bin/chromium``,
or ``$CHROMIUM``) driven by Playwright; Playwright's own browser download is
never used. Screenshots go to ``build/screenshots/`` (or ``$SCREENSHOTS``).
"""

from __future__ import annotations

import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")

from playwright.sync_api import Browser, Page, sync_playwright

from course.classroom.serving import CONNECTION_CLASS

REPOSITORY = Path(__file__).resolve().parent.parent
CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")
# What this machine's Chromium needs: no sandbox as root, no GPU, and no
# background connections (the network is closed, and they fail by the dozen).
CHROMIUM_FLAGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-dev-shm-usage",
]
BIN = Path(sys.executable).parent
SERVER_START_TIMEOUT = 120


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def wait_for_http(url: str, process: subprocess.Popen, log: Path) -> None:
    deadline = time.monotonic() + SERVER_START_TIMEOUT
    while time.monotonic() < deadline:
        if process.poll() is not None:
            raise RuntimeError(
                f"{url}: the server exited ({process.returncode}):\n{log.read_text()}"
            )
        try:
            with urllib.request.urlopen(url, timeout=5) as response:
                if response.status == 200:
                    return
        except (urllib.error.URLError, ConnectionError, TimeoutError):
            pass
        time.sleep(0.3)
    raise RuntimeError(f"{url}: no answer in {SERVER_START_TIMEOUT} s:\n{log.read_text()}")


@contextmanager
def server(command: list[str], root: Path, name: str, port: int, probe: str) -> Iterator[str]:
    """Run ``command`` with the Jupyter folders under ``root``; yield its base URL; stop it."""
    log = root / f"{name}.log"
    with log.open("w") as output:
        process = subprocess.Popen(
            command, stdout=output, stderr=subprocess.STDOUT, env=jupyter_environment(root)
        )
    base = f"http://127.0.0.1:{port}"
    try:
        wait_for_http(base + probe, process, log)
        yield base
    finally:
        stop(process)


def stop(process: subprocess.Popen) -> None:
    process.terminate()
    try:
        process.wait(timeout=20)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()


@pytest.fixture(scope="session")
def screenshots() -> Path:
    folder = Path(os.environ.get("SCREENSHOTS", REPOSITORY / "build" / "screenshots"))
    folder.mkdir(parents=True, exist_ok=True)
    return folder


@pytest.fixture(scope="session")
def served(tmp_path_factory) -> Path:
    """A private copy of the notebooks, and Jupyter folders of its own."""
    root = tmp_path_factory.mktemp("jupyter")
    shutil.copytree(REPOSITORY / "notebooks", root / "notebooks")
    settings = {
        # No "news" question popping up over the notebook in the screenshots.
        "apputils-extension/notification": {"fetchNews": "false"},
        # No empty page after the last cell: the screenshots end where the notebook does.
        "notebook-extension/tracker": {"scrollPastEnd": False},
    }
    for name, values in settings.items():
        path = root / "settings" / "@jupyterlab" / f"{name}.jupyterlab-settings"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(values))
    return root


def jupyter_environment(root: Path) -> dict[str, str]:
    environment = dict(os.environ)
    environment.update(
        JUPYTER_CONFIG_DIR=str(root / "config"),
        JUPYTER_RUNTIME_DIR=str(root / "runtime"),
        JUPYTERLAB_SETTINGS_DIR=str(root / "settings"),
        JUPYTERLAB_WORKSPACES_DIR=str(root / "workspaces"),
        PYDEVD_DISABLE_FILE_VALIDATION="1",
    )
    return environment


def lab_command(root_dir: Path, port: int, nagle: bool = False) -> list[str]:
    """JupyterLab on 127.0.0.1:``port`` serving ``root_dir``, no token, no news, no updates.

    The kernel's websocket sends at once (:mod:`course.classroom.serving`), as
    ``make lab`` has it, unless ``nagle``: jupyter_server's own, which holds
    small messages back for up to 40 ms.
    """
    command = [
        str(BIN / "jupyter"),
        "lab",
        "--no-browser",
        "--ServerApp.ip=127.0.0.1",
        f"--ServerApp.port={port}",
        "--ServerApp.port_retries=0",
        "--IdentityProvider.token=",
        "--ServerApp.password=",
        f"--ServerApp.root_dir={root_dir}",
        "--LabApp.news_url=None",
        "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
    ]
    if not nagle:
        command.append(f"--ServerApp.kernel_websocket_connection_class={CONNECTION_CLASS}")
    if os.geteuid() == 0:
        command.append("--allow-root")
    return command


@pytest.fixture(scope="session")
def lab(served: Path) -> Iterator[str]:
    """A JupyterLab server on 127.0.0.1, token disabled; its base URL."""
    port = free_port()
    command = lab_command(served / "notebooks", port)
    # The test shuts kernels down over the REST API between notebooks.
    command.append("--ServerApp.disable_check_xsrf=True")
    with server(command, served, "lab", port, "/api/status") as base:
        yield base


@pytest.fixture(scope="session")
def voila(served: Path) -> Iterator[str]:
    """A Voila server on 127.0.0.1 over the same notebooks; its base URL."""
    port = free_port()
    command = [
        str(BIN / "voila"),
        str(served / "notebooks"),
        "--no-browser",
        "--Voila.ip=127.0.0.1",
        f"--port={port}",
        "--Voila.port_retries=0",
        "--show_tracebacks=True",
        f"--Voila.kernel_websocket_connection_class={CONNECTION_CLASS}",
    ]
    with server(command, served, "voila", port, "/") as base:
        yield base


@pytest.fixture(scope="session")
def browser() -> Iterator[Browser]:
    if not Path(CHROMIUM).exists():
        pytest.fail(
            f"{CHROMIUM} is missing: install Debian's chromium (apt-get install -y chromium) "
            "or set CHROMIUM to a Chromium binary"
        )
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(
            executable_path=CHROMIUM, headless=True, args=CHROMIUM_FLAGS
        )
        yield browser
        browser.close()


@pytest.fixture
def page(browser: Browser) -> Iterator[Page]:
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    context.set_default_timeout(60_000)
    page = context.new_page()
    yield page
    context.close()
