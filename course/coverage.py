"""How much of each pixel a stroked curve covers: the exact reference and Agg's.

A stroke of width w around a curve is the set of points within w / 2 of it
(round caps at the ends). A pixel is the unit square ``[c, c+1) x [r, r+1)``;
its *coverage* is the area of the square inside the stroke, a number in
[0, 1]. That is the quantity every anti-aliasing method in
:mod:`course.antialias` approximates, and the two references here compute it:

- :func:`reference`: k x k point samples per pixel, each tested with its exact
  distance to the curve flattened far below a pixel (1e-4 px). Only pixels near
  the curve are sampled, so a 700 x 700 canvas costs what its curve costs.
- :func:`agg_render`: matplotlib's Agg renderer stroking the same Bézier path
  (``CURVE4`` codes), the anti-aliasing most Python plots use.

The geometry both the references and the stroke methods need lives here too:
which pixels lie near which polyline segment (:func:`pixels_near`), and the
exact area of a pixel between two parallel lines (:func:`slab_coverage`).

References
----------
.. [1] M. Shemanarev, "Anti-Grain Geometry: the scanline rasterizer", 2006,
   https://agg.sourceforge.net/antigrain.com/doc/introduction/introduction.agdoc.html
.. [2] E. Catmull, "A hidden-surface algorithm with anti-aliasing", SIGGRAPH 1978
   (coverage as the area of a pixel covered by a shape).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import RendererAgg
from matplotlib.path import Path
from matplotlib.transforms import Affine2D

from course._validate import as_curve, as_int, as_positive_float, as_shape
from course.bezier import flatten

__all__ = [
    "REFERENCE_TOLERANCE",
    "NearPixels",
    "agg_draw",
    "agg_path",
    "agg_render",
    "band_coverage",
    "curve_polyline",
    "first_of_runs",
    "pixels_near",
    "reference",
    "slab_coverage",
]

# Distance from a pixel's centre to its farthest corner.
HALF_DIAGONAL = np.sqrt(0.5)
# How far the reference's polyline may stray from the true curve, in pixels.
REFERENCE_TOLERANCE = 1e-4
# Sub-sample rows processed at once by the reference (bounds its memory).
_CHUNK_SAMPLES = 1 << 20


def curve_polyline(points: Any, tolerance: float, max_step: float = 1.0) -> np.ndarray:
    """The curve as a polyline within ``tolerance`` of it, segments <= ``max_step``.

    Short segments keep the neighbourhood of each segment small, which is what
    lets :func:`pixels_near` look only near the curve.

    Examples
    --------
    >>> curve_polyline([[0, 0], [2, 0]], tolerance=0.1)
    array([[0., 0.],
           [1., 0.],
           [2., 0.]])
    """
    control = as_curve(points)
    line = flatten(control, tolerance, max_step=max_step)
    if len(line) == 1:  # a single point: a zero-length segment keeps the caps
        line = np.vstack([line, line])
    return line


def subdivide(polyline: np.ndarray, max_length: float) -> np.ndarray:
    """Split every segment into equal pieces no longer than ``max_length``."""
    pieces = np.maximum(np.ceil(np.hypot(*np.diff(polyline, axis=0).T) / max_length), 1)
    pieces = pieces.astype(np.int64)
    starts = np.repeat(polyline[:-1], pieces, axis=0)
    steps = np.repeat(np.diff(polyline, axis=0) / pieces[:, None], pieces, axis=0)
    # Position of each new vertex within its segment: 0, 1, ..., pieces - 1.
    index = np.arange(pieces.sum()) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    return np.vstack([starts + index[:, None] * steps, polyline[-1:]])


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

    Examples
    --------
    The segment (0, 0.5)-(2, 0.5) is split in two; pixel 0 is 0 from the
    first half and 0.5 from the second:

    >>> near = pixels_near(np.array([[0.0, 0.5], [2.0, 0.5]]), (2, 3), reach=0.6)
    >>> near.x.tolist(), near.segment.tolist(), near.distance.tolist()
    ([0, 0, 1, 1, 2], [0, 1, 1, 0, 1], [0.0, 0.5, 0.0, 0.5, 0.5])
    """
    height, width = shape
    # A window of n x n pixels serves a segment up to n - 2 reach long (see
    # below): split segments to just under that length, the fewest pixels
    # looked at per unit of curve.
    window = np.ceil(2 * reach + 1)
    line = subdivide(polyline, window - 2 * reach - 1e-6)
    start, end = line[:-1], line[1:]
    middle = 0.5 * (start + end)
    half_length = 0.5 * np.hypot(*(end - start).T).max()
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
    direction = end - start
    length = np.hypot(*direction.T)
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
    x = low[segment, 0].astype(np.int64) + column
    y = low[segment, 1].astype(np.int64) + row
    left, top = origin
    on_canvas = (x >= left) & (x < left + width) & (y >= top) & (y < top + height)
    index, segment, x, y = index[on_canvas], segment[on_canvas], x[on_canvas], y[on_canvas]
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
        segment=segment[order],
        distance=distance[order],
        along=along[order],
        across=across[order],
        polyline=line,
    )


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


def slab_coverage(across: Any, normal: Any, width: float) -> np.ndarray:
    """Exact area of a pixel inside a straight band of the given width.

    The band is ``|n . (p - c) + across| <= width / 2``: the pixel's centre c
    lies at signed distance ``across`` from the band's middle line, whose unit
    normal is n. The projection of a uniformly random point of the unit
    square onto n is the sum of two uniform variables, of widths ``|n_x|``
    and ``|n_y|``; its distribution function F is piecewise quadratic, and
    the coverage is ``F(width/2 - across) - F(-width/2 - across)``. For an
    axis-aligned band this is the overlap of two intervals, ``1 - |across|``
    for width 1; at 45 degrees the corners of the square lose area.

    Parameters
    ----------
    across : array_like
        Signed distances from pixel centres to the band's middle line.
    normal : array_like, shape (..., 2)
        Unit normals of the line (any sign).
    width : float
        Width of the band, > 0.

    Examples
    --------
    >>> slab_coverage([0.0, 0.25, 1.0], [[0.0, 1.0]], 1.0)
    array([1.  , 0.75, 0.  ])
    >>> slab_coverage([0.0], [[np.sqrt(0.5), np.sqrt(0.5)]], 1.0).round(4)
    array([0.9142])
    """
    normal = np.abs(np.asarray(normal, dtype=float))
    wide = np.maximum(normal[..., 0], normal[..., 1])
    narrow = np.minimum(normal[..., 0], normal[..., 1])
    return band_coverage(np.asarray(across, dtype=float), wide, narrow, width)


def band_coverage(
    across: np.ndarray, wide: np.ndarray, narrow: np.ndarray, width: float
) -> np.ndarray:
    """:func:`slab_coverage` given the normal's larger and smaller |component|."""
    half = 0.5 * width
    # Both band edges in one call: rows 0 and 1 of a (2, ...) array.
    edges = _projection_cdf(np.stack([half - across, -half - across]), wide, narrow)
    return edges[0] - edges[1]


def _projection_cdf(s: np.ndarray, wide: np.ndarray, narrow: np.ndarray) -> np.ndarray:
    """P(U1 + U2 <= s) for U1 ~ U(-wide/2, wide/2), U2 ~ U(-narrow/2, narrow/2)."""
    a, b = 0.5 * wide, 0.5 * narrow

    def q(u: np.ndarray) -> np.ndarray:
        u = np.maximum(u, 0.0)
        return u * u

    # Below ~1e-6 the quadratic form loses digits to cancellation; the band is
    # then axis-aligned to within 1e-6 and the uniform CDF is exact to that.
    thin = narrow < 1e-6
    safe = np.where(thin, 1.0, 2.0 * wide * narrow)
    quadratic = (q(s + (a + b)) - q(s + (a - b)) - q(s - (a - b)) + q(s - (a + b))) / safe
    uniform = (s + a) / np.where(wide > 0, wide, 1.0)  # wide is 0 only for no normal
    return np.clip(np.where(thin, uniform, quadratic), 0.0, 1.0)


def reference(points: Any, shape: Any, width: float = 1.0, k: int = 16) -> np.ndarray:
    """Exact coverage of every pixel by the stroked curve, by k x k supersampling.

    Each pixel is sampled at the k x k points ``(c + (i + 0.5) / k,
    r + (j + 0.5) / k)``; a sample is inside when its exact distance to the
    curve (flattened to within 1e-4 px) is at most ``width / 2``. The
    coverage is the fraction inside. Only pixels whose centre lies within
    ``width / 2 + sqrt(2) / 2`` of the curve can hold an inside sample; those
    within ``width / 2 - sqrt(2) / 2`` are wholly inside; only the pixels in
    between are sampled.

    The error of one pixel is at most about 1 / k (a straight edge parallel
    to the sample rows) and usually far less; it shrinks as k grows.

    Parameters
    ----------
    points : array_like, shape (N, 2)
        Control points in image space (x right, y down).
    shape : (H, W)
        Canvas size.
    width : float
        Stroke width in pixels, > 0.
    k : int
        Samples per pixel side; 16 or more for a reference.

    Returns
    -------
    ndarray, shape (H, W)
        Coverage in [0, 1].

    Examples
    --------
    A horizontal stroke of width 1 centred a quarter pixel below row 1's
    centre covers row 1 by 3/4 and row 2 by 1/4:

    >>> reference([[0.0, 1.75], [4.0, 1.75]], (4, 4), width=1.0, k=16)[:, 1:3]
    array([[0.  , 0.  ],
           [0.75, 0.75],
           [0.25, 0.25],
           [0.  , 0.  ]])
    """
    control = as_curve(points)
    height, canvas_width = as_shape(shape)
    width = as_positive_float(width, "width")
    k = as_int(k, "k", minimum=1)
    half = 0.5 * width
    line = curve_polyline(control, REFERENCE_TOLERANCE)
    near = pixels_near(line, (height, canvas_width), half + HALF_DIAGONAL)
    image = np.zeros(height * canvas_width)
    if len(near.flat) == 0:
        return image.reshape(height, canvas_width)
    nearest = np.full(height * canvas_width, np.inf)
    np.minimum.at(nearest, near.flat, near.distance)
    inside = nearest <= half - HALF_DIAGONAL
    image[inside] = 1.0
    firsts, coverage = supersample(near, ~inside[near.flat], half, k)
    image[near.flat[firsts]] = coverage
    return image.reshape(height, canvas_width)


@lru_cache(maxsize=8)
def _sample_grid(k: int) -> tuple[np.ndarray, np.ndarray]:
    """Offsets (x, y) of the k x k samples inside a pixel, row by row."""
    grid = (np.arange(k) + 0.5) / k
    sub_x, sub_y = (g.ravel() for g in np.meshgrid(grid, grid))
    sub_x.flags.writeable = sub_y.flags.writeable = False
    return sub_x, sub_y


def supersample(
    near: NearPixels, pairs: np.ndarray, half: float, k: int
) -> tuple[np.ndarray, np.ndarray]:
    """Coverage of the pixels whose pairs are selected, by k x k point samples.

    ``pairs`` is a boolean mask over ``near``'s pairs that selects every pair
    of a pixel or none. A sample of a pixel is inside when it lies within
    ``half`` of any segment paired with that pixel.

    Returns
    -------
    firsts : int ndarray
        For each selected pixel, the index of its first pair in ``near``.
    coverage : float ndarray
        The fraction of its k x k samples inside.
    """
    index = np.flatnonzero(pairs)
    if len(index) == 0:
        return index, np.zeros(0)
    flat = near.flat[index]
    sub_x, sub_y = _sample_grid(k)
    # Pairs are sorted by pixel: each pixel's pairs form one run.
    run_starts = np.flatnonzero(first_of_runs(flat))
    run_ends = np.r_[run_starts[1:], len(flat)]
    pairs_per_chunk = max(1, _CHUNK_SAMPLES // (k * k))
    coverage = np.empty(len(run_starts))
    first = 0
    while first < len(run_starts):
        # Whole runs only, as many as fit in one chunk (at least one).
        limit = run_starts[first] + pairs_per_chunk
        last = max(int(np.searchsorted(run_ends, limit, "right")), first + 1)
        chunk = index[run_starts[first] : run_ends[last - 1]]
        inside = _within(near, chunk, sub_x, sub_y, half)
        covered = np.logical_or.reduceat(inside, run_starts[first:last] - run_starts[first], axis=0)
        coverage[first:last] = covered.mean(axis=1)
        first = last
    return index[run_starts], coverage


def _within(
    near: NearPixels, chunk: np.ndarray, sub_x: np.ndarray, sub_y: np.ndarray, half: float
) -> np.ndarray:
    """Which samples of the chunk's pairs lie within ``half`` of the pair's segment.

    The test of :func:`segment_distance` on squared distances: everything
    that depends on the segment alone is computed once per pair, not once
    per sample, and no square root is taken, which halves the reference's
    time at k = 32.
    """
    segment = near.segment[chunk]
    start = near.polyline[segment]
    direction = near.polyline[segment + 1] - start
    length2 = np.einsum("ij,ij->i", direction, direction)
    # A point (or a segment so short its square is subnormal) is measured from its start.
    inverse = np.where(length2 > 1e-300, 1.0 / np.where(length2 > 1e-300, length2, 1.0), 0.0)
    ux, uy = (direction * inverse[:, None]).T
    dx = (near.x[chunk] - start[:, 0])[:, None] + sub_x
    dy = (near.y[chunk] - start[:, 1])[:, None] + sub_y
    along = np.clip(dx * ux[:, None] + dy * uy[:, None], 0.0, 1.0)
    ex = dx - along * direction[:, 0, None]
    ey = dy - along * direction[:, 1, None]
    return ex * ex + ey * ey <= half * half


def agg_render(points: Any, shape: Any, width: float = 1.0) -> np.ndarray:
    """The curve stroked by matplotlib's Agg renderer, as coverage in [0, 1].

    The control points become a ``matplotlib.path.Path`` with ``CURVE4``
    codes (``CURVE3`` for a quadratic, ``LINETO`` for a line), drawn by
    ``RendererAgg.draw_path`` with round caps and joins (the stroke is the
    set of points within width / 2 of the curve, like :func:`reference`),
    in white on a transparent canvas; the alpha channel, divided by 255, is
    the coverage. Agg computes the exact area of its own flattened outline,
    quantised to 8 bits.

    Conventions, checked by the tests against :func:`reference`: at 72 dpi
    one point of line width is one pixel; Agg's y axis points up, so image
    coordinates are mapped by y -> H - y; Agg's pixel (c, r) is the square
    ``[c, c+1) x [r, r+1)`` like this package's, so no half-pixel shift.
    Snapping is turned off (matplotlib snaps straight horizontal and vertical
    paths to pixel centres otherwise).

    Examples
    --------
    >>> agg_render([[0.0, 1.75], [4.0, 1.75]], (4, 4))[:, 1:3].round(3)
    array([[0.   , 0.   ],
           [0.753, 0.753],
           [0.251, 0.251],
           [0.   , 0.   ]])
    """
    control = as_curve(points)
    height, canvas_width = as_shape(shape)
    width = as_positive_float(width, "width")
    renderer = agg_draw(agg_path(control), (height, canvas_width), width)
    return np.asarray(renderer.buffer_rgba())[..., 3] / 255.0


def agg_path(control: np.ndarray) -> Path:
    """A matplotlib Path for a Bézier curve of degree 1, 2 or 3.

    Examples
    --------
    >>> agg_path(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 2.0], [3.0, 0.0]])).codes
    array([1, 4, 4, 4], dtype=uint8)
    """
    codes = {2: Path.LINETO, 3: Path.CURVE3, 4: Path.CURVE4}
    if len(control) not in codes:
        raise ValueError(
            "points: Agg draws Bézier curves of degree 1 to 3 (2 to 4 control points); "
            f"got {len(control)} points"
        )
    return Path(control, [Path.MOVETO] + [codes[len(control)]] * (len(control) - 1))


def agg_draw(path: Path, shape: tuple[int, int], width: float) -> RendererAgg:
    """Stroke a Path given in image coordinates with ``RendererAgg.draw_path``.

    A new 72 dpi renderer of the canvas's size, white round-capped strokes
    of ``width`` pixels, no snapping, y flipped to Agg's upward axis. The
    caller reads ``renderer.buffer_rgba()``; its alpha channel is coverage.
    """
    height, canvas_width = shape
    renderer = RendererAgg(canvas_width, height, 72)
    context = renderer.new_gc()
    context.set_linewidth(width)
    context.set_capstyle("round")
    context.set_joinstyle("round")
    context.set_antialiased(True)
    context.set_snap(False)
    context.set_foreground((1.0, 1.0, 1.0, 1.0))
    flip = Affine2D().scale(1.0, -1.0).translate(0.0, height)
    renderer.draw_path(context, path, flip)
    context.restore()
    return renderer
