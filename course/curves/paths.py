"""Whole paths: Bézier curves drawn one after another as one stroke.

A *path* is a sequence of curves in image space, each an (N_i, 2) array of
control points. Where a curve starts at the end point of the one before, the
two are *joined*; elsewhere the pen is lifted and a new *subpath* begins. A
path comes as one curve (an (N, 2) array), a list of curves, or a
``matplotlib.path.Path`` with its codes (MOVETO, LINETO, CURVE3, CURVE4,
CLOSEPOLY, STOP), e.g. a glyph outline from ``matplotlib.textpath.TextPath``.

The stroke of a path with round joins and caps is the set of points within
w / 2 of any of its curves, so how the curves are grouped into subpaths never
changes it; the grouping matters to Agg's rendering and to the outline that
:mod:`course.antialias.stroke` draws. :mod:`course.curves.drawable_paths`
writes a path as Agg's ``matplotlib.path.Path`` or flattens it to one polyline.

:func:`text_curves` gives a line of text as such a list of curves, in image
space, ready for :func:`course.antialias.render`; :func:`path_curves` does
the same for any ``matplotlib.path.Path``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from matplotlib.font_manager import FontProperties
from matplotlib.path import Path
from matplotlib.textpath import TextPath

from course import limits
from course._validate import (
    as_curve,
    as_path_arrays,
    as_point,
    as_positive_float,
    describe,
    require_finite,
    require_within,
)
from course.curves._frozen import made
from course.i18n import _

__all__ = [
    "FONT",
    "Curves",
    "as_path",
    "canvas_for",
    "curves_of_path",
    "path_curves",
    "text_curves",
]

#: matplotlib's bundled TrueType font: every installation has it.
FONT = "DejaVu Sans"

# Control points of the curve each code starts (a close is a line).
_CODE_SIZES = np.zeros(256, dtype=np.int64)
_CODE_SIZES[[Path.LINETO, Path.CURVE3, Path.CURVE4, Path.CLOSEPOLY]] = [2, 3, 4, 2]


@dataclass(frozen=True)
class Curves:
    """The validated curves of a path: all control points, curve after curve.

    Attributes
    ----------
    points : float ndarray (P, 2)
        Control points of the first curve, then of the second, ...
    sizes : int ndarray (M,)
        How many control points each curve has (>= 1; 1 is a single point).
    """

    points: np.ndarray
    sizes: np.ndarray

    def __post_init__(self) -> None:
        """Check both fields once: every function that takes Curves trusts them.

        Examples
        --------
        >>> Curves(np.array([[0.0, 0.0], [np.nan, 1.0]]), np.array([2]))
        Traceback (most recent call last):
        ...
        ValueError: points must be finite; got nan at index (1, 0)
        """
        points, sizes = self.points, self.sizes
        if not isinstance(points, np.ndarray) or points.dtype.kind not in "iuf":
            raise TypeError(
                _("points must be a numpy array of real numbers; got {points}").format(
                    points=describe(points)
                )
            )
        if points.ndim != 2 or points.shape[1] != 2:
            raise ValueError(
                _("points must have shape (P, 2); got {points_shape}").format(
                    points_shape=points.shape
                )
            )
        require_finite(points, "points")
        require_within(points, "points", limits.MAX_COORDINATE)
        if not isinstance(sizes, np.ndarray) or sizes.dtype.kind not in "iu" or sizes.ndim != 1:
            raise TypeError(
                _("sizes must be a 1-D integer numpy array; got {sizes}").format(
                    sizes=describe(sizes)
                )
            )
        if sizes.size and sizes.min() < 1:
            raise ValueError(
                _("sizes must be >= 1 (control points per curve); got {smallest}").format(
                    smallest=sizes.min()
                )
            )
        if int(sizes.sum()) != len(points):
            raise ValueError(
                _("sizes must add up to the {points_count} points; they add up to {total}").format(
                    points_count=len(points), total=int(sizes.sum())
                )
            )

    @property
    def starts(self) -> np.ndarray:
        """Index in ``points`` of each curve's first control point."""
        return np.cumsum(self.sizes) - self.sizes

    @property
    def ends(self) -> np.ndarray:
        """Index in ``points`` of each curve's last control point."""
        return np.cumsum(self.sizes) - 1

    def joined(self) -> np.ndarray:
        """True for each curve that starts where the one before it ends (False first)."""
        starts, ends = self.starts, self.ends
        after, before = self.points.take(starts[1:], 0), self.points.take(ends[:-1], 0)
        same = (after[:, 0] == before[:, 0]) & (after[:, 1] == before[:, 1])
        return np.concatenate([[False], same])

    def split(self) -> list[np.ndarray]:
        """The curves as a list of new (N_i, 2) arrays."""
        return [part.copy() for part in np.split(self.points, np.cumsum(self.sizes)[:-1])]

    def moved(self, offset: Any) -> Curves:
        """The same curves translated by ``-offset`` (a point's new coordinates).

        Examples
        --------
        >>> as_path([[1.0, 2.0], [3.0, 4.0]]).moved((1, 2)).points.tolist()
        [[0.0, 0.0], [2.0, 2.0]]
        """
        shift = as_point(offset, "offset", dim=2, bound=limits.MAX_COORDINATE)
        points = self.points - shift
        if points.size and np.abs(points).max() > limits.MAX_COORDINATE:
            raise ValueError(
                _("offset {shift} moves the points beyond +-{most:g}").format(
                    shift=shift.tolist(), most=limits.MAX_COORDINATE
                )
            )
        return _trusted(points, self.sizes)


def _bounded(points: np.ndarray, sizes: np.ndarray) -> Curves:
    """:func:`_trusted` for finite points whose coordinates are not bounded yet."""
    require_within(points, "points", limits.MAX_COORDINATE)
    return _trusted(points, sizes)


def _trusted(points: np.ndarray, sizes: np.ndarray) -> Curves:
    """Curves of fields their maker built from checked input, without checking them again.

    ``points`` finite floats (P, 2) within ``limits.MAX_COORDINATE``, ``sizes`` integers
    >= 1 that add up to P: what :meth:`Curves.__post_init__` checks.
    """
    return made(Curves, points=points, sizes=sizes)


def as_path(points: Any, name: str = "points") -> Curves:
    """Validate one curve, a list of curves or a matplotlib Path; a new :class:`Curves`.

    A 2-D array-like is one curve, validated as before (shape (N, 2),
    finite). A list whose items are 2-D (or a 3-D array) is a list of
    curves; a bad one is named by its index, ``points[3]``. A
    ``matplotlib.path.Path`` is read by :func:`curves_of_path`, its vertices
    taken as image coordinates.

    Examples
    --------
    >>> path = as_path([[[0, 0], [4, 0]], [[4, 0], [4, 3], [8, 3]]])
    >>> path.sizes.tolist(), path.joined().tolist()
    ([2, 3], [False, True])
    """
    if isinstance(points, Path):
        return curves_of_path(points, name=name)
    if _is_curve_list(points):
        return _curve_list(points, name)
    control = as_curve(points, name)
    return _trusted(control, np.array([len(control)]))


def _is_curve_list(points: Any) -> bool:
    if isinstance(points, np.ndarray):
        return points.ndim == 3
    if isinstance(points, (list, tuple)) and len(points) > 0:
        first = points[0]
        return (isinstance(first, np.ndarray) and first.ndim == 2) or _nested_twice(first)
    return False


def _nested_twice(value: Any) -> bool:
    """A list of lists, as a curve's control points are written by hand."""
    return (
        isinstance(value, (list, tuple))
        and len(value) > 0
        and isinstance(value[0], (list, tuple, np.ndarray))
    )


def _curve_list(curves: Any, name: str) -> Curves:
    if len(curves) == 0:
        raise ValueError(
            _("{name} must hold at least one curve; got {curves}").format(
                name=name, curves=describe(curves)
            )
        )
    joined = _joined_arrays(curves)
    if joined is None:
        arrays = []
        for index, curve in enumerate(curves):
            array = curve if isinstance(curve, np.ndarray) else None
            if (
                array is None
                or array.ndim != 2
                or array.shape[1] != 2
                or len(array) == 0
                or array.dtype.kind not in "iuf"
            ):
                array = as_curve(curve, f"{name}[{index}]")  # the one message for a bad curve
            arrays.append(array)
        joined = np.concatenate(arrays), np.fromiter(map(len, arrays), np.int64, len(arrays))
    points, sizes = joined[0].astype(float), joined[1]
    if not np.isfinite(points).all():  # the whole array at once; rows only to name the curve
        bad = ~np.isfinite(points).all(axis=1)
        curve = int(np.searchsorted(np.cumsum(sizes), np.flatnonzero(bad)[0], side="right"))
        as_curve(curves[curve], f"{name}[{curve}]")  # raises, naming the entry
    return _bounded(points, sizes)


def _joined_arrays(curves: Any) -> tuple[np.ndarray, np.ndarray] | None:
    """All the curves' points and sizes, if every curve is a non-empty real (N, 2) array.

    One sweep over the curves, for a path of many (a line of text); None for
    anything else, which :func:`_curve_list` checks curve by curve.
    """
    try:
        kinds = {curve.dtype.kind for curve in curves}
        points = np.concatenate(curves)
    except (AttributeError, TypeError, ValueError):  # not arrays, or of unequal dimensions
        return None
    sizes = np.fromiter(map(len, curves), np.int64, len(curves))
    if not kinds <= set("iuf") or points.ndim != 2 or points.shape[1] != 2 or sizes.min() == 0:
        return None
    return points, sizes


def curves_of_path(path: Path, height: float | None = None, name: str = "points") -> Curves:
    """The Bézier curves of a ``matplotlib.path.Path``, read from its codes.

    MOVETO starts a subpath; LINETO, CURVE3 and CURVE4 add a line, a
    quadratic and a cubic from the current point; CLOSEPOLY adds the line
    back to the subpath's first point (none if it is there already); STOP
    ends the path. A path without codes is one polyline. With ``height``,
    y becomes ``height - y``: matplotlib's y axis points up, image rows down.

    Examples
    --------
    >>> square = Path([[0, 0], [2, 0], [2, 2], [0, 0]], [1, 2, 2, 79])
    >>> [curve.tolist() for curve in curves_of_path(square).split()]
    [[[0.0, 0.0], [2.0, 0.0]], [[2.0, 0.0], [2.0, 2.0]], [[2.0, 2.0], [0.0, 0.0]]]
    """
    if not isinstance(path, Path):
        raise TypeError(
            _("{name} must be a matplotlib.path.Path; got {path}").format(
                name=name, path=describe(path)
            )
        )
    if height is not None:
        height = as_positive_float(height, "height", allow_zero=True)
    return _curves_of_path(path, height, name)


def _curves_of_path(path: Path, height: float | None, name: str) -> Curves:
    """:func:`curves_of_path` of a ``Path`` and a checked ``height``: checks its arrays."""
    vertices, codes = as_path_arrays(path, name, height)  # every vertex gathered below: checked
    if len(codes) == 0:
        return _trusted(np.zeros((0, 2)), np.zeros(0, dtype=np.int64))
    index = np.arange(len(codes))
    change = np.concatenate([[True], codes[1:] != codes[:-1]])
    run = np.cumsum(change) - 1
    position = index - np.flatnonzero(change)[run]
    subpath_start = np.maximum.accumulate(np.where(codes == Path.MOVETO, index, 0))
    command = (
        (codes == Path.LINETO)
        | (codes == Path.CLOSEPOLY)
        | ((codes == Path.CURVE3) & (position % 2 == 0))
        | ((codes == Path.CURVE4) & (position % 3 == 0))
    )
    at = np.flatnonzero(command)
    before = at - 1  # codes[0] is MOVETO, so every command has a vertex before it
    # After CLOSEPOLY the pen is back at the subpath's first point.
    current = np.where(codes[before] == Path.CLOSEPOLY, subpath_start[before], before)
    closing = codes[at] == Path.CLOSEPOLY
    ends_at = np.where(closing, subpath_start[at], at)
    keep = ~closing | np.any(vertices[current] != vertices[ends_at], axis=1)
    at, current, closing = at[keep], current[keep], closing[keep]
    sizes = _CODE_SIZES[codes[at]]
    # Gather: the current point, then the command's own vertices (the start point for a close).
    offsets = np.arange(sizes.sum()) - np.repeat(np.cumsum(sizes) - sizes, sizes)
    command_of = np.repeat(np.arange(len(at)), sizes)
    gather = np.where(offsets == 0, current[command_of], at[command_of] + offsets - 1)
    closing_end = closing[command_of] & (offsets == 1)
    gather = np.where(closing_end, subpath_start[at][command_of], gather)
    return _trusted(vertices[gather], sizes)


# --- paths for the lessons ----------------------------------------------------------


def path_curves(path: Any, height: float) -> list[np.ndarray]:
    """The curves of a ``matplotlib.path.Path`` in image space: y down, ``height`` tall.

    matplotlib's y axis points up; an image's rows go down. A vertex (x, y)
    becomes (x, height - y). The result is a list of new (N_i, 2) control
    point arrays (2 for a line, 3 for a quadratic, 4 for a cubic) that
    :func:`course.antialias.render` and :func:`course.antialias.coverage.reference`
    accept as a path.

    Examples
    --------
    >>> triangle = Path([[0, 0], [4, 0], [0, 3], [0, 0]], closed=True)
    >>> [curve.tolist() for curve in path_curves(triangle, height=5)]
    [[[0.0, 5.0], [4.0, 5.0]], [[4.0, 5.0], [0.0, 2.0]], [[0.0, 2.0], [0.0, 5.0]]]
    """
    if not isinstance(path, Path):
        raise TypeError(
            _("path must be a matplotlib.path.Path; got {path}").format(path=describe(path))
        )
    height = as_positive_float(height, "height", allow_zero=True)
    return _curves_of_path(path, height, "path").split()


def text_curves(
    text: str, size: float = 30.0, margin: float = 2.0, family: str = FONT
) -> list[np.ndarray]:
    """A line of text as image-space curves: its glyph outlines from ``TextPath``.

    The outlines of ``text`` set in ``family`` at ``size`` pixels to the em
    (``matplotlib.textpath.TextPath``, quadratic curves for TrueType fonts),
    flipped to y down and moved so that every control point lies at least
    ``margin`` px from the top and left edges. :func:`canvas_for` gives a
    canvas that holds them.

    Examples
    --------
    >>> curves = text_curves("Bézier", size=30)
    >>> len(curves), canvas_for(curves)
    (101, (29, 95))
    >>> from course.antialias import render
    >>> round(float(render(curves, canvas_for(curves), "stroke_area").max()), 3)
    1.0
    """
    if not isinstance(text, str) or not text.strip():
        raise ValueError(
            _("text must be a non-empty string with some ink; got {text}").format(
                text=describe(text)
            )
        )
    if len(text) > limits.MAX_TEXT_LENGTH:
        raise ValueError(
            _("text must be at most {most} characters; got {text_count}").format(
                most=limits.MAX_TEXT_LENGTH, text_count=len(text)
            )
        )
    size = as_positive_float(size, "size")
    margin = as_positive_float(margin, "margin", allow_zero=True)
    if not isinstance(family, str):
        raise TypeError(
            _("family must be a font family name (str); got {family}").format(
                family=describe(family)
            )
        )
    outline = TextPath((0.0, 0.0), text, size=size, prop=FontProperties(family=family))
    curves = _curves_of_path(outline, 0.0, "text")
    if len(curves.sizes) == 0:
        raise ValueError(
            _("text must hold some ink; {text} has no outline").format(text=repr(text))
        )
    low = curves.points.min(axis=0)
    return curves.moved(low - margin).split()


def canvas_for(curves: Any, margin: float = 2.0) -> tuple[int, int]:
    """The canvas (H, W) from (0, 0) that holds every control point, plus ``margin``.

    Examples
    --------
    >>> canvas_for([[[2.0, 2.0], [10.5, 4.0]]])
    (6, 13)
    """
    path = as_path(curves, "curves")
    margin = as_positive_float(margin, "margin", allow_zero=True)
    high = np.ceil(path.points.max(axis=0) + margin).astype(int)
    return max(int(high[1]), 1), max(int(high[0]), 1)
