"""Pixels of checked points and Bresenham's closed form of checked ends.

Kernels behind :func:`course.raster.lines.nearest_pixels` (:func:`pixels_of`) and
:func:`course.raster.lines.line`'s default form (:func:`bresenham_closed_form`), which check
their arguments before they call these; the handouts' drawing code
(:mod:`course.curves.bezier_handouts`, :mod:`course.curves.handout_loops`) turns its checked
curves into pixels with them. :func:`require_image_space` is
:func:`~course.raster.lines.nearest_pixels`' check of the shape of points already read
(finite, within the coordinates' bound), for the callers that compute such points
themselves.

Unchecked kernels: this module trusts its callers and checks no input
(``UNCHECKED = True``, which the fuzz test reads).
"""

from __future__ import annotations

import numpy as np

from course.i18n import _

__all__ = ["bresenham_closed_form", "pixels_of", "require_image_space"]

UNCHECKED = True  # kernels for checked callers; see the module docstring


def pixels_of(samples: np.ndarray, rounding: str) -> np.ndarray:
    """The (K, 2) int64 pixel of each point of ``samples`` (K, 2), finite and within
    ``limits.MAX_COORDINATE``, by ``rounding``, one of ``"floor"``, ``"round"``, ``"trunc"``.

    Examples
    --------
    >>> pixels_of(np.array([[0.4, 0.6], [-0.5, 1.0]]), "floor").tolist()
    [[0, 0], [-1, 1]]
    """
    if rounding == "floor":
        pixels = np.floor(samples)
    elif rounding == "round":
        # cvRound rounds halves to even, like numpy.
        pixels = np.rint(samples)
    else:
        pixels = np.trunc(samples)
    return pixels.astype(np.int64)


def require_image_space(samples: np.ndarray) -> None:
    """ValueError unless the points ``samples`` (K, d), read and checked, are (x, y) points:
    d = 2."""
    if samples.shape[1] != 2:
        raise ValueError(
            _("points must have shape (K, 2) for image space; got {samples_shape}").format(
                samples_shape=samples.shape
            )
        )


def bresenham_closed_form(x0: int, y0: int, x1: int, y1: int) -> np.ndarray:
    """The (K, 2) pixels of Bresenham's line from integer pixel (x0, y0) to (x1, y1), each
    coordinate within ``limits.MAX_COORDINATE``: step i moves the minor axis by
    round(i * a / n).

    Examples
    --------
    >>> bresenham_closed_form(0, 0, 3, 1).tolist()
    [[0, 0], [1, 0], [2, 1], [3, 1]]
    """
    dx, dy = x1 - x0, y1 - y0
    if abs(dx) >= abs(dy):
        n, a, major0, major1, minor0, minor_step, major_column = abs(dx), abs(dy), x0, x1, y0, dy, 0
    else:
        n, a, major0, major1, minor0, minor_step, major_column = abs(dy), abs(dx), y0, y1, x0, dx, 1
    if n == 0:
        return np.array([[x0, y0]], dtype=np.int64)
    step = 1 if major1 >= major0 else -1
    pixels = np.empty((n + 1, 2), dtype=np.int64)
    pixels[:, major_column] = np.arange(major0, major1 + step, step)
    if a == 0:
        pixels[:, 1 - major_column] = minor0
        return pixels
    # Step i is i * a / n along the minor axis, rounded to nearest with halves
    # toward p0 (the loop's choice, as the tests check): minor0 plus
    # floor((2 i a + n - 1) / (2 n)) going up, minor0 minus it going down.
    # Both are one floor division of an arithmetic sequence, with minor0
    # folded into its start.
    twice_n = 2 * n
    if minor_step > 0:
        start, stride = twice_n * minor0 + n - 1, 2 * a
    else:
        start, stride = twice_n * minor0 + n, -2 * a
    minor = np.arange(start, start + (n + 1) * stride, stride, dtype=np.int64)
    minor //= twice_n
    pixels[:, 1 - major_column] = minor
    return pixels
