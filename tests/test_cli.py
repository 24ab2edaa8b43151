"""course.classroom.cli: ``python -m course``, and what each command has to load."""

import json
import subprocess
import sys

from conftest import write_notebook

from course.classroom.cli import main

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
