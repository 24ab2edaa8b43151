// The picture of a course app: a PNG drawn by the kernel, and the pointer on it.
//
// The kernel (course.widgets.base) draws every picture; this file only shows
// it and reports where the student presses, drags and releases, in picture
// pixels (the PNG's own pixels, whatever the zoom of the page). A drag never
// queues more than one redraw: while the kernel draws, only the latest
// position is kept, and it is sent when the kernel says the picture is done.
// The cursor shows what a press would do, from the grabbable places the
// kernel lists in `handles`. During a drag the kernel sends only the rectangles
// that changed ("patch" messages, one PNG buffer each): they are painted, in
// order, over a canvas holding the picture, which the image then shows; a patch
// that answers a move says so ("drawn": true), as a lone "drawn" does otherwise. The
// release brings the whole picture back as `value`, and a new `value` drops
// any patch still on its way.

function pictureUrl(value, format) {
  const bytes = value instanceof DataView ? value : new Uint8Array(value ?? []);
  return URL.createObjectURL(new Blob([bytes], { type: `image/${format}` }));
}

function render({ model, el }) {
  const image = document.createElement("img");
  image.className = "widget-image course-picture";
  image.draggable = false;
  el.appendChild(image);

  let url = null;
  function display(next) {
    image.src = next;
    if (url) URL.revokeObjectURL(url);
    url = next;
  }

  let generation = 0; // counts whole pictures: a patch for an older one is dropped
  let composed = null; // the 2D context of a canvas holding the picture as patched
  let painting = Promise.resolve(); // patches are painted one after another

  function show() {
    generation += 1;
    composed = null;
    display(pictureUrl(model.get("value"), model.get("format")));
    image.width = model.get("width");
    image.height = model.get("height");
  }
  show();
  model.on("change:value", show);

  function decode(bytes, format) {
    const data = bytes instanceof DataView ? bytes : new Uint8Array(bytes ?? []);
    return createImageBitmap(new Blob([data], { type: `image/${format}` }));
  }

  async function paint(rectangles, buffers, mine) {
    if (!composed) {
      const whole = await decode(model.get("value"), model.get("format"));
      if (mine !== generation) return;
      const canvas = document.createElement("canvas");
      canvas.width = whole.width;
      canvas.height = whole.height;
      composed = canvas.getContext("2d");
      composed.drawImage(whole, 0, 0);
    }
    const pieces = await Promise.all(buffers.map((buffer) => decode(buffer, "png")));
    if (mine !== generation) return;
    rectangles.forEach(([left, top, width, height], index) => {
      composed.clearRect(left, top, width, height);
      composed.drawImage(pieces[index], left, top);
    });
    const blob = await new Promise((resolve) => composed.canvas.toBlob(resolve, "image/png"));
    if (mine !== generation || !blob) return;
    display(URL.createObjectURL(blob));
  }

  // Where the pointer is, in the PNG's pixels (the page may scale the image).
  function position(event) {
    const box = image.getBoundingClientRect();
    const scaleX = (image.naturalWidth || box.width) / box.width;
    const scaleY = (image.naturalHeight || box.height) / box.height;
    return [(event.clientX - box.left) * scaleX, (event.clientY - box.top) * scaleY];
  }

  function over([x, y]) {
    for (const [hx, hy, radius, left, top, right, bottom] of model.get("handles")) {
      if (radius > 0 && Math.hypot(x - hx, y - hy) <= radius) return true;
      if (radius === 0 && x >= left && x <= right && y >= top && y <= bottom) return true;
    }
    return false;
  }

  let dragging = false;
  let waiting = false; // a move has been sent and its picture is not back yet
  let latest = null; // the newest position not yet sent

  function send(kind, [x, y]) {
    model.send({ kind, x, y });
  }

  function flush() {
    if (latest && !waiting) {
      waiting = true;
      send("move", latest);
      latest = null;
    }
  }

  model.on("msg:custom", (message, buffers) => {
    if (message.kind === "patch") {
      const mine = generation;
      painting = painting
        .then(() => paint(message.rectangles, buffers ?? [], mine))
        .catch((error) => console.warn("course picture: a patch was not painted", error));
    }
    // The kernel's answer to a move: alone, or with the step's patch.
    if (message.kind === "drawn" || message.drawn) {
      waiting = false;
      flush();
    }
  });

  image.addEventListener("pointerdown", (event) => {
    if (event.button !== 0) return;
    event.preventDefault();
    dragging = true;
    latest = null;
    waiting = true;
    image.setPointerCapture(event.pointerId);
    image.style.cursor = "grabbing";
    send("down", position(event));
  });

  image.addEventListener("pointermove", (event) => {
    const where = position(event);
    if (dragging) {
      latest = where;
      flush();
    } else {
      image.style.cursor = over(where) ? "grab" : model.get("clickable") ? "crosshair" : "default";
    }
  });

  function release(event) {
    if (!dragging) return;
    dragging = false;
    latest = null; // the release carries the final position, sent even while waiting
    waiting = true;
    image.style.cursor = over(position(event)) ? "grab" : "default";
    send("up", position(event));
  }
  image.addEventListener("pointerup", release);
  image.addEventListener("pointercancel", release);

  image.addEventListener("dblclick", (event) => {
    event.preventDefault();
    waiting = true;
    send("double", position(event));
  });

  return () => {
    if (url) URL.revokeObjectURL(url);
  };
}

export default { render };
