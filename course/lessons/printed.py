"""What the lessons' printed lines share: one-line titles and columns that line up in Chinese.

The lesson modules print their lines in the current language (``course.i18n``); a Chinese
character takes two columns of a monospaced font, so a table pads by display width, not by
``len``. The lesson modules call these with their own strings, never a student's input
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import unicodedata

from course.i18n import _, current_language

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


_CHINESE_DIGITS = "零一二三四五六七八九"


def degree_numeral(degree: int) -> int | str:
    """A curve's degree as the current language writes it in «{degree}次曲线», «degree {degree}».

    Chinese names a degree in words, 三次曲线, as a textbook does: «3 次» reads as "3 times".
    Degrees 0 to 99 and whole hundreds below 1000 are written in words; any other degree is its
    digits and a space («1029 次曲线»). In English the degree stays the number itself, so
    English lines do not change.

    Examples
    --------
    >>> from course.i18n import language
    >>> degree_numeral(3)
    3
    >>> with language("zh-CN"):
    ...     [degree_numeral(n) for n in (3, 10, 20, 26, 400, 1029)]
    ['三', '十', '二十', '二十六', '四百', '1029 ']
    """
    if current_language() == "en" or degree < 0:
        return degree
    tens, ones = divmod(degree, 10)
    if degree < 10:
        return _CHINESE_DIGITS[degree]
    if degree < 100:
        head = "" if tens == 1 else _CHINESE_DIGITS[tens]
        return head + "十" + (_CHINESE_DIGITS[ones] if ones else "")
    if degree < 1000 and degree % 100 == 0:
        return _CHINESE_DIGITS[degree // 100] + "百"
    return f"{degree} "


def degree_column(degree: int, digits: int = 2) -> str:
    """A curve's degree as :func:`degree_numeral` writes it, right-aligned by display width.

    For lines printed one per degree that line up on «{degree:>2}»: English pads the number to
    ``digits`` columns, exactly as ``{degree:>2}`` does; Chinese pads the numeral to twice as
    many, since a wide character takes two columns (三, 二十), so «  三次曲线» lines up with
    «二十次曲线». A longer numeral is left as it is.

    Examples
    --------
    >>> from course.i18n import language
    >>> degree_column(3), degree_column(20), degree_column(100)
    (' 3', '20', '100')
    >>> with language("zh-CN"):
    ...     [degree_column(n) for n in (3, 20, 26)]
    ['  三', '二十', '二十六']
    """
    numeral = str(degree_numeral(degree))
    width = digits if current_language() == "en" else 2 * digits
    return padded(numeral, width, ">")
