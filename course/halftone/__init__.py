"""Halftoning: gray shown with black and white pixels only.

Thresholds, ordered and blue-noise masks (:mod:`~course.halftone.dither`), error diffusion
(:mod:`~course.halftone.diffusion`) and Ulichney's void-and-cluster mask
(:mod:`~course.halftone.blue_noise_masks`).

The public names of :mod:`~course.halftone.dither` are importable from here too.
"""

from course.halftone import dither
from course.halftone.dither import *  # noqa: F403 (the names dither.__all__ lists)

__all__ = list(dither.__all__)
