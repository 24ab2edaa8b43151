"""The zoomed pixel grid lesson 03's apps draw on, in image space (y down).

:func:`pixel_grid` sets up one axes as a size x size grid of pixels and returns
its grid lines; :mod:`.apps` (the line and triangle apps) and
:mod:`.curve_segments` (the lab's Task 7) draw their pixels under it.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection

from course._validate import as_int, describe
from course.i18n import _

__all__ = ["pixel_grid"]


def pixel_grid(axes: Axes, size: int, title: str = "") -> LineCollection:
    """Set up axes as a zoomed size x size pixel grid in image space (y down).

    Returns the grid lines, to be drawn over the pixels: a moving picture
    redraws them after its image, as they are not part of its background.
    """
    if not isinstance(axes, Axes):
        raise TypeError(_("axes must be matplotlib Axes; got {axes}").format(axes=describe(axes)))
    size = as_int(size, "size", minimum=1, maximum=1000)
    axes.set_xlim(0, size)
    axes.set_ylim(size, 0)
    axes.set_aspect("equal")
    axes.set_xticks(np.arange(0, size + 1, 4))
    axes.set_yticks(np.arange(0, size + 1, 4))
    axes.tick_params(which="both", labelsize=7, length=0)
    axes.set_title(title, fontsize=9)
    lines = [[(k, 0), (k, size)] for k in range(size + 1)]
    lines += [[(0, k), (size, k)] for k in range(size + 1)]
    grid = LineCollection(lines, colors="0.85", linewidths=0.5)
    axes.add_collection(grid)
    return grid
