"""course.lessons: notebooks found on disk, registry entries that match the apps' pictures."""

import io
import json
import re

import ipywidgets as widgets
import numpy as np
import pytest
from PIL import Image

from course import lesson_views as views
from course.bezier import de_casteljau
from course.canvas import crop
from course.lessons import LESSONS, NOTEBOOKS, course_map, notebooks
from course.showcase import (
    DIFFERING_SHARE,
    differing_share,
    gray_color,
    nearest_stop,
    neighbour_value,
    readout_shows,
    slider_stops,
    value_after_keys,
)
from course.widgets.antialias import SEED_000_POINTS


def rgb(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


def write_notebook(path, *markdown):
    cells = [{"cell_type": "markdown", "metadata": {}, "source": text} for text in markdown]
    path.write_text(json.dumps({"cells": cells, "metadata": {}, "nbformat": 4}))


def test_every_lesson_notebook_is_found_in_order_and_titled_by_its_first_heading(tmp_path):
    write_notebook(tmp_path / "00_index.ipynb", "# Map")
    write_notebook(
        tmp_path / "09_later.ipynb", "intro without heading", "# Third\n\nIt does | this."
    )
    write_notebook(
        tmp_path / "01_first.ipynb", "# First lesson\n\nFirst line\nof one paragraph.\n\nMore."
    )
    write_notebook(tmp_path / "scratch.ipynb", "# Not a lesson")
    write_notebook(tmp_path / "1_short.ipynb", "# Not a lesson either")
    found = notebooks(tmp_path)
    assert [(book.number, book.title) for book in found] == [
        ("01", "First lesson"),
        ("09", "Third"),
    ]
    assert found[0].summary == "First line of one paragraph."
    assert [book.number for book in notebooks(tmp_path, index=True)] == ["00", "01", "09"]
    # No registry entry for a folder's own lessons beyond the registered numbers.
    assert found[0].lesson is LESSONS["01"]
    table = course_map(tmp_path).splitlines()
    assert len(table) == 2 + 2
    assert table[3].startswith("| [Third](09_later.ipynb) | It does \\| this. |")


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
        # Lessons 01-05 say "Lesson NN · ...", 06-08 "NN · ...": both name the number.
        assert re.match(rf"(Lesson )?{number} · ", found[number].title), found[number].title
        names = [picture.name for picture in lesson.pictures]
        assert all(name.startswith(f"{number}_") for name in names)
    every_name = [picture.name for book in found.values() for picture in book.pictures]
    assert len(set(every_name)) == len(every_name)


SLIDERS = [
    pytest.param(spec, id=f"{number}-{spec.control}")
    for number, lesson in LESSONS.items()
    for spec in lesson.sliders
]


def shows(picture: np.ndarray, landmark) -> bool:
    return np.abs(picture[landmark.row, landmark.column] - landmark.color).max() <= (
        landmark.tolerance
    )


def refreshed(app) -> np.ndarray:
    return rgb(app.refresh())


def test_every_lesson_registers_pictures_and_the_issue_s_lessons_a_slider():
    for number, lesson in LESSONS.items():
        assert lesson.pictures, number
    # Issue 7: slider moves checked against the library for lessons 01, 03, 05 and 06.
    assert {"01", "03", "05", "06"} <= {n for n, lesson in LESSONS.items() if lesson.sliders}


@pytest.mark.parametrize("spec", SLIDERS)
def test_landmarks_are_where_the_picture_shows_them_and_move_with_the_slider(spec):
    """The browser test trusts these landmarks, so they must fail on a stale picture."""
    app = spec.build()
    picture = refreshed(app)
    control = app.controls[spec.control]
    landmarks = spec.landmarks(app)
    assert landmarks
    for landmark in landmarks:
        assert shows(picture, landmark), landmark
    # Move the control down to a quarter of its range and check again; the old
    # landmarks must no longer all hold, or they could not catch a stale picture.
    # (Down, because lesson 01's trace up to B(t) still passes the old points
    # when t grows; the browser test compares the whole picture as well.)
    stops = slider_stops(control)
    target = stops[len(stops) // 4]
    assert control.value != target
    control.value = target
    picture = refreshed(app)
    for landmark in spec.landmarks(app):
        assert shows(picture, landmark), landmark
    assert not all(shows(picture, mark) for mark in landmarks)


@pytest.mark.parametrize("spec", SLIDERS)
def test_after_each_registered_move_the_landmarks_tell_the_value_from_the_next_stop(spec):
    """What the browser test asserts after each move: a picture one stop off fails."""
    app = spec.build()
    control = app.controls[spec.control]
    value = nearest_stop(control, control.value)  # as the browser shows the slider
    for keys in spec.moves:
        value = value_after_keys(control, value, keys)
        control.value = value
        picture = refreshed(app)
        landmarks = spec.landmarks(app)
        assert all(shows(picture, mark) for mark in landmarks)
        control.value = neighbour_value(control, value)
        off_by_one = refreshed(app)
        # The browser test's two checks: the whole picture, then the landmarks.
        share = differing_share(off_by_one, picture)
        stale = all(shows(off_by_one, mark) for mark in landmarks)
        assert share > DIFFERING_SHARE or not stale, (
            f"{keys} -> {value}: a picture one stop off passes ({share:.3%} of the pixels "
            "differ and every landmark holds)"
        )
        control.value = value


def test_de_casteljau_landmark_is_b_of_t_and_bernstein_landmarks_are_the_weights():
    from course.bezier import bernstein_basis, de_casteljau

    (spec,) = LESSONS["01"].sliders
    app = spec.build()
    app.controls["t"].value = 0.25
    (landmark,) = spec.landmarks(app)
    x, y = de_casteljau(app.points, 0.25)
    display_x, display_y = app.axes.transData.transform((x, y))
    # The picture pixel that contains the point: pixel (r, c) spans [c, c + 1).
    assert (landmark.row, landmark.column) == (int(500 - display_y), int(display_x))
    (spec,) = LESSONS["02"].sliders
    app = spec.build()
    marks = spec.landmarks(app)
    assert len(marks) == 4
    rows = [app.axes.transData.transform((0.3, w))[1] for w in bernstein_basis(3, 0.3)[0]]
    assert [mark.row for mark in marks] == [int(350 - row) for row in rows]


def test_zoom_landmarks_are_the_crop_of_each_rendering_around_the_curve_point():
    (spec,) = LESSONS["05"].sliders
    app = spec.build()
    app.controls["position"].value = 0.5  # the middle of the S, by arc length
    renderings, exact = views.seed_000_renderings()
    centre = de_casteljau(np.array(SEED_000_POINTS), 0.5)  # the curve is symmetric about t = 0.5
    marks = spec.landmarks(app)
    panels = [app.value(slot) for slot in ("left", "middle", "right")] + ["exact reference"]
    for name in panels:
        image = exact if name == "exact reference" else renderings[name]
        window, (left, right, bottom, top) = crop(image, centre, 16)
        assert (right - left, bottom - top) == (16, 16)
        own = [mark for mark in marks if mark.what.startswith(f"{name} at position 0.500")]
        # One landmark per pixel of the window, coloured as crop() gives it, in order.
        assert [mark.color for mark in own] == [gray_color(value) for value in window.ravel()]
        assert own[17].what.endswith(f"pixel ({left + 1}, {top + 1}) = {window[1, 1]:.2f}")


def test_line_landmarks_are_every_pixel_of_the_three_rasterizers():
    (spec,) = LESSONS["03"].sliders
    app = spec.build()
    app.controls["y1"].value = 29  # (3, 6) to (27, 29): steep, octant 1
    marks = spec.landmarks(app)
    assert len(marks) == 3 * 32 * 32
    black = [mark for mark in marks if "line((3, 6), (27, 29)) pixel" in mark.what]
    white = [mark for mark in marks if "not a Bresenham pixel" in mark.what]
    assert len(black) == max(27 - 3, 29 - 6) + 1
    assert {mark.color for mark in black} == {(0, 0, 0)}
    # The report's staircase has |dx| + |dy| + 1 pixels, Bresenham's max(|dx|, |dy|) + 1.
    assert len(white) == (24 + 23 + 1) - len(black) and {m.color for m in white} == {(255,) * 3}


def test_gray_level_landmarks_frame_the_pattern_dither_ordered_picks():
    (spec,) = LESSONS["06"].sliders
    assert spec.app == 1  # the notebook's second app: the flat patch
    app = spec.build()
    for level, k in ((0.0, 0), (0.3, 3), (1 / 9 + 1 / 72, 2), (1.0, 9)):
        app.controls["level"].value = level
        (frame,) = [mark for mark in spec.landmarks(app) if "red frame" in mark.what]
        assert f"pattern k = {k} " in frame.what
        assert shows(rgb(bytes(app.view.image.value)), frame)


def test_slider_stops_and_keys_follow_the_slider():
    control = widgets.FloatSlider(value=0.3, min=0.0, max=1.0, step=1 / 72)
    # Off the grid, a key press snaps to the nearest stop past the step; so does the browser.
    assert nearest_stop(control, 0.3) == pytest.approx(22 / 72)
    assert value_after_keys(control, 0.3, ("ArrowRight",)) == pytest.approx(23 / 72)
    assert value_after_keys(control, 0.3, ("ArrowLeft",)) == pytest.approx(21 / 72)
    assert value_after_keys(control, 0.3, ("ArrowLeft", "Home", "ArrowRight")) == 1 / 72
    assert value_after_keys(control, 0.3, ("End", "ArrowRight")) == 1.0
    assert readout_shows(control, 23 / 72, "0.319") and not readout_shows(control, 0.3, "0.319")
    with pytest.raises(ValueError, match="keys"):
        value_after_keys(control, 0.3, ("PageUp",))
    choice = widgets.SelectionSlider(options=(0, 1, 3, 10), value=3)
    assert value_after_keys(choice, 3, ("ArrowLeft", "ArrowLeft")) == 0
    assert readout_shows(choice, 10, "10") and neighbour_value(choice, 10) == 3
    with pytest.raises(TypeError, match="IntSlider, FloatSlider or SelectionSlider"):
        slider_stops(widgets.FloatLogSlider())
