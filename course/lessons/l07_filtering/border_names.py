"""The border rules of lesson 07 by the names a student reads, in the lesson's language.

The values (``'zero'``, ``'replicate'``, ...) are what :func:`course.filters.convolve` takes;
the names are what the apps, figures and printed lines show: the value itself in English,
零填充 / 复制边缘 / 镜像 / 讲义规则 in Chinese (issue 36).
"""

from __future__ import annotations

from course.i18n import N_

__all__ = ["BORDER_LABELS", "BORDER_NAMES"]

#: The border rules of :mod:`course.filters` as a figure or a widget names them: in English
#: the value a student passes (``border="replicate"``), in Chinese the rule's Chinese name.
BORDER_NAMES = {
    "handout": N_("handout"),
    "zero": N_("zero"),
    "replicate": N_("replicate"),
    "reflect": N_("reflect"),
}
#: The same in a title, where English quotes the value as code: ``'replicate'``.
BORDER_LABELS = {
    "handout": N_("'handout'"),
    "zero": N_("'zero'"),
    "replicate": N_("'replicate'"),
    "reflect": N_("'reflect'"),
}
