"""Poisson image editing: seamless cloning and inpainting.

The edit (:mod:`~course.poisson.editing`) sets up its Poisson problem
(:mod:`~course.poisson.problem`) and solves it iteratively (:mod:`~course.poisson.solvers`) or
exactly (:mod:`~course.poisson.capacitance`, on :mod:`~course.poisson.sine_transform`).
``_threads`` bounds the solvers' BLAS and FFT threads.

The public names of :mod:`~course.poisson.editing` are importable from here too.
"""

from course.poisson import editing
from course.poisson.editing import *  # noqa: F403 (the names editing.__all__ lists)

__all__ = list(editing.__all__)
