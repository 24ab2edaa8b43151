"""Filtering with 3 x 3 kernels: box blur, Sobel edges, general convolution.

The lab's loops and their fast forms are in :mod:`~course.filters.convolution`.

The public names of :mod:`~course.filters.convolution` are importable from here too.
"""

from course.filters import convolution
from course.filters.convolution import *  # noqa: F403 (the names convolution.__all__ lists)

__all__ = list(convolution.__all__)
