"""Every notebook run in JupyterLab in Chromium; each registered slider moved, each drag made.

For each ``notebooks/NN_*.ipynb``: open it, clear the committed outputs (so
that only what this run produces is seen), Run All Cells from the menu, wait
until every code cell has run and the kernel is idle, then assert that no
output shows an error and that every slider app rendered its picture. A
screenshot of the whole notebook is kept. For each slider that the lesson's
module in ``course.lessons`` registers, the slider is moved with the keyboard,
and after each move the picture must have changed and match what the
library renders for the value the slider now shows, landmarks included
(lesson 01: the red dot at the point ``de_casteljau`` returns; lesson 03:
the Bresenham pixels where ``course.raster.line`` puts them). Each registered
drag is made with the mouse, pressed where the picture draws the handle, and
the picture must then show what the library draws after the same drag.
"""

from __future__ import annotations

import json
import re
import urllib.request

import pytest
from playwright.sync_api import Page

from course.classroom.notebooks import NOTEBOOKS, notebooks
from course.classroom.registry import lessons
from tests_browser.student import (
    drag_like_a_student,
    error_outputs,
    move_sliders_like_a_student,
    slider_apps_in,
    tall_screenshot,
    unrendered_apps,
    wait_for_pictures,
)

BOOKS = notebooks(NOTEBOOKS, index=True)
LESSONS = lessons()
RUN_TIMEOUT = 300  # seconds for one notebook's Run All


def menu(page: Page, top: str, item: str) -> None:
    page.locator(".lm-MenuBar-itemLabel").get_by_text(top, exact=True).click()
    page.locator(".lm-Menu-itemLabel").get_by_text(item, exact=True).click()


def kernel_idle(page: Page, timeout: float = 60) -> None:
    page.get_by_text(re.compile(r"\| Idle$")).first.wait_for(timeout=timeout * 1000)


def prompts(page: Page) -> list[str]:
    return page.locator(".jp-Notebook .jp-CodeCell .jp-InputPrompt").evaluate_all(
        "prompts => prompts.map(prompt => prompt.textContent.trim())"
    )


def open_notebook(page: Page, base: str, name: str) -> None:
    # A workspace of its own, reset, so no other notebook's tab is restored.
    page.goto(f"{base}/lab/workspaces/{name.split('.')[0]}/tree/{name}?reset")
    page.locator(".jp-Notebook .jp-Cell").first.wait_for()
    kernel_idle(page)
    page.keyboard.press("Control+b")  # hide the file browser: more room for the lesson


def run_all_cells(page: Page) -> None:
    menu(page, "Edit", "Clear Outputs of All Cells")
    page.wait_for_function(
        """() => [...document.querySelectorAll('.jp-Notebook .jp-CodeCell .jp-InputPrompt')]
            .every(prompt => !/\\d/.test(prompt.textContent))"""
    )
    menu(page, "Run", "Run All Cells")
    # Run All queues every cell at once ([*]); it is over when none is
    # queued any more and some have run (an error stops the rest).
    page.wait_for_function(
        """() => {
            const prompts = [...document.querySelectorAll(
                '.jp-Notebook .jp-CodeCell .jp-InputPrompt')].map(p => p.textContent);
            return !prompts.some(p => p.includes('*')) && prompts.some(p => /\\d/.test(p));
        }""",
        timeout=RUN_TIMEOUT * 1000,
    )
    kernel_idle(page)


def shut_down_kernels(base: str) -> None:
    with urllib.request.urlopen(f"{base}/api/sessions") as response:
        sessions = json.load(response)
    for session in sessions:
        request = urllib.request.Request(f"{base}/api/sessions/{session['id']}", method="DELETE")
        urllib.request.urlopen(request).close()


@pytest.mark.parametrize("book", BOOKS, ids=[book.path.stem for book in BOOKS])
def test_notebook_runs_in_jupyterlab_and_its_sliders_work(book, lab, page, screenshots):
    folder = screenshots / "lab"
    folder.mkdir(exist_ok=True)
    open_notebook(page, lab, book.path.name)
    try:
        run_all_cells(page)
        apps = slider_apps_in(book.path)
        if apps:
            wait_for_pictures(page, apps)
        tall_screenshot(page, folder / f"{book.path.stem}.png")

        not_run = [i for i, prompt in enumerate(prompts(page)) if not re.search(r"\d", prompt)]
        assert not error_outputs(page), error_outputs(page)
        assert not not_run, f"code cells {not_run} did not run (an earlier cell failed?)"
        assert page.locator("img.widget-image").count() >= apps
        assert not unrendered_apps(page), unrendered_apps(page)

        lesson = LESSONS.get(book.number)
        moved: dict[int, dict] = {}  # app -> the sliders' values after their moves
        for spec in lesson.sliders if lesson else ():
            value = move_sliders_like_a_student(page, spec, folder, book.path.stem)
            moved.setdefault(spec.app, {})[spec.control] = value
        for spec in lesson.drags if lesson else ():
            drag_like_a_student(page, spec, folder, book.path.stem, moved.get(spec.app))
    finally:
        shut_down_kernels(lab)


BROKEN = {
    "cells": [
        {"cell_type": "markdown", "metadata": {}, "source": "# Broken on purpose"},
        {
            "cell_type": "code",
            "metadata": {},
            "source": "import ipywidgets\n\nipywidgets.Image(format='png')",
            "outputs": [],
            "execution_count": None,
        },
        {
            "cell_type": "code",
            "metadata": {},
            "source": "1 / 0",
            "outputs": [],
            "execution_count": None,
        },
        {
            "cell_type": "code",
            "metadata": {},
            "source": "x = 1",
            "outputs": [],
            "execution_count": None,
        },
    ],
    "metadata": {
        "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}
    },
    "nbformat": 4,
    "nbformat_minor": 5,
}


def test_the_checks_catch_an_error_a_cell_left_unrun_and_an_empty_picture(served, lab, page):
    """The assertions above would pass vacuously if their selectors found nothing."""
    (served / "notebooks" / "broken_on_purpose.ipynb").write_text(json.dumps(BROKEN))
    open_notebook(page, lab, "broken_on_purpose.ipynb")
    try:
        run_all_cells(page)
        errors = error_outputs(page)
        assert len(errors) == 1 and "ZeroDivisionError" in errors[0]
        assert [bool(re.search(r"\d", prompt)) for prompt in prompts(page)] == [True, True, False]
        assert len(unrendered_apps(page)) == 1
    finally:
        shut_down_kernels(lab)
