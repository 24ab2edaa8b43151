"""A validated path in the forms the renderers draw: a matplotlib Path, or one polyline.

Each function here takes a :class:`course.curves.paths.Curves` (from
:func:`course.curves.paths.as_path`), whose curves are already checked.
:func:`matplotlib_path` writes them as a ``matplotlib.path.Path`` for Agg
(:mod:`course.antialias.agg`). Flattened, a path is one polyline and a boolean
per segment, True where the segment is a *gap*: the pen moving between
subpaths, not part of the path. :func:`flatten_uniform` flattens every curve
in Wang's count of uniform t steps (:mod:`course.antialias.rendering`);
:func:`flatten_each` flattens each curve with a given function
(:mod:`course.antialias.coverage`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from matplotlib.path import Path

from course import limits
from course._validate import as_finite_array, as_positive_float, describe
from course.curves._uniform import assemble, uniform_polyline, wang_segment_counts
from course.curves.paths import Curves
from course.i18n import _

__all__ = ["flatten_each", "flatten_uniform", "matplotlib_path", "wang_counts"]

# The matplotlib code that draws a curve of each size (2, 3 or 4 control points).
_SIZE_CODES = np.zeros(5, dtype=np.uint8)
_SIZE_CODES[[2, 3, 4]] = [Path.LINETO, Path.CURVE3, Path.CURVE4]


def matplotlib_path(curves: Curves) -> Path:
    """A ``matplotlib.path.Path`` drawing the curves (degree 1 to 3) as Agg needs them.

    A curve that does not start where the one before ends starts with
    MOVETO; a subpath that ends at its first point is closed with CLOSEPOLY,
    so Agg joins it there instead of capping it twice.

    Examples
    --------
    >>> from course.curves.paths import as_path
    >>> path = matplotlib_path(as_path([[[0, 0], [2, 0]], [[2, 0], [1, 2], [0, 0]]]))
    >>> path.codes.tolist()
    [1, 2, 3, 3, 79]
    """
    sizes = _as_curves(curves).sizes
    drawable = (sizes >= 2) & (sizes <= 4)
    if not drawable.all():
        bad = int(np.flatnonzero(~drawable)[0])
        raise ValueError(
            _(
                "points: Agg draws Bézier curves of degree 1 to 3 (2 to 4 control points); curve "
                "{bad} has {sizes} points"
            ).format(bad=bad, sizes=sizes[bad])
        )
    joined = curves.joined()
    first = np.zeros(len(curves.points), dtype=bool)
    first[curves.starts] = True
    keep = ~(first & np.repeat(joined, sizes))
    codes = np.repeat(_SIZE_CODES[sizes], sizes)
    codes[first] = Path.MOVETO
    vertices, codes = curves.points[keep], codes[keep]
    # Close each subpath that returns to its first point.
    begin = np.flatnonzero(codes == Path.MOVETO)
    end = np.r_[begin[1:], len(codes)] - 1
    closed = (end > begin) & np.all(vertices[begin] == vertices[end], axis=1)
    closes = np.flatnonzero(closed)
    vertices = np.insert(vertices, end[closes] + 1, vertices[begin[closes]], axis=0)
    codes = np.insert(codes, end[closes] + 1, Path.CLOSEPOLY)
    return Path(vertices, codes)


def wang_counts(control: np.ndarray, tolerance: float) -> np.ndarray:
    """Wang's segment count for each curve of a stack ``(M, N, 2)`` of equal degree.

    Uniform t steps of ``1 / count`` keep every chord within ``tolerance``:
    on an interval of width h the chord strays at most ``h^2 / 8 max |B''|``
    and ``|B''| <= n (n - 1) max_i |P[i] - 2 P[i+1] + P[i+2]|``.
    """
    control = as_finite_array(control, "control", shape=_require_curve_stack)
    tolerance = as_positive_float(tolerance, "tolerance")
    return wang_segment_counts(control, tolerance)


def _require_curve_stack(control: np.ndarray) -> None:
    if control.ndim != 3 or control.shape[1] == 0 or control.shape[2] != 2:
        raise ValueError(
            _("control must be a stack (M, N, 2) of curves; got shape {control_shape}").format(
                control_shape=control.shape
            )
        )


def flatten_uniform(curves: Curves, tolerance: float) -> tuple[np.ndarray, np.ndarray]:
    """Every curve in Wang's count of uniform t steps: one polyline and its gaps.

    Curves of one degree are evaluated together (Bernstein form up to cubics,
    de Casteljau beyond), so a glyph's hundreds of curves cost a few array
    operations, not a Python call each.
    """
    curves = _as_curves(curves)
    tolerance = as_positive_float(tolerance, "tolerance")
    return uniform_polyline(curves, tolerance)


def flatten_each(
    curves: Curves, flatten_one: Callable[[np.ndarray], np.ndarray]
) -> tuple[np.ndarray, np.ndarray]:
    """Every curve flattened by ``flatten_one(control) -> (K, 2) vertices``: polyline, gaps."""
    curves = _as_curves(curves)
    if not callable(flatten_one):
        raise TypeError(
            _("flatten_one must be a function of the control points; got {flatten_one}").format(
                flatten_one=describe(flatten_one)
            )
        )
    parts = [_vertices_of(flatten_one(control), control) for control in curves.split()]
    counts = np.array([len(part) for part in parts], dtype=np.int64)
    order = np.arange(len(parts))
    stacked = np.concatenate(parts) if parts else np.zeros((0, 2))
    return assemble(curves, counts, {0: (order, stacked)})


def _vertices_of(part: Any, control: np.ndarray) -> np.ndarray:
    """What ``flatten_one`` returned, checked: finite (K, 2) vertices, K >= 1."""
    try:
        array = np.asarray(part, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(
            _(
                "flatten_one must return (K, 2) vertices; for control {control} it returned {part}"
            ).format(control=control.tolist(), part=describe(part))
        ) from None
    if array.ndim != 2 or array.shape[1] != 2 or len(array) == 0:
        raise ValueError(
            _(
                "flatten_one must return (K, 2) vertices, K >= 1; for control {control} it "
                "returned shape {array_shape}"
            ).format(control=control.tolist(), array_shape=array.shape)
        )
    bad = ~np.isfinite(array)
    if bad.any() or np.abs(array).max() > limits.MAX_COORDINATE:
        worst = array[bad][0] if bad.any() else array.flat[int(np.abs(array).argmax())]
        raise ValueError(
            _(
                "flatten_one must return finite vertices within +-{most:g}; for control {control} "
                "it returned a vertex coordinate {worst:g}"
            ).format(most=limits.MAX_COORDINATE, control=control.tolist(), worst=worst)
        )
    return array


def _as_curves(curves: Any) -> Curves:
    if not isinstance(curves, Curves):
        raise TypeError(
            _("curves must be Curves, e.g. from as_path(points); got {curves}").format(
                curves=describe(curves)
            )
        )
    return curves
