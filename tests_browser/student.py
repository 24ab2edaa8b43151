"""What a student does in the browser, as Playwright steps, and what the test then reads.

Shared by the JupyterLab and the Voila tests: reading an app's picture out
of the page, moving a slider with the keyboard, and comparing the picture
with the one the library renders in this process for the same value.
"""

from __future__ import annotations

import base64
import io
import itertools
import json
import re
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image
from playwright.sync_api import Locator, Page

from course.classroom.pictures import DIFFERING_SHARE, differing_share
from course.classroom.registry import DragMove, Landmark, SliderMove
from course.classroom.sliders import (
    nearest_stop,
    neighbour_value,
    readout_shows,
    value_after_keys,
)

SLIDER_APP_MIME = "application/vnd.jupyter.widget-view+json"

# A drag's steps are drawn on a canvas laid over the image (picture.js), shown until the
# image shows a newer whole picture: the page shows that canvas while it is displayed.
_READ_IMAGE = """async image => {
    const drawn = image.parentElement.querySelector("canvas.course-picture-drawn");
    const blob = drawn && drawn.style.display === "block"
        ? await new Promise(resolve => drawn.toBlob(resolve, "image/png"))
        : await (await fetch(image.src)).blob();
    const bytes = new Uint8Array(await blob.arrayBuffer());
    let text = "";
    for (let i = 0; i < bytes.length; i += 0x8000) {
        text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
    }
    return btoa(text);
}"""

_ERROR_TEXT = re.compile(
    r"Traceback \(most recent call last\)|^\w*(Error|Exception)\b|Error displaying widget",
    re.MULTILINE,
)


def slider_apps_in(path: Path) -> int:
    """How many apps the committed notebook shows (widget view plus a still picture)."""
    notebook = json.loads(path.read_text(encoding="utf-8"))
    return sum(
        1
        for cell in notebook["cells"]
        for output in cell.get("outputs", [])
        if SLIDER_APP_MIME in output.get("data", {})
        and ({"image/png", "image/jpeg"} & set(output.get("data", {})))
    )


def rgb(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


#: What an image widget shows, as a string that changes when it does: its picture's URL
#: and the count of drag steps drawn over it.
PICTURE_STATE = "image => `${image.src}#${image.dataset.drawn ?? 0}`"


def read_picture(image: Locator) -> np.ndarray:
    """The picture an image widget shows (its own, or the drag's canvas over it), as RGB."""
    return rgb(base64.b64decode(image.evaluate(_READ_IMAGE)))


def picture_state(image: Locator) -> str:
    """A string that changes when what ``image`` shows changes (:data:`PICTURE_STATE`)."""
    return image.evaluate(PICTURE_STATE)


def error_outputs(page: Page) -> list[str]:
    """Texts of outputs that show an error: tracebacks and widgets that failed to display."""
    texts = page.locator(
        ".jp-OutputArea-output[data-mime-type='application/vnd.jupyter.stderr'],"
        " .jp-OutputArea-output[data-mime-type='application/vnd.jupyter.error'],"
        " .jupyter-widgets .jp-RenderedText"
    ).evaluate_all("outputs => outputs.map(output => output.textContent)")
    texts += page.get_by_text("Error displaying widget").all_text_contents()
    return [text[:2000] for text in texts if _ERROR_TEXT.search(text)]


def unrendered_apps(page: Page) -> list[str]:
    """Widget images that have no picture: empty src, not loaded, or zero size."""
    return page.locator("img.widget-image").evaluate_all(
        """images => images
            .filter(image => !image.src || !image.complete || image.naturalWidth === 0)
            .map(image => image.outerHTML.slice(0, 200))"""
    )


def wait_for_pictures(page: Page, count: int, timeout: float = 60) -> None:
    """Until ``count`` widget images have loaded a picture."""
    page.wait_for_function(
        """count => [...document.querySelectorAll('img.widget-image')]
            .filter(image => image.src && image.complete && image.naturalWidth > 0)
            .length >= count""",
        arg=count,
        timeout=timeout * 1000,
    )


def wait_for_new_picture(image: Locator, old_state: str, settle: float = 0.8) -> None:
    """Until what the image shows changed from ``old_state`` and then stayed for ``settle`` s.

    Every key press sends a value; the kernel answers each with a picture, so
    the last picture is the one that stops changing.
    """
    image.page.wait_for_function(
        f"([image, old]) => ({PICTURE_STATE})(image) !== old"
        " && image.complete && image.naturalWidth > 0",
        arg=[image.element_handle(), old_state],
    )
    src, since = picture_state(image), time.monotonic()
    deadline = since + 60
    while time.monotonic() < deadline:
        time.sleep(0.1)
        now = picture_state(image)
        if now != src:
            src, since = now, time.monotonic()
        elif time.monotonic() - since >= settle:
            return
    raise AssertionError("the picture kept changing for 60 s after the key presses")


def wait_for_picture_like(image: Locator, expected: np.ndarray, patience: float = 30) -> np.ndarray:
    """The picture once it is ``expected``'s, or once it stayed the same for ``patience`` s."""
    shown, src = read_picture(image), picture_state(image)
    since = time.monotonic()
    while differing_share(shown, expected) > DIFFERING_SHARE:
        if time.monotonic() - since > patience:
            break
        time.sleep(0.2)
        now = picture_state(image)
        if now != src:
            image.page.wait_for_function(
                "image => image.complete && image.naturalWidth > 0", arg=image.element_handle()
            )
            shown, src, since = read_picture(image), now, time.monotonic()
    return shown


_SCROLLER = """() => {
    // The element that scrolls the notebook: the tallest one that overflows and may scroll.
    let best = document.scrollingElement;
    for (const element of document.querySelectorAll('*')) {
        const style = getComputedStyle(element).overflowY;
        if ((style === 'auto' || style === 'scroll') && element.clientHeight > 0
                && element.scrollHeight > element.clientHeight
                && element.scrollHeight > best.scrollHeight) {
            best = element;
        }
    }
    window.__scroller = best;
    return [best.scrollHeight, best.clientHeight];
}"""


def tall_screenshot(
    page: Page, path: Path, viewport_width: int = 1280, limit: int = 8192
) -> list[Path]:
    """Screenshots of the whole notebook, from its top, even though it scrolls inside a panel.

    JupyterLab and Voila scroll the notebook inside an element, so a "full
    page" screenshot shows only the window. The window is made as tall as
    the notebook instead; Chromium captures at most 8192 px of height, so a
    longer notebook is taken in parts (``name.png``, ``name-part2.png``, ...),
    scrolling the panel between them. Returns the files written.
    """
    total, visible = page.evaluate(_SCROLLER)
    page.set_viewport_size(
        {"width": viewport_width, "height": min(total - visible + 900 + 50, limit)}
    )
    page.wait_for_timeout(300)
    total, visible = page.evaluate(_SCROLLER)
    paths, offset = [], 0
    while True:
        page.evaluate("offset => { window.__scroller.scrollTop = offset; }", offset)
        page.wait_for_timeout(500)  # cells scrolled into view render their content
        part = path if not paths else path.with_name(f"{path.stem}-part{len(paths) + 1}.png")
        page.screenshot(path=part)
        paths.append(part)
        if offset + visible >= total or visible <= 0:
            break
        offset = min(offset + visible, total - visible)
    page.set_viewport_size({"width": viewport_width, "height": 900})
    return paths


def nth_app(page: Page, index: int) -> Locator:
    """The page's app number ``index`` (from 0): the box around its picture and controls."""
    picture = page.locator("img.widget-image").nth(index)
    return picture.locator("xpath=ancestor::div[contains(@class, 'widget-hbox')][1]")


def slider(app: Locator, description: str) -> Locator:
    label = app.page.locator("label.widget-label").filter(
        has_text=re.compile(rf"^\s*{re.escape(description)}\s*$")
    )
    return app.locator(".widget-slider").filter(has=label).first


@dataclass
class Move:
    """One key sequence pressed on a slider, and what the browser then showed."""

    keys: tuple[str, ...]
    value: Any
    before: np.ndarray
    after: np.ndarray


def press_on_slider(app: Locator, control, keys: tuple[str, ...], start) -> Move:
    """Focus the slider's handle, press ``keys`` like a student, wait for the new picture.

    The value the slider then holds is predicted from the keys (readouts
    round: two decimals by default), and the readout must show it.
    """
    image = app.locator("img.widget-image").first
    element = slider(app, control.description)
    handle = element.locator(".noUi-handle").first
    handle.scroll_into_view_if_needed()
    before_src = picture_state(image)
    before = read_picture(image)
    handle.focus()
    for key in keys:
        handle.press(key)
    wait_for_new_picture(image, before_src)
    value = value_after_keys(control, start, keys)
    readout = element.locator(".widget-readout").text_content().strip()
    assert readout_shows(control, value, readout), (
        f"{keys} from {start}: expected the slider at {value}; its readout shows {readout}"
    )
    return Move(keys, value, before, read_picture(image))


def library_picture(spec: SliderMove, value, landmarks: bool = True):
    """The picture the library draws for the app with its control at ``value``, and landmarks."""
    app = spec.build()
    app.refresh()
    app.controls[spec.control].value = value
    picture = rgb(app.view.image.value)
    return (picture, spec.landmarks(app)) if landmarks else picture


def failing_landmarks(picture: np.ndarray, landmarks: list[Landmark]) -> list[str]:
    """What each landmark the picture does not show expected, and what is there instead."""
    return [
        f"{landmark.what}: expected colour {landmark.color} at row {landmark.row}, column "
        f"{landmark.column}; the picture shows {picture[landmark.row, landmark.column].tolist()}"
        for landmark in landmarks
        if np.abs(picture[landmark.row, landmark.column] - landmark.color).max()
        > landmark.tolerance
    ]


def assert_shows_what_the_library_computes(move: Move, spec: SliderMove, control) -> None:
    expected, landmarks = library_picture(spec, move.value)
    assert (move.after != move.before).any(), f"{move.keys}: the picture did not change"
    differing = differing_share(move.after, expected)
    assert differing <= DIFFERING_SHARE, (
        f"{move.keys} -> {spec.control} = {move.value}: {differing:.2%} of the pixels differ "
        f"from the library's picture (tolerance {DIFFERING_SHARE:.2%})"
    )
    wrong = failing_landmarks(move.after, landmarks)
    assert not wrong, f"{len(wrong)} of {len(landmarks)} landmarks fail: {wrong[:5]}"
    # The two checks must be able to fail: the library's picture one stop off
    # (what a lagging or misplaced update would show) fails at least one.
    other = neighbour_value(control, move.value)
    off = library_picture(spec, other, landmarks=False)
    assert differing_share(off, expected) > DIFFERING_SHARE or failing_landmarks(off, landmarks), (
        f"the picture for {spec.control} = {other} would pass as {move.value}: move elsewhere"
    )


def key_names(keys: tuple[str, ...]) -> str:
    """Keys for a file name, repeats counted: ``('ArrowRight',) * 3`` is ``3xArrowRight``."""
    groups = [(key, len(list(run))) for key, run in itertools.groupby(keys)]
    return "-".join(key if count == 1 else f"{count}x{key}" for key, count in groups)


def move_sliders_like_a_student(page: Page, spec: SliderMove, folder: Path, stem: str) -> Any:
    """Every registered move on the app's slider, each checked and screenshotted.

    Returns the value the slider is left at.
    """
    control = spec.build().controls[spec.control]
    app = nth_app(page, spec.app)
    # Before any move, the page must show what spec.build() draws: the registry
    # entry builds the same app as the notebook's app cell. (The browser puts
    # a value off the slider's grid on its nearest stop as it shows the slider.)
    value = nearest_stop(control, control.value)
    shown = read_picture(app.locator("img.widget-image").first)
    expected, _ = library_picture(spec, value)
    differing = differing_share(shown, expected)
    assert differing <= DIFFERING_SHARE, (
        f"before any move, {differing:.2%} of the pixels differ from what the registry's "
        "build() draws: does it build the app as the notebook's app cell does?"
    )
    for step, keys in enumerate(spec.moves, start=1):
        move = press_on_slider(app, control, keys, value)
        # A busy machine may draw the last key's picture after a pause longer than the
        # settling time: the picture the library draws, or, once it stops coming, the
        # last one (which the checks below then judge).
        expected = library_picture(spec, move.value, landmarks=False)
        move.after = wait_for_picture_like(app.locator("img.widget-image").first, expected)
        value = move.value
        which = f"-app{spec.app}" if spec.app else ""
        name = f"{stem}{which}-move{step}-{key_names(keys)}-{spec.control}={move.value:g}"
        app.screenshot(path=folder / f"{name}.png")
        assert_shows_what_the_library_computes(move, spec, control)
    assert not error_outputs(page), error_outputs(page)
    return value


#: While a point is held, the browser draws the moving lines, markers and texts itself
#: (course.widgets.browser_drawing): its antialiasing and its font are not Agg's, so
#: the edges of lines and the glyphs differ. A wrong place or colour moves whole artists.
DRAWN_BY_THE_BROWSER_SHARE = 0.03


def drag_like_a_student(
    page: Page, spec: DragMove, folder: Path, stem: str, settings: dict | None = None
) -> None:
    """Press the handle where the page draws it, move along the path, release; then check.

    ``settings`` are the control values the page's app holds already (the
    sliders moved before): the library's app takes them first. The page's
    picture after the drag must be what the library draws after the same
    drag in plain Python (``SliderApp.drag_along``), landmarks included; the
    picture before the drag must fail them.
    """
    app = nth_app(page, spec.app)
    image = app.locator("img.widget-image").first
    image.scroll_into_view_if_needed()
    built = spec.build()
    built.refresh()
    for name, value in (settings or {}).items():
        built.controls[name].value = value
    before = read_picture(image)
    differing = differing_share(before, rgb(bytes(built.view.image.value)))
    assert differing <= DIFFERING_SHARE, (
        f"before the drag, {differing:.2%} of the pixels differ from what the registry's "
        "build() draws: does it build the app as the notebook's cell does?"
    )
    start = built.press_point(spec.handle)
    box = image.bounding_box()
    scale = np.array(
        [box["width"] / built.view.image.width, box["height"] / built.view.image.height]
    )

    def on_page(point: np.ndarray) -> tuple[float, float]:
        x, y = np.array([box["x"], box["y"]]) + np.asarray(point) * scale
        return float(x), float(y)

    built.pointer("down", *start)
    before_src = picture_state(image)
    page.mouse.move(*on_page(start))
    page.mouse.down()
    for offset in spec.path:
        page.mouse.move(*on_page(start + np.asarray(offset)), steps=4)
    # Held still before the release: the page shows the last step as the browser drew
    # it from the kernel's drawing commands (or patched, for pixel panels).
    wait_for_new_picture(image, before_src)
    during, during_src = read_picture(image), picture_state(image)
    app.screenshot(path=folder / f"{stem}-dragging-{spec.handle}.png")
    page.mouse.up()
    wait_for_new_picture(image, during_src)
    after = read_picture(image)
    app.screenshot(path=folder / f"{stem}-drag-{spec.handle}.png")

    # Held at the last move, the library's app draws everything with Agg (patched steps).
    built.view.draw_in_browser = False
    for offset in spec.path:
        built.pointer("move", *(start + np.asarray(offset)))
    held = np.asarray(built.view.pixels())[..., :3]
    built.view.draw_in_browser = True
    built.pointer("up", *(start + np.asarray(spec.path[-1])))
    expected, landmarks = rgb(bytes(built.view.image.value)), spec.landmarks(built)
    # The browser's drawing is the library's picture but for its antialiasing and font.
    share = differing_share(during, held)
    assert share <= DRAWN_BY_THE_BROWSER_SHARE, (
        f"while dragging {spec.handle}, {share:.2%} of the pixels differ from the library's "
        f"picture (tolerance {DRAWN_BY_THE_BROWSER_SHARE:.0%} for the browser's drawing)"
    )
    differing = differing_share(after, expected)
    assert differing <= DIFFERING_SHARE, (
        f"after dragging {spec.handle} along {spec.path}, {differing:.2%} of the pixels differ "
        f"from the library's picture (tolerance {DIFFERING_SHARE:.2%})"
    )
    wrong = failing_landmarks(after, landmarks)
    assert not wrong, f"{len(wrong)} of {len(landmarks)} landmarks fail: {wrong[:5]}"
    # The two checks must be able to fail: the picture before the drag fails one.
    assert differing_share(before, expected) > DIFFERING_SHARE or failing_landmarks(
        before, landmarks
    ), "the picture before the drag would pass as the picture after it"
    assert not error_outputs(page), error_outputs(page)
