"""The handouts' reversed de Casteljau on checked input.

The kernel behind :func:`course.curves.bezier_handouts.de_casteljau_reversed`, which checks
its arguments before it calls :func:`de_casteljau_swapped`; the handouts' drawing loops
(:mod:`course.curves.handout_loops`) evaluate their checked curves with it.

Unchecked kernels: this module trusts its callers and checks no input
(``UNCHECKED = True``, which the fuzz test reads).
"""

from __future__ import annotations

import numpy as np

__all__ = ["de_casteljau_swapped"]

UNCHECKED = True  # kernels for checked callers; see the module docstring


def de_casteljau_swapped(control: np.ndarray, t: np.ndarray) -> np.ndarray:
    """(M, d) points of seeds 002 and 004's de Casteljau, each level
    ``t * P[i] + (1 - t) * P[i + 1]``, of ``control`` (N, d) at ``t`` (M,).

    Examples
    --------
    >>> de_casteljau_swapped(np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]), np.array([0.25]))
    array([[1.5 , 0.75]])
    """
    t_column = t[:, None, None]
    level = np.broadcast_to(control, (len(t), *control.shape))
    while level.shape[1] > 1:
        level = t_column * level[:, :-1] + (1 - t_column) * level[:, 1:]
    return level[:, 0]
