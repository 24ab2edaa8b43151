"""Sampling: aliasing in one dimension, bilinear lookups and supersampling.

Why detail finer than the samples comes back as false detail
(:mod:`~course.sampling.aliasing`), and resampling an image
(:mod:`~course.sampling.resample`).

The public names of :mod:`~course.sampling.aliasing` and :mod:`~course.sampling.resample` are
importable from here too.
"""

from course.sampling import aliasing, resample
from course.sampling.aliasing import *  # noqa: F403 (the names aliasing.__all__ lists)
from course.sampling.resample import *  # noqa: F403 (the names resample.__all__ lists)

__all__ = [*aliasing.__all__, *resample.__all__]
