"""Input checks shared by every public function: the one home of every validator.

Each public function validates once, at its boundary, with these helpers and
then hands plain arrays to pure array code. Every message names the
parameter, the expected shape or type, and what was given (:func:`describe`),
in the language the lesson set (:mod:`course.i18n`); the parameter's name stays
as the code spells it.

A value checked once is not checked again on its way down: a public function that
needs another's work calls its unchecked kernel (a private ``_name`` beside it, or a
module marked ``UNCHECKED = True``), and an argument checked in several steps is checked
by one validator (:func:`as_finite_array`, :func:`as_flattening`, ...).
``tests/test__validate.py`` counts the entries into these checks.

By concept: numbers and choices (:mod:`~course._validate.scalars`), arrays and
images (:mod:`~course._validate.arrays`), points and curves
(:mod:`~course._validate.points`). Every name is importable from here. The bounds on
the work a call asks for (vertices, samples, interpolations), which several arguments
decide together, are :mod:`course.limits`' ``require_*`` checks, not argument checks.
"""

from course._validate.arrays import (
    as_finite_array,
    as_finite_arrays,
    as_float_array,
    as_gray,
    as_image,
    as_image_like,
    as_image_pair,
    as_kernel,
    as_pixels,
    as_real,
    require_finite,
    require_within,
)
from course._validate.points import (
    as_app_points,
    as_curve,
    as_figure_curve,
    as_flattening,
    as_parameter,
    as_path_arrays,
    as_point,
    as_points,
    as_scalar_parameter,
)
from course._validate.scalars import (
    as_choice,
    as_corner,
    as_int,
    as_option,
    as_positive_float,
    as_rng,
    as_shape,
    as_unit,
    describe,
)

__all__ = [
    "as_app_points",
    "as_choice",
    "as_corner",
    "as_curve",
    "as_figure_curve",
    "as_finite_array",
    "as_finite_arrays",
    "as_flattening",
    "as_float_array",
    "as_gray",
    "as_image",
    "as_image_like",
    "as_image_pair",
    "as_int",
    "as_kernel",
    "as_option",
    "as_parameter",
    "as_path_arrays",
    "as_pixels",
    "as_point",
    "as_points",
    "as_positive_float",
    "as_real",
    "as_rng",
    "as_scalar_parameter",
    "as_shape",
    "as_unit",
    "describe",
    "require_finite",
    "require_within",
]
