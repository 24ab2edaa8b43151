"""Error diffusion: threshold each pixel and pass its error on to the next ones.

The lab's ``DitheringErrorDiffuse`` is Floyd-Steinberg: pixels visited row by
row, left to right, each set to 1 where its value (with the errors received)
is > 0.5, and the error ``old - new`` pushed 7/16 to the right and 3/16, 5/16,
1/16 to the row below. Here too: the Jarvis-Judice-Ninke, Stucki and Atkinson
kernels, serpentine scanning, the handout's per-pixel loop beside two faster
forms with the same output bit for bit, and the report's pitfall
(:func:`error_diffusion_wraparound`). :mod:`course.halftone.dither` re-exports it all.
"""

from __future__ import annotations

from collections.abc import Iterator
from itertools import chain
from typing import Any

import numpy as np
from numpy.lib.stride_tricks import as_strided

from course._validate import as_choice, as_gray, describe
from course.halftone._diffusion import FORMS, default_method, diffuse, kernel_offsets
from course.i18n import _

__all__ = [
    "ERROR_DIFFUSION_METHODS",
    "KERNELS",
    "diffusion_offsets",
    "error_diffusion",
    "error_diffusion_values",
    "error_diffusion_wraparound",
]

#: Error-diffusion kernels: (weights, denominator). The current pixel sits in
#: row 0, in the middle column (the left middle one for an even width); the
#: weights left of it in row 0 are zero, as those pixels are already done.
KERNELS: dict[str, tuple[tuple[tuple[int, ...], ...], int]] = {
    "floyd-steinberg": (((0, 0, 7), (3, 5, 1)), 16),
    "jarvis-judice-ninke": (((0, 0, 0, 7, 5), (3, 5, 7, 5, 3), (1, 3, 5, 3, 1)), 48),
    "stucki": (((0, 0, 0, 8, 4), (2, 4, 8, 4, 2), (1, 2, 4, 2, 1)), 42),
    # Atkinson pushes only 6/8 of the error on purpose: darks and lights clip.
    "atkinson": (((0, 0, 1, 1), (1, 1, 1, 0), (0, 1, 0, 0)), 8),
}

ERROR_DIFFUSION_METHODS = ("wavefront", "rows", "loop")


def diffusion_offsets(kernel: str = "floyd-steinberg") -> list[tuple[int, int, float]]:
    """The kernel as (dx, dy, weight) pushes, in raster order of their targets.

    Examples
    --------
    >>> diffusion_offsets()
    [(1, 0, 0.4375), (-1, 1, 0.1875), (0, 1, 0.3125), (1, 1, 0.0625)]
    """
    return kernel_offsets(KERNELS[as_choice(kernel, "kernel", tuple(KERNELS))])


def error_diffusion(
    gray: Any,
    kernel: str = "floyd-steinberg",
    serpentine: bool = False,
    method: str | None = None,
) -> np.ndarray:
    """Error diffusion: threshold each pixel, push its error onto unvisited neighbours.

    Pixels are visited row by row, left to right. Each one is thresholded
    (1 where > 0.5) and its error ``old - new`` is added to the neighbours
    not yet visited, weighted by the kernel: for Floyd-Steinberg 7/16 to the
    right and 3/16, 5/16, 1/16 below left, below and below right. Pushes
    that would leave the image are dropped.

    Parameters
    ----------
    gray : array_like, (H, W), values in [0, 1]
    kernel : {"floyd-steinberg", "jarvis-judice-ninke", "stucki", "atkinson"}
        See ``KERNELS``.
    serpentine : bool
        Visit odd rows right to left with the kernel mirrored, which breaks
        up the diagonal "worms" of raster order.
    method : {"wavefront", "rows", "loop"}, optional
        Three forms with identical output, bit for bit. ``"loop"`` is the
        handout's per-pixel loop. ``"rows"`` runs each row in a loop but
        pushes the row's errors to the rows below as whole-row array
        additions. ``"wavefront"`` processes at once every pixel whose
        neighbours are done: with Floyd-Steinberg, pixel (x, y) waits only
        for its left neighbour and three pixels of the row above, so all
        pixels with the same ``x + 2 y`` are independent. Serpentine order
        has no such wavefront (each row starts where the row above ended),
        so the default is ``"wavefront"`` in raster order and ``"rows"``
        with ``serpentine=True``.

    Returns
    -------
    ndarray, (H, W), of 0.0 and 1.0

    References
    ----------
    R. W. Floyd and L. Steinberg, "An adaptive algorithm for spatial
    greyscale", Proceedings of the Society for Information Display 17(2), 1976.
    J. F. Jarvis, C. N. Judice and W. H. Ninke, "A survey of techniques for
    the display of continuous tone pictures on bilevel displays", Computer
    Graphics and Image Processing 5(1), 1976. P. Stucki, "MECCA: a
    multiple-error correction computation algorithm for bi-level image
    hardcopy reproduction", IBM Research Report RZ1060, 1981.

    Examples
    --------
    >>> error_diffusion(np.full((3, 6), 0.5))
    array([[0., 1., 0., 1., 0., 1.],
           [1., 0., 1., 0., 1., 0.],
           [0., 1., 0., 1., 0., 1.]])
    >>> bool(np.array_equal(error_diffusion(np.full((3, 6), 0.3), method="loop"),
    ...                     error_diffusion(np.full((3, 6), 0.3))))
    True
    """
    return _run(gray, kernel, serpentine, method)[0]


def _run(
    gray: Any, kernel: str, serpentine: bool, method: str | None
) -> tuple[np.ndarray, np.ndarray]:
    """Validate, pick the form, return (output, values)."""
    array = as_gray(gray, "gray", copy=False)  # every form copies before it writes
    offsets = diffusion_offsets(kernel)
    if not isinstance(serpentine, (bool, np.bool_)):
        raise TypeError(
            _("serpentine must be True or False; got {serpentine}").format(
                serpentine=describe(serpentine)
            )
        )
    if method is None:
        method = default_method(serpentine)
    method = as_choice(method, "method", ERROR_DIFFUSION_METHODS)
    if method == "wavefront" and serpentine:
        raise ValueError(
            _(
                "method='wavefront' needs raster order: with serpentine=True each row starts "
                "where the row above ended, so no two rows can run together; use method='rows' "
                "(the default for serpentine)"
            )
        )
    return diffuse(array, offsets, serpentine, method)


def error_diffusion_values(
    gray: Any,
    kernel: str = "floyd-steinberg",
    serpentine: bool = False,
    method: str | None = None,
) -> np.ndarray:
    """What the threshold saw: each pixel's value plus the errors it received.

    Same parameters as :func:`error_diffusion`, whose output is
    ``error_diffusion_values(...) > 0.5``. Values range over about
    [-0.5, 1.5]; the three methods give the same values bit for bit (the
    additions happen in the same order), which is a stronger check than
    equal outputs.

    Examples
    --------
    0.625 becomes 1 and pushes -0.375: 7/16 of it makes its right neighbour
    0.25 - 0.1640625 = 0.0859375, which becomes 0 and pushes +0.0859375...

    >>> error_diffusion_values([[0.625, 0.25], [0.25, 0.875]]) * 32768
    array([[20480.,  2816.],
           [ 4880., 30919.]])
    """
    return _run(gray, kernel, serpentine, method)[1]


def _error_diffusion_loop(
    gray: np.ndarray, offsets: list[tuple[int, int, float]], serpentine: bool
) -> tuple[np.ndarray, np.ndarray]:
    """The handout's form: one pixel at a time, errors pushed into a copy.

    Returns the output and the buffer, which ends up holding the value each
    pixel had when it was thresholded (nothing is pushed to a visited pixel).
    """
    height, width = gray.shape
    buffer = gray.copy()  # the handout's "inputcopy": it collects the errors
    output = np.zeros_like(gray)
    for y in range(height):
        leftward = serpentine and y % 2 == 1
        direction = -1 if leftward else 1
        for x in range(width - 1, -1, -1) if leftward else range(width):
            old = buffer[y, x]
            new = 1.0 if old > 0.5 else 0.0
            output[y, x] = new
            error = old - new
            for dx, dy, weight in offsets:
                target_x, target_y = x + direction * dx, y + dy
                # Both bounds: a negative index would wrap to the other side.
                if 0 <= target_x < width and target_y < height:
                    buffer[target_y, target_x] += error * weight
    return output, buffer


def _error_diffusion_rows(
    gray: np.ndarray, offsets: list[tuple[int, int, float]], serpentine: bool
) -> tuple[np.ndarray, np.ndarray]:
    """A loop along each row; the pushes to the rows below as whole-row additions.

    The result equals the loop's bit for bit because every pixel receives
    the same additions in the same order: from earlier rows first, and
    within a row in visiting order (the pushes with the largest dx come from
    the pixel visited first).
    """
    height, width = gray.shape
    buffer = gray.copy()
    output = np.zeros_like(gray)
    along_row = [(dx, weight) for dx, dy, weight in offsets if dy == 0]
    below = sorted((o for o in offsets if o[1] > 0), key=lambda o: -o[0])
    for y in range(height):
        leftward = serpentine and y % 2 == 1
        # Visit a leftward row as a rightward walk over its mirror image.
        values = (buffer[y, ::-1] if leftward else buffer[y]).tolist()
        errors = [0.0] * width
        for x in range(width):
            new = 1.0 if values[x] > 0.5 else 0.0
            errors[x] = values[x] - new
            for dx, weight in along_row:
                if x + dx < width:
                    values[x + dx] += errors[x] * weight
        row = np.array(values)
        error = np.array(errors)
        if leftward:
            row, error = row[::-1], error[::-1]
        buffer[y] = row
        output[y] = row > 0.5
        for dx, dy, weight in below:
            if y + dy >= height:
                continue
            shift = -dx if leftward else dx
            # Target x receives from source x - shift: slice both to the overlap.
            target = buffer[y + dy, max(shift, 0) : width + min(shift, 0)]
            target += error[max(-shift, 0) : width - max(shift, 0)] * weight
    return output, buffer


def _wavefront_skew(offsets: list[tuple[int, int, float]]) -> int:
    """The smallest s such that wavefront t = x + s y runs the loop's additions in order.

    Two conditions: every push goes to a later wavefront (dx + s dy >= 1),
    and a pixel's sources in earlier rows come no later than its sources in
    later rows (those of equal wavefront are then applied deepest first).
    Floyd-Steinberg gives s = 2, Atkinson 3, Jarvis-Judice-Ninke and Stucki 4.
    """
    skew = 0
    for dx, dy, _weight in offsets:
        if dy > 0:
            skew = max(skew, -((dx - 1) // dy))  # ceil((1 - dx) / dy)
        for other_dx, other_dy, _other_weight in offsets:
            if dy > other_dy:
                skew = max(skew, -(-(other_dx - dx) // (dy - other_dy)))
    return skew


def _error_diffusion_wavefront(
    gray: np.ndarray, offsets: list[tuple[int, int, float]], band: int | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """All pixels of one wavefront x + s y = t at once, t = 0, 1, 2, ...

    The image runs in bands of ``band`` rows, by default ``max(width,
    1024)``, each in a buffer of about ``(width + s band) width / s`` cells
    (see ``_wavefront_band``). A band hands the rows below it their values
    with the errors received so far, added in order, so the result does not
    depend on the banding.
    """
    height, width = gray.shape
    depth = max(dy for _, dy, _ in offsets)
    band = band or max(width, 1024)
    values = np.empty_like(gray)
    below = np.zeros((depth, width))
    below[: min(depth, height)] = gray[:depth]
    for first in range(0, height, band):
        rows = gray[first + depth : first + band + depth]
        below = _wavefront_band(below, rows, offsets, values[first : first + band])
    return (values > 0.5).astype(float), values


def _wavefront_band(
    below: np.ndarray,
    rows: np.ndarray,
    offsets: list[tuple[int, int, float]],
    values: np.ndarray,
) -> np.ndarray:
    """Run the band ``values`` (``below``, then ``rows``), return the rows below it as received.

    Pixel (x, y) lives in cell ``(x + s y) L + y`` of a flat buffer: wavefront
    t = x + s y is then a run of consecutive cells, ``t L + y``, and a push by
    (dx, dy) lands ``(dx + s dy) L + dy`` cells further on. Every step takes
    exactly L cells, from the first row of its pixels, so the pushes of one
    kernel row (dx from ``first`` to ``last``) land in ``last - first + 1``
    runs of L cells that follow each other: one contiguous addition, which
    costs a third of a strided one (a step costs a few numpy calls whatever
    its length, so the calls' overhead is the time).

    The cells after a step's ``n`` pixels are not pixels; their errors are
    zeroed, so that they push exactly 0, wherever that lands. Nothing else
    reads a cell, so pixels must only not share a cell with each other or
    with a cell pushes reach. L is the smaller of two widths that ensure it:
    ``count + depth`` (rows never share a cell), or ``s L >= width + reach -
    1``, cells beside the image by up to ``reach`` columns then lie too far
    in x from every pixel (beside cells may share cells with each other:
    they only receive).
    """
    count, width = values.shape
    depth = len(below)
    skew = _wavefront_skew(offsets)
    steps = width + skew * (count - 1)
    reach = max(max(abs(dx) for dx, _dy, _w in offsets), 1)
    length = min(-(-(width + reach - 1) // skew), count + depth)
    # Room for the views of up to 2 s steps past the last one, and their pushes.
    furthest = max(dx for dx, _dy, _w in offsets) + skew * (depth + 3) + 2
    pending = np.zeros((steps + furthest) * length + count + depth + 3)
    image = np.ndarray(
        (count + depth, width), buffer=pending, strides=((skew * length + 1) * 8, length * 8)
    )
    image[:depth] = below
    _copy(image[depth : depth + len(rows)], rows, skew)

    # One block addition per kernel row, deepest first: a block spans the row's dx range.
    weights, blocks = [], []
    for dy in sorted({dy for _dx, dy, _weight in offsets}, reverse=True):
        row = {dx: weight for dx, other_dy, weight in offsets if other_dy == dy}
        first, last = min(row), max(row)
        start = len(weights)
        weights.extend(row.get(dx, 0.0) for dx in range(first, last + 1))
        blocks.append(((first + skew * dy) * length + dy, last - first + 1, start))
    # A full weight matrix times a broadcast error: faster than broadcasting the weights.
    weight_matrix = np.repeat(np.array(weights)[:, None], length, axis=1)
    error = np.zeros(length)
    error_rows = np.broadcast_to(error, weight_matrix.shape)
    pushed = np.empty_like(weight_matrix)
    above = np.empty(length, dtype=bool)
    shares = [pushed[start : start + span].reshape(-1) for _offset, span, start in blocks]
    targets = [
        _step_windows(pending, offset, span * length, length, width, skew, steps)
        for offset, span, _start in blocks
    ]
    windows = _step_windows(pending, 0, length, length, width, skew, steps)
    # Step t's pixels: rows lo to min(count, t // s + 1), lo = max(0, ceil((t - width + 1) / s)).
    t = np.arange(steps)
    pixels = np.minimum(count, t // skew + 1) - np.maximum(0, -((width - 1 - t) // skew))
    tails = [error[n:] for n in range(length)] + [None]
    # One per step: the loops stop with it, the views run on past the last step.
    cuts = map(tails.__getitem__, pixels.tolist())

    add, greater, multiply, subtract = np.add, np.greater, np.multiply, np.subtract
    # Unrolled for two kernel rows (Floyd-Steinberg): a loop over the blocks
    # would cost a tenth of the step.
    if len(blocks) == 2:
        (deep, shallow), (deep_share, shallow_share) = targets, shares
        for cut, value, deep_target, shallow_target in zip(
            cuts, windows, deep, shallow, strict=False
        ):
            greater(value, 0.5, above)
            subtract(value, above, error)
            if cut is not None:
                cut.fill(0.0)
            multiply(weight_matrix, error_rows, pushed)
            add(deep_target, deep_share, deep_target)
            add(shallow_target, shallow_share, shallow_target)
    else:
        for cut, value, *step_targets in zip(cuts, windows, *targets, strict=False):
            greater(value, 0.5, above)
            subtract(value, above, error)
            if cut is not None:
                cut.fill(0.0)
            multiply(weight_matrix, error_rows, pushed)
            for target, share in zip(step_targets, shares, strict=True):
                add(target, share, target)

    # A pixel's value is final once its wavefront has run.
    _copy(values, image[:count], skew)
    return image[count:].copy()


def _step_windows(
    array: np.ndarray, offset: int, size: int, length: int, width: int, skew: int, steps: int
) -> Iterator[np.ndarray]:
    """Views ``array[start + offset : start + offset + size]`` for steps t = 0, 1, 2, ...

    Step t starts at ``t L + lo``. Until t = width - 1, lo = 0; then lo grows
    by one every s steps, so the starts of every s-th step are evenly spaced
    and s strided views make all of them, interleaved. Iterating an array
    is the cheapest way to make many views; it stops only when the caller
    does (the views run past the last step).
    """
    early = width - 1

    def views(start: int, number: int, stride: int) -> np.ndarray:
        return np.ndarray(
            (number, size),
            buffer=array,
            offset=(start + offset) * 8,
            strides=(stride * 8, 8),
        )

    number = -(-(steps - early) // skew) + 1
    phases = [views((early + r) * length + (r > 0), number, skew * length + 1) for r in range(skew)]
    return chain(views(0, early, length), chain.from_iterable(zip(*phases, strict=True)))


def _copy(target: np.ndarray, source: np.ndarray, skew: int, rows: int = 16) -> None:
    """``target[...] = source``, one of them the band's pixels in the buffer (cells L apart).

    Along a row, the buffer's pixels lie L cells apart, so a plain copy
    touches a cache line per pixel; along a wavefront they are contiguous.
    So bands of ``rows`` rows are copied as pieces of wavefronts, ``rows``
    long (one strided view over all bands), then the corners the pieces miss.
    Half the time of a plain copy.
    """
    height, width = source.shape
    margin = skew * (rows - 1)
    bands = height // rows if width > margin else 0
    if bands:

        def pieces(array: np.ndarray) -> np.ndarray:
            # Piece (band, i) holds pixels (margin + i - s j, band * rows + j), j < rows.
            down, across = array.strides
            shape = (bands, width - margin, rows)
            return as_strided(array[:, margin:], shape, (rows * down, across, down - skew * across))

        pieces(target)[...] = pieces(source)
        done = bands * rows
        target[:done, :margin] = source[:done, :margin]
        target[:done, width - margin :] = source[:done, width - margin :]
    target[bands * rows :] = source[bands * rows :]


# The forms, by method, for every caller of the kernel (see course.halftone._diffusion).
FORMS.update(
    loop=_error_diffusion_loop, rows=_error_diffusion_rows, wavefront=_error_diffusion_wavefront
)


def error_diffusion_wraparound(gray: Any) -> np.ndarray:
    """PITFALL: Floyd-Steinberg with the left-edge check missing, as numpy runs it.

    The lab report notes that ``x - 1 >= 0`` with an unsigned ``x`` is always
    true, so the 3/16 push below-left is never skipped. In numpy the same
    slip is quieter: ``buffer[y + 1, x - 1]`` at ``x = 0`` is
    ``buffer[y + 1, -1]``, the last pixel of the next row. No error is
    raised; the left column's errors land on the right edge. Compare with
    ``error_diffusion(gray, method="loop")``, which checks both bounds.

    Examples
    --------
    >>> gray = np.full((4, 4), 0.4)
    >>> error_diffusion_wraparound(gray) - error_diffusion(gray)
    array([[ 0.,  0.,  0.,  0.],
           [ 0.,  0.,  0.,  0.],
           [ 0.,  0.,  0.,  1.],
           [ 0.,  0.,  0., -1.]])
    """
    array = as_gray(gray, "gray")
    height, width = array.shape
    buffer = array.copy()
    output = np.zeros_like(array)
    for y in range(height):
        for x in range(width):
            old = buffer[y, x]
            new = 1.0 if old > 0.5 else 0.0
            output[y, x] = new
            error = old - new
            if x + 1 < width:
                buffer[y, x + 1] += error * (7 / 16)
            if y + 1 < height:
                buffer[y + 1, x - 1] += error * (3 / 16)  # the slip: no x - 1 >= 0
                buffer[y + 1, x] += error * (5 / 16)
                if x + 1 < width:
                    buffer[y + 1, x + 1] += error * (1 / 16)
    return output
