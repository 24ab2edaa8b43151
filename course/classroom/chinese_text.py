"""The rules a Chinese text keeps: no Latin word outside the allow-list, Chinese punctuation.

A :class:`Shown` is a text a Chinese student sees, with where it is;
:mod:`course.classroom.chinese_review` gathers them, :mod:`course.classroom.glossary` checks
their terms, and this module their words and their punctuation (issue 36):

* :func:`latin_words`: a Latin word (a run of Latin letters, with its digits) is allowed only
  as one of these, and nowhere else:

  - a math symbol: one letter, with digits after it (``t``, ``x``, ``P0``, ``B(t)``), a
    differential (``dx``), a component (``Gx``), or a polygon or an edge named by its
    vertices (``ABC``, ``AC``: capitals A to H, none repeated);
  - an equation's or a call's name: a word right before ``=`` or ``(`` (``dx = 0.5``);
  - a unit: :data:`UNITS`; a name of :data:`ACRONYMS` (the handouts' courses and the
    software the course runs on); a proper name of :data:`NAMES` (an algorithm's author,
    as Chinese graphics texts write them: Bresenham 算法, Sobel 算子);
  - inside LaTeX, a code span, a format field, a URL, a path or a file name;
  - a gloss: Latin inside full-width parentheses right after a Chinese character,
    «泼溅（splat）», or after a numbered Chinese term's number, «任务 1（Task 1）»;
  - code, in a printed line or a catalog message (``loose``), where no code span can mark
    it: a word with ``_``, ``.``, ``::``, ``'``-quoted, with digits, in CamelCase, followed
    by ``[``, a keyword argument's value written against its ``name=`` (``force=True``:
    the call as it is typed, not a value shown), a Python exception's name or keyword
    (``for``, ``return``), or a name of :func:`code_names` (the functions and
    classes the course and its lessons define, Python's built-ins; in a catalog message
    the parameters' names too). Never in a figure or a widget, whose texts are labels,
    and never a bare ``True``, ``False`` or ``None``: a printed value is a word.

  Other names (Jacobi, Wu, Bernstein) have a Chinese term in the glossary: glossed once,
  then translated.
* :func:`ascii_punctuation`: an ASCII ``,`` ``;`` ``:`` with a space after it, between two
  clauses that both hold Chinese (or a format field, with Chinese on one side), or ASCII
  parentheses around Chinese; code spans, LaTeX, fields and code-like tuples are excepted.
* :func:`quotation_marks`: the edition's quotation marks, as mainland textbooks write them.
  「」 name only a control or an option the student sees on screen (「规则」, 「按弧长」:
  Chinese fonts have no italics), and :func:`~course.classroom.chinese_review.control_mentions`
  checks each against the labels of the lesson's apps; “” quote everything else: a stub's text
  (“在这里写你的代码”), a term being defined, a word or a heading quoted. So «», 『』 and ASCII
  double quotes around Chinese never appear, and “” and 「」 come in pairs; code spans, LaTeX
  and fields are excepted (a code span quotes as Python does: ``raise NotImplementedError("…")``).

Classroom tooling over the course's own files, never given a student's input: it checks none
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import ast
import builtins
import json
import keyword
import re
from dataclasses import dataclass
from pathlib import Path

UNCHECKED = True  # see the module docstring

__all__ = [
    "ACRONYMS",
    "CATALOG",
    "NAMES",
    "NOTEBOOKS",
    "UNITS",
    "Shown",
    "ascii_punctuation",
    "code_names",
    "latin_words",
    "prose",
    "quotation_marks",
]

_ROOT = Path(__file__).resolve().parents[2]
#: The lessons, English and (in ``zh-CN/``) Chinese.
NOTEBOOKS = _ROOT / "notebooks"
#: The library's catalog of Chinese messages.
CATALOG = _ROOT / "course" / "locale" / "zh_CN" / "LC_MESSAGES" / "course.po"

#: Units a Chinese text writes in Latin letters.
UNITS = frozenset({"px", "ms"})
#: Names that stay as they are: the handouts' courses and the software the course runs on.
ACRONYMS = frozenset({"RGB", "GAMES101", "VS2022", "OpenCV", "numpy", "Python", "Jupyter"})
#: Proper names a Chinese graphics text writes in Latin letters, as the handouts do: the
#: authors an algorithm is named after (Bresenham 算法, Sobel 算子, de Casteljau 算法) and the
#: software and formats the course names. Not the names the glossary gives in Chinese
#: (Jacobi, Gauss-Seidel, Wu, Bernstein), which are glossed once and then translated.
NAMES = (
    "de Casteljau",
    "Bézier",
    "Bresenham",
    "Sobel",
    "Floyd-Steinberg",
    "Floyd–Steinberg",
    "Jarvis-Judice-Ninke",
    "Jarvis–Judice–Ninke",
    "Stucki",
    "Atkinson",
    "Bayer",
    "Agg",
    "matplotlib",
    "scipy",
    "SciPy",
    "Pillow",
    "nbgrader",
    "nbformat",
    "JupyterLab",
    "JupyterHub",
    "JSON",
    "CSV",
    "Markdown",
    "Voila",
    "Pineda",
)

CJK = "\u3400-\u4dbf\u4e00-\u9fff\uf900-\ufaff"
_CJK = re.compile(f"[{CJK}]")
# A Latin word: letters (with accents), then letters and digits, joined by - or '.
# (Latin-1's × and ÷ are signs, not letters.)
_LETTER = "A-Za-zÀ-ÖØ-öø-ɏ"
_WORD = re.compile(f"[{_LETTER}][{_LETTER}0-9_]*(?:[-'’][{_LETTER}][{_LETTER}0-9_]*)*")
_NAME = re.compile("|".join(rf"(?<![{_LETTER}]){re.escape(name)}(?![{_LETTER}])" for name in NAMES))
# Python's keywords, in code written without code spans (not its values True, False, None).
_KEYWORDS = frozenset(keyword.kwlist) - {"True", "False", "None"}
_FIELD = re.compile(r"(?<!\{)\{[A-Za-z_0-9.\[\]]*(?:![rsa])?(?::[^{}]*)?\}(?!\})|%\(\w+\)[sdfr]")
# Spans whose Latin is never a word: LaTeX, code spans and fences, HTML tags, link targets,
# URLs, paths and file names.
_SPANS = re.compile(
    r"\$\$.+?\$\$|(?<![\\$])\$[^$]+?\$|```.*?```|`[^`\n]+`|</?[a-zA-Z][^>]*>|\]\([^)\s]*\)"
    r"|https?://\S+|[\w.-]*/[\w./-]+|[\w-]+\.(?:ipynb|py|po|pot|png|jpe?g|json|tsv|csv|txt|md)\b",
    re.DOTALL,
)
# Numbers, with an exponent or as a size 3x3: their letters are not words.
_NUMBER = re.compile(r"(?<![A-Za-zÀ-ÖØ-öø-ɏ0-9_.])\d+(?:\.\d+)?(?:[eE][-+−]?\d+|x\d+)?")
# A gloss: Latin in full-width parentheses right after a Chinese character.
# A numbered term's gloss follows its number: 任务 1（Task 1）.
_GLOSS = re.compile(f"(?<=[{CJK}])(?: ?[0-9]+)?（[^（）{CJK}]+）")
# Code in plain text: 'quoted', dotted.names, cv::Point, names with _ or digits.
_QUOTED = re.compile(r"'[^'\s]+'|\"[^\"\s]+\"")
# A math symbol: a letter and its digits (P0, x1), a differential (dx), a component (Gx).
# A polygon or an edge by its vertices' names (ABC, ACD, AC): capitals A to H, each once.
_SYMBOL = re.compile(r"[A-Za-z]\d*|d[xyt]|[A-Z][xy]|(?!([A-H])[A-H]*\1)[A-H]{2,4}")
_EXCEPTIONS = frozenset(
    name
    for name, value in vars(builtins).items()
    if isinstance(value, type) and issubclass(value, BaseException)
)


def _mask(text: str, pattern: re.Pattern, by: str = " ") -> str:
    return pattern.sub(lambda found: by * len(found.group(0)), text)


def latin_words(
    text: str, loose: bool = False, names: frozenset[str] = frozenset(), markup: bool = True
) -> list[str]:
    """The Latin words of ``text`` outside the allow-list (see the module docstring).

    ``loose`` for a printed line or a catalog message, where code is written without code
    spans; a figure's or a widget's text is a label, never code. There ``names`` are the
    code's names a word may be (:func:`code_names`). Without ``markup`` (a printed line) a
    code span is not markdown but backticks shown as they are: it is found, whole.

    Examples
    --------
    >>> latin_words("点 P0 在 t = 0.5 处，宽 3 px，误差 1e-05，用 GAMES101 作业报告的循环")
    []
    >>> latin_words("泼溅（splat）的 `count` 与 $B_{i,n}(t)$，{name} 在 x1 处")
    []
    >>> latin_words("任务 1（Task 1）与任务 2，步长 0.5（step）")
    ['step']
    >>> latin_words("Bresenham 算法画 3 × 3 的网格，de Casteljau 算法与 Jacobi 迭代")
    ['Jacobi']
    >>> latin_words("规则 'top-left'，按 count 加权：True")
    ['top-left', 'count', 'True']
    >>> latin_words("规则 'top-left'，用 int() 与 np.floor 和 arc_length", loose=True)
    []
    >>> latin_words("wavefront：与循环版逐位相同：True", loose=True)
    ['wavefront', 'True']
    >>> latin_words("请传入 force=True；应为 True", loose=True)
    ['True']
    >>> latin_words("讲义里的 `float t` 会漂移", loose=True, markup=False)
    ['`float t`']
    """
    found = [] if markup else re.findall(r"`[^`\n]+`", text)
    text = _mask(text, _SPANS)
    text = _mask(text, _FIELD)
    text = _mask(text, _GLOSS)
    text = _mask(text, _NAME)
    if loose:
        text = _mask(text, _QUOTED)
        text = _mask(text, re.compile(r"[\w]+(?:(?:\.|::)\w+)+"))
    text = _mask(text, _NUMBER)
    for word in _WORD.finditer(text):
        name, after = word.group(0), text[word.end() :].lstrip(" ")
        if name in UNITS or name in ACRONYMS or _SYMBOL.fullmatch(name):
            continue
        if after.startswith("=") and not after.startswith("=="):
            continue  # an equation's or a keyword argument's name
        if text[word.end() : word.end() + 1] == "(":
            continue  # a call, or a function of math: B(t), int(), comb(m, n)
        if loose and (name in names or _looks_like_code(name, text, word)):
            continue
        found.append(name)
    return found


def _looks_like_code(name: str, text: str, word: re.Match) -> bool:
    before = text[: word.start()]
    return (
        "_" in name
        or text[word.end() : word.end() + 1] == "["
        or before.endswith("_")
        or re.search(r"\w=$", before) is not None  # a keyword argument: force=True
        or re.search(r"\d", name) is not None
        or re.search(r"[a-z][A-Z]", name) is not None
        or name in _EXCEPTIONS
        or name in _KEYWORDS
    )


def _source(value) -> str:
    return value if isinstance(value, str) else "".join(value)


def code_names(parameters: bool, notebooks: Path = NOTEBOOKS) -> frozenset[str]:
    """The names code gives that a printed line or a message may show as they are.

    The functions and classes the course's modules and the English lessons' code cells
    define, Python's built-in functions and types (not ``True``, ``False``, ``None``:
    a value shown bare is a word to translate), and with ``parameters`` the course's
    parameters' names too, which its messages about an argument name.
    """
    found = {
        name
        for name, value in vars(builtins).items()
        if callable(value) and not name.startswith("_")
    }
    sources = [path.read_text(encoding="utf-8") for path in (_ROOT / "course").rglob("*.py")]
    for path in sorted(notebooks.glob("[0-9][0-9]_*.ipynb")):
        notebook = json.loads(path.read_text(encoding="utf-8"))
        sources += [_source(c["source"]) for c in notebook["cells"] if c["cell_type"] == "code"]
    for source in sources:
        try:
            tree = ast.parse(source)
        except SyntaxError:
            continue  # a cell with IPython's own syntax
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                found.add(node.name)
            elif parameters and isinstance(node, ast.arg):
                found.add(node.arg)
    return frozenset(found)


@dataclass(frozen=True)
class Shown:
    """A text a Chinese student sees: where (lesson and place), and the text itself.

    ``lesson`` is the lesson's number, ``""`` for a text no lesson owns (a shared module's
    message). ``loose`` says that code may be written in it without code spans.
    """

    lesson: str
    where: str
    text: str
    loose: bool = False
    markup: bool = True

    def latin(self, names: frozenset[str] = frozenset()) -> list[str]:
        """Its Latin words outside the allow-list (:func:`latin_words`)."""
        return latin_words(self.text, self.loose, names, self.markup)


def prose(text: str) -> str:
    """``text`` with its code spans, LaTeX and fields blanked: where its words are."""
    return _mask(_mask(text, _SPANS), _FIELD)


# --- punctuation ----------------------------------------------------------------------------

_CLAUSE_END = "，；：。！？、\n"
# A tuple, a call, an index or an interval, with no Chinese inside: (2, 1), int(x), (0, 1].
_CODE_BRACKETS = re.compile(f"[\\[(][^()\\[\\]（）{CJK}]*[\\])]")
_ASCII_MARK = re.compile(r"[,;:](?=\s|$)")


def ascii_punctuation(text: str) -> list[str]:
    """The ASCII punctuation between Chinese clauses of ``text``, each with its context.

    Examples
    --------
    >>> ascii_punctuation("期望 16，得到 10; g 中差别最大")
    ['16，得到 10; g 中差别最大']
    >>> ascii_punctuation("像素 (2, 1) 得 0.25, 像素 (2, 2) 得 0.25")
    [') 得 0.25, 像素 (2,']
    >>> ascii_punctuation("对 x, y >= 0：`a, b` 与 $x: y$；{name}：通过 (t, 1 - t)")
    []
    >>> ascii_punctuation("t 在 [(k - 1)/9, k/9] 内时，n 在 (0, 0.5] 之内")
    []
    >>> ascii_punctuation("规则 (左上) 与 {count}, 次")
    ['{count}, 次', '规则 (左上) 与']
    """
    masked, before = _mask(text, _SPANS, "x"), ""
    while masked != before:  # nested brackets, innermost first: [(k - 1)/9, k/9]
        masked, before = _mask(masked, _CODE_BRACKETS, "x"), masked
    fields = _mask(masked, _FIELD, "x") != masked
    field_mask = _FIELD.sub(lambda found: "\0" * len(found.group(0)), masked)
    found = []
    for mark in _ASCII_MARK.finditer(field_mask):
        before = re.split(f"[{_CLAUSE_END},;:]", field_mask[: mark.start()])[-1]
        after = re.split(f"[{_CLAUSE_END},;:]", field_mask[mark.end() :])[0]
        sides = [bool(_CJK.search(side)) for side in (before, after)]
        with_field = [("\0" in side) for side in (before, after)] if fields else [False, False]
        if all(s or f for s, f in zip(sides, with_field, strict=True)) and any(sides):
            found.append(text[max(0, mark.start() - 8) : mark.end() + 8].strip())
    for parentheses in re.finditer(r"\(([^()\[\]]*)\)", field_mask):
        if _CJK.search(parentheses.group(1)):
            start, end = parentheses.span()
            found.append(text[max(0, start - 3) : end + 3].strip())
    return found


# --- quotation marks ------------------------------------------------------------------------

_FOREIGN_QUOTES = re.compile("[«»『』]")
_ASCII_QUOTED = re.compile(f'"[^"\\n]*[{CJK}][^"\\n]*"')
_PAIRS = (("“", "”"), ("「", "」"))


def quotation_marks(text: str) -> list[str]:
    """The quotation marks of ``text`` that break the edition's convention, each in context.

    «», 『』 and ASCII double quotes around Chinese; an unpaired “” or 「」. Code spans,
    LaTeX and fields are excepted (see the module docstring for the convention).

    Examples
    --------
    >>> quotation_marks("你的函数抛出了 NotImplementedError，提示“在这里写你的代码”")
    []
    >>> quotation_marks('把「规则」切换成「左上规则」；`raise NotImplementedError("写代码")`')
    []
    >>> quotation_marks("提示«在这里写你的代码»")
    ['«', '»']
    >>> quotation_marks('提示"在这里写你的代码"，或『规则』')
    ['『', '』', '"在这里写你的代码"']
    >>> quotation_marks("提示“在这里写你的代码")
    ['“ without ”']
    """
    masked = prose(text)
    found = [hit.group(0) for hit in _FOREIGN_QUOTES.finditer(masked)]
    found += [hit.group(0) for hit in _ASCII_QUOTED.finditer(masked)]
    for left, right in _PAIRS:
        depth = 0
        for mark in re.findall(f"[{left}{right}]", masked):
            depth += 1 if mark == left else -1
            if depth not in (0, 1):
                break
        if depth:
            found.append(f"{left} without {right}" if depth > 0 else f"{right} without {left}")
    return found
