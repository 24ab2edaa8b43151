"""A moving line replayed into the browser's recorder makes the commands a full draw makes.

``LineReplay`` reads a line's paint (colours, widths, dashes, markers, the
transform to the picture) once, and at later steps builds only the
vertices. Whatever the new data (NaNs, lists of floats, long lines that Agg
simplifies, horizontal ones it snaps), the commands and their buffers must be
those of drawing the line through a fresh ``CommandRecorder``: byte for byte.
"""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from course.widgets.browser_drawing import CommandRecorder
from course.widgets.line_replay import LineReplay

STYLES = [
    {"color": "crimson", "linewidth": 2.5},
    {"color": "0.3", "linewidth": 1, "linestyle": "--", "marker": "o", "markersize": 6},
    {"linestyle": "none", "marker": "s", "markerfacecolor": "none", "markersize": 9},
    {"color": "tab:blue", "linestyle": ":", "marker": "x", "alpha": 0.5},
]


def _axes():
    figure = Figure(figsize=(2, 2), dpi=100)
    canvas = FigureCanvasAgg(figure)
    axes = figure.add_axes((0.1, 0.1, 0.8, 0.8), xlim=(-1, 11), ylim=(11, -1))
    return axes, canvas.get_renderer()


def _recorded(line, recorder, replay=None):
    recorder.start()
    if replay is None:
        line.draw(recorder)
    else:
        assert replay.draw(recorder)
    return recorder.finish()


coordinates = st.floats(-3, 14, allow_nan=False)
data = st.one_of(
    st.lists(st.tuples(coordinates, coordinates), min_size=1, max_size=40),
    st.integers(1, 300).map(  # long lines: Agg simplifies from 128 points
        lambda n: [(10 * i / n, 5 + np.sin(10 * i / n)) for i in range(n)]
    ),
    st.integers(2, 6).map(lambda n: [(float(i), 4.0) for i in range(n)]),  # snapped
)


@settings(max_examples=60, deadline=None)
@given(
    style=st.sampled_from(STYLES), first=data, later=data, gap=st.booleans(), lists=st.booleans()
)
def test_a_replayed_line_makes_the_commands_of_a_full_draw(style, first, later, gap, lists):
    axes, agg = _axes()
    (line,) = axes.plot(*np.transpose(first), **style)
    recorder = CommandRecorder(agg)
    recorder.start()
    replay = LineReplay.record(line, recorder)
    assert replay is not None
    x, y = (np.array(column, dtype=float) for column in np.transpose(later))
    if gap and len(x) > 2:
        y[len(y) // 2] = np.nan  # Agg leaves the point out
    if lists:
        x, y = [float(v) for v in x], list(map(np.float64, y))
    line.set_data(x, y)
    replayed = _recorded(line, recorder, replay)
    line.set_data(x, y)  # invalid again: the full draw recaches as matplotlib does
    assert replayed == _recorded(line, CommandRecorder(agg))


def test_a_changed_style_is_refused_and_data_matplotlib_must_convert_are_recached():
    axes, agg = _axes()
    (line,) = axes.plot([0.0, 5.0], [1.0, 2.0], color="red")
    recorder = CommandRecorder(agg)
    replay = LineReplay.record(line, recorder)
    line.set_data([1, 2, 3], [3, 2, 1])  # ints: recache converts them
    assert _recorded(line, recorder, replay) == _recorded(line, CommandRecorder(agg))
    line.set_color("blue")
    recorder.start()
    assert replay.draw(recorder) is False and recorder.commands == []
