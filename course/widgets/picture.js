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
// way a canvas is composed, which the image then shows; a message that
// answers a move says so ("drawn": true), as a lone "drawn" does otherwise.
// The release brings the whole picture back as `value`, and a new `value`
// drops any drawing or patch still on its way.

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

function fillAndStroke(context, style) {
  if (style.fill) {
    context.fillStyle = rgba(style.fill);
    context.fill();
  }
  if (style.stroke) {
    context.strokeStyle = rgba(style.stroke);
    context.lineWidth = style.width;
    context.lineCap = style.cap;
    context.lineJoin = style.join;
    context.setLineDash(style.dash ? style.dash[1] : []);
    context.lineDashOffset = style.dash ? style.dash[0] : 0;
    context.stroke();
  }
}

// A canvas's pixels as an uncompressed BMP file: the image shows each step of a drag,
// and encoding PNG (canvas.toBlob) took longer than the kernel's whole step. The
// header is a BITMAPV4HEADER (108 bytes): rows top-down (a negative height) and 32-bit
// pixels whose masks read the canvas's RGBA bytes as they are, so the pixels are the
// file's without a copy or a conversion.
function bitmapFile(context) {
  const { width, height } = context.canvas;
  const pixels = context.getImageData(0, 0, width, height).data;
  const headers = 14 + 108;
  const header = new DataView(new ArrayBuffer(headers));
  header.setUint16(0, 0x4d42, true); // "BM"
  header.setUint32(2, headers + pixels.length, true);
  header.setUint32(10, headers, true); // where the pixels start
  header.setUint32(14, 108, true);
  header.setInt32(18, width, true);
  header.setInt32(22, -height, true);
  header.setUint16(26, 1, true); // planes
  header.setUint16(28, 32, true); // bits per pixel
  header.setUint32(30, 3, true); // BI_BITFIELDS: the masks below
  header.setUint32(34, pixels.length, true);
  header.setUint32(54, 0x000000ff, true); // red: each pixel's first byte
  header.setUint32(58, 0x0000ff00, true); // green
  header.setUint32(62, 0x00ff0000, true); // blue
  header.setUint32(66, 0xff000000, true); // alpha
  header.setUint32(70, 0x73524742, true); // "sRGB": the canvas's colour space
  return new Blob([header, pixels], { type: "image/bmp" });
}

// A pixel panel's pixels (RGB, row by row, from byte `start`), each `zoom` x `zoom`
// picture pixels from (left, top), written over whatever is there whatever the clip,
// as FigureView.paste writes them into Agg's canvas.
function putPixels(context, pixels, [start, width, height], [left, top], zoom) {
  const zoomed = context.createImageData(width * zoom, height * zoom);
  // A pixel as one 32-bit word, its bytes R, G, B, A in memory (every browser's
  // platform is little-endian): a run of `zoom` of them is one fill.
  const words = new Uint32Array(zoomed.data.buffer);
  const rowWords = width * zoom;
  for (let y = 0; y < height; y++) {
    const row = y * zoom * rowWords;
    for (let x = 0; x < width; x++) {
      const from = start + 3 * (y * width + x);
      const [red, green, blue] = [pixels[from], pixels[from + 1], pixels[from + 2]];
      const word = (0xff000000 | (blue << 16) | (green << 8) | red) >>> 0;
      words.fill(word, row + x * zoom, row + (x + 1) * zoom);
    }
    for (let copy = 1; copy < zoom; copy++) {
      words.copyWithin(row + copy * rowWords, row, row + rowWords);
    }
  }
  context.putImageData(zoomed, left, top);
}

// The commands of course/widgets/browser_drawing.py, in their order.
function drawCommands(context, commands, pixels, vertices, codes) {
  for (const command of commands) {
    if (command.pixels) {
      putPixels(context, pixels, command.pixels, command.at, command.zoom);
      continue;
    }
    context.save();
    clipTo(context, command.clip);
    if (command.path) {
      context.beginPath();
      trace(context, vertices, codes, command.path);
      fillAndStroke(context, command);
    } else if (command.marker) {
      const [start, count] = command.at;
      for (let i = start; i < start + count; i++) {
        context.beginPath();
        trace(context, vertices, codes, command.marker, vertices[2 * i], vertices[2 * i + 1]);
        fillAndStroke(context, command);
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
    }
    context.restore();
  }
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
  let backdrop = null; // the still background a drag's drawings are drawn over
  let painting = Promise.resolve(); // patches are painted one after another

  function show() {
    generation += 1;
    composed = null;
    backdrop = null;
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

  function canvasFor(bitmap) {
    const canvas = document.createElement("canvas");
    canvas.width = bitmap.width;
    canvas.height = bitmap.height;
    return canvas.getContext("2d");
  }

  function showComposed(mine) {
    if (mine !== generation) return;
    display(URL.createObjectURL(bitmapFile(composed)));
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
