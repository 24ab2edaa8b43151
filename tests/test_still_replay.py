"""An unchanged artist's commands made again are a fresh draw's; a changed one is drawn anew."""

from __future__ import annotations

from matplotlib.collections import LineCollection
from matplotlib.patches import Rectangle

from course.widgets.browser_drawing import CommandRecorder
from course.widgets.figure_view import FigureView
from course.widgets.still_replay import StillReplay


def _view_with_grid():
    view = FigureView(shape=(60, 80))
    axes = view.figure.add_axes((0, 0, 1, 1), xlim=(0, 8), ylim=(6, 0))
    (line,) = axes.plot([0, 8], [0, 6], animated=True)
    grid = axes.add_collection(
        LineCollection([[(x, 0), (x, 6)] for x in range(9)], color="0.5", animated=True)
    )
    return view, axes, line, grid


def test_a_replay_after_other_commands_makes_the_commands_a_fresh_draw_makes():
    view, axes, line, grid = _view_with_grid()
    box = axes.add_patch(Rectangle((1, 1), 2, 3, facecolor="teal", animated=True))
    recorder = CommandRecorder(view.canvas.get_renderer())
    recorder.start()
    replays = [StillReplay.record(artist, recorder) for artist in (grid, box)]
    recorder.start()
    line.draw(recorder)  # other commands first: the replayed ones start further on
    assert all(replay.draw(recorder) for replay in replays)
    replayed = recorder.finish()
    recorder.start()
    for artist in (line, grid, box):
        artist.draw(recorder)
    assert replayed == recorder.finish()


def test_a_changed_artist_or_a_whole_draw_drops_the_replay():
    view, _, line, grid = _view_with_grid()
    sent = []
    view.image.send = lambda content, buffers=None: sent.append(buffers)
    view.render_moving([line, grid])
    for step in range(3):
        line.set_data([0, 8], [step, 6])
        if step == 2:
            grid.set_color("red")
        view.render_moving([line, grid], patches=True)
    assert isinstance(view._command_replays[grid], StillReplay)
    strokes = [buffers[-3].count(b'"stroke":[1.0,0.0,0.0,1.0]') for buffers in sent]
    assert strokes[:2] == [0, 0] and strokes[2] == 9  # the red grid: drawn anew
    # A whole draw (a slider while nothing is held) leaves the artist not stale, changed
    # or not: the next drag step draws it anew.
    grid.set_color("blue")
    view.render_moving([line, grid])
    assert view._command_replays == {}
    view.render_moving([line, grid], patches=True)
    assert sent[-1][-3].count(b'"stroke":[0.0,0.0,1.0,1.0]') == 9


def test_a_replayed_run_of_paths_skips_the_empty_ones_as_a_fresh_draw_does():
    view, axes, line, _grid = _view_with_grid()
    nan = float("nan")
    segments = [[(0, 1), (8, 1)], [(nan, nan), (nan, nan)], [(0, 2), (8, 2)], [(0, 3), (8, 5)]]
    ragged = axes.add_collection(LineCollection(segments, color="0.2", animated=True))
    recorder = CommandRecorder(view.canvas.get_renderer())
    recorder.start()
    replay = StillReplay.record(ragged, recorder)
    fresh = recorder.finish()
    assert [method for method, _ in replay.calls] == ["_paths"]  # one run, not four calls
    assert len(recorder.recorded()) == 3  # the NaN segment draws nothing
    recorder.start()
    line.draw(recorder)
    assert replay.draw(recorder)
    replayed = recorder.finish()
    recorder.start()
    line.draw(recorder)
    ragged.draw(recorder)
    assert replayed == recorder.finish() and fresh[2] in replayed[2]


def test_a_hidden_artist_is_neither_drawn_nor_recorded_until_it_shows_again():
    view, axes, line, _grid = _view_with_grid()
    box = axes.add_patch(Rectangle((1, 1), 2, 3, edgecolor="red", fill=False, animated=True))
    box.set_visible(False)
    sent = []
    view.image.send = lambda content, buffers=None: sent.append(buffers)
    view.render_moving([line, box])
    for step in range(2):
        line.set_data([0, 8], [step, 6])
        view.render_moving([line, box], patches=True)
    assert box not in view._command_replays
    assert all(b'"stroke":[1.0,0.0,0.0,1.0]' not in buffers[-3] for buffers in sent)
    box.set_visible(True)
    line.set_data([0, 8], [3, 6])
    view.render_moving([line, box], patches=True)
    assert sent[-1][-3].count(b'"stroke":[1.0,0.0,0.0,1.0]') == 1
