"""Anti-aliasing a curve: the handouts' splats, stroke coverage, one render.

One render (:mod:`~course.antialias.rendering`) over the splats (:mod:`~course.antialias.splats`),
the exact stroke (:mod:`~course.antialias.stroke`, with its private kernels ``_segments``,
``_overlaps``, ``_integrate`` and ``_fill``), straight bands (:mod:`~course.antialias.slab`),
the exact reference (:mod:`~course.antialias.coverage`), matplotlib's Agg as the production
anchor (:mod:`~course.antialias.agg`), how good each result is
(:mod:`~course.antialias.curve_quality`) and a zoom window of any of them, drawn alone
(:mod:`~course.antialias.windows`).

The public names of :mod:`~course.antialias.rendering` are importable from here too.
"""

from course.antialias import rendering
from course.antialias.rendering import *  # noqa: F403 (the names rendering.__all__ lists)

__all__ = list(rendering.__all__)
