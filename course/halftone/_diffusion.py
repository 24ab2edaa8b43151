"""Error diffusion on checked input: what :func:`course.halftone.diffusion.error_diffusion` runs.

Nothing here checks its input (``UNCHECKED = True``): ``gray`` is a gray float
``(H, W)`` array in [0, 1], ``kernel`` an entry of :data:`course.halftone.diffusion.KERNELS`,
``method`` one of the forms that goes with ``serpentine``, as
:mod:`course.halftone.diffusion` makes sure before it calls :func:`diffuse`;
:func:`course.halftone.dither.all_methods` calls it too, on an image it checked once.

The forms themselves live beside :func:`~course.halftone.diffusion.error_diffusion`, as
``_error_diffusion_<method>`` (where ``course.classroom.source.form_of`` finds them), and
are registered in :data:`FORMS` when :mod:`course.halftone.diffusion` is imported.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

__all__ = ["FORMS", "default_method", "diffuse", "kernel_offsets"]

UNCHECKED = True  # kernels for checked callers; see the module docstring

#: The forms of error diffusion by method, as course.halftone.diffusion registers them:
#: (gray, offsets) for the wavefront, (gray, offsets, serpentine) for the others, each
#: returning (output, values).
FORMS: dict[str, Callable[..., tuple[np.ndarray, np.ndarray]]] = {}


def kernel_offsets(
    kernel: tuple[tuple[tuple[int, ...], ...], int],
) -> list[tuple[int, int, float]]:
    """The kernel ``(weights, denominator)`` as (dx, dy, weight) pushes, in raster order of
    their targets."""
    rows, denominator = kernel
    origin = (len(rows[0]) - 1) // 2
    return [
        (column - origin, dy, weight / denominator)
        for dy, row in enumerate(rows)
        for column, weight in enumerate(row)
        if weight
    ]


def default_method(serpentine: bool) -> str:
    """The wavefront in raster order; rows in serpentine order, which has no wavefront."""
    return "rows" if serpentine else "wavefront"


def diffuse(
    gray: np.ndarray, offsets: list[tuple[int, int, float]], serpentine: bool, method: str
) -> tuple[np.ndarray, np.ndarray]:
    """(output, values) of error diffusion by the form ``method``."""
    if method == "wavefront":
        return FORMS[method](gray, offsets)
    return FORMS[method](gray, offsets, bool(serpentine))
