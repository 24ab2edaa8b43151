"""What the lessons' printed lines share: one-line titles and columns that line up in Chinese.

The lesson modules print their lines in the current language (``course.i18n``); a Chinese
character takes two columns of a monospaced font, so a table pads by display width, not by
``len``. The lesson modules call these with their own strings, never a student's input
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import unicodedata

from course.i18n import _

UNCHECKED = True  # see the module docstring


def display_width(text: str) -> int:
    """Columns ``text`` takes in a monospaced font: a wide (CJK) character takes two.

    Examples
    --------
    >>> display_width("blur"), display_width("模糊")
    (4, 4)
    """
    return sum(2 if unicodedata.east_asian_width(char) in "WF" else 1 for char in text)


def padded(text: str, width: int, align: str = "<") -> str:
    """``text`` padded with spaces to ``width`` display columns, on the right (``"<"``) or left.

    Examples
    --------
    >>> padded("模糊", 6) + "|", padded("blur", 6, ">")
    ('模糊  |', '  blur')
    """
    space = " " * max(width - display_width(text), 0)
    return text + space if align == "<" else space + text


def yes_no(flag: bool) -> str:
    """A printed boolean as a student reads it, in the current language: yes or no.

    Examples
    --------
    >>> yes_no(True), yes_no(False)
    ('yes', 'no')
    """
    return _("yes") if flag else _("no")


def title_on_one_line(title: str) -> str:
    """An app's panel title of several lines as one printed line, joined as the language does.

    Examples
    --------
    >>> title_on_one_line("rule open: 42 + 48 pixels\\n0 painted twice")
    'rule open: 42 + 48 pixels: 0 painted twice'
    >>> title_on_one_line("'zero', 8 blurs\\nedge at 0.40\\ndark frame: 4 px deep")
    "'zero', 8 blurs: edge at 0.40: dark frame: 4 px deep"
    """
    heading, *details = title.split("\n")
    # A heading and its details on one line: English ": ", Chinese its own punctuation.
    for detail in details:
        heading = _("{heading}: {details}").format(heading=heading, details=detail)
    return heading
