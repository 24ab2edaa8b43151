"""docs/hub.md's "On a university's server", as written: the hub from a copied configuration.

The server's steps are read from docs/hub.md's code block and run in a temporary folder
(``/etc/jupyterhub`` and ``/srv/course`` under it, ``/opt/course`` this checkout), except
the three that install what ``make``'s hub set has installed. Then, on the hub they
start: a student logs in and is served the course map, the student edition built on that
first start; the teacher releases lesson 01 and a quiz, the student submits the lesson
they worked in and fetches and submits the quiz (the Assignments panel's handlers), the
teacher collects both; and two Ctrl-C stop it all, with no error in the hub's log.
``make test`` installs the hub set; ``npm ci`` (a docs step) installs the proxy.
"""

from __future__ import annotations

import asyncio
import contextlib
import http.cookiejar
import json
import os
import re
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.parse
import urllib.request
from pathlib import Path
from types import SimpleNamespace

import nbformat
import pytest

pytest.importorskip("jupyterhub", reason="the hub set is not installed (make test installs it)")
pytest.importorskip("nbgrader", reason="the hub set is not installed (make test installs it)")
psutil = pytest.importorskip("psutil")

REPOSITORY = Path(__file__).resolve().parent.parent
DOCS = REPOSITORY / "docs" / "hub.md"
BIN = Path(sys.executable).parent
# The steps that install the course: make's hub set has done them in this checkout.
INSTALLED = (r"git clone \S+ /opt/course$", r"python3 -m venv \.venv$", r"\.venv/bin/pip install ")
TIMEOUT = 120  # seconds, for any one wait


def server_steps() -> list[str]:
    """The commands of docs/hub.md's "On a university's server" block, one a line."""
    section = DOCS.read_text().split("**On a university's server.**", 1)[1]
    block = re.search(r"```sh\n(.*?)```", section, re.DOTALL)
    assert block, "docs/hub.md's server section has no ```sh block"
    return [line for line in block.group(1).splitlines() if line.strip()]


def without_sudo(line: str) -> str:
    return re.sub(r"(^|&& )sudo ", r"\1", line)


def here(line: str, root: Path) -> str:
    """A docs line for this machine: the server's folders in ``root``, this checkout's venv."""
    line = line.replace("/opt/course/.venv/bin/", f"{BIN}/")
    line = line.replace("/opt/course", str(REPOSITORY))
    for folder in ("/etc/jupyterhub", "/srv/course"):
        line = line.replace(folder, str(root / folder.lstrip("/")))
    return line


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def default_sigint():
    # pytest may run under a shell that ignores Ctrl-C in the background; a hub is stopped
    # with it here, as in a terminal.
    signal.signal(signal.SIGINT, signal.SIG_DFL)


class Client:
    """A browser's cookies, or the admin token, against the hub at ``url``."""

    def __init__(self, url: str, token: str | None = None) -> None:
        self.url = url
        self.token = token
        self.opener = urllib.request.build_opener(
            urllib.request.HTTPCookieProcessor(http.cookiejar.CookieJar())
        )

    def request(self, method: str, path: str, form: dict | None = None):
        """(status, final address, body) of a request, redirects followed."""
        request = urllib.request.Request(
            self.url + path,
            method=method,
            data=None if form is None else urllib.parse.urlencode(form).encode(),
            headers={"Authorization": f"token {self.token}"} if self.token else {},
        )
        try:
            with self.opener.open(request, timeout=TIMEOUT) as response:
                return response.status, response.url, response.read().decode()
        except urllib.error.HTTPError as error:
            return error.code, error.url, error.read().decode(errors="replace")

    def json(self, method: str, path: str, form: dict | None = None):
        status, _, body = self.request(
            method, path, {} if form is None and method == "POST" else form
        )
        assert status < 300, f"{method} {path}: {status} {body[:500]}"
        return json.loads(body) if body else None


def wait_for(what: str, check, hub: subprocess.Popen, log: Path):
    deadline = time.monotonic() + TIMEOUT
    while time.monotonic() < deadline:
        assert hub.poll() is None, f"the hub exited while waiting for {what}:\n{log.read_text()}"
        with contextlib.suppress(OSError, AssertionError, ValueError):
            result = check()
            if result:
                return result
        time.sleep(0.3)
    raise TimeoutError(f"{what}: not within {TIMEOUT} s; the hub's log:\n{log.read_text()}")


def ready(admin: Client, user: str) -> dict | None:
    server = admin.json("GET", f"/hub/api/users/{user}")["servers"].get("")
    return server if server and server["ready"] else None


def test_the_docs_server_steps_run_a_class(tmp_path):
    steps = [without_sudo(line) for line in server_steps()]
    installed = [s for s in steps if any(re.match(p, s) for p in INSTALLED)]
    assert len(installed) == len(INSTALLED), f"the docs' install steps changed: {steps}"
    assert "requirements/hub.txt" in installed[-1]  # the set make's hub target installs
    *setup, start = [here(s, tmp_path) for s in steps if s not in installed]
    assert re.search(r"jupyterhub -f \S+/etc/jupyterhub/jupyterhub_config\.py$", start), start
    if shutil.which("npm") is None:
        pytest.fail("npm is missing: docs/hub.md's steps install the proxy with npm ci")
    done = subprocess.run(
        ["bash", "-euo", "pipefail", "-xc", "\n".join(setup)],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )
    assert done.returncode == 0, f"docs/hub.md's steps failed:\n{done.stdout}{done.stderr}"
    config = tmp_path / "etc" / "jupyterhub" / "jupyterhub_config.py"
    assert config.read_bytes() == (REPOSITORY / "hub" / "jupyterhub_config.py").read_bytes()

    data = tmp_path / "srv" / "course"
    port, token, password = free_port(), secrets.token_hex(32), secrets.token_hex(8)
    env = {
        key: value
        for key, value in os.environ.items()
        if not key.startswith(("COURSE_HUB_", "JUPYTER_"))
    }
    env.update(
        COURSE_HUB_PORT=str(port),
        COURSE_HUB_API_PORT=str(free_port()),
        COURSE_HUB_PROXY_API_PORT=str(free_port()),
        COURSE_HUB_PASSWORD=password,
        COURSE_HUB_ADMIN_TOKEN=token,
    )
    log = tmp_path / "hub.log"
    with log.open("w") as output:
        hub = subprocess.Popen(
            ["bash", "-c", start],
            env=env,
            stdout=output,
            stderr=subprocess.STDOUT,
            start_new_session=True,
            preexec_fn=default_sigint,
        )
    url = f"http://127.0.0.1:{port}"
    admin = Client(url, token)
    pids = []
    try:
        wait_for("the hub", lambda: admin.json("GET", "/hub/api/"), hub, log)
        # The data where the docs say: the folder the hub was started in.
        assert (data / "jupyterhub.sqlite").is_file()
        # The proxy `npm ci` installed in the checkout's hub/, found from /etc/jupyterhub.
        proxy = psutil.Process(int((data / "proxy.pid").read_text()))
        assert str(REPOSITORY / "hub" / "node_modules") in " ".join(proxy.cmdline())
        assert not (tmp_path / "etc" / "build").exists()  # the old rule: beside the config

        # A student logs in with the login form, as a browser does.
        student = Client(url)
        status, _, page = student.request("GET", "/hub/login")
        assert status == 200
        xsrf = re.search(r'name="_xsrf" value="([^"]+)"', page).group(1)
        student.request(
            "POST", "/hub/login", {"username": "ana", "password": password, "_xsrf": xsrf}
        )
        server = wait_for("ana's server", lambda: ready(admin, "ana"), hub, log)
        pids.append(server["state"]["pid"])
        admin.json("POST", "/hub/api/users/teacher/server")  # the teacher's, meanwhile

        # The course map, served: the edition was built on this first start, then seeded.
        lab = "/user/ana/lab/tree/student/00_index.ipynb"
        status, address, page = student.request("GET", lab)
        assert (status, urllib.parse.urlsplit(address).path) == (200, lab), page[:500]
        assert "jupyter-config-data" in page  # JupyterLab's page
        status, _, body = student.request("GET", "/user/ana/api/contents/student/00_index.ipynb")
        assert status == 200 and json.loads(body)["type"] == "notebook"
        assert (data / "student-edition" / "00_index.ipynb").is_file()
        assert "Building the student edition" in log.read_text()
        # The grader's panels are not a student's.
        disabled = json.loads(
            re.search(r'id="jupyter-config-data"[^>]*>(.*?)</script>', page, re.S).group(1)
        )["disabledExtensions"]
        assert "@jupyter/nbgrader:formgrader" in disabled
        assert student.request("GET", "/user/ana/formgrader")[0] == 404

        # nbgrader's exchange: nothing released yet, says the student's Assignments panel.
        listed = admin.json("GET", "/user/ana/assignments?course_id=course")
        assert listed == {"success": True, "value": []}, listed

        # The teacher releases two assignments from their nbgrader folder (the formgrader's
        # handlers): lesson 01, and one of their own.
        teacher = wait_for("the teacher's server", lambda: ready(admin, "teacher"), hub, log)
        pids.append(teacher["state"]["pid"])
        grading = data / "homes" / "teacher" / "nbgrader"
        for assignment in ("01_de_casteljau", "quiz"):
            source = grading / "source" / assignment
            source.mkdir(parents=True)
            nbformat.write(
                nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("answer = 42")]),
                source / f"{assignment}.ipynb",
            )
            for step in ("assign", "release"):
                api = f"/user/teacher/formgrader/api/assignment/{assignment}/{step}"
                answer = admin.json("POST", api)
                assert answer["success"], answer
        # The student's Assignments panel: lesson 01 is the one in the course map, already
        # there to submit; the quiz is to fetch.
        listed = admin.json("GET", "/user/ana/assignments?course_id=course")["value"]
        assert [(a["assignment_id"], a["status"], a["path"]) for a in listed] == [
            ("01_de_casteljau", "fetched", "assignments/01_de_casteljau"),
            ("quiz", "released", str(data / "exchange" / "course" / "outbound" / "quiz")),
        ]
        home = data / "homes" / "ana"
        worked = home / "student" / "01_de_casteljau.ipynb"
        lesson = nbformat.read(worked, as_version=4)
        lesson.cells.append(nbformat.v4.new_code_cell("# ana's work"))
        nbformat.write(lesson, worked)  # saved from the course map's lesson
        for action, assignment in (
            ("fetch", "quiz"),
            ("submit", "quiz"),
            ("submit", "01_de_casteljau"),
        ):
            form = {"course_id": "course", "assignment_id": assignment}
            answer = admin.json("POST", f"/user/ana/assignments/{action}", form)
            assert answer["success"], (action, assignment, answer)
        assert (home / "assignments" / "quiz" / "quiz.ipynb").is_file()
        collected = [
            admin.json("POST", f"/user/teacher/formgrader/api/assignment/{assignment}/collect")
            for assignment in ("01_de_casteljau", "quiz")
        ]
        assert all(answer["success"] for answer in collected), collected
        submitted = grading / "submitted" / "ana"
        assert (submitted / "quiz" / "quiz.ipynb").is_file()
        # What the teacher collects is the notebook the student worked in.
        handed_in = submitted / "01_de_casteljau" / "01_de_casteljau.ipynb"
        assert handed_in.read_bytes() == worked.read_bytes()
    finally:
        # Ctrl-C, twice, as an impatient teacher presses it.
        with contextlib.suppress(ProcessLookupError):
            os.killpg(hub.pid, signal.SIGINT)
            time.sleep(0.5)
            os.killpg(hub.pid, signal.SIGINT)
        try:
            hub.wait(timeout=60)
        except subprocess.TimeoutExpired:
            os.killpg(hub.pid, signal.SIGKILL)
            raise
        for pid in pids:  # the servers the hub started, ended by it
            with contextlib.suppress(ProcessLookupError, ChildProcessError):
                os.kill(pid, 0)
                os.kill(pid, signal.SIGKILL)
                pytest.fail(f"a student's server ({pid}) outlived the hub")
    shown = log.read_text()
    assert hub.returncode == 0, shown
    for error in ("Failed to stop user", "Task was destroyed", "Traceback"):
        assert error not in shown, shown
    assert "Cleaning up single-user servers" in shown


def test_with_the_lessons_repository_the_hub_opens_the_link_s_folder(tmp_path, monkeypatch):
    from traitlets.config.loader import PyFileConfigLoader

    from course.classroom.link import nbgitpuller_link, pull_path

    repository = "https://github.com/ORG/cg-student.git"
    monkeypatch.setenv("COURSE_HUB_LESSONS_REPO", repository)
    monkeypatch.chdir(tmp_path)
    config = PyFileConfigLoader("jupyterhub_config.py", str(REPOSITORY / "hub")).load_config()
    # The start page is the link's pull, into the link's folder: one copy of the lessons.
    assert config.Spawner.default_url == "/" + pull_path(repository)
    assert nbgitpuller_link("https://hub.uni.edu", repository).endswith(pull_path(repository))
    assert "targetpath=cg-student&" in config.Spawner.default_url
    assert (tmp_path / "exchange").stat().st_mode & 0o777 == 0o777
    # At a start, the hub builds and copies no edition; the lessons pulled are the student's
    # assignments, as the edition's are.
    home = tmp_path / "homes" / "ana"
    (home / "cg-student").mkdir(parents=True)
    (home / "cg-student" / "01_de_casteljau.ipynb").write_text("{}")
    student = SimpleNamespace(home_dir=str(home), user=SimpleNamespace(admin=False), log=None)
    asyncio.run(config.Spawner.pre_spawn_hook(student))
    assert sorted(path.name for path in home.iterdir()) == ["assignments", "cg-student"]
    linked = home / "assignments" / "01_de_casteljau" / "01_de_casteljau.ipynb"
    assert linked.resolve() == (home / "cg-student" / "01_de_casteljau.ipynb").resolve()
    assert not (tmp_path / "student-edition").exists()
