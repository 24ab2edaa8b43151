"""course.curves.paths: a path as a list of curves or a matplotlib Path, text as curves."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.path import Path
from matplotlib.textpath import TextPath

from course.antialias import RENDER_METHODS, render
from course.antialias.near_pixels import segment_distance
from course.curves.bezier import de_casteljau
from course.curves.drawable_paths import flatten_uniform, matplotlib_path
from course.curves.paths import (
    as_path,
    canvas_for,
    curves_of_path,
    path_curves,
    text_curves,
)

coordinate = st.integers(0, 64).map(lambda n: n / 4)
curves = st.lists(
    st.lists(st.tuples(coordinate, coordinate), min_size=2, max_size=4).map(np.array),
    min_size=1,
    max_size=5,
)


def test_one_curve_a_list_and_an_array_of_curves_are_paths():
    assert as_path([[0, 0], [1, 2]]).sizes.tolist() == [2]
    assert as_path([[[0, 0], [1, 2]], [[1, 2], [3, 3], [4, 0]]]).sizes.tolist() == [2, 3]
    assert as_path(np.zeros((3, 2, 2))).sizes.tolist() == [2, 2, 2]
    assert as_path([np.zeros((2, 2)), np.ones((4, 2))]).joined().tolist() == [False, False]


def test_the_codes_of_a_path_become_curves():
    path = Path(
        [[0, 0], [4, 0], [4, 4], [0, 4], [9, 9], [9, 9], [6, 6], [7, 8], [8, 6], [0, 0]],
        [1, 2, 3, 3, 79, 1, 4, 4, 4, 0],
    )
    got = [curve.tolist() for curve in curves_of_path(path).split()]
    assert got == [
        [[0.0, 0.0], [4.0, 0.0]],
        [[4.0, 0.0], [4.0, 4.0], [0.0, 4.0]],
        [[0.0, 4.0], [0.0, 0.0]],  # CLOSEPOLY: back to the subpath's start
        [[9.0, 9.0], [6.0, 6.0], [7.0, 8.0], [8.0, 6.0]],
    ]


@settings(max_examples=30, deadline=None)
@given(path=curves)
def test_matplotlib_path_and_back_gives_the_same_curves(path):
    again = curves_of_path(matplotlib_path(as_path(path))).split()
    expected = [np.asarray(curve, dtype=float) for curve in path]
    # A subpath that returns to its start is closed by CLOSEPOLY: same curves.
    assert len(again) == len(expected)
    for a, b in zip(again, expected, strict=True):
        np.testing.assert_array_equal(a, b)


@settings(max_examples=30, deadline=None)
@given(path=curves)
def test_flatten_uniform_passes_through_every_end_point(path):
    line, gaps = flatten_uniform(as_path(path), 0.01)
    assert len(gaps) == len(line) - 1
    for curve in path:
        for point in (curve[0], curve[-1]):
            assert np.any(np.all(line == point, axis=1))
    # Every curve lies within the tolerance of the drawn segments.
    drawn = np.flatnonzero(~gaps)
    for curve in path:
        points = de_casteljau(np.asarray(curve, dtype=float), np.linspace(0, 1, 50))
        distance, _, _ = segment_distance(
            points[:, 0, None], points[:, 1, None], line[drawn], line[drawn + 1]
        )
        assert distance.min(axis=1).max() <= 0.01 + 1e-9


def test_text_curves_are_in_image_space():
    curves = text_curves("Ty", size=40, margin=3.0)
    points = np.concatenate(curves)
    assert points.min(axis=0) == pytest.approx([3.0, 3.0])
    height, width = canvas_for(curves, margin=3.0)
    assert points[:, 1].max() <= height and points[:, 0].max() <= width
    # y down: the T's bar (the top of the line) has the smallest y, and the
    # y's tail hangs below the T's foot.
    outline = TextPath((0, 0), "Ty", size=40)
    assert len(curves) == len(curves_of_path(outline).sizes)
    image = render(curves, (height, width), "stroke_area")
    rows = np.flatnonzero(image.sum(axis=1))
    assert rows[0] <= 4 and image[rows[-1]].nonzero()[0].min() > width / 3


def test_path_curves_flips_y_and_leaves_the_path_alone():
    path = Path([[1.0, 1.0], [5.0, 1.0], [5.0, 4.0]])
    vertices = path.vertices.copy()
    got = path_curves(path, height=10)
    assert [curve.tolist() for curve in got] == [[[1.0, 9.0], [5.0, 9.0]], [[5.0, 9.0], [5.0, 6.0]]]
    np.testing.assert_array_equal(path.vertices, vertices)


@pytest.mark.parametrize("method", RENDER_METHODS)
def test_render_draws_a_text_path_with_every_method(method):
    curves = text_curves("a", size=20)
    image = render(curves, canvas_for(curves), method)
    assert image.max() > 0.5 and image.min() == 0.0


@pytest.mark.parametrize(
    ("path", "error", "words"),
    [
        (Path([[0, 0], [1, 1]], [1, 5]), ValueError, r"points.codes must hold only MOVETO \(1\)"),
        (Path([[0, 0], [1, 1], [2, 2]], [1, 3, 2]), ValueError, "CURVE3 vertices come in pairs"),
        (Path([[0, 0], [np.nan, 1]]), ValueError, r"points.vertices must be finite; got nan"),
    ],
)
def test_bad_paths_are_refused_by_name(path, error, words):
    with pytest.raises(error, match=words):
        as_path(path)


def test_a_closepoly_vertex_may_hold_anything():
    path = Path([[0, 0], [3, 0], [3, 3], [np.nan, np.nan]], [1, 2, 2, 79])
    assert as_path(path).sizes.tolist() == [2, 2, 2]


@pytest.mark.parametrize(
    ("call", "error", "words"),
    [
        (
            lambda: path_curves([[0, 0], [1, 1]], 4),
            TypeError,
            "path must be a matplotlib.path.Path",
        ),
        (lambda: path_curves(Path([[0, 0], [1, 1]]), np.nan), ValueError, "height must be finite"),
        (lambda: text_curves("", 10), ValueError, "text must be a non-empty string"),
        (lambda: text_curves("a", -1), ValueError, "size must be > 0"),
        (lambda: text_curves("a", 10, family=3), TypeError, "family must be a font family"),
        (lambda: canvas_for([[0, 0], [1, np.inf]]), ValueError, "curves must be finite"),
        (
            lambda: render([np.zeros((2, 2)), np.zeros((2, 3))], (4, 4), "stroke_area"),
            ValueError,
            r"points\[1\] must have shape \(N, 2\)",
        ),
    ],
)
def test_bad_input_is_refused_by_name(call, error, words):
    with pytest.raises(error, match=words):
        call()


def test_render_does_not_modify_a_path():
    path = [np.array([[0.0, 0.0], [3.0, 3.0]]), np.array([[3.0, 3.0], [5.0, 1.0], [6.0, 4.0]])]
    copies = [curve.copy() for curve in path]
    for method in RENDER_METHODS:
        render(path, (8, 8), method)
    for curve, copy in zip(path, copies, strict=True):
        np.testing.assert_array_equal(curve, copy)


# --- Curves and the callbacks: checked once, at the boundary ---------------------------


@pytest.mark.parametrize("bad", [np.nan, np.inf, 1e200])
def test_curves_refuse_points_that_are_not_finite_or_far_away(bad):
    from course.curves.paths import Curves

    points = np.array([[0.0, 0.0], [bad, 1.0]])
    with pytest.raises(ValueError, match="points"):
        Curves(points, np.array([2]))


def test_curves_refuse_sizes_that_disagree_with_their_points():
    from course.curves.drawable_paths import flatten_uniform
    from course.curves.paths import Curves

    with pytest.raises(ValueError, match="sizes must add up to the 4 points"):
        flatten_uniform(Curves(np.zeros((4, 2)), np.array([3, 3])), 0.1)
    with pytest.raises(ValueError, match="sizes must be >= 1"):
        Curves(np.zeros((4, 2)), np.array([4, 0]))
    with pytest.raises(TypeError, match="sizes must be a 1-D integer"):
        Curves(np.zeros((4, 2)), np.array([4.0]))


@pytest.mark.parametrize("offset", [None, (np.nan, 0.0), (np.inf, 0.0), (1.0,), "ab"])
def test_moved_refuses_an_offset_that_is_not_a_point(offset):
    path = as_path([[0.0, 0.0], [3.0, 4.0]])
    with pytest.raises((TypeError, ValueError), match="offset"):
        path.moved(offset)


def test_moved_refuses_to_move_points_past_the_coordinate_bound():
    path = as_path([[0.0, 0.0], [3.0, 4.0]])
    with pytest.raises(ValueError, match="offset"):
        path.moved((-(2.0**20), 0.0))


@pytest.mark.parametrize(
    ("answer", "error", "message"),
    [
        (lambda control: np.full((3, 2), np.nan), ValueError, "finite vertices"),
        (lambda control: control * 1e200, ValueError, "finite vertices"),
        (lambda control: np.zeros((2, 3)), ValueError, r"\(K, 2\) vertices"),
        (lambda control: np.zeros((0, 2)), ValueError, r"K >= 1"),
        (lambda control: None, ValueError, "flatten_one must return"),
        (lambda control: "abc", TypeError, "flatten_one must return"),
    ],
)
def test_flatten_each_checks_what_its_callback_returns(answer, error, message):
    from course.curves.drawable_paths import flatten_each

    with pytest.raises(error, match=message):
        flatten_each(as_path([[0.0, 0.0], [3.0, 4.0], [5.0, 0.0]]), answer)


def test_flatten_each_keeps_a_good_callback_s_vertices():
    from course.curves.drawable_paths import flatten_each

    path = as_path([[[0.0, 0.0], [3.0, 4.0]], [[3.0, 4.0], [5.0, 0.0]]])
    line, gaps = flatten_each(path, lambda control: control)
    np.testing.assert_array_equal(line, [[0.0, 0.0], [3.0, 4.0], [5.0, 0.0]])
    assert not gaps.any()


def test_text_has_a_bounded_length():
    with pytest.raises(ValueError, match="text must be at most 1000 characters"):
        text_curves("W" * 1001)
