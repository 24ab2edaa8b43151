"""Fast kernels behind :mod:`course.curves.bezier`: pure array code on validated input.

Both kernels work on chunks of parameters so that the intermediate arrays
stay in the CPU cache, in a ``(rows, d, chunk)`` layout whose inner axis is
contiguous over t, with in-place ufuncs (``out=``) so that no temporary is
allocated per step. The readable forms they must agree with live in
:mod:`course.curves.bezier`.

References
----------
.. [1] L. L. Schumaker and W. Volk, "Efficient evaluation of multivariate
   polynomials", Computer Aided Geometric Design 3(2), 1986, pp. 149-154
   (Horner's rule in t / (1 - t) for the Bernstein form).
"""

from __future__ import annotations

import numpy as np

# About 1 MiB of float64 per working array, measured best on a 1 MiB L2 cache
# and again on a 2 MiB one (smaller chunks pay more per-call overhead than they
# gain in locality, larger ones spill out of the cache).
_CACHE_ELEMENTS = 1 << 17
_MIN_CHUNK, _MAX_CHUNK = 256, 8192
# A cache line. With chunks a multiple of 8 floats and buffers that start on a
# line, every row of a level starts on one too: rows that start mid-line make
# vector loads straddle two lines, which cost 15-20% of de_casteljau_chunked's
# time at degrees 3 and 9 (10^5 and 10^6 t, 2 coordinates).
_LINE_BYTES = 64
_LINE_FLOATS = _LINE_BYTES // 8
_ALIGNED_FROM = 1 << 14  # elements (see _line_aligned_empty)


def _chunk_size(rows: int, dimension: int) -> int:
    chunk = min(max(_CACHE_ELEMENTS // max(rows * dimension, 1), _MIN_CHUNK), _MAX_CHUNK)
    return chunk - chunk % _LINE_FLOATS


def _line_aligned_empty(size: int) -> np.ndarray:
    """An uninitialized float64 array of ``size`` whose data starts on a cache line.

    A small one (a drag's curve: 4 x 2 x 402) as numpy places it: there aligning
    costs more (a sixth of the call) than the loads it spares.
    """
    if size < _ALIGNED_FROM:
        return np.empty(size)
    raw = np.empty(size + _LINE_FLOATS)
    skip = (-raw.__array_interface__["data"][0] % _LINE_BYTES) // raw.itemsize
    return raw[skip : skip + size]


def de_casteljau_chunked(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(M, d) curve points by de Casteljau; ``control`` (N, d), ``t`` (M,).

    Every level is one line of the textbook, ``(1 - t) * P[i] + t * P[i + 1]``,
    applied to all rows and coordinates of a chunk at once. Multiplying by
    ``1 - t`` and ``t`` (rather than ``P[i] + t * (P[i + 1] - P[i])``) keeps
    ``B(0) = P[0]`` and ``B(1) = P[n]`` exact.
    """
    count, dimension = control.shape
    curve = np.empty((len(t), dimension))
    if count == 1:
        curve[:] = control[0]
        return curve
    # No bigger than the input: flatten evaluates a few thousand t at a time.
    chunk = min(_chunk_size(count, dimension), max(len(t), 1))
    column = control[:, :, None]
    pairs = (count - 1) * dimension  # (row, coordinate) pairs of a level
    level_buffer = _line_aligned_empty(pairs * chunk)
    work_buffer = _line_aligned_empty(pairs * chunk)
    for start in range(0, len(t), chunk):
        t_chunk = t[start : start + chunk]
        s_chunk = 1.0 - t_chunk
        size = len(t_chunk)
        # Contiguous views of the flat buffers, the last short chunk included,
        # so that each ufunc call runs over one block of memory.
        shape = (count - 1, dimension, size)
        level = level_buffer[: pairs * size].reshape(shape)
        work = work_buffer[: pairs * size].reshape(shape)
        # Level 1 straight from the control points, then level m from m + 1 rows.
        np.multiply(column[:-1], s_chunk, out=level)
        np.multiply(column[1:], t_chunk, out=work)
        level += work
        for rows in range(count - 2, 0, -1):
            np.multiply(level[1 : rows + 1], t_chunk, out=work[:rows])
            level[:rows] *= s_chunk
            level[:rows] += work[:rows]
        # One coordinate at a time: a transposing copy of the (d, size) block
        # runs its inner loop over d, 3% (degree 9) to 15% (degree 3) slower.
        for axis in range(dimension):
            curve[start : start + size, axis] = level[0, axis]
    return curve


def levels_at(control: np.ndarray, t: float) -> list[np.ndarray]:
    """Every level of de Casteljau's algorithm at one ``t``: ``control`` (N, d), N levels.

    Each level is one line of the textbook applied to the level before,
    down to the single point B(t).
    """
    level = control
    levels = [level]
    while len(level) > 1:
        level = level[:-1] * (1 - t) + level[1:] * t
        levels.append(level)
    return levels


def bernstein_horner(control: np.ndarray, binomials: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(M, d) points of the Bernstein form by Horner's rule in u = t / (1 - t).

    ``B(t) = (1 - t)^n * sum_i C(n, i) P[i] u^i`` for t < 1/2, and the same
    with the points reversed and u = (1 - t) / t, times t^n, for t >= 1/2, so
    that |u| <= 1 for every real t: O(n) work per parameter instead of the
    O(n^2) of de Casteljau. ``binomials`` holds C(n, i) as floats.
    """
    count, dimension = control.shape
    curve = np.empty((len(t), dimension))
    if count == 1:
        curve[:] = control[0]
        return curve
    weighted = (binomials[:, None] * control)[:, :, None]
    chunk = _chunk_size(2, dimension)
    buffer = np.empty((dimension, chunk))
    for start in range(0, len(t), chunk):
        t_chunk = t[start : start + chunk]
        low = t_chunk < 0.5
        if low.all() or not low.any():
            # Sorted parameters (the common case) rarely straddle 1/2 in a chunk.
            groups = [(slice(None), bool(low[0]))]
        else:
            groups = [(np.flatnonzero(low), True), (np.flatnonzero(~low), False)]
        for where, is_low in groups:
            x = t_chunk[where]
            accumulator = buffer[:, : len(x)]
            _horner_group(weighted if is_low else weighted[::-1], x, is_low, accumulator)
            curve[start : start + len(t_chunk)][where] = accumulator.T
    return curve


def _horner_group(
    weighted: np.ndarray, x: np.ndarray, is_low: bool, accumulator: np.ndarray
) -> None:
    """Horner in u on one group; ``weighted`` rows run from the u^0 term up."""
    complement = 1.0 - x
    if is_low:
        u, base = x / complement, complement
    else:
        u, base = complement / x, x
    degree = len(weighted) - 1
    np.multiply(weighted[degree], u, out=accumulator)
    accumulator += weighted[degree - 1]
    for i in range(degree - 2, -1, -1):
        accumulator *= u
        accumulator += weighted[i]
    accumulator *= _integer_power(base, degree)


def _integer_power(base: np.ndarray, exponent: int) -> np.ndarray:
    """``base ** exponent`` by repeated squaring (numpy's float power calls pow())."""
    result = None
    square = base
    while exponent:
        if exponent & 1:
            result = square.copy() if result is None else result * square
        exponent >>= 1
        if exponent:
            square = square * square
    return np.ones_like(base) if result is None else result
