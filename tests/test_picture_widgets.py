"""course.widgets.picture: the encoders, blitting and pixels written as they are."""

import base64
import io
import itertools
import json
import math
import shutil
import subprocess

import numpy as np
import pytest
from matplotlib.backends import backend_agg
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.text import Text
from matplotlib.transforms import IdentityTransform
from PIL import Image

from course.widgets import line_replay, picture, text_cache
from course.widgets.figure_view import FigureView
from course.widgets.picture import (
    Picture,
    PixelPanel,
    Still,
    ZoomedPixels,
    pixel_axes,
    pixel_figure,
    png_bytes,
)


def decoded(data: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(data)).convert("RGB"))


def test_png_bytes_decode_to_the_pixels_they_encode():
    rng = np.random.default_rng(3)
    pixels = rng.integers(0, 256, size=(37, 53, 3), dtype=np.uint8)
    data = png_bytes(pixels)
    assert data.startswith(b"\x89PNG\r\n\x1a\n")
    np.testing.assert_array_equal(decoded(data), pixels)


def test_png_bytes_refuses_anything_but_rgb_bytes():
    with pytest.raises(
        ValueError,
        match=r"pixels must be an \(H, W, 3\) or \(H, W, 4\) uint8 array; got an array of shape "
        r"\(4, 4\) and "
        r"dtype float64",
    ):
        png_bytes(np.zeros((4, 4)))
    with pytest.raises(ValueError, match=r"got an array of shape \(2, 2, 3\) and dtype int64"):
        png_bytes(np.zeros((2, 2, 3), dtype=np.int64))


class Blank:
    """What PixelPanel needs of an app: where to leave the pixels it writes."""

    def __init__(self) -> None:
        self.pixel_images: dict = {}


def test_a_pixel_panel_shows_what_imshow_nearest_shows_at_a_whole_zoom():
    values = np.array([[0.0, 0.25, 1.0], [0.5, 0.75, 0.1]])
    zoom = 7
    pictures = []
    for pasted in (False, True):
        view = FigureView(shape=(40, 60))
        axes = pixel_axes(view.figure, 10, 12, 3 * zoom, 2 * zoom)
        axes.set_axis_off()
        if pasted:
            app = Blank()
            PixelPanel(app, axes, values.shape, zoom).set_data(values)
            view.render_moving([], app.pixel_images)
        else:
            axes.imshow(values, cmap="gray", vmin=0, vmax=1, interpolation="nearest")
            view.render()
        pictures.append(view.pixels()[..., :3])
    np.testing.assert_array_equal(pictures[0], pictures[1])
    # The top-left image pixel is black, at the axes' top-left corner: 40 - 12 - 14 = 14.
    assert (pictures[1][14 : 14 + zoom, 10 : 10 + zoom] == 0).all()


def test_pasting_an_image_of_the_wrong_size_names_both_sizes():
    view = FigureView(shape=(40, 60))
    axes = pixel_axes(view.figure, 0, 0, 20, 10)
    view.render_moving([])
    with pytest.raises(ValueError, match=r"image: expected the axes' 10 x 20 pixels; got 5 x 20"):
        view.paste(axes, np.zeros((5, 20, 3), dtype=np.uint8))
    window = ZoomedPixels(np.zeros((2, 3, 3), dtype=np.uint8), 2, at=(15, 4))
    with pytest.raises(
        ValueError,
        match=r"expected a window inside the axes' 10 x 20 pixels; got 4 x 6 from \(15, 4\)",
    ):
        view.paste(axes, window)


def test_a_window_of_zoomed_pixels_goes_over_the_still_picture_from_its_corner():
    view = FigureView(shape=(40, 60))
    axes = pixel_axes(view.figure, 10, 5, 20, 10)
    view.still_images[axes] = np.full((10, 20, 3), 50, dtype=np.uint8)
    window = ZoomedPixels(np.array([[[200, 0, 0], [0, 200, 0]]], dtype=np.uint8), 3, at=(4, 2))
    view.render_moving([], {axes: window})
    panel = view.pixels()[25:35, 10:30, :3]  # 40 - 5 - 10 = 25 rows down
    expected = np.full((10, 20, 3), 50, dtype=np.uint8)
    expected[2:5, 4:7] = [200, 0, 0]
    expected[2:5, 7:10] = [0, 200, 0]
    np.testing.assert_array_equal(panel, expected)


def test_blitting_redraws_only_the_moving_artists_over_the_still_rest():
    view = FigureView(shape=(50, 50))
    axes = view.figure.add_axes((0, 0, 1, 1))
    axes.set_xlim(0, 1)
    axes.set_ylim(0, 1)
    axes.set_axis_off()
    still = axes.axvline(0.2, color="blue", linewidth=3)
    (moving,) = axes.plot([0.5, 0.5], [0, 1], color="red", linewidth=3, animated=True)
    view.render_moving([moving])
    moving.set_xdata([0.8, 0.8])
    view.render_moving([moving])
    assert columns_of(view, "red") == pytest.approx(40, abs=1.5)  # the old red is gone
    assert columns_of(view, "blue") == pytest.approx(10, abs=1.5)
    still.set_xdata([0.6, 0.6])  # a change to the background shows only once invalidated
    view.render_moving([moving])
    assert columns_of(view, "blue") == pytest.approx(10, abs=1.5)
    view.invalidate()
    view.render_moving([moving])
    assert columns_of(view, "blue") == pytest.approx(30, abs=1.5)


def columns_of(view: FigureView, colour: str) -> float:
    """The mean column of the pure red or pure blue pixels across the middle row."""
    red, _, blue = view.pixels()[25, :, :3].astype(int).T
    strong, weak = (red, blue) if colour == "red" else (blue, red)
    return float(np.flatnonzero((strong > 200) & (weak < 80)).mean())


def test_jpeg_pictures_stay_close_to_the_canvas_and_formats_are_checked():
    view = FigureView(shape=(64, 64), format="jpeg")
    axes = view.figure.add_axes((0, 0, 1, 1))
    axes.set_axis_off()
    rng = np.random.default_rng(0)
    photo = np.cumsum(np.cumsum(rng.normal(size=(64, 64, 3)), axis=0), axis=1)
    axes.imshow((photo - photo.min()) / np.ptp(photo), interpolation="nearest")
    data = view.render()
    assert data.startswith(b"\xff\xd8") and view.image.format == "jpeg"
    difference = np.abs(decoded(data).astype(int) - view.pixels()[..., :3].astype(int))
    assert difference.mean() < 2 and difference.max() <= 40
    with pytest.raises(ValueError, match=r"format must be one of 'png', 'jpeg'; got 'gif'"):
        FigureView(format="gif")


def test_a_figure_view_is_the_size_it_is_asked_for():
    view = FigureView(shape=(123, 45))
    assert isinstance(view.figure, Figure)
    view.render()
    assert view.pixels().shape == (123, 45, 4)
    assert (view.image.height, view.image.width) == (123, 45)


def test_a_still_shows_as_its_image_and_reads_as_its_caption():
    figure = Figure(figsize=(1.2, 0.8), dpi=100)
    still = Still.of(figure, "a caption with numbers 1.5")
    assert repr(still) == "a caption with numbers 1.5"
    assert still._repr_png_().startswith(b"\x89PNG") and still._repr_jpeg_() is None
    assert Image.open(io.BytesIO(still.png)).size == (120, 80)
    jpeg = Still(b"\xff\xd8\xff\xe0 jpeg", "photo")
    assert jpeg._repr_png_() is None and jpeg._repr_jpeg_() == b"\xff\xd8\xff\xe0 jpeg"


def test_pixel_figures_draw_every_pixel_as_a_whole_square():
    rng = np.random.default_rng(5)
    windows = [
        (rng.uniform(size=(5, 7, 3)), (10, 17, 25, 20), "a"),
        (rng.uniform(size=(5, 7)), (0, 7, 5, 0), "b"),
    ]
    zoom = 9
    figure, axes_list = pixel_figure(windows, zoom=zoom, legend=[("red", "red")])
    still = Still.of(figure, "x")
    shown = np.asarray(Image.open(io.BytesIO(still.png)).convert("RGB")).astype(int)
    height = shown.shape[0]
    for (window, _, _), axes in zip(windows, axes_list, strict=True):
        box = axes.get_window_extent()
        assert (round(box.width), round(box.height)) == (7 * zoom, 5 * zoom)
        left, top = round(box.x0), round(height - box.y1)
        # The centre of each zoomed pixel holds the window's value (gray: as imshow maps it).
        centres = shown[
            top + zoom // 2 : top + 5 * zoom : zoom, left + zoom // 2 : left + 7 * zoom : zoom
        ]
        expected = window if window.ndim == 3 else np.repeat(window[..., None], 3, axis=2)
        assert np.abs(centres - np.round(expected * 255)).max() <= 2  # a colormap has 256 steps
        # A whole square is one colour: the pixel next to the centre matches it.
        beside = shown[
            top + zoom // 2 : top + 5 * zoom : zoom, left + zoom // 2 + 2 : left + 7 * zoom : zoom
        ]
        assert np.array_equal(beside, centres)


@pytest.mark.parametrize(("zoom", "error"), [(0, ValueError), (129, ValueError), (2.5, TypeError)])
def test_pixel_figure_refuses_a_zoom_by_name_for_every_figure_that_passes_one_on(zoom, error):
    window = (np.zeros((2, 3)), (0, 3, 2, 0), "")
    with pytest.raises(error, match="zoom"):
        pixel_figure([window], zoom)


class Sent:
    """What a Picture sends to the browser, kept instead: (content, buffers) per message."""

    def __init__(self, view: FigureView) -> None:
        self.messages: list = []
        view.image.send = lambda content, buffers=None: self.messages.append((content, buffers))


def patched(shown: np.ndarray, messages: list) -> np.ndarray:
    """The browser's picture: ``shown`` with each patch painted over it, in order."""
    picture = shown.copy()
    for content, buffers in messages:
        assert content["kind"] == "patch" and len(buffers) == len(content["rectangles"])
        for (left, top, width, height), data in zip(content["rectangles"], buffers, strict=True):
            piece = np.asarray(Image.open(io.BytesIO(data)).convert("RGBA"))
            assert piece.shape == (height, width, 4)
            picture[top : top + height, left : left + width] = piece
    return picture


def test_patches_bring_the_browser_s_picture_to_the_canvas_exactly():
    view = FigureView(shape=(120, 160))
    view.draw_in_browser = False  # Agg's pixels, patched
    axes = view.figure.add_axes((0, 0, 1, 1))
    axes.set_xlim(0, 1)
    axes.set_ylim(0, 1)
    axes.set_axis_off()
    axes.axvline(0.3, color="blue")
    (moving,) = axes.plot([0.1, 0.2], [0.1, 0.9], color="red", linewidth=2, animated=True)
    label = axes.text(0.5, 0.95, "", animated=True)
    sent = Sent(view)
    view.render_moving([moving, label])
    shown = decoded_rgba(view.image.value)
    whole = view.image.value
    for step in range(1, 6):
        moving.set_data([0.1 * step, 0.2], [0.1, 0.9 - 0.1 * step])
        label.set_text(f"step {step}")
        assert view.render_moving([moving, label], patches=True) == b""
        np.testing.assert_array_equal(patched(shown, sent.messages), view.pixels())
    assert view.image.value == whole  # the whole picture waits for the drag's end
    # Far apart changes go as separate rectangles: the label's band and the line's.
    bands = [rectangle[1] for rectangle in sent.messages[-1][0]["rectangles"]]
    assert len(bands) == 2 and bands[0] < 20 < bands[1]
    view.render_moving([moving, label])
    np.testing.assert_array_equal(decoded_rgba(view.image.value), view.pixels())


def test_a_step_that_changes_nothing_sends_nothing_and_jpeg_is_never_patched():
    view = FigureView(shape=(40, 40))
    view.draw_in_browser = False  # Agg's pixels, patched
    view.figure.add_axes((0, 0, 1, 1)).set_axis_off()
    sent = Sent(view)
    assert view.render_moving([], patches=True) != b""  # no whole picture yet: one is sent
    assert view.render_moving([], patches=True) == b"" and sent.messages == []
    photo = FigureView(shape=(40, 40), format="jpeg")
    photo.draw_in_browser = False
    photo.figure.add_axes((0, 0, 1, 1)).set_axis_off()
    photo.render_moving([])
    assert photo.render_moving([], patches=True).startswith(b"\xff\xd8")


def decoded_rgba(data: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(data)).convert("RGBA"))


def test_cached_glyphs_paint_exactly_what_agg_paints(monkeypatch):
    # Layouts cached, and composed from pairs for the numbers of the last text.
    texts = ["degree 3, t = 0.50: B(t) = (355.0, 213.8)", "P1", "Wavy AV (12.3, 4.5)"]
    texts.append("(-7.25, 1) + (40.0, 613.9)")
    pictures = []
    for cached in (False, True):
        view = FigureView(shape=(110, 300))
        axes = view.figure.add_axes((0, 0, 1, 1))
        axes.set_axis_off()
        artists = [
            axes.text(0.013 + 0.1 * i, 0.1 + 0.22 * i, text, fontsize=9 + i, animated=True)
            for i, text in enumerate(texts)
        ]
        artists.append(axes.text(0.5, 0.5, "turned", rotation=30, animated=True))
        with monkeypatch.context() as patch:
            if not cached:  # Agg's own drawing: the cache is never installed
                patch.setattr(text_cache.GlyphCache, "install", classmethod(lambda cls, r: None))
            frames = draw_shifted(view, artists)
        drawer = view.canvas.get_renderer()._draw_text_glyphs_and_boxes
        assert isinstance(drawer, text_cache.GlyphCache) == cached
        pictures.append(frames)
    for agg, cache in zip(*pictures, strict=True):
        assert (agg < 250).any()  # something was drawn
        np.testing.assert_array_equal(cache, agg)


def draw_shifted(view: FigureView, artists: list) -> list[np.ndarray]:
    """The picture with the texts moved by whole and fractional pixels: bitmaps are reused."""
    frames = []
    for shift in (0.0, 0.37, 1.0):
        for artist in artists[:3]:
            artist.set_x(artist.get_position()[0] + shift / 300)
        view.render_moving(artists)
        frames.append(view.pixels())
    return frames


NODE = shutil.which("node")

HARNESS = r"""
const painted = [];
const text = (part) =>
  new TextDecoder().decode(part instanceof DataView ? part : new Uint8Array(part));
globalThis.Blob = class {
  constructor(parts, options) {
    this.text = parts.map(text).join("");
    this.type = options.type;
  }
};
globalThis.URL = { createObjectURL: (blob) => blob.text, revokeObjectURL: () => {} };
// Time is counted in turns of the event loop, not milliseconds, so a busy machine
// cannot reorder what follows: a patch takes a few turns to decode, as in a browser;
// the whole picture fewer.
const turns = async (count) => {
  for (let turn = 0; turn < count; turn++) await new Promise((resolve) => setImmediate(resolve));
};
globalThis.createImageBitmap = (blob) =>
  turns(blob.text.startsWith("P") ? 5 : 0).then(() => ({ width: 5, height: 4, text: blob.text }));
const warnings = [];
console.warn = (...parts) => warnings.push(parts.join(" "));
const image = { addEventListener() {}, style: {}, dataset: {}, decode: () => turns(2) };
let overlay = null;  // the canvas laid over the image, drawn on
globalThis.document = {
  createElement(tag) {
    if (tag === "img") return image;
    const canvas = { getContext: () => context, width: 5, height: 4, style: {} };
    overlay = canvas;
    const context = {
      canvas,
      drawImage: (bitmap, x, y) => painted.push(`${bitmap.text}@${x},${y}`),
      clearRect: () => {},
    };
    return canvas;
  },
};
const handlers = {};
const state = {
  value: new TextEncoder().encode("V0"), format: "png", width: 5, height: 4, handles: [],
};
const model = {
  get: (key) => state[key],
  on: (event, handler) => { handlers[event] = handler; },
  send: () => {},
};
// More turns than every decode and encode above put together.
const settle = () => turns(200);
const bytes = (s) => new DataView(new TextEncoder().encode(s).buffer);
const patch = (name, x, y) =>
  handlers["msg:custom"]({ kind: "patch", rectangles: [[x, y, 2, 1]] }, [bytes(name)]);
const { default: widget } = await import(process.argv[2]);
widget.render({ model, el: { appendChild() {}, style: {} } });
// What the page shows: the canvas while it is shown over the image, else the image.
const shown = () => (overlay.style.display === "block" ? "canvas:" + painted.join(" ") : image.src);
const seen = [shown()];
patch("P1", 1, 1);
patch("P2", 3, 2);
await settle();
seen.push(shown());
patch("P3", 0, 0);  // being decoded when the whole picture comes back: dropped
await turns(1);
state.value = new TextEncoder().encode("V1");
handlers["change:value"]();
seen.push(shown());
await settle();
seen.push(shown());
patch("P4", 2, 2);  // a patch for the new picture starts from it
await settle();
seen.push(shown());
console.log(JSON.stringify({ seen, warnings }));
"""


# picture.js in Node with a stand-in page (an image, a canvas that records what
# is painted, blobs and bitmaps that carry their bytes as text): a browser is too
# heavy for a unit test; tests_browser drives the real one.
def picture_js_in_node(tmp_path, harness: str) -> object:
    """What ``harness`` prints (JSON) after it imported picture.js in Node."""
    module = tmp_path / "picture.mjs"
    module.write_text(Picture._esm, encoding="utf-8")
    script = tmp_path / "harness.mjs"
    script.write_text(harness, encoding="utf-8")
    done = subprocess.run(
        [NODE, str(script), module.as_uri()], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.mark.skipif(NODE is None, reason="Node.js runs picture.js outside a browser")
def test_picture_js_paints_patches_in_order_and_a_new_picture_drops_the_stale_ones(tmp_path):
    printed = picture_js_in_node(tmp_path, HARNESS)
    assert printed["warnings"] == []
    assert printed["seen"] == [
        "V0",
        "canvas:V0@0,0 P1@1,1 P2@3,2",
        "canvas:V0@0,0 P1@1,1 P2@3,2",  # until the image has decoded V1: no flash of V0
        "V1",
        "canvas:V0@0,0 P1@1,1 P2@3,2 V1@0,0 P4@2,2",
    ]


DRAG_HARNESS = r"""
const listeners = {};
const image = {
  addEventListener: (kind, listener) => { listeners[kind] = listener; },
  getBoundingClientRect: () => ({ left: 0, top: 0, width: 5, height: 4 }),
  setPointerCapture() {},
  naturalWidth: 5,
  naturalHeight: 4,
  style: {},
  decode: async () => {},
};
globalThis.document = { createElement: () => image };
globalThis.Blob = class {};
globalThis.URL = { createObjectURL: () => "url", revokeObjectURL: () => {} };
const handlers = {};
const sent = [];
const state = { value: new Uint8Array(), format: "png", width: 5, height: 4, handles: [] };
const model = {
  get: (key) => state[key],
  on: (event, handler) => { handlers[event] = handler; },
  send: (message) => sent.push(`${message.kind}@${message.x}`),
};
const { default: widget } = await import(process.argv[2]);
widget.render({ model, el: { appendChild() {}, style: {} } });
const at = (x) => ({ button: 0, clientX: x, clientY: 1, pointerId: 1, preventDefault() {} });
const steps = [];
const step = (name, act) => { act(); steps.push(`${name}: ${sent.splice(0).join(" ")}`); };
step("down", () => listeners.pointerdown(at(1)));
step("two moves while the press is drawn", () => {
  listeners.pointermove(at(2));
  listeners.pointermove(at(3));
});
step("drawn", () => handlers["msg:custom"]({ kind: "drawn" }, []));
step("a move", () => listeners.pointermove(at(4)));
step("a patch that is not the answer", () =>
  handlers["msg:custom"]({ kind: "patch", rectangles: [] }, []));
step("the patch that answers", () =>
  handlers["msg:custom"]({ kind: "patch", rectangles: [], drawn: true }, []));
step("a move", () => listeners.pointermove(at(5)));
step("the drawing that answers", () =>
  handlers["msg:custom"]({ kind: "drawing", drawn: true }, []));
step("up", () => listeners.pointerup(at(6)));
console.log(JSON.stringify(steps));
"""


@pytest.mark.skipif(NODE is None, reason="Node.js runs picture.js outside a browser")
def test_picture_js_sends_a_move_only_once_the_last_is_answered(tmp_path):
    assert picture_js_in_node(tmp_path, DRAG_HARNESS) == [
        "down: down@1",
        "two moves while the press is drawn: ",
        "drawn: move@3",  # the latest position only: the one before it was merged
        "a move: ",
        "a patch that is not the answer: ",
        "the patch that answers: move@4",
        "a move: ",
        "the drawing that answers: move@5",
        "up: up@6",
    ]


def test_numbers_laid_out_from_their_pairs_are_laid_out_as_agg_lays_them_out():
    view = FigureView(shape=(40, 40))
    renderer = view.canvas.get_renderer()
    text_cache.GlyphCache.install(renderer)
    layouts = renderer.draw_text
    flags = backend_agg.get_hinting_flag()
    rng = np.random.default_rng(7)
    alphabet = sorted(text_cache._LayoutCache.COMPOSABLE)
    for size in (7, 10, 13.5):
        font = renderer._prepare_font(FontProperties(size=size))
        strings = ["".join(pair) for pair in itertools.product(alphabet, repeat=2)]
        strings += ["".join(rng.choice(alphabet, rng.integers(3, 20))) for _ in range(150)]
        for text in strings:
            agg = [
                (item.ft_object, size, item.glyph_index, 0, 1, item.x, item.y)
                for item in font._layout(text, flags=flags)
            ]
            assert layouts._composed(font, text, size, flags) == agg, text
    # Letters are shaped by Agg: ligatures and kerning reach beyond a pair.
    assert layouts._composed(font, "ffi 1", 10, flags) is None


def test_fixed_text_draws_what_text_draws_and_falls_back_where_it_cannot():
    strings = ["(355.0, 213.8)", "(-4.5, 0.0)", "1", "(9, 9)", "--", ", .", "(0.1, 22.7)"]
    drawn = {}
    for kind in (Text, text_cache.FixedText):
        view = FigureView(shape=(60, 200))
        texts = [
            kind(13.3, 21.7, "", transform=IdentityTransform(), fontsize=11, va="bottom"),
            kind(100.6, 40.2, "", transform=IdentityTransform(), fontsize=9, va="baseline"),
            kind(150, 30, "", transform=IdentityTransform(), fontsize=8, ha="center"),
            kind(60, 10, "", transform=IdentityTransform(), fontsize=8, rotation=20),
        ]
        for text in texts:
            text.set_animated(True)
            view.figure.add_artist(text)
        frames = []
        for shown in strings:  # a text's ascent and descent change with its characters
            for text in texts:
                text.set_text(shown)
            view.render_moving(texts)
            frames.append(view.pixels())
        drawn[kind] = frames
        if kind is text_cache.FixedText:  # placed once per ascent and descent; the rest by Text
            assert len(texts[0]._origins) > 1 and texts[1]._origins
            assert not texts[2]._origins and not texts[3]._origins
    for text_frame, fixed_frame in zip(drawn[Text], drawn[text_cache.FixedText], strict=True):
        assert (text_frame[..., 0] < 200).any()
        np.testing.assert_array_equal(fixed_frame, text_frame)


@pytest.mark.parametrize(("align", "share"), [("center", 0.5), ("right", 1.0)])
def test_steady_text_stands_where_text_puts_its_string_with_zeros_for_digits(align, share):
    strings = ["RMSE here 0.123", "RMSE here 0.000", "at (500, 300)", "at (17, 9)", "(-4.5, 0.0)"]
    for shown in strings:
        zeros = shown.translate(str.maketrans("123456789", "000000000"))
        drawn = []
        for kind in ("steady", "placed by hand", "zeros by Text"):
            view = FigureView(shape=(40, 240))
            if kind == "steady":
                text = text_cache.SteadyText(120.3, 14.6, shown, ha=align, va="bottom")
            else:
                width = view.canvas.get_renderer().get_text_width_height_descent(
                    zeros, FontProperties(size=9), False
                )[0]
                text = (
                    Text(120.3 - share * width, 14.6, shown, ha="left", va="bottom")
                    if kind == "placed by hand"
                    else Text(120.3, 14.6, zeros, ha=align, va="bottom")
                )
            text.set_transform(IdentityTransform())
            text.set_fontsize(9)
            text.set_animated(True)
            view.figure.add_artist(text)
            view.render_moving([text])
            drawn.append(view.pixels())
        assert (drawn[0][..., 0] < 200).any()
        np.testing.assert_array_equal(drawn[0], drawn[1])  # the digits' own glyphs, in place
        if shown == zeros:
            np.testing.assert_array_equal(drawn[0], drawn[2])  # centred as Text centres it


def test_a_replayed_line_is_drawn_as_matplotlib_draws_it_and_a_restyled_one_anew():
    def drag(change: str, replay: bool) -> list[np.ndarray]:
        view = FigureView(shape=(80, 120))
        view.draw_in_browser = False  # Agg's pixels, patched
        axes = view.figure.add_axes((0.05, 0.05, 0.9, 0.9))
        axes.set_xlim(0, 10)
        axes.set_ylim(0, 10)
        (line,) = axes.plot([1, 5, 9], [1, 8, 2], "o--", color="C0", animated=True)
        (tail,) = axes.plot([], [], color="C3", linewidth=3, animated=True)
        view.render_moving([line, tail])
        frames = []
        for step in range(1, 6):
            line.set_data([1, 5 + 0.37 * step, 9], [1, 8 - 0.61 * step, 2])
            tail.set_data(np.linspace(0, step, 30), np.sqrt(np.linspace(0, step, 30)))
            if change == "style" and step == 3:
                line.set_color("C2")
                line.set_markersize(9)
            if change == "view" and step == 3:
                axes.set_xlim(-2, 12)
                view.invalidate()  # as an app does when its view changes
            if not replay:
                view.invalidate()  # a whole draw at every step: no replay
            view.render_moving([line, tail], patches=replay)
            frames.append(view.pixels())
        if replay:
            assert set(view._replays) == {line, tail}  # both were replayed
        return frames

    for change in ("", "style", "view"):
        for agg, replayed in zip(drag(change, False), drag(change, True), strict=True):
            np.testing.assert_array_equal(replayed, agg)


def test_lines_on_a_log_axis_are_drawn_by_matplotlib_not_replayed():
    view = FigureView(shape=(60, 60))
    axes = view.figure.add_axes((0.1, 0.1, 0.8, 0.8))
    axes.set_yscale("log")
    (line,) = axes.plot([1, 2, 3], [1, 10, 100], animated=True)
    view.render_moving([line])
    assert line_replay.LineReplay.record(line, view.canvas.get_renderer()) is None


def test_a_still_in_a_notebook_shows_its_picture_then_its_caption_as_text(monkeypatch, capsys):
    shown = []
    monkeypatch.setattr(picture, "display", lambda bundle, raw: shown.append((bundle, raw)))
    still = Still(png_bytes(np.zeros((2, 3, 3), dtype=np.uint8)), "two by three, all black")
    still._ipython_display_()
    ((bundle, raw),) = shown
    assert raw and bundle["text/plain"] == "two by three, all black"  # the site's alt text
    assert decoded(base64.b64decode(bundle["image/png"])).shape == (2, 3, 3)
    assert capsys.readouterr().out == "two by three, all black\n"  # what a student reads


def mounted_on_canvas(width: int, height: int) -> str:
    """JavaScript mounting picture.js on the harness's ``image`` and canvas ``context`` stubs,
    ``width`` x ``height``: the drawing harnesses' common start (``handlers`` receive messages)."""
    return f"""
const made = [];  // the canvases picture.js makes
globalThis.document = {{
  createElement: (tag) =>
    tag === "img" ? image : made[made.push({{ getContext: () => context, style: {{}} }}) - 1],
}};
const handlers = {{}};
const state = {{
  value: new Uint8Array(), format: "png", width: {width}, height: {height}, handles: [],
}};
const model = {{
  get: (key) => state[key],
  on: (event, handler) => {{ handlers[event] = handler; }},
}};
const {{ default: widget }} = await import(process.argv[2]);
widget.render({{ model, el: {{ appendChild() {{}}, style: {{}} }} }});
"""


# picture.js mounted on a context that records every call and setting as text.
RECORDING_CONTEXT = r"""
const calls = [];
const text = (part) =>
  new TextDecoder().decode(part instanceof DataView ? part : new Uint8Array(part));
globalThis.Blob = class {
  constructor(parts, options) {
    this.text = parts.map(text).join("");
  }
};
globalThis.URL = { createObjectURL: (blob) => blob.text, revokeObjectURL: () => {} };
const turns = async (count) => {
  for (let turn = 0; turn < count; turn++) await new Promise((resolve) => setImmediate(resolve));
};
globalThis.createImageBitmap = (blob) =>
  turns(3).then(() => ({ width: 5, height: 4, text: blob.text }));
const warnings = [];
console.warn = (...parts) => warnings.push(parts.join(" "));
const image = { addEventListener() {}, style: {}, dataset: {}, decode: async () => {} };
const pixelsOf = (width, height) => new Uint8ClampedArray(4 * width * height);
const context = new Proxy(
  {},
  {
    get(target, name) {
      if (name === "canvas") return { width: 5, height: 4 };
      if (name === "createImageData")
        return (width, height) => ({ width, height, data: pixelsOf(width, height) });
      if (name === "putImageData")
        return ({ width, height, data }, x, y) =>
          calls.push(`putImageData(${width}x${height}:${data},${x},${y})`);
      return (...args) => calls.push(`${name}(${args.map((a) => (a.text ?? a)).join(",")})`);
    },
    set(target, name, value) {
      calls.push(`${name}=${Array.isArray(value) ? `[${value}]` : value}`);
      return true;
    },
  },
);
""" + mounted_on_canvas(5, 4)

DRAWING_HARNESS = (
    RECORDING_CONTEXT
    + r"""
// A DataView that starts at an odd byte, as a buffer cut from a message may.
const view = (typed) => {
  const bytes = new Uint8Array(typed.buffer);
  const padded = new Uint8Array(bytes.length + 1);
  padded.set(bytes, 1);
  return new DataView(padded.buffer, 1, bytes.length);
};
const vertices = view(new Float32Array([1, 2, 3, 4, 0, -1, 1, 1, -1, 1, 2.5, 3.5]));
const codes = view(new Uint8Array([1, 2, 1, 2, 79, 1]));
const commands = [
  { pixels: [3, 2, 1], at: [1, 2], zoom: 2 },
  { path: [0, 2], stroke: [1, 0, 0, 0.5], fill: null, width: 2, dash: [1, [3, 2]],
    cap: "butt", join: "round", clip: [0, 0, 5, 4] },
  { marker: [2, 3], at: [5, 1], stroke: null, fill: [0, 0, 1, 1], width: 0, dash: null,
    cap: "butt", join: "miter", clip: null },
  { text: "B(t)", x: 1, y: 3, angle: 90, font: [12.5, 700, "italic", ["DejaVu Sans", "sans-serif"]],
    color: [0, 0, 0, 1], clip: null },
];
const backdrop = new DataView(new TextEncoder().encode("BACK").buffer);
const listed = view(new TextEncoder().encode(JSON.stringify(commands)));
// Two RGB pixels from byte 3 (the buffer's first three bytes belong to another panel).
const pixels = view(new Uint8Array([9, 9, 9, 10, 20, 30, 40, 50, 60]));
const empty = new DataView(new ArrayBuffer(0));
const first_message = [backdrop, pixels, listed, vertices, codes];
handlers["msg:custom"]({ kind: "drawing", backdrop: true }, first_message);
await turns(50);
const first = calls.splice(0);
// A drawing sent before a whole picture came back is dropped, and so are the next ones
// until a drawing brings the new picture's background.
handlers["msg:custom"]({ kind: "drawing" }, [pixels, listed, vertices, codes]);
state.value = new TextEncoder().encode("V1");
handlers["change:value"]();
const none = view(new TextEncoder().encode("[]"));
handlers["msg:custom"]({ kind: "drawing" }, [empty, none, vertices, codes]);
await turns(50);
console.log(JSON.stringify({ first, after: calls, shown: image.src, warnings }));
"""
)


@pytest.mark.skipif(NODE is None, reason="Node.js runs picture.js outside a browser")
def test_picture_js_draws_a_drawing_s_commands_over_its_backdrop(tmp_path):
    printed = picture_js_in_node(tmp_path, DRAWING_HARNESS)
    assert printed["warnings"] == [] and printed["after"] == []
    assert printed["shown"] == "V1"
    assert printed["first"] == [
        "drawImage(BACK,0,0)",
        # The pixels as they are, on a canvas of their own size, then drawn each
        # 2 x 2 from (1, 2), unsmoothed and unclipped.
        "putImageData(2x1:10,20,30,255,40,50,60,255,0,0)",
        "save()",
        "imageSmoothingEnabled=false",
        "drawImage([object Object],1,2,4,2)",
        "restore()",
        # The path: clipped, traced, stroked half-transparent with its dashes.
        "save()",
        "beginPath()",
        "rect(0,0,5,4)",
        "clip()",
        "beginPath()",
        "moveTo(1,2)",
        "lineTo(3,4)",
        "strokeStyle=rgba(255, 0, 0, 0.5)",
        "lineWidth=2",
        "lineCap=butt",
        "lineJoin=round",
        "setLineDash(3,2)",
        "lineDashOffset=1",
        "stroke()",
        # The marker, unclipped: the path's clip goes. A closed triangle at
        # (2.5, 3.5), filled, not stroked.
        "restore()",
        "beginPath()",
        "moveTo(2.5,2.5)",
        "lineTo(3.5,4.5)",
        "closePath()",
        "fillStyle=rgba(0, 0, 255, 1)",
        "fill()",
        # The text at its baseline's start, turned as matplotlib turns it, then turned back.
        'font=italic 700 12.5px "DejaVu Sans", sans-serif',
        "fillStyle=rgba(0, 0, 0, 1)",
        "textAlign=left",
        "textBaseline=alphabetic",
        "translate(1,3)",
        f"rotate({-math.pi / 2})",
        "fillText(B(t),0,0)",
        "resetTransform()",
    ]


def line_run_harness(commands: str) -> str:
    """A drawing of ``commands`` (JavaScript), of a 1-pixel picture and one ``line``."""
    return (
        RECORDING_CONTEXT
        + r"""
const vertices = new Float32Array([0, 0, 1, 1]);
const codes = new Uint8Array([1, 2]);
const line = { path: [0, 2], stroke: [0, 0, 0, 1], fill: null, width: 1, dash: null,
  cap: "butt", join: "round", clip: [0, 0, 5, 4] };
const pixels = { pixels: [0, 1, 1], at: [0, 0], zoom: 1 };
const listed = new TextEncoder().encode(JSON.stringify("""
        + commands
        + r"""));
handlers["msg:custom"]({ kind: "drawing", backdrop: true }, [
  new TextEncoder().encode("BACK"), new Uint8Array([1, 2, 3]), listed, vertices.buffer,
  codes.buffer,
]);
await turns(50);
console.log(JSON.stringify({ calls }));
"""
    )


@pytest.mark.skipif(NODE is None, reason="Node.js runs picture.js outside a browser")
def test_picture_js_sets_a_run_s_clip_once_and_writes_pixels_whatever_the_clip(tmp_path):
    calls = picture_js_in_node(
        tmp_path, line_run_harness("[line, line, pixels, line, { ...line, clip: [1, 1, 2, 2] }]")
    )["calls"]
    shown = [call for call in calls if call in ("save()", "restore()", "clip()", "stroke()")]
    shown += [call for call in calls if call.startswith(("putImageData", "rect"))]
    assert shown == [
        *("save()", "clip()", "stroke()", "stroke()", "restore()"),  # two lines, one clip
        *("save()", "clip()", "stroke()", "restore()"),  # after the pixels, clipped anew
        *("save()", "clip()", "stroke()", "restore()"),  # another clip
        *("rect(0,0,5,4)", "putImageData(1x1:1,2,3,255,0,0)", "rect(0,0,5,4)", "rect(1,1,2,2)"),
    ]
    # The pixels come between the first clip's restore and the second's save.
    first_restore = calls.index("restore()")
    assert calls.index("putImageData(1x1:1,2,3,255,0,0)") == first_restore + 1


@pytest.mark.skipif(NODE is None, reason="Node.js runs picture.js outside a browser")
def test_picture_js_sets_a_run_s_stroke_once_and_again_after_a_restore(tmp_path):
    calls = picture_js_in_node(
        tmp_path,
        line_run_harness(
            """[line, line, { ...line, stroke: [1, 0, 0, 1] }, line,
                { ...line, dash: [0, [2, 1]] }, { ...line, dash: [0, [2, 1]] }, pixels, line]"""
        ),
    )["calls"]
    styles = [call for call in calls if call.startswith(("strokeStyle", "setLineDash"))]
    assert calls.count("stroke()") == 7
    assert styles == [
        *("strokeStyle=rgba(0, 0, 0, 1)", "setLineDash()"),  # two lines, one setting
        *("strokeStyle=rgba(255, 0, 0, 1)", "setLineDash()"),  # another colour
        *("strokeStyle=rgba(0, 0, 0, 1)", "setLineDash()"),  # the first again
        *("strokeStyle=rgba(0, 0, 0, 1)", "setLineDash(2,1)"),  # dashed, twice
        *("strokeStyle=rgba(0, 0, 0, 1)", "setLineDash()"),  # the pixels restored the context
    ]


STAMP_HARNESS = (
    RECORDING_CONTEXT
    + r"""
// Eight squares, 1 px wide, filled, at whole pixels from (10, 20): stamped.
const square = [-1, -1, 1, -1, 1, 1, -1, 1, 0, 0];
const places = Array.from({ length: 16 }, (_, i) => (i % 2 ? 20 : 10 + 3 * (i >> 1)));
const vertices = new Float32Array([...square, ...places]);
const codes = new Uint8Array([1, 2, 2, 2, 79, ...Array(8).fill(1)]);
const commands = [
  { marker: [0, 5], at: [5, 8], stroke: [0, 0, 0, 1], fill: [1, 0, 0, 1], width: 1, dash: null,
    cap: "butt", join: "miter", clip: null },
];
const listed = new TextEncoder().encode(JSON.stringify(commands));
const empty = new DataView(new ArrayBuffer(0));
handlers["msg:custom"]({ kind: "drawing", backdrop: true }, [
  new TextEncoder().encode("BACK"), empty, listed, vertices.buffer, codes.buffer,
]);
await turns(50);
console.log(JSON.stringify({ calls, made: made.map((canvas) => [canvas.width, canvas.height]) }));
"""
)


@pytest.mark.skipif(NODE is None, reason="Node.js runs picture.js outside a browser")
def test_picture_js_draws_many_markers_once_and_copies_them_to_their_whole_pixels(tmp_path):
    printed = picture_js_in_node(tmp_path, STAMP_HARNESS)
    calls = printed["calls"]
    # The square reaches 1 px and its stroke 5 widths more (a miter), 2 more for
    # antialiasing: its canvas is 16 x 16 from (-8, -8), the square traced in it once.
    assert printed["made"][-1] == [16, 16]
    assert calls.count("moveTo(7,7)") == 1 and calls.count("fill()") == 1
    copies = [call for call in calls if call.startswith("drawImage([object Object]")]
    assert copies == [f"drawImage([object Object],{10 + 3 * i - 8},12)" for i in range(8)]


OVERLAY_HARNESS = (
    r"""
// A drawing is shown on the canvas laid over the image, where the image is; a new whole
// picture hides it once the image shows that picture, not before.
globalThis.Blob = class {};
globalThis.URL = { createObjectURL: () => "url", revokeObjectURL: () => {} };
globalThis.createImageBitmap = async () => ({ width: 3, height: 2 });
const context = { canvas: { width: 3, height: 2 }, drawImage() {} };
let decoded = () => {};  // resolves the image's newest decode
const image = {
  addEventListener() {},
  style: {},
  dataset: {},
  offsetLeft: 7,
  offsetTop: 9,
  offsetWidth: 30,
  offsetHeight: 20,
  decode: () => new Promise((resolve) => { decoded = resolve; }),
};
"""
    + mounted_on_canvas(3, 2)
    + r"""
const [overlay] = made;
const before = overlay.style.display;
const empty = new DataView(new TextEncoder().encode("[]").buffer);
const none = new DataView(new ArrayBuffer(0));
handlers["msg:custom"]({ kind: "drawing", backdrop: true }, [none, none, empty, none, none]);
await new Promise((resolve) => setTimeout(resolve, 50));
const during = {
  ...overlay.style, size: [overlay.width, overlay.height], drawn: image.dataset.drawn,
};
state.value = new TextEncoder().encode("V1");
handlers["change:value"]();
await new Promise((resolve) => setTimeout(resolve, 20));
const decoding = overlay.style.display;
decoded();
await new Promise((resolve) => setTimeout(resolve, 20));
console.log(JSON.stringify({ before, during, decoding, after: overlay.style.display }));
"""
)


@pytest.mark.skipif(NODE is None, reason="Node.js runs picture.js outside a browser")
def test_picture_js_shows_a_drawing_on_a_canvas_over_the_image_until_a_new_picture_shows(
    tmp_path,
):
    printed = picture_js_in_node(tmp_path, OVERLAY_HARNESS)
    assert printed["before"] == "none"
    assert printed["during"] == {
        "position": "absolute",
        "pointerEvents": "none",
        "display": "block",
        "left": "7px",
        "top": "9px",
        "width": "30px",
        "height": "20px",
        "size": [3, 2],
        "drawn": "1",
    }
    assert printed["decoding"] == "block" and printed["after"] == "none"
