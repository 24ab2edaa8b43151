"""course.lessons: each lesson module's landmarks are where its app's picture shows them.

The browser tests trust the registered landmarks to tell the library's
picture from a stale or wrong one; these tests prove, in plain Python, that
they hold on the picture the app draws and fail on the picture one slider
stop away.
"""

import io
import re

import numpy as np
import pytest
from PIL import Image

from course.classroom.pictures import DIFFERING_SHARE, differing_share, gray_color
from course.classroom.registry import lessons
from course.classroom.sliders import (
    nearest_stop,
    neighbour_value,
    slider_stops,
    value_after_keys,
)
from course.curves.bezier import bernstein_basis, de_casteljau
from course.images import SEED_000_CUBIC
from course.lessons.l05_antialiasing.lesson import seed_000_renderings
from course.raster.canvas import crop


def rgb(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


LESSONS = lessons()
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
    assert spec.app == 1  # the notebook's second app: StepApp comes first
    app = spec.build()
    app.controls["position"].value = 0.5  # the middle of the S, by arc length
    renderings, exact = seed_000_renderings()
    centre = de_casteljau(SEED_000_CUBIC, 0.5)  # the curve is symmetric about t = 0.5
    marks = spec.landmarks(app)
    panels = [app.value(slot) for slot in ("left", "middle", "right")] + ["exact reference"]
    for name in panels:
        image = exact if name == "exact reference" else renderings[name]
        window, (left, right, bottom, top) = crop(image, centre, 16)
        assert (right - left, bottom - top) == (16, 16)
        own = [mark for mark in marks if mark.what.startswith(f"{name} at position 0.500")]
        # One landmark per pixel of the window, coloured as the whole rendering's crop.
        assert [mark.color for mark in own] == [gray_color(value) for value in window.ravel()]
        assert own[17].what.endswith(f"pixel ({left + 1}, {top + 1}) = {window[1, 1]:.2f}")


def test_line_landmarks_are_every_pixel_of_the_three_rasterizers():
    spec = next(drag for drag in LESSONS["03"].drags if drag.handle == "p1")
    app = spec.build()
    app.controls["endpoints"].value = "3, 6; 27, 29"  # steep, octant 1
    marks = spec.landmarks(app)
    near_ends = 2 * 9 - 2  # pixels within 1.5 of an end: 9 around each, less what they share
    assert len(marks) == 3 * (32 * 32 - 2 * 9)
    black = [mark for mark in marks if "line((3, 6), (27, 29)) pixel" in mark.what]
    white = [mark for mark in marks if "not a Bresenham pixel" in mark.what]
    assert len(black) == max(27 - 3, 29 - 6) + 1 - 4  # less the two pixels next to each end
    assert {mark.color for mark in black} == {(0, 0, 0)}
    assert near_ends == 16
    # The report's staircase has |dx| + |dy| + 1 pixels, Bresenham's max(|dx|, |dy|) + 1.
    assert {m.color for m in white} == {(255,) * 3} and len(white) > 15


def test_triangle_landmarks_colour_each_pixel_by_who_paints_it():
    spec = next(drag for drag in LESSONS["03"].drags if drag.handle == "B")
    app = spec.build()
    app.controls["rule"].value = "closed"
    marks = spec.landmarks(app)
    both = [mark for mark in marks if mark.what.endswith("painted by both")]
    assert {mark.color for mark in both} == {(220, 20, 60)}  # crimson
    listed = {tuple(map(int, re.findall(r"pixel \((\d+), (\d+)\)", m.what)[0])) for m in both}
    doubled = {(int(c), int(r)) for r, c in np.argwhere(app.counts == 2)}
    # Every pixel painted twice is a landmark, but those under a vertex's label.
    far = {p for p in doubled if np.hypot(*(app.vertices() - np.add(p, 0.5)).T).min() >= 2}
    assert far and far <= listed <= doubled


DRAGS = [
    pytest.param(spec, id=f"{number}-{spec.handle}")
    for number, lesson in LESSONS.items()
    for spec in lesson.drags
]


def test_the_issue_s_drags_are_registered():
    assert {"01-P1", "03-B", "08-foreground"} <= {param.id for param in DRAGS}


@pytest.mark.parametrize("spec", DRAGS)
def test_after_a_registered_drag_the_landmarks_hold_and_the_picture_before_fails_them(spec):
    app = spec.build()
    before = refreshed(app)
    start = app.press_point(spec.handle)
    assert app.handle_at(*start).name == spec.handle  # a press there grabs it
    app.drag_along(spec.handle, spec.path)
    assert app.grabbed is None
    after = rgb(bytes(app.view.image.value))
    landmarks = spec.landmarks(app)
    assert landmarks and all(shows(after, mark) for mark in landmarks)
    # The browser test checks the same: a picture that missed the drag must fail.
    assert differing_share(before, after) > DIFFERING_SHARE
    assert not all(shows(before, mark) for mark in landmarks)


def test_gray_level_landmarks_frame_the_pattern_dither_ordered_picks():
    (spec,) = LESSONS["06"].sliders
    assert spec.app == 0  # the notebook's first app: the flat patch
    app = spec.build()
    for level, k in ((0.0, 0), (0.3, 3), (1 / 9 + 1 / 72, 2), (1.0, 9)):
        app.controls["level"].value = level
        (frame,) = [mark for mark in spec.landmarks(app) if "red frame" in mark.what]
        assert f"pattern k = {k} " in frame.what
        assert shows(rgb(bytes(app.view.image.value)), frame)
