"""Rasterization: from geometry to pixel coordinates, and the one function that paints.

Lines (:mod:`~course.raster.lines`), filled triangles (:mod:`~course.raster.triangles`) and
canvases (:mod:`~course.raster.canvas`). Rasterizers return pixels; only
:func:`course.raster.canvas.paint` writes them.

The public names of :mod:`~course.raster.lines` are importable from here too.
"""

from course.raster import lines
from course.raster.lines import *  # noqa: F403 (the names lines.__all__ lists)

__all__ = list(lines.__all__)
