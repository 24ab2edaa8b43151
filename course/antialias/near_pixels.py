"""Which pixels lie near which segment of a polyline, and how far.

Every stroke method and the exact reference look only at the pixels whose
centre lies within some reach of the curve: :func:`pixels_near` finds them
segment by segment, in time proportional to the curve's length, never to the
canvas. A polyline may have *gaps*, segments that are the pen moving between
the subpaths of a path, not part of it; they are skipped.

Unchecked kernels: like dhermes/bezier's ``hazmat``, this module trusts its
caller and checks no input (``UNCHECKED = True``, which the fuzz test reads).
Its public callers (:mod:`course.antialias`, :mod:`course.antialias.coverage`) validate
once, at their boundary.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = [
    "HALF_DIAGONAL",
    "NearPixels",
    "first_of_runs",
    "pixels_near",
    "pixels_within",
    "segment_distance",
    "subdivide",
]

UNCHECKED = True  # kernels for checked callers; see the module docstring

#: Distance from a pixel's centre to its farthest corner.
HALF_DIAGONAL = float(np.sqrt(0.5))


def subdivide(polyline: np.ndarray, max_length: float) -> np.ndarray:
    """Split every segment into equal pieces no longer than ``max_length``.

    Examples
    --------
    >>> subdivide(np.array([[0.0, 0.0], [3.0, 0.0]]), 1.5)
    array([[0. , 0. ],
           [1.5, 0. ],
           [3. , 0. ]])
    """
    return _split(polyline, max_length, np.zeros(len(polyline) - 1, dtype=bool))[0]


def _split(
    polyline: np.ndarray, max_length: float, gaps: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`subdivide`, leaving gaps whole (nothing is drawn along them); new gaps."""
    step = np.diff(polyline, axis=0)
    length = np.hypot(step[:, 0], step[:, 1])
    pieces = np.where(gaps, 1, np.maximum(np.ceil(length / max_length), 1)).astype(np.int64)
    starts = np.repeat(polyline[:-1], pieces, axis=0)
    steps = np.repeat(step / pieces[:, None], pieces, axis=0)
    # Position of each new vertex within its segment: 0, 1, ..., pieces - 1.
    index = np.arange(pieces.sum()) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    line = np.vstack([starts + index[:, None] * steps, polyline[-1:]])
    # The original vertices stay exact: joins and gaps land where they were.
    line[np.cumsum(pieces)] = polyline[1:]
    return line, np.repeat(gaps, pieces)


@dataclass(frozen=True)
class NearPixels:
    """Pairs (pixel, segment) with the pixel's centre within reach of the segment.

    One entry per pair, sorted by pixel (row-major ``flat = y * W + x``) and,
    for each pixel, by distance: a pixel near several segments appears once
    per segment, its nearest segment first.

    Attributes
    ----------
    x, y : int arrays
        The pixel.
    flat : int array
        ``y * W + x`` (from the canvas's origin), the pixel's index in the
        flattened image.
    segment : int array
        Index i of the segment ``polyline[i] -> polyline[i + 1]``.
    distance : float array
        From the pixel's centre to the segment (to its nearest point).
    along : float array
        Where that nearest point lies on the segment, 0 at its start, 1 at its end.
    across : float array
        Signed distance from the centre to the segment's *line*, positive to
        the left of its direction in image space (y down).
    polyline : ndarray (K, 2)
        The polyline the segment indices refer to: the input with long
        segments split.
    """

    x: np.ndarray
    y: np.ndarray
    flat: np.ndarray
    segment: np.ndarray
    distance: np.ndarray
    along: np.ndarray
    across: np.ndarray
    polyline: np.ndarray


def pixels_near(
    polyline: np.ndarray,
    shape: tuple[int, int],
    reach: float,
    origin: tuple[int, int] = (0, 0),
    gaps: np.ndarray | None = None,
) -> NearPixels:
    """Every on-canvas pixel whose centre lies within ``reach`` of a segment.

    The work is proportional to the number of segments times the area of
    one segment's neighbourhood, never to the canvas: each segment looks only
    at the pixels around it. Long segments are split first.

    Parameters
    ----------
    polyline : ndarray, shape (K, 2), K >= 2
    shape : (H, W)
    reach : float
        Largest centre-to-segment distance kept.
    origin : (x, y) ints
        The canvas's top-left pixel; ``flat`` counts from it. (0, 0) for an
        image; elsewhere to cover a curve that runs off every image.
    gaps : bool ndarray (K - 1,), optional
        True for the segments that are not drawn (the pen moving between
        subpaths); no pair names them.

    Examples
    --------
    The segment (0, 0.5)-(2, 0.5) is split in two; pixel 0 is 0 from the
    first half and 0.5 from the second:

    >>> near = pixels_near(np.array([[0.0, 0.5], [2.0, 0.5]]), (2, 3), reach=0.6)
    >>> near.x.tolist(), near.segment.tolist(), near.distance.tolist()
    ([0, 0, 1, 1, 2], [0, 1, 1, 0, 1], [0.0, 0.5, 0.0, 0.5, 0.5])
    """
    height, width = shape
    line, drawn, found = _candidates(polyline, reach, gaps)
    if found is None:
        empty = np.zeros(0, dtype=np.int64)
        return NearPixels(empty, empty, empty, empty, *(np.zeros(0),) * 3, line)
    index, segment, x, y, projection, across, distance2, length = found
    left, top = origin
    on_canvas = (x >= left) & (x < left + width) & (y >= top) & (y < top + height)
    index, segment, x, y = index[on_canvas], segment[on_canvas], x[on_canvas], y[on_canvas]
    number = drawn[segment]  # the segment's index in the whole split polyline
    distance = np.sqrt(distance2.take(index))
    has_length = length[segment] > 0
    along = np.where(has_length, projection.take(index) / length.clip(1e-300)[segment], 0.0)
    along = np.clip(along, 0.0, 1.0)
    # A point has no line: its "across" is the distance itself.
    across = np.where(has_length, across.take(index), distance)
    flat = (y - top) * width + (x - left)
    # Sort by pixel, then by distance: one float key, far cheaper than lexsort.
    # distance / (2 reach + 1) < 1/2 never reaches the next pixel's key.
    order = np.argsort(flat + distance / (2 * reach + 1))
    return NearPixels(
        x=x[order],
        y=y[order],
        flat=flat[order],
        segment=number[order],
        distance=distance[order],
        along=along[order],
        across=across[order],
        polyline=line,
    )


def pixels_within(
    polyline: np.ndarray, shape: tuple[int, int], reach: float, gaps: np.ndarray | None = None
) -> np.ndarray:
    """The flat indices ``y * W + x`` of the pixels of :func:`pixels_near`, each once, sorted.

    Examples
    --------
    >>> pixels_within(np.array([[0.0, 0.5], [2.0, 0.5]]), (2, 3), reach=0.6).tolist()
    [0, 1, 2]
    """
    height, width = shape
    found = _candidates(polyline, reach, gaps)[2]
    if found is None:
        return np.zeros(0, dtype=np.int64)
    x, y = found[2], found[3]
    on_canvas = (x >= 0) & (x < width) & (y >= 0) & (y < height)
    return np.unique((y * width + x)[on_canvas])


def _candidates(
    polyline: np.ndarray, reach: float, gaps: np.ndarray | None
) -> tuple[np.ndarray, np.ndarray, tuple[np.ndarray, ...] | None]:
    """Every (pixel, segment) with the centre within ``reach``, canvas or not.

    Returns the split polyline, its drawn segments and, unless none is drawn,
    the pairs: flat index on the (segments, rows, columns) grid, segment (of
    the drawn ones), x, y, and on the grid the projection, the signed
    distance across and the squared distance; and the drawn segments' lengths.
    """
    # A window of n x n pixels serves a segment up to n - 2 reach long (see
    # below): split segments to just under that length, the fewest pixels
    # looked at per unit of curve.
    window = np.ceil(2 * reach + 1)
    if gaps is None:
        gaps = np.zeros(len(polyline) - 1, dtype=bool)
    line, split_gaps = _split(polyline, window - 2 * reach - 1e-6, gaps)
    drawn = np.flatnonzero(~split_gaps)
    if len(drawn) == 0:
        return line, drawn, None
    start, end = line.take(drawn, 0), line.take(drawn + 1, 0)
    middle = 0.5 * (start + end)
    direction = end - start
    length = np.hypot(direction[:, 0], direction[:, 1])
    half_length = 0.5 * length.max()
    # A centre c + 0.5 within reach of a segment is within reach + half its
    # length of its middle m: c lies in [m - 0.5 - r, m - 0.5 + r], an interval
    # holding floor(2 r) + 1 integers. One such window of columns and rows.
    radius = reach + half_length
    size = int(np.floor(2 * radius)) + 1
    offsets = np.arange(size, dtype=float) + 0.5
    low = np.ceil(middle - 0.5 - radius)
    # Centres relative to each segment's start, on the (segments, rows,
    # columns) grid by broadcasting; the projections onto the segment's unit
    # direction give distance and side without a division per candidate.
    # A zero-length segment is a point: any unit vector measures its distance.
    unit = np.where(
        (length > 0)[:, None], direction / np.where(length > 0, length, 1.0)[:, None], [1.0, 0.0]
    )
    dx = (low[:, 0] - start[:, 0])[:, None, None] + offsets[None, None, :]
    dy = (low[:, 1] - start[:, 1])[:, None, None] + offsets[None, :, None]
    ux, uy = unit[:, 0, None, None], unit[:, 1, None, None]
    projection = dx * ux + dy * uy
    across = dx * uy - dy * ux
    beyond = projection - np.clip(projection, 0.0, length[:, None, None])
    distance2 = beyond * beyond + across * across
    index = np.flatnonzero(distance2 <= reach * reach)
    segment, cell = np.divmod(index, size * size)
    row, column = np.divmod(cell, size)
    x = low[:, 0].take(segment).astype(np.int64) + column
    y = low[:, 1].take(segment).astype(np.int64) + row
    return line, drawn, (index, segment, x, y, projection, across, distance2, length)


def first_of_runs(values: np.ndarray) -> np.ndarray:
    """True at the first element of each run of equal neighbours.

    Examples
    --------
    >>> first_of_runs(np.array([4, 4, 7, 9, 9])).tolist()
    [True, False, True, True, False]
    """
    return np.concatenate([values[:1] == values[:1], values[1:] != values[:-1]])


def segment_distance(
    px: np.ndarray, py: np.ndarray, start: np.ndarray, end: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Distance from points (px, py) to segments start -> end, elementwise.

    Returns ``(distance, along, across)``: the distance to the segment, the
    parameter in [0, 1] of its nearest point, and the signed distance to the
    segment's line (positive on the left in image space). A zero-length
    segment is a point: ``across`` is then the distance itself.

    Examples
    --------
    >>> segment_distance(np.array([1.0, 3.0]), np.array([1.0, 0.0]),
    ...                  np.array([[0.0, 0.0]]), np.array([[2.0, 0.0]]))
    (array([1., 1.]), array([0.5, 1. ]), array([-1.,  0.]))
    """
    direction = end - start
    # hypot, not the squared length: a tiny segment's square underflows to a
    # subnormal and loses its digits.
    length = np.hypot(direction[..., 0], direction[..., 1])
    dx, dy = px - start[..., 0], py - start[..., 1]
    safe = np.where(length > 0, length, 1.0)
    unit_x, unit_y = direction[..., 0] / safe, direction[..., 1] / safe
    along = np.clip((dx * unit_x + dy * unit_y) / safe, 0.0, 1.0)
    distance = np.hypot(dx - along * direction[..., 0], dy - along * direction[..., 1])
    # Left of the direction with y down: the cross product direction x offset < 0.
    across = dx * unit_y - dy * unit_x
    across = np.where(length > 0, across, distance)
    return distance, along, across
