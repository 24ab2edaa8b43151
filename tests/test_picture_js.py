"""course/widgets/picture.js: patches painted in order over the picture, stale ones dropped.

Runs picture.js in Node with a stand-in page (an image, a canvas that records
what is painted, blobs and bitmaps that carry their bytes as text), since a
browser is too heavy for a unit test; ``tests_browser`` drives the real one.
"""

import json
import shutil
import subprocess

import pytest

from course.widgets.picture import Picture

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
// A patch takes a few milliseconds to decode, as in a browser; the whole picture less.
globalThis.createImageBitmap = (blob) => new Promise((resolve) =>
  setTimeout(
    () => resolve({ width: 5, height: 4, text: blob.text }),
    blob.text.startsWith("P") ? 5 : 0,
  ));
const warnings = [];
console.warn = (...parts) => warnings.push(parts.join(" "));
const image = { addEventListener() {}, style: {} };
globalThis.document = {
  createElement(tag) {
    if (tag === "img") return image;
    const canvas = {
      getContext: () => context,
      toBlob: (done) => setTimeout(() => done({ text: "canvas:" + painted.join(" ") }), 0),
    };
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
// Longer than every decode and encode above put together, however busy the machine.
const settle = () => new Promise((resolve) => setTimeout(resolve, 300));
const bytes = (s) => new DataView(new TextEncoder().encode(s).buffer);
const patch = (name, x, y) =>
  handlers["msg:custom"]({ kind: "patch", rectangles: [[x, y, 2, 1]] }, [bytes(name)]);
const { default: widget } = await import(process.argv[2]);
widget.render({ model, el: { appendChild() {} } });
const seen = [image.src];
patch("P1", 1, 1);
patch("P2", 3, 2);
await settle();
seen.push(image.src);
patch("P3", 0, 0);  // being decoded when the whole picture comes back: dropped
await new Promise((resolve) => setTimeout(resolve, 1));
state.value = new TextEncoder().encode("V1");
handlers["change:value"]();
seen.push(image.src);
await settle();
seen.push(image.src);
patch("P4", 2, 2);  // a patch for the new picture starts from it
await settle();
seen.push(image.src);
console.log(JSON.stringify({ seen, warnings }));
"""


@pytest.mark.skipif(NODE is None, reason="Node.js runs picture.js outside a browser")
def test_patches_paint_in_order_and_a_new_picture_drops_the_stale_ones(tmp_path):
    module = tmp_path / "picture.mjs"
    module.write_text(Picture._esm, encoding="utf-8")
    harness = tmp_path / "harness.mjs"
    harness.write_text(HARNESS, encoding="utf-8")
    done = subprocess.run(
        [NODE, str(harness), module.as_uri()], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["warnings"] == []
    assert json.loads(done.stdout)["seen"] == [
        "V0",
        "canvas:V0@0,0 P1@1,1 P2@3,2",
        "V1",
        "V1",
        "canvas:V0@0,0 P1@1,1 P2@3,2 V1@0,0 P4@2,2",
    ]
