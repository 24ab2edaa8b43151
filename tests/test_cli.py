"""course.classroom.cli: ``python -m course``, and what each command has to load."""

import importlib.util
import json
import os
import re
import select
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest
from conftest import write_notebook

from course.classroom.cli import app_command, lab_command, main
from course.classroom.folders import inside_folder
from course.classroom.notebooks import NOTEBOOKS

# Runs ``python -m course ARGS`` in a fresh interpreter, then reports which of the
# heavy packages that run imported.
PROBE = """
import runpy, sys
sys.argv = ["python -m course", *sys.argv[1:]]
try:
    runpy.run_module("course", run_name="__main__", alter_sys=True)
except SystemExit as stop:
    code = stop.code
heavy = ("ipywidgets", "matplotlib", "PIL", "numpy", "scipy")
print(sorted(name for name in heavy if name in sys.modules), code, file=sys.stderr)
"""


class Servers(list):
    """``subprocess.Popen``'s stand-in for the servers: keeps each command; each stops at once."""

    def __call__(self, command: list[str]) -> "Servers":
        self.append(command)
        return self

    def __enter__(self) -> "Servers":
        return self

    def __exit__(self, *exception) -> None:
        return None

    def wait(self) -> int:
        return 0


def servers(monkeypatch) -> Servers:
    """The servers ``python -m course lab`` and ``app`` start, none of them really."""
    started = Servers()
    monkeypatch.setattr("subprocess.Popen", started)
    return started


def run_course(*args: str) -> tuple[list[str], int]:
    done = subprocess.run(
        [sys.executable, "-c", PROBE, *args], capture_output=True, text=True, check=True
    )
    loaded, code = done.stderr.strip().splitlines()[-1].rsplit(" ", 1)
    return json.loads(loaded.replace("'", '"')), int(code)


def test_the_student_edition_runs_without_numpy_matplotlib_or_ipywidgets(tmp_path):
    write_notebook(tmp_path / "01_first.ipynb", "# First")
    loaded, code = run_course("student", "--notebooks", str(tmp_path), "--out", str(tmp_path / "s"))
    assert code == 0 and (tmp_path / "s" / "01_first.ipynb").is_file()
    assert loaded == []


def test_the_probe_sees_what_a_command_loads(tmp_path):
    """The gallery draws, so it loads matplotlib: the probe above can tell."""
    write_notebook(tmp_path / "01_de_casteljau.ipynb", "# Lesson 01")
    loaded, code = run_course("gallery", "--notebooks", str(tmp_path), "--out", str(tmp_path))
    assert code == 2  # the folder holds the notebook: refused, after loading the lessons
    assert {"matplotlib", "ipywidgets", "numpy"} <= set(loaded)


def test_bad_arguments_are_reported_without_a_traceback(tmp_path, capsys):
    assert main(["student", "--notebooks", str(tmp_path / "none"), "--out", str(tmp_path)]) == 2
    assert "expected a folder of NN_topic.ipynb files" in capsys.readouterr().err


def test_an_out_folder_the_user_cannot_enter_is_a_message(tmp_path, capsys, monkeypatch):
    """As root every folder can be entered: the refusal the file system gives is simulated."""
    locked = tmp_path / "locked"
    real_exists = Path.exists

    def exists(path, *args, **kwargs):
        if path == locked / "out" or locked in path.parents:
            raise PermissionError(13, "Permission denied", str(path))
        return real_exists(path, *args, **kwargs)

    monkeypatch.setattr(Path, "exists", exists)
    write_notebook(tmp_path / "01_first.ipynb", "# First")
    out = locked / "out" / "student"
    assert main(["student", "--notebooks", str(tmp_path), "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert "Permission denied" in error and len(error.strip().splitlines()) == 1


def test_map_readme_refuses_a_folder_a_missing_file_and_a_read_only_one(
    tmp_path, capsys, monkeypatch
):
    write_notebook(tmp_path / "01_first.ipynb", "# First")
    for readme, said in [(tmp_path, "is a folder"), (tmp_path / "none.md", "is missing")]:
        assert main(["map", "--notebooks", str(tmp_path), "--readme", str(readme)]) == 2
        error = capsys.readouterr().err
        assert said in error and len(error.strip().splitlines()) == 1
    readme = tmp_path / "README.md"
    readme.write_text("no table\n")
    # os.access answers True to root for a read-only file: ask it as a student would be.
    monkeypatch.setattr("os.access", lambda path, mode: False)
    assert main(["map", "--notebooks", str(tmp_path), "--readme", str(readme)]) == 2
    assert "permission denied" in capsys.readouterr().err
    assert readme.read_text() == "no table\n"


def test_a_path_suffix_that_leaves_its_folder_is_refused():
    with pytest.raises(ValueError, match="suffix"):
        inside_folder(Path("out"), "a", "/../../x")
    with pytest.raises(ValueError, match="name"):
        inside_folder(Path("out"), "..", "")
    assert inside_folder(Path("out"), "a", ".png") == Path("out/a.png")


def test_lab_opens_the_student_edition_or_the_teachers_with_allow_root_as_root(monkeypatch):
    notebooks = Path("/course/notebooks")
    student = lab_command(notebooks, False, ["--no-browser"])
    teacher = lab_command(notebooks, True, [])
    assert "--LabApp.default_url=/lab/tree/student/00_index.ipynb" in student
    assert "--LabApp.default_url=/lab/tree/notebooks/00_index.ipynb" in teacher
    assert student[-1] == "--no-browser" and "--ServerApp.root_dir=/course" in student
    monkeypatch.setattr("os.geteuid", lambda: 0)
    assert "--allow-root" in lab_command(notebooks, False, [])
    monkeypatch.setattr("os.geteuid", lambda: 1000)
    assert "--allow-root" not in lab_command(notebooks, False, [])


def test_the_nbgrader_command_writes_a_course_folder_and_keeps_a_teachers_config(tmp_path):
    out = tmp_path / "grading"
    assert main(["nbgrader", "--out", str(out)]) == 0
    sources = sorted(path.parent.name for path in out.glob("source/*/*.ipynb"))
    assert sources and all(re.fullmatch(r"\d\d_\w+", name) for name in sources)
    assert "00_index" not in sources
    (out / "nbgrader_config.py").write_text("c = get_config()  # mine\n")
    assert main(["nbgrader", "--out", str(out)]) == 2  # not empty: --force to rewrite
    assert main(["nbgrader", "--out", str(out), "--force"]) == 0
    assert "# mine" in (out / "nbgrader_config.py").read_text()


def test_lab_takes_over_a_student_folder_written_before_the_manifest(tmp_path, monkeypatch):
    lessons = tmp_path / "notebooks"
    lessons.mkdir()
    write_notebook(lessons / "01_first.ipynb", "# First")
    old = tmp_path / "student" / "01_first.ipynb"
    old.parent.mkdir()
    old.write_text(json.dumps({"cells": [], "metadata": {}, "nbformat": 4, "nbformat_minor": 5}))
    started = servers(monkeypatch)
    assert main(["lab", "--notebooks", str(lessons), "--no-browser"]) == 0
    assert started and started[0][-1] == "--no-browser"
    assert json.loads(old.read_text())["cells"] == []  # the old copy is kept as the student's
    assert (tmp_path / "student" / "01_first.new.ipynb").is_file()


def twin_folder(tmp_path: Path) -> Path:
    """A course folder with one English lesson and its Chinese twin."""
    lessons = tmp_path / "notebooks"
    (lessons / "zh-CN").mkdir(parents=True)
    write_notebook(lessons / "00_index.ipynb", "# Course map")
    write_notebook(lessons / "zh-CN" / "00_index.ipynb", "# 课程地图")
    return lessons


def test_lab_in_chinese_writes_the_chinese_student_edition_and_opens_its_map(
    tmp_path, monkeypatch, capsys
):
    lessons = twin_folder(tmp_path)
    started = servers(monkeypatch)
    monkeypatch.delenv("COURSE_LANG", raising=False)
    assert main(["lab", "--notebooks", str(lessons), "--language", "zh-CN"]) == 0
    chinese = json.loads((tmp_path / "student" / "zh-CN" / "00_index.ipynb").read_text())
    assert chinese["cells"][0]["source"] == "# 课程地图"
    assert not (tmp_path / "student" / "00_index.ipynb").exists()
    assert "--LabApp.default_url=/lab/tree/student/zh-CN/00_index.ipynb" in started[-1]
    # The command's own report speaks the edition's language too.
    assert "student/zh-CN/: 写入 1 个笔记本" in capsys.readouterr().err
    # COURSE_LANG says the same when --language is not given; --language wins over it.
    monkeypatch.setenv("COURSE_LANG", "zh-CN")
    assert main(["lab", "--notebooks", str(lessons), "--teacher"]) == 0
    assert "--LabApp.default_url=/lab/tree/notebooks/zh-CN/00_index.ipynb" in started[-1]
    assert main(["lab", "--notebooks", str(lessons), "--language", "en"]) == 0
    assert "--LabApp.default_url=/lab/tree/student/00_index.ipynb" in started[-1]
    english = json.loads((tmp_path / "student" / "00_index.ipynb").read_text())
    assert english["cells"][0]["source"] == "# Course map"


@pytest.mark.parametrize(
    ("arguments", "variable", "named"),
    [
        (["lab", "--language", "fr"], None, "--language"),
        (["app", "--language", ""], None, "--language"),
        (["student", "--out", "OUT"], "zh_CN", "COURSE_LANG"),
        (["nbgrader", "--out", "OUT", "--language", "ZH-cn"], None, "--language"),
    ],
)
def test_an_unknown_language_is_one_line_exit_2_naming_the_choices(
    tmp_path, monkeypatch, capsys, arguments, variable, named
):
    lessons = twin_folder(tmp_path)
    started = servers(monkeypatch)
    if variable is None:
        monkeypatch.delenv("COURSE_LANG", raising=False)
    else:
        monkeypatch.setenv("COURSE_LANG", variable)
    out = tmp_path / "out"
    arguments = [str(out) if argument == "OUT" else argument for argument in arguments]
    assert main([*arguments, "--notebooks", str(lessons)]) == 2
    error = capsys.readouterr().err.strip()
    assert len(error.splitlines()) == 1
    assert error.startswith(f"python -m course {arguments[0]}: {named}: expected one of ")
    assert "en, zh-CN" in error
    assert not started and not out.exists() and not (tmp_path / "student").exists()


def test_app_serves_a_languages_lessons_in_voila_with_the_prompt_connection(tmp_path, monkeypatch):
    lessons = twin_folder(tmp_path)
    started = servers(monkeypatch)
    monkeypatch.delenv("COURSE_LANG", raising=False)
    assert (
        main(["app", "--notebooks", str(lessons), "--port", "9000", "--show_tracebacks=True"]) == 0
    )
    assert main(["app", "--notebooks", str(lessons), "--language", "zh-CN"]) == 0
    english, chinese = started
    # Each starts through the module that spares a Ctrl-C during start-up its traceback.
    assert english[1:5] == ["-m", "course.classroom.foreground", "voila", str(lessons)]
    assert chinese[1:5] == ["-m", "course.classroom.foreground", "voila", str(lessons / "zh-CN")]
    assert "--port=9000" in english and "--show_tracebacks=True" in english
    assert "--port=8866" in chinese
    for command in started:
        assert command[-1] == (
            "--Voila.kernel_websocket_connection_class=course.classroom.serving.PromptConnection"
        )
    with pytest.raises(ValueError, match="port"):
        app_command(lessons, 0, [])


def test_make_passes_course_lang_to_every_edition_and_never_reads_lang():
    makefile = (Path(__file__).resolve().parent.parent / "Makefile").read_text()
    assert "\nCOURSE_LANG ?= en\n" in makefile
    for command in ("lab", "lab --teacher", "app", "student", "nbgrader"):
        # Single quotes: make runs the line itself, not through sh (see the Ctrl-C test).
        assert f"-m course {command} --language '$(COURSE_LANG)'" in makefile, command
    assert "$(LANG)" not in makefile and "${LANG}" not in makefile


def test_the_readme_names_only_targets_that_take_course_lang():
    """``make test`` and ``make site`` ignore COURSE_LANG (both do both languages)."""
    repository = Path(__file__).resolve().parent.parent
    makefile = (repository / "Makefile").read_text()
    readme = (repository / "README.md").read_text(encoding="utf-8")
    taking = set(
        re.findall(
            r"^(\w[\w-]*):.*\n(?:\t.*\n)*?\t.*--language '\$\(COURSE_LANG\)'",
            makefile,
            re.MULTILINE,
        )
    )
    named = set(re.findall(r"make (\w[\w-]*) COURSE_LANG=zh-CN", readme))
    assert {"lab", "teach", "app", "student", "nbgrader"} <= named <= taking, (named, taking)


def test_the_english_edition_goes_beside_a_chinese_one_written_first(tmp_path, monkeypatch):
    lessons = twin_folder(tmp_path)
    monkeypatch.delenv("COURSE_LANG", raising=False)
    student = tmp_path / "student"
    chinese = ["student", "--notebooks", str(lessons), "--out", str(student / "zh-CN")]
    assert main([*chinese, "--language", "zh-CN"]) == 0
    assert main(["student", "--notebooks", str(lessons), "--out", str(student)]) == 0
    assert (student / "00_index.ipynb").is_file() and (
        student / "zh-CN" / "00_index.ipynb"
    ).is_file()
    # Anything else in the folder is still refused without --force.
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "notes.txt").write_text("mine")
    assert main(["student", "--notebooks", str(lessons), "--out", str(tmp_path / "other")]) == 2


def test_student_without_out_writes_student_beside_the_lessons_as_make_student(
    tmp_path, monkeypatch
):
    """The README's ``python -m course student``: student/, student/zh-CN/ in Chinese."""
    lessons = twin_folder(tmp_path)
    monkeypatch.delenv("COURSE_LANG", raising=False)
    assert main(["student", "--notebooks", str(lessons)]) == 0
    assert main(["student", "--notebooks", str(lessons), "--language", "zh-CN"]) == 0
    assert main(["student", "--notebooks", str(lessons)]) == 0  # again: an update
    assert (tmp_path / "student" / "00_index.ipynb").is_file()
    assert (tmp_path / "student" / "zh-CN" / "00_index.ipynb").is_file()
    with pytest.raises(SystemExit):
        main(["nbgrader", "--notebooks", str(lessons)])  # where a course goes: say it


def test_a_chinese_editions_errors_are_chinese_and_the_library_is_english_after(
    tmp_path, monkeypatch, capsys
):
    import course

    lessons = twin_folder(tmp_path)
    monkeypatch.setenv("COURSE_LANG", "zh-CN")
    afile = tmp_path / "a file"
    afile.write_text("not a folder")
    student = ["student", "--notebooks", str(lessons), "--out"]
    assert main([*student, str(afile)]) == 2
    assert (
        capsys.readouterr().err
        == f"python -m course student: out：应为文件夹；实际为文件 {afile}\n"
    )
    assert main([*student, str(afile / "inside")]) == 2
    assert "不是文件夹" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main([*student, str(tmp_path / "out"), "--bogus"])
    assert "无法识别的参数：--bogus" in capsys.readouterr().err
    assert course.current_language() == "en"
    # English unchanged.
    assert main([*student, str(afile), "--language", "en"]) == 2
    assert capsys.readouterr().err == (
        f"python -m course student: out: expected a folder; got the file {afile}\n"
    )


# Ctrl-C, as a terminal sends it: SIGINT to every process of the foreground group, here the
# command and the server it started (its own session, so pytest is spared).
POSIX_ONLY = pytest.mark.skipif(os.name != "posix", reason="process groups and ptys are POSIX")


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def start_server(tmp_path: Path, command: str, port: int, **streams) -> subprocess.Popen:
    """``python -m course lab --no-browser`` or ``app`` on a free port, on two tiny lessons."""
    lessons = tmp_path / "notebooks"
    lessons.mkdir()
    write_notebook(lessons / "00_index.ipynb", "# Course map")
    write_notebook(lessons / "01_first.ipynb", "# First")
    options = {
        "lab": ["--no-browser", f"--ServerApp.port={port}", "--ServerApp.port_retries=0"],
        "app": ["--port", str(port)],
    }[command]
    environment = {k: v for k, v in os.environ.items() if k != "COURSE_LANG"}
    environment |= {"JUPYTER_CONFIG_DIR": str(tmp_path / "config")}
    environment |= {"JUPYTER_RUNTIME_DIR": str(tmp_path / "runtime")}
    return subprocess.Popen(
        [sys.executable, "-m", "course", command, "--notebooks", str(lessons), *options],
        cwd=tmp_path,
        env=environment,
        start_new_session=True,
        preexec_fn=terminal_sigint,
        **streams,
    )


def terminal_sigint() -> None:
    # A shell without job control starts its background jobs with Ctrl-C ignored, and an
    # ignored signal stays ignored through exec: a test run started that way would hand
    # every server it starts a deaf ear. The server gets Ctrl-C as a terminal's program does.
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def wait_until_up(server: subprocess.Popen, url: str, log) -> None:
    deadline = time.monotonic() + 120
    while True:
        assert server.poll() is None, log()
        try:
            with urllib.request.urlopen(url, timeout=5):
                return
        except urllib.error.HTTPError:
            return  # it answers: up (JupyterLab asks for its token)
        except (urllib.error.URLError, ConnectionError, TimeoutError):
            assert time.monotonic() < deadline, log()
            time.sleep(0.3)


@POSIX_ONLY
@pytest.mark.parametrize("command", ["lab", "app"])
def test_ctrl_c_stops_the_server_without_a_traceback(tmp_path, command):
    """Without a terminal, as in a service's log: one Ctrl-C stops the server, status 0."""
    if command == "app" and importlib.util.find_spec("voila") is None:
        pytest.skip("Voila is in the app set, not installed here")
    port = free_port()
    log = tmp_path / "server.log"
    with log.open("w") as output:
        server = start_server(
            tmp_path, command, port, stdout=output, stderr=subprocess.STDOUT, text=True
        )
    try:
        wait_until_up(server, f"http://127.0.0.1:{port}/", log.read_text)
        os.killpg(server.pid, signal.SIGINT)
        assert server.wait(timeout=15) == 0, log.read_text()
    finally:
        if server.poll() is None:
            os.killpg(server.pid, signal.SIGKILL)
            server.wait()
    said = log.read_text()
    assert "Traceback" not in said and "KeyboardInterrupt" not in said, said
    assert ("Interrupted..." if command == "lab" else "[Voila] Stopping...") in said


@POSIX_ONLY
def test_in_a_terminal_ctrl_c_asks_jupyterlabs_question_and_y_stops_it(tmp_path):
    """The README's words: Ctrl-C, then y; this command waits for the answer, alive."""
    port = free_port()
    controller, terminal = os.openpty()
    server = start_server(tmp_path, "lab", port, stdin=terminal, stdout=terminal, stderr=terminal)
    os.close(terminal)
    said = b""

    def read(until: bytes, seconds: float) -> bytes:
        nonlocal said
        deadline = time.monotonic() + seconds
        while until not in said and time.monotonic() < deadline:
            if select.select([controller], [], [], 0.2)[0]:
                try:
                    said += os.read(controller, 65536)
                except OSError:  # the terminal closed: every process of it ended
                    break
        return said

    try:
        wait_until_up(server, f"http://127.0.0.1:{port}/", lambda: read(b"", 1).decode())
        read(b"twice to skip confirmation", 60)
        os.killpg(server.pid, signal.SIGINT)
        assert b"Shut down this Jupyter server (y/[n])?" in read(b"(y/[n])?", 15)
        assert server.poll() is None, "the first Ctrl-C leaves the answer to the user"
        os.write(controller, b"y\n")
        assert b"Shutdown confirmed" in read(b"Shutdown confirmed", 15)
        assert server.wait(timeout=15) == 0
    finally:
        if server.poll() is None:
            os.killpg(server.pid, signal.SIGKILL)
            server.wait()
        os.close(controller)
    assert b"Traceback" not in said and b"KeyboardInterrupt" not in said, said.decode()
    readme = (Path(__file__).resolve().parent.parent / "README.md").read_text(encoding="utf-8")
    assert (
        "press Ctrl-C in that terminal: JupyterLab asks `Shut down this Jupyter server "
        "(y/[n])?`; answer `y` and Enter, or press Ctrl-C again"
    ) in " ".join(readme.split())


@POSIX_ONLY
def test_ctrl_c_while_the_server_starts_ends_it_quietly_as_interrupted(tmp_path):
    """Before JupyterLab answers Ctrl-C itself, the command ends as Ctrl-C ends a program."""
    port = free_port()
    server = start_server(
        tmp_path, "lab", port, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
    )
    try:
        # Its first line: the student edition written, JupyterLab starting (importing).
        assert server.stdout.readline().startswith("student/: ")
        os.killpg(server.pid, signal.SIGINT)
        # How it ends, not how fast: on a fresh clone under a parallel test run the first
        # start also compiles the Jupyter stack's bytecode (15 s was once not enough).
        said, _ = server.communicate(timeout=120)
    finally:
        if server.poll() is None:
            os.killpg(server.pid, signal.SIGKILL)
            server.wait()
    assert server.returncode == -signal.SIGINT, said
    assert "Traceback" not in said and "KeyboardInterrupt" not in said, said


# --- what a student or a careless folder hands the commands (issue 34) ------------------------


def deep_notebook(path: Path, depth: int) -> None:
    """A notebook whose cell metadata nests ``depth`` lists deep."""
    write_notebook(path, "# Deep")
    notebook = json.loads(path.read_text())
    text = json.dumps(notebook).replace('"metadata": {}', '"metadata": {"deep": []}', 1)
    path.write_text(text.replace("[]", "[" * depth + "]" * depth, 1))


@pytest.mark.parametrize("depth", [100_000, 700])  # json.loads gives up; what follows did
@pytest.mark.parametrize("command", ["student", "map", "nbgrader"])
def test_json_nested_deep_is_one_line_naming_the_file(tmp_path, capsys, command, depth):
    lessons = tmp_path / "lessons"
    lessons.mkdir()
    write_notebook(lessons / "01_first.ipynb", "# First")
    deep_notebook(lessons / "02_deep.ipynb", depth)
    out = [] if command == "map" else ["--out", str(tmp_path / "out")]
    assert main([command, "--notebooks", str(lessons), *out]) == 2
    error = capsys.readouterr().err
    assert len(error.strip().splitlines()) == 1
    assert f"{lessons / '02_deep.ipynb'}: not a notebook file" in error
    assert "nested deeper than 100 levels" in error


def test_a_students_deep_notebook_in_the_edition_is_kept_as_their_work(tmp_path, capsys):
    lessons = tmp_path / "lessons"
    lessons.mkdir()
    write_notebook(lessons / "01_first.ipynb", "# First")
    out = tmp_path / "student"
    assert main(["student", "--notebooks", str(lessons), "--out", str(out)]) == 0
    deep_notebook(out / "01_first.ipynb", 100_000)
    assert main(["student", "--notebooks", str(lessons), "--out", str(out)]) == 0
    assert (out / "01_first.ipynb").read_text().startswith('{"cells"')  # untouched
    assert "notebooks written: 0; unchanged: 0; with your edits kept: 1" in capsys.readouterr().err


def run_command(*args: str) -> subprocess.CompletedProcess:
    """``python -m course ARGS`` in a fresh interpreter: a command that waits fails, not hangs."""
    return subprocess.run(
        [sys.executable, "-m", "course", *args], capture_output=True, text=True, timeout=300
    )


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")
def test_a_pipe_named_as_a_lesson_is_one_line_naming_it_never_waited_on(tmp_path):
    lessons = tmp_path / "lessons"
    lessons.mkdir()
    write_notebook(lessons / "01_first.ipynb", "# First")
    os.mkfifo(lessons / "01_x.ipynb")
    done = run_command("student", "--notebooks", str(lessons), "--out", str(tmp_path / "out"))
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1
    assert f"{lessons / '01_x.ipynb'}: not a notebook file (not a regular file" in done.stderr
    # In the edition's own folder: the name the edition needs is refused, nothing written.
    (lessons / "01_x.ipynb").unlink()
    out = tmp_path / "student"
    out.mkdir()
    os.mkfifo(out / "01_first.ipynb")
    done = run_command("student", "--notebooks", str(lessons), "--out", str(out), "--force")
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1
    assert f"out: {out / '01_first.ipynb'} is not a regular file" in done.stderr
    assert [path.name for path in out.iterdir()] == ["01_first.ipynb"]


def test_nbgrader_force_writes_nothing_through_a_source_link_that_leads_out(tmp_path, capsys):
    lessons = tmp_path / "lessons"
    lessons.mkdir()
    shutil.copy(NOTEBOOKS / "01_de_casteljau.ipynb", lessons)
    outside, out = tmp_path / "outside", tmp_path / "course"
    outside.mkdir()
    out.mkdir()
    (out / "source").symlink_to(outside)
    command = ["nbgrader", "--notebooks", str(lessons), "--out", str(out), "--force"]
    assert main(command) == 2
    error = capsys.readouterr().err
    assert len(error.strip().splitlines()) == 1
    assert f"{out / 'source' / '01_de_casteljau'}" in error and "leads outside" in error
    assert list(outside.iterdir()) == [] and sorted(p.name for p in out.iterdir()) == ["source"]
    # A link that stays inside the folder is followed.
    (out / "source").unlink()
    (out / "lessons").mkdir()
    (out / "source").symlink_to("lessons")
    assert main(command) == 0
    assert (out / "lessons" / "01_de_casteljau" / "01_de_casteljau.ipynb").is_file()


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")
def test_gallery_force_replaces_a_pipe_of_a_pictures_name_never_waits_on_it(tmp_path):
    out = tmp_path / "gallery"
    out.mkdir()
    os.mkfifo(out / "02_pascal_triangle.png")
    done = run_command("gallery", "--only", "02_pascal_triangle", "--out", str(out), "--force")
    assert done.returncode == 0, done.stderr
    assert (out / "02_pascal_triangle.png").read_bytes().startswith(b"\x89PNG")
    assert [path.name for path in out.iterdir()] == ["02_pascal_triangle.png"]
