"""One lesson as ``make app`` serves it: Voila, code hidden, the slider and the drags live.

The lesson is the first one whose module in ``course.lessons`` registers a
slider. Voila streams the page while its kernel runs the notebook, so the
page has loaded when every cell has run; then the pictures must appear,
no output may show an error, no line of code may be visible, and moving the
slider with the keyboard must redraw what the library computes.

The Chinese twin of the first lesson whose slider's label the library translates
(``make app COURSE_LANG=zh-CN`` serves ``notebooks/zh-CN/``) must show that label in
Chinese, and not in English, and its picture as the library draws it in Chinese, with no
error: one page load, no moves.
"""

from __future__ import annotations

import json

import pytest

from course.classroom.notebooks import NOTEBOOKS, language_folder, notebooks
from course.classroom.pictures import DIFFERING_SHARE, differing_share
from course.classroom.registry import lessons
from course.classroom.sliders import nearest_stop
from course.i18n import language
from tests_browser.student import (
    drag_like_a_student,
    error_outputs,
    library_picture,
    move_sliders_like_a_student,
    nth_app,
    read_picture,
    slider,
    slider_apps_in,
    tall_screenshot,
    unrendered_apps,
    wait_for_pictures,
)

LESSONS = lessons()
WITH_SLIDER = [
    book for book in notebooks(NOTEBOOKS) if book.number in LESSONS and LESSONS[book.number].sliders
]
TWINS = language_folder(NOTEBOOKS, "zh-CN")


def translated_slider() -> tuple | None:
    """The first twin's slider whose label the library translates, with both labels."""
    for book in WITH_SLIDER:
        twin = TWINS / book.path.name
        for spec in LESSONS[book.number].sliders if twin.is_file() else ():
            english = spec.build().controls[spec.control].description
            with language("zh-CN"):
                chinese = spec.build().controls[spec.control].description
            if chinese != english:
                return twin, spec, english, chinese
    return None


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


def test_a_chinese_lesson_served_by_voila_shows_its_app_in_chinese(voila, page, screenshots):
    found = translated_slider()
    if found is None:
        pytest.skip("no Chinese twin has a slider whose label the library translates")
    twin, spec, english, chinese = found
    page.goto(f"{voila}/voila/render/zh-CN/{twin.name}", timeout=300_000)
    apps = slider_apps_in(twin)
    assert apps > 0
    wait_for_pictures(page, apps)
    (screenshots / "voila").mkdir(exist_ok=True)
    tall_screenshot(page, screenshots / "voila" / f"zh-CN_{twin.stem}.png")
    assert not error_outputs(page), error_outputs(page)
    assert not unrendered_apps(page), unrendered_apps(page)
    app = nth_app(page, spec.app)
    assert slider(app, chinese).count() == 1, f"no slider labelled {chinese!r}"
    assert slider(app, english).count() == 0, f"a slider still labelled {english!r}"
    # The picture is the one the library draws in Chinese, not the English one.
    shown = read_picture(app.locator("img.widget-image").first)
    control = spec.build().controls[spec.control]
    value = nearest_stop(control, control.value)
    with language("zh-CN"):
        in_chinese = differing_share(shown, library_picture(spec, value, landmarks=False))
    in_english = differing_share(shown, library_picture(spec, value, landmarks=False))
    assert in_chinese <= DIFFERING_SHARE, f"{in_chinese:.2%} differ from the Chinese picture"
    assert in_chinese < in_english, f"as close to the English picture: {in_english:.2%}"
    shown_text = page.locator("body").inner_text()
    assert not [line for line in code_lines(twin) if line in shown_text], "code is visible"
