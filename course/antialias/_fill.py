"""Filling a closed outline by signed area: the exact area of each pixel inside it.

Each directed edge of the outline is cut at every pixel boundary; each piece
adds to its pixel the signed area between it and the pixel's right side, and
its height to every pixel to the right of it (a running sum along the row)
[1]_. For closed loops, that gives each pixel the integral over its square
of the winding number: its exact area inside the outline where the winding
number is 0 or 1. The running sums only run through the blocks of a row that
the outline touches, so a long thin shape on a large canvas costs what its
outline costs. Part of the outline may come as polylines of many short edges
(the chords of round joins and caps): a run of them within one pixel is
filled as the one edge from its first point to its last, plus the area
between them, the same sums in fewer pieces.

References
----------
.. [1] R. Levien, "Inside the fastest font renderer in the world" (font-rs),
   2016, https://medium.com/@raphlinus/inside-the-fastest-font-renderer-in-the-world-75ae5270c445;
   the same accumulation as M. Shemanarev's Anti-Grain Geometry scanline
   rasterizer.
"""

from __future__ import annotations

import numpy as np

__all__ = ["accumulate"]

# Columns per block of the running sums: 2 ** _BLOCK_BITS.
_BLOCK_BITS = 5
_BLOCK = 1 << _BLOCK_BITS
# Canvas cells per value below which the running sums cover the whole canvas.
_DENSE = 16


def accumulate(
    starts: np.ndarray,
    ends: np.ndarray,
    shape: tuple[int, int],
    clip: bool = False,
    chains: tuple[np.ndarray, np.ndarray] | None = None,
) -> np.ndarray:
    """The signed area each pixel of the canvas holds inside the closed outline.

    ``starts``, ``ends`` (E, 2): the directed edges of closed loops (in any
    order). ``chains``, optional, more of them as polylines: ``(points,
    last)``, the points (N, 2) of one polyline after another and True at
    each one's last point. Each pixel gets the integral over its square of
    the winding number, with the sign of the loops' orientation. With
    ``clip``, values are clipped to [0, 1] and the rounding the running sums
    leave (below 1e-9) set to 0, only where the outline passes: a large
    canvas is never swept whole.
    """
    height, width = shape
    patch_cells, patch_areas = np.zeros(0, dtype=np.int64), np.zeros(0)
    if chains is not None:
        chain_starts, chain_ends, patch_cells, patch_areas = _merged(*chains, height, width)
        starts = np.concatenate([starts, chain_starts])
        ends = np.concatenate([ends, chain_ends])
    x0, y0, x1, y1, inside = _clip(starts, ends, height, width)
    # Every edge now spans at most one pixel boundary each way. Most cross
    # none: one piece each. An edge that crosses one boundary is cut at t1
    # in two pieces, one that crosses both at t1 and t2 in three.
    column, row = np.floor(np.minimum(x0, x1)), np.floor(np.minimum(y0, y1))
    across_x = np.maximum(x0, x1) > column + 1
    across_y = np.maximum(y0, y1) > row + 1
    cut = np.flatnonzero(across_x | across_y)
    x0c, y0c, x1c, y1c = x0.take(cut), y0.take(cut), x1.take(cut), y1.take(cut)
    sxc, syc = x1c - x0c, y1c - y0c
    cut_x, cut_y = across_x.take(cut), across_y.take(cut)
    # A nearly flat piece divides by a tiny step: inf, then 1 by the where.
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        tx = np.where(cut_x, (column.take(cut) + 1 - x0c) / sxc, 1.0)
        ty = np.where(cut_y, (row.take(cut) + 1 - y0c) / syc, 1.0)
    t1 = np.minimum(tx, ty)
    xa, ya = x0c + t1 * sxc, y0c + t1 * syc
    twice = np.flatnonzero(cut_x & cut_y)
    t2 = np.maximum(tx.take(twice), ty.take(twice))
    xb, yb = x0c.take(twice) + t2 * sxc.take(twice), y0c.take(twice) + t2 * syc.take(twice)
    # The pieces: every edge's first (to t1, the whole edge if uncut), then
    # the cut edges' second (t1 to t2 or the end), then the third (t2 to the end).
    first_x, first_y = x1.copy(), y1.copy()
    first_x[cut], first_y[cut] = xa, ya
    second_x, second_y = x1c.copy(), y1c.copy()
    second_x[twice], second_y[twice] = xb, yb
    start_x = np.concatenate([x0, xa, xb])
    start_y = np.concatenate([y0, ya, yb])
    end_x = np.concatenate([first_x, second_x, x1c.take(twice)])
    end_y = np.concatenate([first_y, second_y, y1c.take(twice)])
    rise = end_y - start_y  # a piece of no height adds 0
    middle_x = 0.5 * (start_x + end_x)
    cell_x = np.floor(middle_x)
    area = rise * (cell_x + 1 - middle_x)  # between the piece and the pixel's right side
    # On the canvas only a flat piece on its bottom side has its middle on
    # row H (it adds 0); cut to the canvas, a rounding can leave one just off.
    cell_y = np.minimum(np.floor(0.5 * (start_y + end_y)), height - 1)
    # The area goes to the piece's pixel, the rest of its rise to the next
    # one. Left of the canvas the whole rise goes to column 0, where the
    # running sums start; right of it to column W, dropped.
    column = cell_x
    if not inside:
        area = np.where(cell_x < 0, rise, area)
        column = np.minimum(np.maximum(cell_x, 0), width)
        cell_y = np.maximum(cell_y, 0)
    cells = (cell_y * (width + 1) + column).astype(np.int64)
    if len(patch_cells):
        cells = np.concatenate([cells, patch_cells])
        area = np.concatenate([area, patch_areas])
        rise = np.concatenate([rise, np.zeros(len(patch_areas))])
    return _running_sums(cells, area, rise, (height, width), clip)


def _merged(
    points: np.ndarray, last: np.ndarray, height: int, width: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The polylines' edges, a run of edges within one pixel as one edge and its patch.

    The chords of a round join or cap are short: most lie in the same pixel
    as their neighbours. Within a pixel, a run of edges adds to it what the
    straight edge from the run's first point to its last adds, plus the
    area between the run and that edge (the *patch*), and the same rise to
    the pixels on its right: one edge and one area instead of many edges.
    Returns the edges' starts and ends, and the patches' cells ``row * (W +
    1) + column`` and areas, for the pixels on the canvas (off it, the
    patch adds nothing: the running sums only carry the rise).
    """
    x, y = points[:, 0], points[:, 1]
    column, row = np.floor(x), np.floor(y)
    # Edge i runs from point i to point i + 1, unless point i ends a polyline.
    edge = ~last[:-1]
    within = edge & (column[1:] == column[:-1]) & (row[1:] == row[:-1])
    # An edge continues a run when it and the edge before it both stay in their pixel.
    continues = np.zeros(len(within), dtype=bool)
    continues[1:] = within[1:] & within[:-1]
    ends_run = np.zeros(len(within), dtype=bool)
    ends_run[:-1] = continues[1:]
    first = np.flatnonzero(edge & ~continues)
    final = np.flatnonzero(edge & ~ends_run) + 1
    # What each edge adds to its pixel, the fill's formula (for those within
    # one pixel), summed over each run and compared with the run's straight edge.
    rise = y[1:] - y[:-1]
    middle = 0.5 * (x[1:] + x[:-1])
    area = np.where(within, rise * (column[:-1] + 1 - middle), 0.0)
    long = np.flatnonzero(final - first > 1)
    run_first, run_final = first[long], final[long]
    run_column, run_row = column.take(run_first), row.take(run_first)
    run_rise = y.take(run_final) - y.take(run_first)
    run_middle = 0.5 * (x.take(run_first) + x.take(run_final))
    # Runs follow one another (a polyline's last point adds 0 between them).
    patch = np.add.reduceat(area, first).take(long)
    patch -= run_rise * (run_column + 1 - run_middle)
    on_canvas = (run_column >= 0) & (run_column < width) & (run_row >= 0) & (run_row < height)
    cells = (run_row * (width + 1) + run_column)[on_canvas].astype(np.int64)
    return points.take(first, 0), points.take(final, 0), cells, patch[on_canvas]


def _clip(
    starts: np.ndarray, ends: np.ndarray, height: int, width: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, bool]:
    """Edges within the canvas's rows, none longer than a pixel either way.

    Parts above or below the canvas and right of it add nothing to it and are
    dropped; a part left of it adds only its rise to every pixel of its rows,
    so it is moved to x = -0.5 (one vertical edge). Also returns whether every
    edge lay on the canvas already (nothing moved left of it).
    """
    x0, y0 = starts[:, 0].copy(), starts[:, 1].copy()
    x1, y1 = ends[:, 0].copy(), ends[:, 1].copy()
    inside = not (
        min(starts.min(initial=0), ends.min(initial=0)) < 0
        or max(x0.max(initial=0), x1.max(initial=0)) > width
        or max(y0.max(initial=0), y1.max(initial=0)) > height
    )
    if not inside:
        x0, y0, x1, y1 = _clip_to(x0, y0, x1, y1, height, width)
    # Split edges longer than a pixel in x or y into equal parts (few are):
    # each keeps its first part in place, the others follow all the edges.
    dx, dy = x1 - x0, y1 - y0
    parts = np.ceil(np.maximum(np.abs(dx), np.abs(dy)))
    long = np.flatnonzero(parts > 1)
    if len(long):
        parts = parts[long].astype(np.int64)
        edge = np.repeat(long, parts - 1)
        step = 1 + np.arange(len(edge)) - np.repeat(np.cumsum(parts - 1) - (parts - 1), parts - 1)
        count = np.repeat(parts, parts - 1)
        ex, ey = dx[edge], dy[edge]
        begin, end = step / count, (step + 1) / count
        last = step == count - 1
        # The last part ends exactly where the edge does, so the loops stay closed.
        tail_x1 = np.where(last, x1[edge], x0[edge] + end * ex)
        tail_y1 = np.where(last, y1[edge], y0[edge] + end * ey)
        x1[long] = x0[long] + dx[long] / parts
        y1[long] = y0[long] + dy[long] / parts
        x0 = np.concatenate([x0, x0[edge] + begin * ex])
        y0 = np.concatenate([y0, y0[edge] + begin * ey])
        x1, y1 = np.concatenate([x1, tail_x1]), np.concatenate([y1, tail_y1])
    return x0, y0, x1, y1, inside


def _clip_to(x0, y0, x1, y1, height, width):
    """Cut edges to rows [0, height] and columns up to width; move the part left of 0."""
    moving = y0 != y1  # a horizontal edge adds nothing
    x0, y0, x1, y1 = x0[moving], y0[moving], x1[moving], y1[moving]
    # Rows: keep the parameter range with 0 <= y <= height.
    dy = y1 - y0  # never 0 here, but may be tiny
    with np.errstate(over="ignore"):
        t_top, t_bottom = (0 - y0) / dy, (height - y0) / dy
    t_low = np.clip(np.minimum(t_top, t_bottom), 0, 1)
    t_high = np.clip(np.maximum(t_top, t_bottom), 0, 1)
    keep = t_high > t_low
    x0, y0, x1, y1, t_low, t_high = (v[keep] for v in (x0, y0, x1, y1, t_low, t_high))
    dx, dy = x1 - x0, y1 - y0
    x0, y0, x1, y1 = x0 + t_low * dx, y0 + t_low * dy, x0 + t_high * dx, y0 + t_high * dy
    # Columns: cut at x = 0 and x = width; drop what lies right of the canvas.
    pieces = [(x0, y0, x1, y1)]
    for bound in (0.0, float(width)):
        x0, y0, x1, y1 = (np.concatenate(v) for v in zip(*pieces, strict=True))
        dx = x1 - x0
        crosses = (np.minimum(x0, x1) < bound) & (np.maximum(x0, x1) > bound)
        t = np.where(crosses, (bound - x0) / np.where(crosses, dx, 1.0), 1.0)
        xm, ym = x0 + t * dx, y0 + t * (y1 - y0)
        xm = np.where(t < 1.0, bound, xm)
        pieces = [(x0, y0, xm, ym), (xm, ym, x1, y1)]
    x0, y0, x1, y1 = (np.concatenate(v) for v in zip(*pieces, strict=True))
    keep = (y0 != y1) & (np.maximum(x0, x1) <= width)
    x0, y0, x1, y1 = x0[keep], y0[keep], x1[keep], y1[keep]
    x0 = np.where(x0 < 0, -0.5, x0)
    x1 = np.where(x1 < 0, -0.5, x1)
    return x0, y0, x1, y1


def _running_sums(
    cell: np.ndarray, area: np.ndarray, rise: np.ndarray, shape: tuple[int, int], clip: bool
) -> np.ndarray:
    """Row-wise running sums of pieces of outline in ``cell = row * (W + 1) + column``.

    Each piece adds its ``area`` to its cell and the rest of its ``rise`` to
    the next cell on the right, so a pixel holds its own pieces' areas and
    the rises of every piece left of it. Column W, past the canvas, is
    dropped. Only the blocks of ``_BLOCK`` columns that hold a value, or that
    a value on their left leaves non-zero, are summed; the rest of the canvas
    is 0. A canvas no larger than ``_DENSE`` cells per value is summed whole:
    the bookkeeping of the blocks would cost more than it saves.
    """
    height, width = shape
    stride = width + 1
    if len(area) == 0:  # nothing on the canvas (bincount would return ints)
        return np.zeros((height, width))
    if height * stride <= _DENSE * 2 * len(area):
        areas = np.bincount(cell, area, height * stride).reshape(height, stride)
        rises = np.bincount(cell, rise, height * stride).reshape(height, stride)
        image = areas[:, :width].copy()
        image[:, 1:] += np.cumsum(rises[:, : width - 1], axis=1)
        return _clipped(image, clip)
    # The rest of the rise, in the next column (column W keeps its own: dropped).
    next_cell = cell + (cell % stride < width)
    value = np.concatenate([area, rise - area])
    cell = np.concatenate([cell, next_cell])
    row, column = np.divmod(cell, stride)
    blocks = (stride + _BLOCK - 1) >> _BLOCK_BITS
    block = row * blocks + (column >> _BLOCK_BITS)
    total = np.bincount(block, value, height * blocks).reshape(height, blocks)
    carry = (np.cumsum(total, axis=1) - total).ravel()  # what enters each block from the left
    has = np.bincount(block, minlength=height * blocks) > 0
    busy = np.flatnonzero(has | (np.abs(carry) > 1e-12))
    rank = np.full(height * blocks, -1)
    rank[busy] = np.arange(len(busy))
    cell = rank[block] * _BLOCK + (column & (_BLOCK - 1))
    local = np.bincount(cell, value, len(busy) * _BLOCK).reshape(len(busy), _BLOCK)
    sums = _clipped(np.cumsum(local, axis=1) + carry[busy][:, None], clip)
    busy_row, busy_block = np.divmod(busy, blocks)
    columns = busy_block[:, None] * _BLOCK + np.arange(_BLOCK)
    flat = (busy_row * width)[:, None] + columns
    image = np.zeros((height, width))
    on_canvas = columns < width  # the last block of a row reaches past the canvas
    image.ravel()[flat[on_canvas]] = sums[on_canvas]
    return image


def _clipped(values: np.ndarray, clip: bool) -> np.ndarray:
    """``values`` clipped to [0, 1] with rounding noise set to 0, in place (if ``clip``)."""
    if clip:
        np.clip(values, 0.0, 1.0, out=values)
        values[values < 1e-9] = 0.0
    return values
