"""The exact area of a pixel inside a straight band: the stroke of a long line.

Away from its ends and joins, the stroke of a straight segment is a band
between two parallel lines, and the area of a unit pixel inside it has a
closed form (:func:`slab_coverage`). It is the building block of
:func:`course.antialias.stroke_area` before joins were exact, and what the
tests measure the reference's supersampling error against.

Unchecked kernels: like dhermes/bezier's ``hazmat``, this module trusts its
caller and checks no input (``UNCHECKED = True``, which the fuzz test reads).
Its public callers (:mod:`course.antialias`, :mod:`course.antialias.coverage`) validate
once, at their boundary.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["band_coverage", "slab_coverage"]

UNCHECKED = True  # kernels for checked callers; see the module docstring


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
