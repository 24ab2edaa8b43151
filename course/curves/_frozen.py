"""A frozen dataclass made of fields its maker checked, without checking them again.

:class:`course.curves.paths.Curves` checks its fields when it is made, so that every
function taking one may trust it. A maker that built the fields from checked input (a
curve through :func:`course._validate.as_curve`, a path's vertices checked finite and
bounded) makes it here instead, so each argument is validated once.

Unchecked kernels: this module trusts its callers and checks no input
(``UNCHECKED = True``, which the fuzz test reads).
"""

from __future__ import annotations

from typing import Any, TypeVar

__all__ = ["made"]

UNCHECKED = True  # kernels for checked callers; see the module docstring

Kind = TypeVar("Kind")


def made(kind: type[Kind], **fields: Any) -> Kind:
    """A ``kind`` (a frozen dataclass) of these fields, without its ``__post_init__``.

    Examples
    --------
    >>> import numpy as np
    >>> from course.curves.paths import Curves
    >>> made(Curves, points=np.zeros((2, 2)), sizes=np.array([2])).sizes
    array([2])
    """
    made = object.__new__(kind)
    for name, value in fields.items():
        object.__setattr__(made, name, value)
    return made
