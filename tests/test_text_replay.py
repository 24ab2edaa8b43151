"""A moving label's commands, moved with its point, are those of drawing it there anew."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from course.widgets.browser_drawing import CommandRecorder
from course.widgets.text_cache import FixedText, SteadyText
from course.widgets.text_replay import TextReplay


def _axes():
    figure = Figure(figsize=(3, 2), dpi=100)
    canvas = FigureCanvasAgg(figure)
    axes = figure.add_axes((0.1, 0.1, 0.8, 0.8), xlim=(0, 10), ylim=(10, 0))
    return axes, CommandRecorder(canvas.get_renderer())


def _fresh(text, recorder):
    recorder.start()
    text.draw(recorder)
    return recorder.recorded()


def _replayed(replay, recorder):
    recorder.start()
    assert replay.draw(recorder)
    return recorder.recorded()


def _assert_same(replayed, fresh):
    assert len(replayed) == len(fresh)
    for moved, drawn in zip(replayed, fresh, strict=True):
        assert {k: v for k, v in moved.items() if k not in "xy"} == {
            k: v for k, v in drawn.items() if k not in "xy"
        }
        # Both places are kept to 1/10,000 pixel: they may round apart by one step.
        assert moved["x"] == pytest.approx(drawn["x"], abs=1.5e-4)
        assert moved["y"] == pytest.approx(drawn["y"], abs=1.5e-4)


place = st.tuples(st.floats(-2, 12), st.floats(-2, 12))


@settings(max_examples=40, deadline=None)
@given(first=place, later=place, label=st.sampled_from(["P1", "B(t)", "two\nlines"]))
def test_a_label_moved_with_its_point_is_drawn_where_a_new_draw_puts_it(first, later, label):
    axes, recorder = _axes()
    annotation = axes.annotate(
        label, first, xytext=(7, 7), textcoords="offset points", annotation_clip=False
    )
    text = axes.text(*first, label, rotation=30, ha="center")
    for artist in (annotation, text):
        recorder.start()
        replay = TextReplay.record(artist, recorder)
        assert replay is not None
        if artist is annotation:
            artist.xy = later
        else:
            artist.set_position(later)
        _assert_same(_replayed(replay, recorder), _fresh(artist, recorder))


def test_a_changed_string_or_font_is_drawn_anew_and_a_hidden_label_draws_nothing():
    axes, recorder = _axes()
    label = axes.annotate("P0", (2, 2), xytext=(7, 7), textcoords="offset points")
    label.set_annotation_clip(False)
    replay = TextReplay.record(label, recorder)
    label.set_text("P9")
    assert replay.draw(recorder) is False
    replay = TextReplay.record(label, recorder)
    label.set_fontsize(20)
    assert replay.draw(recorder) is False
    label.set_visible(False)
    replay = TextReplay.record(label, recorder)
    label.set_text("anything")
    assert _replayed(replay, recorder) == []


def test_texts_that_do_not_move_with_an_anchor_have_no_replay():
    axes, recorder = _axes()
    clipped = axes.annotate("P0", (2, 2), xytext=(7, 7), textcoords="offset points")
    in_data = axes.annotate("P0", (2, 2), xytext=(5, 5), textcoords="data", annotation_clip=False)
    boxed = axes.text(1, 1, "boxed", bbox={"facecolor": "yellow"})
    for text in (clipped, in_data, boxed):
        recorder.start()
        assert TextReplay.record(text, recorder) is None
        assert recorder.commands  # drawn all the same


numbers = st.tuples(st.floats(-999, 999), st.floats(-999, 999)).map(
    lambda point: f"({point[0]:.1f}, {point[1]:.1f})"
)


@settings(max_examples=40, deadline=None)
@given(first=numbers, later=st.lists(numbers | st.sampled_from(["", "$x$", "a\nb"]), max_size=4))
def test_numbers_whose_characters_change_are_drawn_where_a_new_draw_puts_them(first, later):
    axes, recorder = _axes()
    text = axes.figure.add_artist(FixedText(0.1, 0.1, first, fontsize=10))
    recorder.start()
    replay = TextReplay.record(text, recorder)
    assert replay is not None
    for string in later:
        text.set_text(string)
        recorder.start()
        if not replay.draw(recorder):  # empty, several lines, mathtext: drawn by Text.draw
            assert string in ("", "$x$", "a\nb")
            continue
        assert recorder.recorded() == _fresh(text, recorder)


@settings(max_examples=30, deadline=None)
@given(
    first=numbers, later=st.lists(numbers, max_size=4), align=st.sampled_from(["center", "right"])
)
def test_steady_numbers_are_replayed_where_a_new_draw_puts_them(first, later, align):
    axes, recorder = _axes()
    text = axes.figure.add_artist(SteadyText(0.5, 0.1, f"at {first}", fontsize=10, ha=align))
    recorder.start()
    replay = TextReplay.record(text, recorder)
    assert replay is not None
    for string in later:
        text.set_text(f"at {string}")
        recorder.start()
        assert replay.draw(recorder)
        assert recorder.recorded() == _fresh(text, recorder)


def test_numbers_drawn_anew_once_their_font_or_rotation_changes():
    axes, recorder = _axes()
    text = axes.figure.add_artist(FixedText(0.1, 0.1, "(1.0, 2.0)"))
    for change in (lambda: text.set_fontsize(14), lambda: text.set_rotation(10)):
        replay = TextReplay.record(text, recorder)
        change()
        assert replay.draw(recorder) is False
