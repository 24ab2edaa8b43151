"""course.lessons: notebooks found on disk, registry entries that match the apps' pictures."""

import io
import json

import numpy as np
import pytest
from PIL import Image

from course.lessons import LESSONS, NOTEBOOKS, course_map, notebooks


def rgb(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


def write_notebook(path, *markdown):
    cells = [{"cell_type": "markdown", "metadata": {}, "source": text} for text in markdown]
    path.write_text(json.dumps({"cells": cells, "metadata": {}, "nbformat": 4}))


def test_every_lesson_notebook_is_found_in_order_and_titled_by_its_first_heading(tmp_path):
    write_notebook(tmp_path / "00_index.ipynb", "# Map")
    write_notebook(
        tmp_path / "03_later.ipynb", "intro without heading", "# Third\n\nIt does | this."
    )
    write_notebook(
        tmp_path / "01_first.ipynb", "# First lesson\n\nFirst line\nof one paragraph.\n\nMore."
    )
    write_notebook(tmp_path / "scratch.ipynb", "# Not a lesson")
    write_notebook(tmp_path / "1_short.ipynb", "# Not a lesson either")
    found = notebooks(tmp_path)
    assert [(book.number, book.title) for book in found] == [
        ("01", "First lesson"),
        ("03", "Third"),
    ]
    assert found[0].summary == "First line of one paragraph."
    assert [book.number for book in notebooks(tmp_path, index=True)] == ["00", "01", "03"]
    # No registry entry for a folder's own lessons beyond the registered numbers.
    assert found[0].lesson is LESSONS["01"]
    table = course_map(tmp_path).splitlines()
    assert len(table) == 2 + 2
    assert table[3].startswith("| [Third](03_later.ipynb) | It does \\| this. |")


def test_a_notebook_without_a_heading_is_refused_by_name(tmp_path):
    write_notebook(tmp_path / "04_bad.ipynb", "no heading here")
    with pytest.raises(ValueError, match=r"04_bad\.ipynb"):
        notebooks(tmp_path)
    with pytest.raises(ValueError, match="expected a folder"):
        notebooks(tmp_path / "missing")


def test_the_repository_notebooks_and_the_registry_agree():
    found = {book.number: book for book in notebooks()}
    on_disk = sorted(path.name[:2] for path in NOTEBOOKS.glob("[0-9][0-9]_*.ipynb"))
    assert sorted(found) == [number for number in on_disk if number != "00"]
    for number, lesson in LESSONS.items():
        assert number in found, f"lesson {number} is registered but has no notebook"
        assert lesson.number == number
        assert found[number].title.startswith(f"Lesson {number}")
        names = [picture.name for picture in lesson.pictures]
        assert all(name.startswith(f"{number}_") for name in names)
    every_name = [picture.name for book in found.values() for picture in book.pictures]
    assert len(set(every_name)) == len(every_name)


@pytest.mark.parametrize("number", [n for n, lesson in LESSONS.items() if lesson.slider])
def test_landmarks_are_where_the_picture_shows_them_and_move_with_the_slider(number):
    """The browser test trusts these landmarks, so they must fail on a stale picture."""
    slider = LESSONS[number].slider
    app = slider.build()
    picture = rgb(app.refresh())
    control = app.controls[slider.control]
    landmarks = slider.landmarks(app)
    assert landmarks
    for landmark in landmarks:
        assert np.abs(picture[landmark.row, landmark.column] - landmark.color).max() <= 40, landmark
    # Move the control down to a quarter of its range and check again; the old
    # landmarks must no longer all hold, or they could not catch a stale picture.
    # (Down, because lesson 01's trace up to B(t) still passes the old points
    # when t grows; the browser test compares the whole picture as well.)
    old = landmarks
    target = control.min + 0.25 * (control.max - control.min)
    assert control.value != target
    control.value = target
    picture = rgb(app.view.image.value)
    for landmark in slider.landmarks(app):
        assert np.abs(picture[landmark.row, landmark.column] - landmark.color).max() <= 40, landmark
    stale = [np.abs(picture[mark.row, mark.column] - mark.color).max() <= 40 for mark in old]
    assert not all(stale)


def test_de_casteljau_landmark_is_b_of_t_and_bernstein_landmarks_are_the_weights():
    from course.bezier import bernstein_basis, de_casteljau

    app = LESSONS["01"].slider.build()
    app.controls["t"].value = 0.25
    (landmark,) = LESSONS["01"].slider.landmarks(app)
    x, y = de_casteljau(app.points, 0.25)
    display_x, display_y = app.axes.transData.transform((x, y))
    assert (landmark.row, landmark.column) == (round(500 - display_y), round(display_x))
    app = LESSONS["02"].slider.build()
    marks = LESSONS["02"].slider.landmarks(app)
    assert len(marks) == 4
    rows = [app.axes.transData.transform((0.3, w))[1] for w in bernstein_basis(3, 0.3)[0]]
    assert [mark.row for mark in marks] == [round(350 - row) for row in rows]
