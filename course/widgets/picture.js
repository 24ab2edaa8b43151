// The picture of a course app: a PNG drawn by the kernel, and the pointer on it.
//
// The kernel (course.widgets.base) draws every picture; this file only shows
// it and reports where the student presses, drags and releases, in picture
// pixels (the PNG's own pixels, whatever the zoom of the page). A drag never
// queues more than one redraw: while the kernel draws, only the latest
// position is kept, and it is sent when the kernel says the picture is done.
// The cursor shows what a press would do, from the grabbable places the
// kernel lists in `handles`. During a drag the kernel sends what moves as drawing
// commands ("drawing" messages: pixel panels, paths, markers and texts in picture
// pixels, as matplotlib would draw them, see course/widgets/browser_drawing.py), drawn here
// over the still background it sends with the first of them; or, where the
// browser cannot draw what moves, only the rectangles that changed ("patch"
// messages, one PNG buffer each), painted in order over the picture. Either
// way a canvas laid over the image is drawn on, and shows until the image
// shows a newer whole picture; a message that answers a move says so
// ("drawn": true), as a lone "drawn" does otherwise. The release brings the
// whole picture back as `value`, and a new `value` drops any drawing or patch
// still on its way.

function pictureUrl(value, format) {
  const bytes = value instanceof DataView ? value : new Uint8Array(value ?? []);
  return URL.createObjectURL(new Blob([bytes], { type: `image/${format}` }));
}

// A buffer of the kernel's as a typed array of its own (a DataView may start at
// any byte, where a Float32Array must start at a multiple of four).
function floats(buffer) {
  const bytes = buffer instanceof DataView ? buffer : new Uint8Array(buffer ?? []);
  return new Float32Array(new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength).slice().buffer);
}

function octets(buffer) {
  const bytes = buffer instanceof DataView ? buffer : new Uint8Array(buffer ?? []);
  return new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
}

const rgba = ([r, g, b, a]) =>
  `rgba(${Math.round(255 * r)}, ${Math.round(255 * g)}, ${Math.round(255 * b)}, ${a})`;
const GENERIC = new Set(["serif", "sans-serif", "cursive", "fantasy", "monospace"]);
const family = (name) => (GENERIC.has(name) ? name : `"${name.replace(/"/g, "")}"`);

// matplotlib's path codes: 1 move, 2 line, 3 and 4 the control points of a
// quadratic and a cubic Bezier (the last one is where it ends), 79 close.
function trace(context, vertices, codes, [start, count], dx = 0, dy = 0) {
  const x = (i) => vertices[2 * i] + dx;
  const y = (i) => vertices[2 * i + 1] + dy;
  for (let i = start; i < start + count; i++) {
    const code = codes[i];
    if (code === 1) context.moveTo(x(i), y(i));
    else if (code === 2) context.lineTo(x(i), y(i));
    else if (code === 3) {
      context.quadraticCurveTo(x(i), y(i), x(i + 1), y(i + 1));
      i += 1;
    } else if (code === 4) {
      context.bezierCurveTo(x(i), y(i), x(i + 1), y(i + 1), x(i + 2), y(i + 2));
      i += 2;
    } else if (code === 79) context.closePath();
  }
}

function clipTo(context, clip) {
  if (!clip) return;
  context.beginPath();
  context.rect(...clip);
  context.clip();
}

// Fills and strokes the path traced, with `style`'s paint; `set` is the stroke's
// style the context holds already (or null), whose settings are not made again (a
// pixel grid's dozens of lines share one). Returns the stroke's style it holds then.
function fillAndStroke(context, style, set = null) {
  if (style.fill) {
    context.fillStyle = rgba(style.fill);
    context.fill();
  }
  if (!style.stroke) return set;
  if (!sameStroke(style, set)) {
    context.strokeStyle = rgba(style.stroke);
    context.lineWidth = style.width;
    context.lineCap = style.cap;
    context.lineJoin = style.join;
    context.setLineDash(style.dash ? style.dash[1] : []);
    context.lineDashOffset = style.dash ? style.dash[0] : 0;
  }
  context.stroke();
  return style;
}

const sameNumbers = (a, b) => a === b || (!!a && !!b && a.length === b.length && a.every((v, i) => v === b[i]));

function sameStroke(style, set) {
  if (set === null) return false;
  const dash = style.dash, other = set.dash;
  return (
    style.width === set.width && style.cap === set.cap && style.join === set.join &&
    sameNumbers(style.stroke, set.stroke) &&
    (dash === other || (!!dash && !!other && dash[0] === other[0] && sameNumbers(dash[1], other[1])))
  );
}

// A pixel panel's pixels (RGB, row by row, from byte `start`), each `zoom` x `zoom`
// picture pixels from (left, top), written over whatever is there whatever the clip,
// as FigureView.paste writes them into Agg's canvas. Zoomed, they go through a canvas
// of their own size, scaled by whole pixels without smoothing: each pixel's square
// (writing every picture pixel of four 192 x 192 panels in script cost more).
function putPixels(context, pixels, [start, width, height], [left, top], zoom) {
  const image = context.createImageData(width, height);
  // A pixel as one 32-bit word, its bytes R, G, B, A in memory (every browser's
  // platform is little-endian).
  const words = new Uint32Array(image.data.buffer);
  for (let i = 0, from = start; i < words.length; i++, from += 3) {
    words[i] = (0xff000000 | (pixels[from + 2] << 16) | (pixels[from + 1] << 8) | pixels[from]) >>> 0;
  }
  if (zoom === 1) {
    context.putImageData(image, left, top);
    return;
  }
  const small = document.createElement("canvas");
  small.width = width;
  small.height = height;
  small.getContext("2d").putImageData(image, 0, 0);
  context.save(); // the pixels are opaque: drawn over, they replace what was there
  context.imageSmoothingEnabled = false;
  context.drawImage(small, left, top, width * zoom, height * zoom);
  context.restore();
}

// Markers stand at whole pixels (as Agg places them), so from this many on one is
// drawn once, on a canvas of its own, and copied to each place: the same pixels
// (the canvas draws a path moved by whole pixels alike), a tenth of the time.
const STAMPED = 8;

// A marker drawn on a canvas of its own, and where that canvas's corner goes
// from a marker's place: [canvas, left, top], whole pixels.
function markerStamp(command, vertices, codes) {
  const [start, count] = command.marker;
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let i = start; i < start + count; i++) {
    [x0, x1] = [Math.min(x0, vertices[2 * i]), Math.max(x1, vertices[2 * i])];
    [y0, y1] = [Math.min(y0, vertices[2 * i + 1]), Math.max(y1, vertices[2 * i + 1])];
  }
  // A mitred corner reaches at most the miter limit (10) times half the width.
  const reach = (command.stroke ? 5 * command.width : 0) + 2;
  const [left, top] = [Math.floor(x0 - reach), Math.floor(y0 - reach)];
  const canvas = document.createElement("canvas");
  canvas.width = Math.ceil(x1 + reach) - left;
  canvas.height = Math.ceil(y1 + reach) - top;
  const stamp = canvas.getContext("2d");
  stamp.beginPath();
  trace(stamp, vertices, codes, command.marker, -left, -top);
  fillAndStroke(stamp, command);
  return [canvas, left, top];
}

// The commands of course/widgets/browser_drawing.py, in their order. A run of commands
// with the same clip (a pixel grid's dozens of lines) sets it once: every command sets
// the styles it draws with, and a text undoes its own transform.
// (Saving and restoring the context around each of them cost more than drawing them.)
function drawCommands(context, commands, pixels, vertices, codes) {
  let clipped = null; // the clip in force: none at first
  let stroked = null; // the stroke's style the context holds, since the last restore
  for (const command of commands) {
    if (command.pixels) {
      if (clipped !== null) context.restore(); // written whatever the clip
      clipped = stroked = null;
      putPixels(context, pixels, command.pixels, command.at, command.zoom);
      continue;
    }
    const clip = command.clip ?? null;
    if (!sameNumbers(clip, clipped)) {
      if (clipped !== null) {
        context.restore(); // back to the settings before the clip
        stroked = null;
      }
      if (clip !== null) {
        context.save();
        clipTo(context, clip);
      }
      clipped = clip;
    }
    if (command.path) {
      context.beginPath();
      trace(context, vertices, codes, command.path);
      stroked = fillAndStroke(context, command, stroked);
    } else if (command.marker) {
      const [start, count] = command.at;
      if (count >= STAMPED) {
        const [stamp, left, top] = markerStamp(command, vertices, codes);
        for (let i = start; i < start + count; i++) {
          context.drawImage(stamp, vertices[2 * i] + left, vertices[2 * i + 1] + top);
        }
      } else {
        for (let i = start; i < start + count; i++) {
          context.beginPath();
          trace(context, vertices, codes, command.marker, vertices[2 * i], vertices[2 * i + 1]);
          stroked = fillAndStroke(context, command, stroked);
        }
      }
    } else if (command.text !== undefined) {
      const [size, weight, style, families] = command.font;
      context.font = `${style} ${weight} ${size}px ${families.map(family).join(", ")}`;
      context.fillStyle = rgba(command.color);
      context.textAlign = "left";
      context.textBaseline = "alphabetic";
      context.translate(command.x, command.y);
      context.rotate((-command.angle * Math.PI) / 180);
      context.fillText(command.text, 0, 0);
      context.resetTransform(); // no other command sets one
    }
  }
  if (clipped !== null) context.restore();
}

function render({ model, el }) {
  const image = document.createElement("img");
  image.className = "widget-image course-picture";
  image.draggable = false;
  el.appendChild(image);
  // A drag's steps are drawn on this canvas, laid over the image where it is: shown
  // as drawn, where a picture file made of each step (a BMP) cost the browser more
  // than the kernel's step. Pointer events go through it to the image.
  const drawn = document.createElement("canvas");
  drawn.className = "course-picture-drawn";
  Object.assign(drawn.style, {
    position: "absolute",
    pointerEvents: "none",
    display: "none",
  });
  el.style.position = "relative";
  el.appendChild(drawn);

  let url = null;
  function display(next) {
    image.src = next;
    if (url) URL.revokeObjectURL(url);
    url = next;
  }

  let generation = 0; // counts whole pictures: a patch for an older one is dropped
  let composed = null; // the 2D context of the canvas, holding the picture as drawn
  let backdrop = null; // the still background a drag's drawings are drawn over
  let painting = Promise.resolve(); // patches are painted one after another
  let drawings = 0; // the drawings shown on the canvas, also the image's data-drawn

  function show() {
    generation += 1;
    composed = null;
    backdrop = null;
    display(pictureUrl(model.get("value"), model.get("format")));
    image.width = model.get("width");
    image.height = model.get("height");
    // The canvas stays until the image shows the new picture, unless a drawing
    // came since (the next drag's).
    const since = drawings;
    const hide = () => {
      if (drawings === since) drawn.style.display = "none";
    };
    image.decode().then(hide, hide);
  }
  show();
  model.on("change:value", show);

  function decode(bytes, format) {
    const data = bytes instanceof DataView ? bytes : new Uint8Array(bytes ?? []);
    return createImageBitmap(new Blob([data], { type: `image/${format}` }));
  }

  function canvasFor(bitmap) {
    drawn.width = bitmap.width;
    drawn.height = bitmap.height;
    return drawn.getContext("2d");
  }

  function showComposed(mine) {
    if (mine !== generation) return;
    Object.assign(drawn.style, {
      left: `${image.offsetLeft}px`,
      top: `${image.offsetTop}px`,
      width: `${image.offsetWidth}px`,
      height: `${image.offsetHeight}px`,
      display: "block",
    });
    drawings += 1;
    image.dataset.drawn = String(drawings);
  }

  async function paint(rectangles, buffers, mine) {
    if (!composed) {
      const whole = await decode(model.get("value"), model.get("format"));
      if (mine !== generation) return;
      composed = canvasFor(whole);
      composed.drawImage(whole, 0, 0);
    }
    const pieces = await Promise.all(buffers.map((buffer) => decode(buffer, "png")));
    if (mine !== generation) return;
    rectangles.forEach(([left, top, width, height], index) => {
      composed.clearRect(left, top, width, height);
      composed.drawImage(pieces[index], left, top);
    });
    showComposed(mine);
  }

  async function draw(message, buffers, mine) {
    let parts = buffers;
    if (message.backdrop) {
      const bitmap = await decode(parts[0], model.get("format"));
      if (mine !== generation) return;
      backdrop = bitmap;
      parts = parts.slice(1);
    }
    if (!backdrop) return; // its background belonged to an older picture
    if (!composed) composed = canvasFor(backdrop);
    composed.drawImage(backdrop, 0, 0);
    const commands = JSON.parse(new TextDecoder().decode(octets(parts[1])));
    drawCommands(composed, commands, octets(parts[0]), floats(parts[2]), octets(parts[3]));
    showComposed(mine);
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
    if (message.kind === "drawing") {
      const mine = generation;
      painting = painting
        .then(() => draw(message, buffers ?? [], mine))
        .catch((error) => console.warn("course picture: a drawing was not drawn", error));
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
