"""A drag's moving artists drawn by the browser: the recorded commands, and what they draw.

The commands are carried out here by an independent player, Agg's renderer
driven from nothing but a message's commands and buffers, over the backdrop the
message carries. Its picture must be the one matplotlib draws of the same
artists: every number the browser needs (places, colours, widths, dashes,
clips, fonts) is in the message.
"""

from __future__ import annotations

import io
import json
import math

import numpy as np
import pytest
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle
from matplotlib.path import Path as MatplotlibPath
from matplotlib.transforms import Affine2D, Bbox, IdentityTransform
from PIL import Image

from course.lessons.l01_de_casteljau.apps import DeCasteljauApp
from course.lessons.l03_lines_and_triangles.apps import TriangleApp
from course.lessons.l05_antialiasing.apps import ZoomApp
from course.lessons.l08_poisson.apps import CloneApp
from course.widgets.browser_drawing import CommandRecorder
from course.widgets.figure_view import FigureView
from course.widgets.picture import ZoomedPixels

GENERIC = ("serif", "sans-serif", "cursive", "fantasy", "monospace")
_CAPSTYLES = {"butt": "butt", "square": "projecting", "round": "round"}


def played(content: dict, buffers: list, backdrop: np.ndarray, dpi: float) -> np.ndarray:
    """The picture ``picture.js`` draws from one "drawing" message, drawn by Agg."""
    height, width = backdrop.shape[:2]
    renderer = RendererAgg(width, height, dpi)
    np.asarray(renderer.buffer_rgba())[...] = backdrop
    vertices = np.frombuffer(buffers[-2], "<f4").reshape(-1, 2).astype(float)
    codes = np.frombuffer(buffers[-1], np.uint8)
    up = Affine2D().scale(1, -1).translate(0, height)  # the message's y runs down
    points = 72 / dpi
    pixels = np.frombuffer(buffers[-4], np.uint8)
    for command in commands_of(buffers):
        if "pixels" in command:  # written as they are, each zoom x zoom
            (start, w, h), (left, top), zoom = command["pixels"], command["at"], command["zoom"]
            panel = pixels[start : start + 3 * w * h].reshape(h, w, 3)
            panel = np.repeat(np.repeat(panel, zoom, axis=0), zoom, axis=1)
            canvas = np.asarray(renderer.buffer_rgba())
            canvas[top : top + h * zoom, left : left + w * zoom] = 255
            canvas[top : top + h * zoom, left : left + w * zoom, :3] = panel
            continue
        gc = renderer.new_gc()
        gc.set_snap(False)  # the message's places are snapped where Agg snaps already
        if command["clip"] is not None:
            left, top, w, h = command["clip"]
            gc.set_clip_rectangle(Bbox([[left, height - top - h], [left + w, height - top]]))
        if "text" in command:
            size, weight, style, families = command["font"]
            families = [name for name in families if name in GENERIC][:1] or families
            gc.set_foreground(command["color"], isRGBA=True)
            font = FontProperties(family=families, size=size * points, weight=weight, style=style)
            renderer.draw_text(
                gc, command["x"], command["y"], command["text"], font, command["angle"]
            )
            continue
        stroke, fill = command["stroke"], command["fill"]
        gc.set_linewidth(command["width"] * points if stroke else 0)
        if stroke:
            gc.set_foreground(stroke, isRGBA=True)
        if command["dash"]:
            offset, dashes = command["dash"]
            gc.set_dashes(offset * points, [dash * points for dash in dashes])
        gc.set_capstyle(_CAPSTYLES[command["cap"]])
        gc.set_joinstyle(command["join"])

        def path(start_count: list[int]) -> MatplotlibPath:
            start, count = start_count
            return MatplotlibPath(vertices[start : start + count], codes[start : start + count])

        if "path" in command:
            renderer.draw_path(gc, path(command["path"]), up, fill)
        else:
            marker = path(command["marker"])
            at = path(command["at"])
            # Agg moves an unsnapped marker by half a pixel, which the message has done.
            shape = Affine2D().translate(-0.5, -0.5).scale(1, -1)
            renderer.draw_markers(gc, marker, shape, at, up, fill)
    return np.asarray(renderer.buffer_rgba()).copy()


def commands_of(buffers: list) -> list[dict]:
    """A drawing message's commands: its third buffer from the end, JSON."""
    return json.loads(bytes(buffers[-3]))


class Sent:
    def __init__(self, view: FigureView) -> None:
        self.messages: list = []
        view.image.send = lambda content, buffers=None: self.messages.append((content, buffers))


def decoded(data: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(data)).convert("RGBA"))


def assert_close(drawn: np.ndarray, expected: np.ndarray, apart: int = 20) -> None:
    """Equal but for rounding: colours are sent to 1/1000, places as float32 or to 1e-4.

    At most ``apart`` pixels differ by more than 2 of 255: the glyphs of a long
    line of text drift by a fraction of a pixel, placed one by one.
    """
    difference = np.abs(drawn.astype(int) - expected.astype(int)).max(axis=2)
    assert (expected < 200).any()
    assert difference.max() <= 8, np.argwhere(difference > 8)[:5]
    assert np.count_nonzero(difference > 2) <= apart, np.argwhere(difference > 2)[:5]


def test_lesson_01_s_drag_drawn_from_its_commands_is_the_picture_agg_draws():
    app = DeCasteljauApp()
    app.refresh()
    sent = Sent(app.view)
    x, y, *_ = app.view.image.handles[1]
    app.pointer("down", x, y)  # the press draws the highlight: the background goes with it
    ((pressed, buffers),) = sent.messages
    assert pressed["kind"] == "drawing" and pressed["backdrop"] is True
    backdrop = decoded(buffers[0])
    # Agg's own drawing of each step, below, stays on the canvas: a published whole
    # picture would make the browser drop its backdrop.
    app.view.publish = lambda: b""
    for step in range(1, 8):
        angle = 0.9 * step
        app.view.awaited = True
        app.pointer("move", x + 40 * (1 - math.cos(angle)), y + 40 * math.sin(angle))
        content, buffers = sent.messages[-1]
        assert content["kind"] == "drawing" and content["drawn"] is True
        assert "backdrop" not in content and len(buffers) == 4 and buffers[0] == b""
        drawn = played(content, buffers, backdrop, app.view.figure.dpi)
        assert_close(drawn, agg_picture(app))
        # Agg is left to the release: a step's message is small.
        assert len(json.dumps(content)) + sum(len(b) for b in buffers) < 12_000
    del app.view.publish
    app.pointer("up", x, y)
    assert decoded(app.view.image.value).shape == backdrop.shape


def agg_picture(app) -> np.ndarray:
    """The app's picture as Agg draws it now: the moving artists over the background.

    A whole draw drops the drawing's replays; they are kept, so that the next
    step's message is made by them, as in a drag where Agg draws nothing. A
    step drawn from arrays (ArrayStep) left the artists as they were: they
    are brought to the app's state first, as ``refresh`` brings them.
    """
    view = app.view
    replays = dict(view._command_replays)
    app.update()
    app._place_highlight()
    view.render_moving(app.moving, app.pixel_images)
    view._command_replays.update(replays)
    return view.pixels()


def grabbed(app, index: int) -> tuple[Sent, tuple[float, float], np.ndarray]:
    """The app's messages from now on, where its handle ``index`` was pressed, the backdrop.

    The press sends the backdrop; Agg's drawing of each later step stays on the
    canvas (a published whole picture would make the browser drop its backdrop).
    """
    app.refresh()
    sent = Sent(app.view)
    handle = app.handles()[index]
    x, y = app.picture_point(handle.axes, handle.at)
    app.pointer("down", x, y)
    ((pressed, buffers),) = sent.messages
    assert pressed["kind"] == "drawing" and pressed["backdrop"] is True
    app.view.publish = lambda: b""
    return sent, (x, y), decoded(buffers[0])


def moved(app, sent: Sent, x: float, y: float) -> tuple[dict, list, list[dict]]:
    """The drawing message a move to (x, y) sends: its content, buffers and pixel commands."""
    app.view.awaited = True
    app.pointer("move", x, y)
    content, buffers = sent.messages[-1]
    assert content["kind"] == "drawing" and len(buffers) == 4
    return content, buffers, [command for command in commands_of(buffers) if "pixels" in command]


@pytest.mark.parametrize("kind", [TriangleApp, ZoomApp])
def test_pixel_panels_drawn_from_a_drag_s_message_are_the_picture_agg_draws(kind):
    # Lesson 03's triangles and lesson 05's zoom: their panels' pixels travel as they
    # are, a zoom-squared of what the picture shows, and the browser zooms them.
    app = kind()
    sent, (x, y), backdrop = grabbed(app, 1)
    for step in range(1, 4):
        content, buffers, panels = moved(app, sent, x + 9 * step, y - 6 * step)
        assert panels and all(command["zoom"] > 1 for command in panels)
        drawn = played(content, buffers, backdrop, app.view.figure.dpi)
        texts = sum("text" in command for command in commands_of(buffers))
        assert_close(drawn, agg_picture(app), apart=20 * texts)
        assert len(buffers[0]) * min(command["zoom"] for command in panels) ** 2 <= sum(
            3 * image.shape[0] * image.shape[1] for image in app.pixel_images.values()
        )


def test_lesson_08_s_drag_sends_only_the_windows_the_foreground_covers_over_the_still_lake():
    # Both panels are the half-size lake but for the blocks the foreground covers: the
    # backdrop holds the lake (a JPEG), each step only those two windows, exact.
    app = CloneApp()
    sent, (x, y), backdrop = grabbed(app, 0)
    height, width = app.foreground.shape[:2]
    for step in range(1, 4):
        content, buffers, windows = moved(app, sent, x + 9 * step, y - 6 * step)
        assert len(windows) == 2 and {command["zoom"] for command in windows} == {1}
        # Each window is the half-size blocks the foreground covers, not the panel.
        for command in windows:
            _, w, h = command["pixels"]
            assert w <= width // 2 + 1 and h <= height // 2 + 1
        drawn = played(content, buffers, backdrop, app.view.figure.dpi)
        expected = agg_picture(app)
        for command in windows:
            (_, w, h), (left, top) = command["pixels"], command["at"]
            window = (slice(top, top + h), slice(left, left + w))
            np.testing.assert_array_equal(drawn[window], expected[window])
        difference = np.abs(drawn.astype(int) - expected.astype(int))
        assert difference.max() <= 19  # the backdrop's JPEG (FigureView.JPEG_QUALITY)


def limits_scene() -> tuple[FigureView, Axes, Line2D, LineCollection]:
    """A view with a moving line in data coordinates and a grid line in the axes' own."""
    view = FigureView(shape=(60, 90))
    axes = view.figure.add_axes((0.1, 0.1, 0.8, 0.8), xlim=(0, 10), ylim=(0, 10))
    axes.set_axis_off()  # no ticks: new limits leave the background as it was
    (line,) = axes.plot([1, 5, 9], [2, 8, 3], "o-", animated=True)
    grid = axes.add_collection(
        LineCollection([[(0.5, 0), (0.5, 1)]], transform=axes.transAxes, animated=True)
    )
    return view, axes, line, grid


def test_new_limits_during_a_drag_move_the_lines_drawn_through_them_not_the_grid():
    # A replay keeps its recording's transform: an app that moves its view at a step
    # (lesson 05's panels follow their window) must not get the line where it was.
    view, axes, line, grid = limits_scene()
    view.render_moving([line, grid])
    sent = Sent(view)
    view.render_moving([line, grid], patches=True)
    ((_, buffers),) = sent.messages
    backdrop = decoded(buffers[0])
    for low in (1, 3):
        axes.set_xlim(low, low + 10)
        line.set_data([1, 5, 9 + low], [2, 8, 3])
        view.render_moving([line, grid], patches=True)
        content, buffers = sent.messages[-1]
        assert view._command_replays.get(grid) is not None  # in the axes' box: kept
        # The same step drawn by Agg, in a view of its own (a whole draw drops replays).
        agg, agg_axes, agg_line, agg_grid = limits_scene()
        agg_axes.set_xlim(low, low + 10)
        agg_line.set_data([1, 5, 9 + low], [2, 8, 3])
        agg.render_moving([agg_line, agg_grid])
        assert_close(played(content, buffers, backdrop, view.figure.dpi), agg.pixels())


def test_dashes_markers_fills_clips_and_turned_text_are_drawn_as_agg_draws_them():
    view = FigureView(shape=(120, 200))
    axes = view.figure.add_axes((0.1, 0.1, 0.8, 0.8), xlim=(0, 10), ylim=(0, 5))
    moving = [
        *axes.plot([0, 4, 12], [1, 4, 2], "--o", color="teal", linewidth=2.5, markersize=9),
        *axes.plot([1, 9], [4, 0.5], linestyle="-.", color="0.3", marker="D", mfc="none"),
        *axes.plot([5, 6, 7], [2, 2.5, 2], "^", color="orange", alpha=0.6),
        axes.add_patch(Rectangle((6, 1), 3, 2, facecolor=(0, 0, 1, 0.3), edgecolor="navy")),
        axes.text(2, 2, "tilted 42", rotation=30, fontsize=11, color="purple"),
        axes.text(5, 4.5, "B(t) = (1.0, 2.5)", ha="center", weight="bold"),
        view.figure.text(0.02, 0.02, "corner", transform=view.figure.transFigure, style="italic"),
        # Collections: one style for all their paths, moved by one offset or by several.
        axes.add_collection(
            LineCollection(
                [[(0, 0), (1, 1)], [(1, 0), (0, 1)]],
                offsets=[(7.5, 3.5)],
                offset_transform=axes.transData,
                colors="crimson",
                linewidths=1.5,
            )
        ),
        axes.add_collection(
            LineCollection(
                [[(0.5, 0.2), (2, 0.2)], [(0.5, 0.6), (2, 0.6)]],
                colors=["green", "black"],
                linestyles=["-", ":"],
            )
        ),
    ]
    for artist in moving:
        artist.set_animated(True)
    view.render_moving(moving)
    sent = Sent(view)
    view.render_moving(moving, patches=True)
    ((content, buffers),) = sent.messages
    kinds = [
        next(key for key in ("path", "marker", "text") if key in c) for c in commands_of(buffers)
    ]
    assert kinds.count("marker") == 3 and kinds.count("text") == 3
    assert any(c.get("dash") for c in commands_of(buffers))
    drawn = played(content, buffers, decoded(buffers[0]), view.figure.dpi)
    view.render_moving(moving)
    assert_close(drawn, view.pixels())


def test_what_only_agg_draws_sends_patches_until_the_background_changes():
    view = FigureView(shape=(60, 60))
    axes = view.figure.add_axes((0, 0, 1, 1))
    axes.set_axis_off()
    (line,) = axes.plot([0, 1], [0, 1], animated=True)
    picture = axes.imshow(np.eye(3), extent=(0, 1, 0, 1), animated=True)
    formula = axes.text(0.1, 0.5, "$x^2$", animated=True)
    tries = []
    publish_drawing = view.publish_drawing
    view.publish_drawing = lambda *given: tries.append(1) or publish_drawing(*given)
    for moving in ([picture, line], [line, formula]):
        view.invalidate()
        view.render_moving(moving)
        sent = Sent(view)
        tries.clear()
        for step in (1, 2):
            line.set_data([0, 0.5], [1, 0.1 * step])
            view.render_moving(moving, patches=True)
        assert [content["kind"] for content, _ in sent.messages] == ["patch", "patch"]
        assert len(tries) == 1  # known after the first step: not tried again
    view.invalidate()
    sent = Sent(view)
    view.render_moving([line], patches=True)
    assert [content["kind"] for content, _ in sent.messages] == ["drawing"]
    # Patches only: the first step sends the whole picture (the browser's is a drawing).
    view.draw_in_browser = False
    whole = view.image.value
    line.set_data([0, 1], [1, 0])
    assert view.render_moving([line], patches=True) == view.image.value != whole
    line.set_data([0, 1], [0.5, 0])
    view.render_moving([line], patches=True)
    assert [content["kind"] for content, _ in sent.messages] == ["drawing", "patch"]


def test_the_backdrop_is_sent_once_per_background_and_pixel_panels_are_patched():
    view = FigureView(shape=(50, 80))
    axes = view.figure.add_axes((0, 0, 1, 1), xlim=(0, 1), ylim=(0, 1))
    (line,) = axes.plot([0, 1], [0, 1], animated=True)
    view.render_moving([line])
    sent = Sent(view)
    for step in range(3):
        line.set_data([0, 1], [0, 1 - 0.1 * step])
        view.render_moving([line], patches=True)
    view.render_moving([line], patches=True)  # nothing moved: nothing sent
    view.invalidate()
    view.render_moving([line], patches=True)
    assert [content.get("backdrop", False) for content, _ in sent.messages] == [
        True,
        False,
        False,
        True,
    ]
    assert [len(buffers) for _, buffers in sent.messages] == [5, 4, 4, 5]
    # A whole-size image is patched; zoomed pixels travel as they are.
    panel = np.zeros((50, 80, 3), dtype=np.uint8)
    view.render_moving([line], {axes: panel})
    view.render_moving([line], {axes: panel + 9}, patches=True)
    assert sent.messages[-1][0]["kind"] == "patch"
    zoomed = ZoomedPixels(np.full((5, 8, 3), 9, dtype=np.uint8), 10)
    view.render_moving([line], {axes: zoomed}, patches=True)
    assert (
        sent.messages[-1][0]["kind"] == "drawing"
        and sent.messages[-1][1][1] == zoomed.pixels.tobytes()
    )


def test_a_drag_after_a_whole_picture_sends_the_backdrop_again():
    # picture.js drops its backdrop when a whole picture comes (a release): the next
    # drag's first drawing must bring it again, even when the background did not change.
    view = FigureView(shape=(50, 80))
    axes = view.figure.add_axes((0, 0, 1, 1), xlim=(0, 1), ylim=(0, 1))
    (line,) = axes.plot([0, 1], [0, 1], animated=True)
    view.render_moving([line])
    sent = Sent(view)
    for _drag in range(2):
        for step in range(2):
            line.set_data([0, 1], [0, 0.9 - 0.1 * step])
            view.render_moving([line], patches=True)
        view.render_moving([line])  # the release: a whole picture
    assert [content.get("backdrop", False) for content, _ in sent.messages] == [
        True,
        False,
        True,
        False,
    ]


def test_a_recorder_measures_text_as_agg_does_and_finishes_empty_when_nothing_is_drawn():
    figure = Figure(figsize=(2, 1), dpi=72)
    agg = FigureCanvasAgg(figure).get_renderer()
    recorder = CommandRecorder(agg)
    font = FontProperties(size=12)
    assert recorder.get_text_width_height_descent("P1", font, False) == (
        agg.get_text_width_height_descent("P1", font, False)
    )
    assert recorder.points_to_pixels(72) == 72 and recorder.flipy()
    assert recorder.finish() == [b"", b"[]", b"", b""]
    text = figure.text(0, 0, "x", transform=IdentityTransform(), fontsize=12)
    text.draw(recorder)
    (command,) = json.loads(recorder.finish()[1])
    assert command["font"][0] == pytest.approx(12.0) and command["text"] == "x"


def test_markers_at_nan_or_infinite_places_are_dropped_and_the_rest_kept():
    # As Agg: a marker whose place is not finite is not drawn; huge finite ones are.
    figure = Figure(figsize=(1, 1), dpi=100)
    canvas = FigureCanvasAgg(figure)
    axes = figure.add_axes((0, 0, 1, 1), xlim=(0, 1), ylim=(0, 1))
    recorder = CommandRecorder(canvas.get_renderer())
    for x, y, kept in (
        ([0.2, np.nan, 0.6, 0.8], [0.5, 0.5, 0.5, np.inf], 2),
        ([0.2, 0.4, 0.6], [0.5, -np.inf, 0.5], 2),
        ([0.2, 1e306, 1e306], [0.5, 0.5, 0.5], 3),
        ([0.2, 0.4], [0.5, 0.6], 2),
    ):
        (line,) = axes.plot(x, y, "o", markersize=4)
        recorder.start()
        line.draw(recorder)
        (command,) = recorder.recorded()
        assert command["at"][1] == kept, (x, y)
        line.remove()


def test_a_zoom_step_that_keeps_its_window_keeps_the_panels_recordings():
    # New limits drop the recordings drawn through an axes' data: a panel whose
    # window stays sets none, so its curve's recording serves the next step.
    app = ZoomApp()
    sent, (x, y), _backdrop = grabbed(app, 1)
    moved(app, sent, x + 0.3, y)
    curve = app.panels[0].curve
    recorded = app.view._command_replays[curve]
    box, box_recorded = app.window_box.get_bbox().bounds, app.view._command_replays[app.window_box]
    extent = app.panels[0].axes.get_xlim()
    moved(app, sent, x + 0.4, y)
    assert app.panels[0].axes.get_xlim() == extent
    assert app.view._command_replays[curve] is recorded
    # The overview's window box, where the window stays, is not drawn anew either.
    assert app.window_box.get_bbox().bounds == box
    assert app.view._command_replays[app.window_box] is box_recorded
