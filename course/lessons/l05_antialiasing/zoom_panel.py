"""Zoomed pixel views of a rendered curve: where the window sits, one panel, a still grid.

:class:`CurveWalk` finds the point a fraction of the way along a curve (by
arc length), where a zoom window sits; :class:`ZoomPanel` shows one window
of an image as flat pixels, with the pixel grid and the true curve on top;
:func:`zoom_figure` lays out a still grid of such panels. :mod:`.apps`
builds its zoom and step apps from them.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from course import limits
from course._validate import (
    as_curve,
    as_float_array,
    as_image,
    as_int,
    as_point,
    as_positive_float,
    as_scalar_parameter,
    describe,
    require_finite,
)
from course.antialias.coverage import curve_polyline
from course.curves.drawable_paths import flatten_uniform
from course.curves.paths import as_path
from course.i18n import _
from course.raster.canvas import crop
from course.widgets.base import SliderApp
from course.widgets.picture import ZoomedPixels
from course.widgets.text_cache import SteadyText

__all__ = ["CurveWalk", "ZoomPanel", "zoom_figure"]


# Half the walk's 1e-3: the chords' lengths then sum to within 1e-3 pixel of the curve's.
QUICK_TOLERANCE = 5e-4


class CurveWalk:
    """Points of a curve by fraction of its arc length, for moving a window along it.

    Its polyline lies within 1e-3 pixel of the curve, in segments of at most
    a pixel: vertices on the curve, or with ``quick``, vertices at Wang's
    count of uniform t steps for 5e-4 pixel, on the curve, and the chords
    between them cut evenly (a tenth of the work, for a curve being
    dragged: Wang's bound needs no search; its length is within 1e-3 pixel
    of the other's).
    """

    def __init__(self, points: Any, quick: bool = False) -> None:
        control = as_curve(points)
        if quick:
            self.polyline = _chords_cut(flatten_uniform(as_path(control), QUICK_TOLERANCE)[0])
        else:
            self.polyline = curve_polyline(control, 1e-3)
        self.quick = quick
        pieces = np.hypot(*np.diff(self.polyline, axis=0).T)
        self.lengths = np.concatenate([[0.0], np.cumsum(pieces)])

    def at(self, fraction: float) -> np.ndarray:
        """The (x, y) point ``fraction`` of the way along the curve (clipped to 0 to 1).

        Examples
        --------
        >>> CurveWalk([[0, 0], [10, 0]]).at(0.25)
        array([2.5, 0. ])
        >>> CurveWalk([[0, 0], [10, 0]]).at(float("nan"))
        Traceback (most recent call last):
        ...
        ValueError: fraction must be finite; got nan
        """
        fraction = as_scalar_parameter(fraction, "fraction")
        s = min(max(fraction, 0.0), 1.0) * self.lengths[-1]
        return np.array(
            [np.interp(s, self.lengths, self.polyline[:, i]) for i in range(2)], dtype=float
        )


def _chords_cut(line: np.ndarray) -> np.ndarray:
    """``line`` with each segment cut into equal pieces of at most a pixel.

    Examples
    --------
    >>> _chords_cut(np.array([[0.0, 0.0], [2.5, 0.0], [2.5, 0.5]]))
    array([[0.        , 0.        ],
           [0.83333333, 0.        ],
           [1.66666667, 0.        ],
           [2.5       , 0.        ],
           [2.5       , 0.5       ]])
    """
    steps = np.diff(line, axis=0)
    pieces = np.maximum(1, np.ceil(np.hypot(*steps.T))).astype(np.int64)
    index = np.arange(pieces.sum()) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    fractions = index / np.repeat(pieces, pieces)
    cut = np.repeat(line[:-1], pieces, axis=0) + fractions[:, None] * np.repeat(
        steps, pieces, axis=0
    )
    return np.vstack([cut, line[-1:]])


class ZoomPanel:
    """One axes showing a zoomed crop: flat pixels, the pixel grid, the true curve.

    Built once; :meth:`show` changes the picture, the grid and the view. The
    title names the picture; the note, a line under it, carries what changes
    as the window moves (an app keeps the title in its still background).
    With ``app``, the pixels are written into the app's picture as they are,
    at a whole zoom (as :class:`course.widgets.picture.PixelPanel` does), not
    resampled by ``imshow``: the axes' width in picture pixels must then be
    a whole multiple of every window size shown. The axes' data are then the
    window's own pixels, from its top-left corner, where the app draws the
    curve: limits that change with the window's size alone, so a drag that
    moves the window keeps the recordings of the panel's lines.
    """

    def __init__(self, axes: Axes, curve: np.ndarray, app: SliderApp | None = None) -> None:
        if not isinstance(axes, Axes):
            raise TypeError(
                _("axes must be a matplotlib Axes; got {axes}").format(axes=describe(axes))
            )
        if app is not None and not isinstance(app, SliderApp):
            raise TypeError(
                _("app must be a SliderApp or None; got {app}").format(app=describe(app))
            )
        curve = as_curve(curve, "curve")  # the polyline drawn over the pixels
        self.axes = axes
        self.app = app
        self.picture = axes.imshow(
            np.zeros((2, 2)), cmap="gray", vmin=0.0, vmax=1.0, interpolation="nearest"
        )
        self.picture.set_visible(app is None)
        # In the axes' coordinates: a window of the same size has the same grid wherever
        # it is, so a drag does not change it (it is replayed, not laid out again).
        self.grid = LineCollection(
            [], colors="#3a6ea5", linewidths=0.5, alpha=0.6, transform=axes.transAxes
        )
        axes.add_collection(self.grid)
        self._grid_size: tuple[int, int] | None = None
        (self.curve,) = axes.plot(curve[:, 0], curve[:, 1], color="#e8502f", linewidth=1.0)
        self.title = axes.set_title("", fontsize=9, pad=16 if app else 6)
        # Its numbers change at every step of a drag: placed without measuring each one.
        self.note = axes.add_artist(
            SteadyText(
                0.5,
                1.015,
                "",
                transform=axes.transAxes,
                ha="center",
                va="bottom",
                fontsize=9,
                clip_on=False,
            )
        )
        axes.set_xticks([])
        axes.set_yticks([])

    def artists(self) -> list[Any]:
        """What changes as the window moves: for an app that redraws only those."""
        moving = [self.grid, self.curve, self.note]
        return moving if self.app else [self.picture, *moving]

    def show(self, image: np.ndarray, centre: Any, size: int, title: str) -> np.ndarray:
        """Show the ``size`` x ``size`` crop of ``image`` around ``centre``; return it."""
        window, extent = crop(image, centre, size)
        return self.show_window(window, extent, title)

    def show_window(
        self, window: np.ndarray, extent: Any, title: str, note: str = ""
    ) -> np.ndarray:
        """Show ``window``, a crop with extent ``(left, right, bottom, top)``; return it.

        The extent is in whole pixels and spans the window exactly: ``right - left``
        columns and ``bottom - top`` rows.
        """
        window = as_float_array(window, "window")
        if window.ndim != 2 or 0 in window.shape:
            raise ValueError(
                _("window must be a gray (H, W) crop; got shape {window_shape}").format(
                    window_shape=window.shape
                )
            )
        require_finite(window, "window")  # values past 1 are ink piled up, drawn as 1
        if not isinstance(extent, (tuple, list)) or len(extent) != 4:
            raise ValueError(
                _("extent must be (left, right, bottom, top) in pixels; got {extent}").format(
                    extent=describe(extent)
                )
            )
        bound = limits.MAX_COORDINATE
        x0, x1, y1, y0 = (as_int(v, f"extent[{i}]", maximum=bound) for i, v in enumerate(extent))
        if (x1 - x0, y1 - y0) != (window.shape[1], window.shape[0]):
            raise ValueError(
                _(
                    "extent must span the window's {window_columns} columns and {window_rows} "
                    "rows; got {width} x {height}"
                ).format(
                    window_columns=window.shape[1],
                    window_rows=window.shape[0],
                    width=x1 - x0,
                    height=y1 - y0,
                )
            )
        return self.show_checked(window, (x0, x1, y1, y0), title, note)

    def show_checked(
        self, window: np.ndarray, extent: tuple[int, int, int, int], title: str, note: str
    ) -> np.ndarray:
        """:meth:`show_window` of a window and an extent the calling app checked."""
        x0, x1, y1, y0 = extent
        size = (x1 - x0, y1 - y0)
        if self.app is None:
            self.picture.set_data(window)
            self.picture.set_extent(extent)
        else:
            zoom = round(self.axes.get_window_extent().width) // window.shape[1]
            gray = (np.clip(window, 0.0, 1.0) * 255).astype(np.uint8)  # as imshow maps gray
            self.app.pixel_images[self.axes] = ZoomedPixels(np.repeat(gray[..., None], 3, 2), zoom)
        if size != self._grid_size:
            self._grid_size = size
            columns = [[(i / size[0], 1.0), (i / size[0], 0.0)] for i in range(size[0] + 1)]
            rows = [[(0.0, 1 - j / size[1]), (1.0, 1 - j / size[1])] for j in range(size[1] + 1)]
            self.grid.set_segments(columns + rows)
        # Only new limits are set: they drop the drag's recordings of the axes' lines
        # (FigureView listens for them), and most steps keep them.
        x_limits, y_limits = (
            ((x0, x1), (y1, y0)) if self.app is None else ((0, size[0]), (size[1], 0))
        )
        if self.axes.get_xlim() != x_limits or self.axes.get_ylim() != y_limits:
            self.axes.set_xlim(*x_limits)
            self.axes.set_ylim(*y_limits)  # y down, as in the image
        self.title.set_text(title)
        self.note.set_text(note)
        return window


def zoom_figure(
    images: Mapping[str, np.ndarray],
    points: Any,
    centre: Any,
    size: int = 16,
    columns: int = 4,
    panel_inches: float = 2.4,
    figure: Figure | None = None,
) -> Figure:
    """A still grid of zoomed crops, one per named image, all around ``centre``.

    Drawn into ``figure`` if given (e.g. ``pyplot.figure()`` in a notebook,
    which then shows it), resized to fit; otherwise into a new Figure.

    Examples
    --------
    >>> figure = zoom_figure({"a": np.zeros((20, 20))}, [[0, 0], [20, 20]], (10, 10), 8)
    >>> len(figure.axes)
    1
    """
    if not isinstance(images, Mapping) or not images:
        raise TypeError(
            _("images must map names to images; got {images}").format(images=describe(images))
        )
    images = {str(name): as_image(image, f"images[{name!r}]") for name, image in images.items()}
    as_point(centre, "centre", dim=2, bound=limits.MAX_COORDINATE)
    size = as_int(size, "size", minimum=1, maximum=1000)
    columns = as_int(columns, "columns", minimum=1, maximum=100)
    panel_inches = as_positive_float(panel_inches, "panel_inches", smallest=0.1, largest=20.0)
    if figure is not None and not isinstance(figure, Figure):
        raise TypeError(
            _("figure must be a matplotlib Figure or None; got {figure}").format(
                figure=describe(figure)
            )
        )
    curve = CurveWalk(points).polyline
    rows = -(-len(images) // columns)
    inches = (panel_inches * columns, (panel_inches + 0.3) * rows)
    if figure is None:
        figure = Figure(figsize=inches, dpi=100)
    else:
        figure.set_size_inches(*inches)
    for index, (name, image) in enumerate(images.items()):
        panel = ZoomPanel(figure.add_subplot(rows, columns, index + 1), curve)
        panel.show(image, centre, size, name)
    figure.tight_layout()
    return figure
