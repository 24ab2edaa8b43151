"""How the course is installed: make's help and checks, the locks, the README's plain commands.

The slowest test here runs the README's POSIX commands (a venv, pip install from the lock,
jupyter lab) in a temporary copy of the repository, so that they cannot rot.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import socket
import stat
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

import course

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10: pytest's own TOML reader
    import tomli as tomllib

REPOSITORY = Path(__file__).resolve().parent.parent
PYPROJECT = tomllib.loads((REPOSITORY / "pyproject.toml").read_text(encoding="utf-8"))
LOCKS = REPOSITORY / "requirements"
SETS = ("lab", "grade", "app", "test", "browser", "bench", "site", "hub")
REQUIREMENT = re.compile(r"^([A-Za-z0-9][A-Za-z0-9._-]*)(\[[^]]*\])?\s*(.*)$")


def name_of(requirement: str) -> str:
    return re.sub(r"[-_.]+", "-", REQUIREMENT.match(requirement).group(1)).lower()


def pins(lock: Path) -> dict[tuple[str, str], str]:
    """(name, environment marker) -> version, for every line of a lock."""
    found = {}
    for line in lock.read_text(encoding="utf-8").splitlines():
        line = line.split("#")[0].strip()
        if not line or line.startswith("-"):
            continue
        requirement, _, marker = line.partition(";")
        name, equals, version = requirement.partition("==")
        assert equals, f"{lock.name}: not pinned: {line}"
        found[(re.sub(r"[-_.]+", "-", name.strip()).lower(), marker.strip())] = version.strip()
    return found


def make(*arguments: str, **environment: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        ["make", "--no-print-directory", "-C", str(REPOSITORY), *arguments],
        capture_output=True,
        text=True,
        env={**os.environ, **environment},
        timeout=120,
    )


def test_make_alone_prints_one_line_per_target():
    done = make()
    assert done.returncode == 0, done.stderr
    lines = {line.split()[0]: line for line in done.stdout.splitlines() if line.startswith("  ")}
    for target in ("lab", "test", "test-latest", "test-browser", "site", "lock", "fuzz", "app"):
        assert target in lines and len(lines[target].split()) > 2, done.stdout
    assert "a longer fuzz campaign over every public function" in lines["fuzz"]


def test_reading_a_notebook_does_not_build_the_iri_grammar():
    # Installed, rfc3987-syntax is imported by jsonschema with nbformat and builds its Lark
    # grammar: 2.8 s for every nbgrader command and Jupyter server. make's install step
    # removes it (see the Makefile); a lock that brought it back would fail here.
    done = subprocess.run(
        [
            sys.executable,
            "-c",
            "import sys, nbformat; print(sorted({'rfc3987_syntax', 'lark'} & set(sys.modules)))",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"


def fake_python(tmp_path: Path, script: str) -> Path:
    path = tmp_path / "python"
    path.write_text(f"#!/bin/sh\n{script}\n")
    path.chmod(path.stat().st_mode | stat.S_IEXEC)
    return path


def test_make_lab_asks_for_python_3_10_before_installing(tmp_path):
    """As on macOS, whose command-line tools bring Python 3.9."""
    old = fake_python(tmp_path, 'case "$2" in *print*) echo 3.9;; *) exit 1;; esac')
    done = make("lab", f"PYTHON={old}", f"VENV={tmp_path / 'venv'}")
    assert done.returncode != 0
    assert "needs Python 3.10 or newer" in done.stderr and "is 3.9" in done.stderr
    assert not (tmp_path / "venv").exists()


def test_make_test_names_python3_venv_when_the_venv_module_cannot_work(tmp_path):
    """As on Debian and Ubuntu without python3-venv, where ensurepip is missing."""
    debian = fake_python(
        tmp_path, f'case "$2" in *ensurepip*) exit 1;; esac\nexec {sys.executable} "$@"'
    )
    done = make("test", f"PYTHON={debian}", f"VENV={tmp_path / 'venv'}")
    assert done.returncode != 0
    assert "sudo apt install python3-venv" in done.stderr
    assert not (tmp_path / "venv").exists()


def test_make_site_asks_for_node_and_npm_before_fetching_mathjax(tmp_path):
    """MathJax comes from npm's registry: without node and npm, one clear message first."""
    tools = tmp_path / "bin"  # make and what the Makefile itself runs, but no node, no npm
    tools.mkdir()
    for tool in ("make", "id"):
        (tools / tool).symlink_to(shutil.which(tool))
    mathjax = tmp_path / "mathjax"
    done = make(f"MATHJAX={mathjax}", f"{mathjax}/es5/tex-mml-chtml.js", PATH=str(tools))
    assert done.returncode != 0
    assert "make site: needs Node.js with its npm; node is missing, npm missing." in done.stderr
    assert "https://nodejs.org" in done.stderr and not mathjax.exists()


@pytest.mark.skipif(shutil.which("node") is None, reason="needs node")
def test_node_check_names_the_version_a_target_needs_and_the_one_it_found():
    """``$(call NODE_CHECK,MINIMUM,TARGET)``, as the hub's proxy rule calls it."""
    found = subprocess.run(["node", "--version"], capture_output=True, text=True).stdout.strip()
    major = int(found.lstrip("v").split(".")[0])
    for minimum, passes in [(str(major), True), (f"{major}.0", True), (str(major + 1), False)]:
        done = make("--eval", f"probe: ; $(call NODE_CHECK,{minimum},probe)", "probe")
        assert (done.returncode == 0) == passes, done.stderr
        if not passes:
            assert f"make probe: needs Node.js {minimum} or newer; node is {found}" in done.stderr


def declared() -> dict[str, list[str]]:
    """Each install set's requirements as pyproject.toml declares them."""
    extras = PYPROJECT["project"]["optional-dependencies"]
    groups = PYPROJECT["dependency-groups"]
    return {"core": PYPROJECT["project"]["dependencies"], **extras, **groups}


def test_extras_do_not_repeat_each_other_and_floors_agree():
    sets = declared()
    seen: dict[str, tuple[str, str]] = {}
    for where, requirements in sets.items():
        for requirement in requirements:
            if name_of(requirement) == "course":  # an extra built on another
                continue
            name, specifier = name_of(requirement), REQUIREMENT.match(requirement).group(3)
            if name in seen:
                other, other_specifier = seen[name]
                assert specifier == other_specifier, f"{name}: {other} {other_specifier}"
                assert where in ("dev", "site") or other in ("dev", "site"), (
                    f"{name} is in both {other} and {where}: an extra builds on another instead"
                )
            seen[name] = (where, specifier)
    assert "course[lab]" in sets["app"] and "course[app]" in sets["browser"]


def test_ruff_and_playwright_are_pinned():
    requirements = [r for rs in declared().values() for r in rs]
    assert any(re.fullmatch(r"ruff==[\d.]+", r) for r in requirements)
    assert any(re.fullmatch(r"playwright==[\d.]+", r) for r in requirements)


def test_every_set_is_locked_within_the_whole_lock():
    """A set's versions are the whole lock's (markers may differ: a set forks less)."""
    whole: dict[str, set[str]] = {}
    for (name, _), version in pins(LOCKS / "all.txt").items():
        whole.setdefault(name, set()).add(version)
    for lock in SETS:
        versions = pins(LOCKS / f"{lock}.txt")
        assert versions, lock
        astray = {name: v for (name, _), v in versions.items() if v not in whole.get(name, ())}
        assert astray == {}, f"{lock}.txt: versions that all.txt does not hold"
    for requirement in [r for rs in declared().values() for r in rs]:
        if name_of(requirement) != "course":
            assert name_of(requirement) in whole, f"{requirement} is missing from all.txt"


def test_a_student_installs_no_developer_tools():
    lab = {name for name, _ in pins(LOCKS / "lab.txt")}
    assert {"jupyterlab", "ipywidgets", "numpy"} <= lab
    assert not lab & {"pytest", "hypothesis", "ruff", "playwright", "sphinx", "voila", "nbgrader"}
    grade = {name for name, _ in pins(LOCKS / "grade.txt")}
    assert {"nbgrader", "jupyterlab", "numpy"} <= grade
    browser = {name for name, _ in pins(LOCKS / "browser.txt")}
    assert {"playwright", "voila", "jupyterlab"} <= browser


def test_the_version_is_written_once():
    assert course.__version__ == PYPROJECT["project"]["version"]
    assert (
        PYPROJECT["project"]["version"] not in (REPOSITORY / "course" / "__init__.py").read_text()
    )


def run_installed(site_packages: Path, cwd: Path, *arguments: str):
    environment = {k: v for k, v in os.environ.items() if k != "COURSE_NOTEBOOKS"}
    environment["PYTHONPATH"] = str(site_packages)
    return subprocess.run(
        [sys.executable, "-m", "course", *arguments],
        cwd=cwd,
        env=environment,
        capture_output=True,
        text=True,
        timeout=300,
    )


def test_an_installed_package_draws_the_gallery_and_asks_for_the_notebooks(tmp_path):
    """The package as ``pip install .`` lays it out: in site-packages, no notebooks beside."""
    site_packages = tmp_path / "site-packages"
    shutil.copytree(
        REPOSITORY / "course",
        site_packages / "course",
        ignore=shutil.ignore_patterns("__pycache__"),
    )
    where = run_installed(site_packages, tmp_path, "map")
    assert where.returncode == 2
    assert "--notebooks DIR" in where.stderr and "notebooks/ folder" in where.stderr
    student = run_installed(site_packages, tmp_path, "student", "--out", str(tmp_path / "s"))
    assert student.returncode == 2 and "--notebooks DIR" in student.stderr
    pointed = run_installed(
        site_packages,
        tmp_path,
        "student",
        "--out",
        str(tmp_path / "s"),
        "--notebooks",
        str(REPOSITORY / "notebooks"),
    )
    assert pointed.returncode == 0, pointed.stderr
    assert (tmp_path / "s" / "01_de_casteljau.ipynb").is_file()
    gallery = run_installed(
        site_packages,
        tmp_path,
        "gallery",
        "--out",
        str(tmp_path / "g"),
        "--only",
        "01_three_points",
    )
    assert gallery.returncode == 0, gallery.stderr
    assert (tmp_path / "g" / "01_three_points.png").is_file()
    probe = run_installed(
        site_packages, tmp_path, "map", "--notebooks", str(REPOSITORY / "notebooks")
    )
    assert probe.returncode == 0 and "Lesson 01" in probe.stdout


def readme_block(language: str, after: str) -> list[str]:
    readme = (REPOSITORY / "README.md").read_text(encoding="utf-8")
    section = readme[readme.index(after) :]
    block = re.search(rf"```{language}\n(.*?)```", section, re.DOTALL).group(1)
    return [line for line in block.splitlines() if line.strip()]


def copy_of_the_repository(destination: Path) -> None:
    """The files git would commit: tracked, and untracked but not ignored."""
    listed = subprocess.run(
        ["git", "-C", str(REPOSITORY), "ls-files", "-co", "--exclude-standard", "-z"],
        capture_output=True,
        check=True,
    ).stdout.decode()
    for name in filter(None, listed.split("\0")):
        source = REPOSITORY / name
        if source.is_file() and not name.startswith(("build/", "student/")):
            (destination / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, destination / name)


def test_the_readmes_windows_commands_are_the_posix_ones():
    posix = readme_block("sh", "### Without make")
    windows = readme_block("powershell", "### Without make")
    assert len(posix) == len(windows) == 3
    for unix, powershell in zip(posix, windows, strict=True):
        unix = unix.replace("python3 -m venv", "py -m venv").replace(".venv/bin/", ".venv/Scripts/")
        assert powershell.replace("\\", "/") == unix


@pytest.mark.skipif(not (REPOSITORY / ".git").exists(), reason="needs the git repository")
def test_the_readmes_commands_install_from_the_lock_and_start_jupyterlab(tmp_path):
    """The README's POSIX commands, as written, in a copy of the repository."""
    clone = tmp_path / "course"
    copy_of_the_repository(clone)
    *install, start = readme_block("sh", "### Without make")
    assert start == ".venv/bin/python -m course lab"
    for command in install:
        done = subprocess.run(
            command, shell=True, cwd=clone, capture_output=True, text=True, timeout=1200
        )
        assert done.returncode == 0, f"{command}\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    python = clone / ".venv" / "bin" / "python"
    slim = subprocess.run([python, "-c", "import pytest"], capture_output=True)
    assert slim.returncode != 0, "a student's install has no test tools"

    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    extra = f" --no-browser --ServerApp.port={port} --ServerApp.port_retries=0"
    # Only what a test needs on top: a free port, no browser, no token. As root too, the
    # block as printed must start the server (python -m course lab adds --allow-root).
    extra += " --IdentityProvider.token="
    log = (tmp_path / "lab.log").open("w")
    server = subprocess.Popen(
        start + extra,
        shell=True,
        cwd=clone,
        stdout=log,
        stderr=subprocess.STDOUT,
        env={**os.environ, "JUPYTER_CONFIG_DIR": str(tmp_path / "config")},
        start_new_session=True,
    )
    try:
        base = f"http://127.0.0.1:{port}"
        deadline = time.monotonic() + 180
        while True:
            assert server.poll() is None, (tmp_path / "lab.log").read_text()
            try:
                with urllib.request.urlopen(base + "/api/status", timeout=5) as response:
                    assert response.status == 200
                    break
            except (urllib.error.URLError, ConnectionError, TimeoutError):
                assert time.monotonic() < deadline, (tmp_path / "lab.log").read_text()
                time.sleep(0.5)
        # The server opens the student edition, written before it started.
        with urllib.request.urlopen(base + "/api/contents/student/00_index.ipynb") as response:
            assert response.status == 200
        with urllib.request.urlopen(base + "/api/contents/student/01_de_casteljau.ipynb") as got:
            lesson = json.loads(got.read())["content"]
        assert any("your code here" in "".join(cell["source"]) for cell in lesson["cells"])
    finally:
        os.killpg(server.pid, 15)
        server.wait(timeout=30)
        log.close()
