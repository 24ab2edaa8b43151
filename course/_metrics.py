"""The measures behind :mod:`course.metrics`: pure array code on validated input.

Nothing here checks its input (``UNCHECKED = True``): both arrays are images of
the same shape, float values in [0, 1], as :func:`course.metrics.rmse` makes sure
before it calls :func:`rms_difference`. A caller that checked its images once
(:func:`course.antialias.curve_quality.quality_table`) measures them here.
"""

from __future__ import annotations

import numpy as np

__all__ = ["max_difference", "rms_difference"]

UNCHECKED = True  # kernels for checked callers; see the module docstring


def rms_difference(first: np.ndarray, second: np.ndarray) -> float:
    """Root-mean-square difference over every pixel (and channel)."""
    return float(np.sqrt(np.mean((first - second) ** 2)))


def max_difference(first: np.ndarray, second: np.ndarray) -> float:
    """Largest absolute difference at any pixel (and channel)."""
    return float(np.abs(first - second).max())
