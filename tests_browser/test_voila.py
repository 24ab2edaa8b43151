"""One lesson as ``make app`` serves it: Voila, code hidden, the slider and the drags live.

The lesson is the first one whose module in ``course.lessons`` registers a
slider. Voila streams the page while its kernel runs the notebook, so the
page has loaded when every cell has run; then the pictures must appear,
no output may show an error, no line of code may be visible, and moving the
slider with the keyboard must redraw what the library computes.
"""

from __future__ import annotations

import json

import pytest

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

LESSONS = lessons()
WITH_SLIDER = [
    book for book in notebooks(NOTEBOOKS) if book.number in LESSONS and LESSONS[book.number].sliders
]


def code_lines(path) -> list[str]:
    """Lines of the notebook's code cells that no markdown cell or output also shows."""
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    shown_anyway = "\n".join(
        "".join(cell["source"]) if cell["cell_type"] == "markdown" else json.dumps(cell["outputs"])
        for cell in cells
        if cell["cell_type"] == "markdown" or cell.get("outputs")
    )
    lines = (
        line.strip()
        for cell in cells
        if cell["cell_type"] == "code"
        for line in "".join(cell["source"]).splitlines()
    )
    return [line for line in lines if len(line) > 20 and line not in shown_anyway]


@pytest.mark.skipif(not WITH_SLIDER, reason="no lesson registers a slider")
def test_a_lesson_served_by_voila_hides_its_code_and_its_slider_works(voila, page, screenshots):
    book = WITH_SLIDER[0]
    folder = screenshots / "voila"
    folder.mkdir(exist_ok=True)
    page.goto(f"{voila}/voila/render/{book.path.name}", timeout=300_000)
    apps = slider_apps_in(book.path)
    assert apps > 0
    wait_for_pictures(page, apps)
    tall_screenshot(page, folder / f"{book.path.stem}.png")

    assert not error_outputs(page), error_outputs(page)
    assert not unrendered_apps(page), unrendered_apps(page)
    shown = page.locator("body").inner_text()
    visible_code = [line for line in code_lines(book.path) if line in shown]
    assert not visible_code, f"code is visible: {visible_code[:5]}"
    assert code_lines(book.path), "the check above needs code lines to look for"

    moved: dict[int, dict] = {}  # app -> the sliders' values after their moves
    for spec in LESSONS[book.number].sliders:
        value = move_sliders_like_a_student(page, spec, folder, book.path.stem)
        moved.setdefault(spec.app, {})[spec.control] = value
    for spec in LESSONS[book.number].drags:
        drag_like_a_student(page, spec, folder, book.path.stem, moved.get(spec.app))
