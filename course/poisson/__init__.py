"""Poisson image editing: seamless cloning and inpainting.

The edit (:mod:`~course.poisson.editing`) sets up its Poisson problem
(:mod:`~course.poisson.problem`, from the inputs :mod:`~course.poisson.inputs` checks)
and solves it (:mod:`~course.poisson.methods`) iteratively (:mod:`~course.poisson.solvers`)
or exactly (:mod:`~course.poisson.capacitance`, on :mod:`~course.poisson.sine_transform`).
:mod:`~course.poisson.windows` cuts windows and changes the channel order, on the kernels of
``_layout``; ``_threads`` bounds the solvers' BLAS and FFT threads.

The public names of :mod:`~course.poisson.editing` and :mod:`~course.poisson.methods` are
importable from here too.
"""

from course.poisson import editing, methods
from course.poisson.editing import *  # noqa: F403 (the names editing.__all__ lists)
from course.poisson.methods import *  # noqa: F403 (the names methods.__all__ lists)

__all__ = [*editing.__all__, *methods.__all__]
