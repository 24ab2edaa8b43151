"""Opening, running and saving a lesson in JupyterLab leaves ``git status`` clean.

The lessons are copied into a temporary git repository and committed; a
JupyterLab of its own serves that copy. Each lesson is opened and saved at
once (JupyterLab rewrites the kernelspec it finds unless it is its own), then
run from the top (Run All) and saved again: ``git diff --quiet`` after each.
The status is printed (``-s``) for the record.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from collections.abc import Iterator
from pathlib import Path

import pytest
from playwright.sync_api import Page

from tests_browser.conftest import REPOSITORY, free_port, lab_command, server
from tests_browser.test_lab import kernel_idle, run_all_cells, shut_down_kernels


def git(copy: Path, *arguments: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        ["git", "-C", str(copy), *arguments], capture_output=True, text=True, check=False
    )


@pytest.fixture(scope="module")
def copy(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("clean") / "course"
    shutil.copytree(REPOSITORY / "notebooks", folder / "notebooks")
    shutil.copy2(REPOSITORY / ".gitignore", folder / ".gitignore")  # JupyterLab's checkpoints
    for command in (
        ["init", "-q"],
        ["add", "-A"],
        ["-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "lessons"],
    ):
        assert git(folder, *command).returncode == 0
    return folder


@pytest.fixture(scope="module")
def clean_lab(copy: Path, served: Path) -> Iterator[str]:
    port = free_port()
    command = [*lab_command(copy, port), "--ServerApp.disable_check_xsrf=True"]
    with server(command, served, "lab-clean", port, "/api/status") as base:
        yield base


def save(page: Page, path: Path) -> None:
    """Ctrl+S in the notebook, then wait until the file on disk has been rewritten."""
    before = path.stat().st_mtime_ns
    page.locator(".jp-Notebook").first.click()
    page.keyboard.press("Control+s")
    for _ in range(600):
        if path.stat().st_mtime_ns != before:
            break
        page.wait_for_timeout(100)
    else:
        raise AssertionError(f"{path.name} was not saved")
    page.wait_for_timeout(500)  # the whole file, not its first bytes


def open_lesson(page: Page, base: str, name: str) -> None:
    page.goto(f"{base}/lab/workspaces/clean-{name.split('.')[0]}/tree/notebooks/{name}?reset")
    page.locator(".jp-Notebook .jp-Cell").first.wait_for()
    kernel_idle(page)


def status(copy: Path) -> str:
    return git(copy, "status", "--porcelain").stdout.strip()


@pytest.mark.parametrize(
    "name",
    ["00_index.ipynb", "01_de_casteljau.ipynb"],
)
def test_open_run_all_and_save_leaves_git_clean(name, copy, clean_lab, page: Page):
    open_lesson(page, clean_lab, name)
    path = copy / "notebooks" / name
    try:
        save(page, path)
        opened = status(copy)
        print(f"\n{name}: after open and save, git status: {opened or 'clean'}")
        assert git(copy, "diff", "--quiet").returncode == 0, git(copy, "diff").stdout[:3000]
        assert opened == ""
        run_all_cells(page)
        save(page, path)
        ran = status(copy)
        print(f"{name}: after Run All and save, git status: {ran or 'clean'}")
        difference = git(copy, "diff").stdout
        changed = re.findall(r"^[-+](?![-+]).*$", difference, re.MULTILINE)
        if changed:
            print(f"{name}: {len(changed)} changed lines, such as:", *changed[:6], sep="\n  ")
        assert git(copy, "diff", "--quiet").returncode == 0, (changed, difference[:3000])
        assert ran == ""
    finally:
        shut_down_kernels(clean_lab)
        git(copy, "checkout", "--", ".")
