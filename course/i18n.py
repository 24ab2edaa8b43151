"""The language the library shows a student: English by default, or Simplified Chinese.

``course.use_language("zh-CN")`` switches every string the library shows (app labels,
legends, titles, status lines, captions) through gettext; ``course.use_language("en")``
switches back. The messages are marked in the source with :func:`_` (shown at once),
:func:`ngettext` (a count) and :func:`N_` (a constant defined at import time, translated
where it is shown with :func:`_`), and extracted with Babel::

    pybabel extract -F babel.cfg -o course/locale/course.pot course
    pybabel update -i course/locale/course.pot -d course/locale -D course

The translations are gettext catalogs, committed as ``course/locale/zh_CN/LC_MESSAGES/
course.po``. ``make`` compiles them to ``course.mo`` when it installs the course, and so does
``pip install .`` (setup.py's build step); a catalog whose ``.mo`` is missing or older than
its ``.po`` (an editable install, a fresh clone) is compiled in memory by Babel on first use.

English never goes through a catalog: its messages are the source's own strings, so an
English notebook's output is byte for byte what it was before the strings were marked.

Placeholders are ``str.format`` fields with names, ``_("{count} pixels").format(count=n)``,
so a translation can move them; a test fails when a translation's fields differ from its
English's.

The language line of the Chinese lessons. Each twin ``notebooks/zh-CN/NN_topic.ipynb``
(written by ``python -m course twins``) is its English lesson with :data:`LANGUAGE_LINES`
put before the first code cell's source: ``import course`` and
``course.use_language("zh-CN")``, ahead of the imports so that every module the lesson
imports afterwards already speaks Chinese.

Only :func:`use_language` is called by a student, and it checks its argument; the other
functions get the library's own messages, never a student's input, so this module is
``UNCHECKED`` for the fuzz test.

Examples
--------
>>> import course
>>> course.current_language()
'en'
>>> _("RMS error")
'RMS error'
"""

from __future__ import annotations

import dataclasses
import gettext
import io
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

__all__ = [
    "DEFAULT_LANGUAGE",
    "LANGUAGES",
    "LANGUAGE_LINES",
    "N_",
    "_",
    "current_language",
    "gettext_catalog",
    "language",
    "message_language",
    "ngettext",
    "use_language",
    "yes_no",
]

UNCHECKED = True  # see the module docstring

#: The gettext domain of the library's own messages.
DOMAIN = "course"
#: Where the catalogs are: ``LOCALE_DIR / "zh_CN" / "LC_MESSAGES" / "course.po"``.
LOCALE_DIR = Path(__file__).parent / "locale"
DEFAULT_LANGUAGE = "en"
#: The languages :func:`use_language` accepts, with their gettext locale (None: the source's).
LANGUAGES: dict[str, str | None] = {"en": None, "zh-CN": "zh_CN"}
#: The lines the builder of the Chinese lessons puts before a twin's first code cell.
LANGUAGE_LINES = 'import course\ncourse.use_language("zh-CN")\n\n'

# The package of the font the Chinese edition adds after matplotlib's font families.
CJK_FONT_PACKAGE = "pylopdf_fonts_zh_cn"

_language = DEFAULT_LANGUAGE
_translations: gettext.NullTranslations = gettext.NullTranslations()
_loaded: dict[str, gettext.NullTranslations] = {}
_english_families: list[str] | None = None


def gettext_catalog(locale: str) -> gettext.NullTranslations:
    """The compiled catalog of ``locale`` (``"zh_CN"``), compiled in memory if need be.

    The ``.mo`` beside the ``.po`` is used when it is at least as new as the ``.po``;
    otherwise Babel compiles the ``.po`` (fuzzy entries left out, as ``pybabel compile``
    does), so an editable install or a fresh clone needs no build step.

    Examples
    --------
    >>> gettext_catalog("zh_CN").gettext("RMS error")
    '均方根误差'
    """
    if locale in _loaded:
        return _loaded[locale]
    po_path = LOCALE_DIR / locale / "LC_MESSAGES" / f"{DOMAIN}.po"
    mo_path = po_path.with_suffix(".mo")
    if mo_path.exists() and (
        not po_path.exists() or mo_path.stat().st_mtime >= po_path.stat().st_mtime
    ):
        with mo_path.open("rb") as mo_file:
            translations = gettext.GNUTranslations(mo_file)
    elif po_path.exists():
        translations = gettext.GNUTranslations(io.BytesIO(compile_po(po_path)))
    else:
        raise FileNotFoundError(f"no catalog for locale {locale!r}: {po_path} is missing")
    _loaded[locale] = translations
    return translations


def compile_po(po_path: Path) -> bytes:
    """The ``.mo`` bytes of the catalog at ``po_path``, compiled by Babel."""
    from babel.messages.mofile import write_mo
    from babel.messages.pofile import read_po

    with po_path.open("rb") as po_file:
        catalog = read_po(po_file)
    buffer = io.BytesIO()
    write_mo(buffer, catalog, use_fuzzy=False)
    return buffer.getvalue()


def use_language(code: str) -> None:
    """Show every string of the library in ``code``: ``"en"`` (the default) or ``"zh-CN"``.

    Called in a lesson's first cell, before the course's modules are imported. Chinese also
    adds a CJK font (Noto Sans SC) after matplotlib's font families; English restores them.

    Parameters
    ----------
    code : str
        One of :data:`LANGUAGES`.

    Raises
    ------
    TypeError
        If ``code`` is not a str.
    ValueError
        If ``code`` is not one of :data:`LANGUAGES`.

    Examples
    --------
    >>> use_language("zh-CN")
    >>> _("RMS error")
    '均方根误差'
    >>> use_language("en")
    >>> _("RMS error")
    'RMS error'
    """
    _use_messages(code)
    if LANGUAGES[code] is None:
        _restore_english_fonts()
    else:
        _add_cjk_font()


def _use_messages(code: str) -> None:
    """Switch the messages (not the fonts) to ``code``, checked; its errors in the language
    shown until then, the student's."""
    global _language, _translations
    if not isinstance(code, str):
        raise TypeError(
            _("code must be a str such as 'zh-CN', not {code_type}").format(
                code_type=type(code).__name__
            )
        )
    if code not in LANGUAGES:
        raise ValueError(
            _("code must be one of {choices}, not {code}").format(
                choices=", ".join(map(repr, LANGUAGES)), code=repr(code)
            )
        )
    locale = LANGUAGES[code]
    _translations = gettext.NullTranslations() if locale is None else gettext_catalog(locale)
    _language = code


@contextmanager
def message_language(code: str) -> Iterator[None]:
    """Show the library's messages in ``code`` inside a ``with`` block; fonts left alone.

    For the command line, which prints but draws nothing: unlike :func:`language`, it
    imports no matplotlib.

    Examples
    --------
    >>> with message_language("zh-CN"):
    ...     _("RMS error")
    '均方根误差'
    >>> _("RMS error")
    'RMS error'
    """
    before = current_language()
    _use_messages(code)
    try:
        yield
    finally:
        _use_messages(before)


def current_language() -> str:
    """The code :func:`use_language` last set, ``"en"`` until then.

    Examples
    --------
    >>> current_language()
    'en'
    """
    return _language


@contextmanager
def language(code: str) -> Iterator[None]:
    """Show the library's strings in ``code`` inside a ``with`` block, then as before.

    Examples
    --------
    >>> with language("zh-CN"):
    ...     current_language()
    'zh-CN'
    >>> current_language()
    'en'
    """
    before = current_language()
    use_language(code)
    try:
        yield
    finally:
        use_language(before)


def _(message: str) -> str:
    """``message`` in the current language (unchanged in English).

    Examples
    --------
    >>> _("RMS error")
    'RMS error'
    """
    return _translations.gettext(message)


def ngettext(singular: str, plural: str, count: int) -> str:
    """``singular`` or ``plural`` for ``count``, in the current language.

    Examples
    --------
    >>> ngettext("{count} pixel", "{count} pixels", 2).format(count=2)
    '2 pixels'
    """
    return _translations.ngettext(singular, plural, count)


def N_(message: str) -> str:
    """Mark ``message`` for extraction only: it is translated where it is shown, by :func:`_`.

    Examples
    --------
    >>> N_("RMS error")
    'RMS error'
    """
    return message


#: What :func:`yes_no` shows, marked for the catalog (是 / 否 in Chinese).
YES = N_("yes")
NO = N_("no")


def yes_no(value: object) -> str:
    """A truth value as a student reads it: "yes" or "no" in the current language.

    For a printed line that tells whether something holds ("equal to the loop bit for bit:
    yes"), where Python's ``True`` / ``False`` would be English in a Chinese lesson.

    Examples
    --------
    >>> yes_no(True), yes_no(1 > 2)
    ('yes', 'no')
    >>> with message_language("zh-CN"):
    ...     yes_no(True), yes_no(False)
    ('是', '否')
    """
    return _(YES) if value else _(NO)


def cjk_font_path() -> Path:
    """The Noto Sans SC font file of the font package the Chinese edition depends on."""
    import importlib

    package = importlib.import_module(CJK_FONT_PACKAGE)
    return Path(package.sans_path())


def _add_cjk_font() -> None:
    global _english_families
    import matplotlib as mpl
    from matplotlib import font_manager

    path = cjk_font_path()
    known = [entry for entry in font_manager.fontManager.ttflist if entry.fname == str(path)]
    if not known:
        font_manager.fontManager.addfont(str(path))
        (regular,) = [e for e in font_manager.fontManager.ttflist if e.fname == str(path)]
        # The package has no bold face. Bold titles would make matplotlib log "Failed to find
        # font weight bold" and fall back anyway: the regular face stands in for bold, quietly.
        font_manager.fontManager.ttflist.append(dataclasses.replace(regular, weight=700))
        font_manager.fontManager._findfont_cached.cache_clear()
    name = font_manager.FontProperties(fname=str(path)).get_name()
    if _english_families is None:
        _english_families = list(mpl.rcParams["font.family"])
    # Matplotlib falls back along font.family glyph by glyph (one font per entry): Latin
    # letters and digits keep the English edition's font, the rest comes from Noto Sans SC.
    mpl.rcParams["font.family"] = [*_english_families, name]


def _restore_english_fonts() -> None:
    global _english_families
    if _english_families is None:
        return
    import matplotlib as mpl

    mpl.rcParams["font.family"] = _english_families
    _english_families = None
