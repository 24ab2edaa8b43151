"""The Chinese lessons: ``python -m course twins`` writes each twin from its catalog.

The translation of ``notebooks/NN_topic.ipynb`` is the gettext catalog
``notebooks/zh-CN/NN_topic.po``: one message per markdown cell, ``msgctxt`` the cell's id,
``msgid`` its source, ``msgstr`` the Chinese. The twin ``notebooks/zh-CN/NN_topic.ipynb`` is
the English lesson with each markdown cell replaced by its translation, the code cells copied,
and :data:`course.i18n.LANGUAGE_LINES` put before the first code cell. Its outputs come from
executing it (``make notebooks``); the builder writes a twin only when its cells changed (their
ids, kinds or sources), and then with the English outputs cleared: the other twins, and their
outputs, stay as they are.

A code cell's words are translated too, and nothing else of it: each docstring of a function
or class, with ``msgctxt`` ``<cell id>:docstring`` (``<cell id>:docstring:<name>`` when the
cell documents more than one), and each comment, ``<cell id>:comment`` (``<cell id>:comment:<n>``,
counted from 1, when it has more), their ``msgid`` the English as the cell has it (a
docstring's lines without their indentation). The twin's cell is the English one with only
those texts replaced, byte for byte elsewhere (:func:`code_skeleton` compares the two);
an untranslated one stays English, and is reported as a markdown cell is.

Cell ids are stable (nbformat 4.5, kept by ``nbstripout --keep-id``), so inserting, moving or
deleting a cell leaves every other cell's message, and its translation, where it was. A message
is found by its exact id and source only: a cell whose English changed is untranslated until a
translator looks at it, never filled from a near match.

``--update-po`` merges the English markdown into the catalogs: a new or changed cell becomes
an untranslated message, a message no cell has any more becomes obsolete (``#~``). ``--check``
writes nothing and fails when a message is untranslated or a translation lost the LaTeX, code
spans, links' targets or HTML tags of its English (it may mark more as math or code; it adds no
link or tag).

Needs Babel (a dependency of the course) and the standard library only. A command-line tool
over the course's own files, never given a student's input: it checks none
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import ast
import copy
import io
import json
import re
import tokenize
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from course.i18n import LANGUAGE_LINES, _

UNCHECKED = True  # see the module docstring

#: The twins' folder, inside the English lessons' folder.
TWIN_FOLDER = "zh-CN"
LOCALE = "zh_CN"

# What a translation must keep exactly, in order: display and inline LaTeX, fenced code,
# code spans, link and image targets, HTML tags.
_KEPT = re.compile(
    r"\$\$.+?\$\$|(?<![\\$])\$[^$]+?\$|```.*?```|`[^`\n]+`|\]\((?!#)[^)\s]*\)|</?[a-zA-Z][^>]*>",
    re.DOTALL,
)
# The spans a translation may add: inline LaTeX and code spans.
_MARKED = re.compile(r"(?<![\\$])\$[^$]+?\$|`[^`\n]+`")
#: Link targets whose anchor is a heading's text, as the twin's translated heading makes it.
TRANSLATED_ANCHORS = {"](00_index.ipynb#The-handouts)": "](00_index.ipynb#讲义)"}
# str.format fields ({x}, {x:.2f}) and printf conversions (%d, %(x)s); not {{ or }}.
_PLACEHOLDER = re.compile(
    r"(?<!\{)\{[A-Za-z_0-9.\[\]]*(?:![rsa])?(?::[^{}]*)?\}(?!\})"
    r"|%(?:\([^)]*\))?[-#0+]*\d*(?:\.\d+)?[diouxXeEfFgGcrs]"
)


# A comment in a fenced block, with the spaces before it: words a translation may change.
_FENCED_COMMENT = re.compile(r"[ \t]*#[^\n]*")


def kept_spans(text: str) -> list[str]:
    """The LaTeX, code spans, link targets and HTML tags of a markdown text, in order.

    A fenced block is kept without its comments (from ``#`` to the end of the line), which
    are words: the twin says them in Chinese, its code stays the English's.

    Examples
    --------
    >>> kept_spans("The point $B(t)$ of `de_casteljau`, see [here](01_x.ipynb).")
    ['$B(t)$', '`de_casteljau`', '](01_x.ipynb)']
    >>> kept_spans("```\\nif D > 0:  # the next row\\n    y += 1\\n```")
    ['```\\nif D > 0: #\\n    y += 1\\n```']
    """
    return [
        _FENCED_COMMENT.sub(" #", span) if span.startswith("```") else span
        for span in _KEPT.findall(text)
    ]


def placeholders(text: str) -> list[str]:
    """The format fields and printf conversions of a message, sorted.

    Examples
    --------
    >>> placeholders("{count} pixels at %d dpi, {rate:.2f}")
    ['%d', '{count}', '{rate:.2f}']
    """
    return sorted(_PLACEHOLDER.findall(text))


def english_lessons(notebooks: Path) -> list[Path]:
    """The English lessons ``NN_topic.ipynb`` of ``notebooks``, in order."""
    return sorted(notebooks.glob("[0-9][0-9]_*.ipynb"))


def read_notebook(path: Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))


def write_notebook(path: Path, notebook: dict) -> None:
    # nbformat's own layout, so that nbstripout and git see no difference in form.
    text = json.dumps(notebook, indent=1, sort_keys=True, ensure_ascii=False) + "\n"
    path.write_text(text, encoding="utf-8")


def cell_source(cell: dict) -> str:
    source = cell["source"]
    return source if isinstance(source, str) else "".join(source)


def markdown_messages(notebook: dict) -> list[tuple[str, str]]:
    """``(cell id, source)`` of every markdown cell with text."""
    return [
        (cell["id"], cell_source(cell))
        for cell in notebook["cells"]
        if cell["cell_type"] == "markdown" and cell_source(cell).strip()
    ]


@dataclass(frozen=True)
class CodeText:
    """A docstring's or a comment's words in a code cell: what its twin translates."""

    context: str  # the message's msgctxt: "<cell id>:docstring", "<cell id>:comment:2"
    english: str  # the msgid: the words as the cell has them, a docstring's lines dedented
    start: int  # where the words are in the cell's source: source[start:end]
    end: int
    indent: str = ""  # a docstring's indentation, put back before its later lines

    def written(self, words: str) -> str:
        """``words`` as the cell's source holds them (a docstring's later lines indented)."""
        first, *rest = words.split("\n")
        return "\n".join([first, *(self.indent + line if line else line for line in rest)])


# A string literal's prefix, quotes and words.
_LITERAL = re.compile(r"([rRuU]?)(\"\"\"|\'\'\'|\"|\')(.*)\2", re.DOTALL)
# Comments that are instructions to tools or to the editions, never words for a student.
_TOOL_COMMENT = re.compile(r"#(?:#|!|\s*(?:noqa|type:|fmt:|pragma))")


def _offsets(source: str) -> list[int]:
    """The offset in ``source`` of each line's start (1-based lines: index 0 unused)."""
    starts = [0, 0]
    for line in io.StringIO(source).readlines():  # lines as ast and tokenize count them
        starts.append(starts[-1] + len(line))
    return starts


def _docstrings(cell_id: str, source: str, tree: ast.Module) -> list[CodeText]:
    starts = _offsets(source)
    lines = io.StringIO(source).readlines()

    def offset(line: int, byte_column: int) -> int:  # ast's columns count UTF-8 bytes
        return starts[line] + len(lines[line - 1].encode("utf-8")[:byte_column].decode("utf-8"))

    found = []
    for node in ast.walk(tree):
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            continue
        first = node.body[0]
        if not (
            isinstance(first, ast.Expr)
            and isinstance(first.value, ast.Constant)
            and isinstance(first.value.value, str)
        ):
            continue
        start = offset(first.value.lineno, first.value.col_offset)
        end = offset(first.value.end_lineno, first.value.end_col_offset)
        literal = _LITERAL.fullmatch(source[start:end])
        if literal is None:  # implicitly joined strings: left as they are
            continue
        prefix, quotes, words = literal.groups()
        indent = " " * first.col_offset
        later = words.split("\n")[1:]
        if not all(line.startswith(indent) or not line for line in later):
            indent = ""
        english = "\n".join([words.split("\n")[0], *(line[len(indent) :] for line in later)])
        inner = start + len(prefix) + len(quotes)
        found.append((node.name, english, inner, end - len(quotes), indent))
    context = f"{cell_id}:docstring"
    if len(found) == 1:
        return [CodeText(context, *found[0][1:])]
    return [CodeText(f"{context}:{name}", *rest) for name, *rest in found]


def _comments(cell_id: str, source: str) -> list[CodeText]:
    starts = _offsets(source)
    found = []
    try:
        for token in tokenize.generate_tokens(io.StringIO(source).readline):
            if token.type != tokenize.COMMENT or _TOOL_COMMENT.match(token.string):
                continue
            words = token.string[1:].lstrip(" ")
            if not words.strip():
                continue
            end = starts[token.start[0]] + token.end[1]
            found.append((words, end - len(words), end))
    except (tokenize.TokenError, SyntaxError):
        return []
    context = f"{cell_id}:comment"
    if len(found) == 1:
        return [CodeText(context, *found[0])]
    return [CodeText(f"{context}:{number}", *text) for number, text in enumerate(found, 1)]


def code_texts(cell_id: str, source: str) -> list[CodeText]:
    """The docstrings and comments of a code cell that its twin translates, in order.

    Examples
    --------
    >>> source = 'def area(w, h):\\n    "Width times height."\\n    return w * h  # in px'
    >>> [(text.context, text.english) for text in code_texts("c1", source)]
    [('c1:docstring', 'Width times height.'), ('c1:comment', 'in px')]
    """
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError):  # IPython's own syntax (%magic, !shell): words kept
        return []
    texts = _docstrings(cell_id, source, tree) + _comments(cell_id, source)
    return sorted(texts, key=lambda text: text.start)


def code_skeleton(source: str) -> str:
    """``source`` with the words of its docstrings and comments taken out: what a twin's code
    cell shares, byte for byte, with its English one.

    Examples
    --------
    >>> code_skeleton("x = 1  # one") == code_skeleton("x = 1  # 一")
    True
    """
    for text in reversed(code_texts("", source)):
        source = source[: text.start] + source[text.end :]
    return source


def code_messages(notebook: dict) -> list[tuple[str, str]]:
    """``(context, English)`` of every docstring and comment of the code cells."""
    return [
        (text.context, text.english)
        for cell in notebook["cells"]
        if cell["cell_type"] == "code"
        for text in code_texts(cell["id"], cell_source(cell))
    ]


def translated_code(cell_id: str, source: str, catalog) -> tuple[str, list[str], list[str]]:
    """The code cell ``source`` with its docstrings and comments in the catalog's words; the
    contexts left untranslated and the problems (a translation that would break the code)."""
    untranslated, problems = [], []
    for text in reversed(code_texts(cell_id, source)):
        chinese = translation(catalog, text.context, text.english)
        if chinese is None:
            untranslated.append(text.context)
            continue
        if text.context.startswith(f"{cell_id}:comment") and "\n" in chinese:
            problems.append(f"{text.context}: a comment's translation must be one line")
            continue
        changed = source[: text.start] + text.written(chinese) + source[text.end :]
        if code_skeleton(changed) != code_skeleton(source):
            problems.append(f"{text.context}: the translation changes the code around it")
            continue
        problems += translation_problems(text.context, text.english, chinese)
        source = changed
    return source, untranslated[::-1], problems


def read_catalog(path: Path):
    from babel.messages.pofile import read_po

    with path.open("rb") as po_file:
        return read_po(po_file, locale=LOCALE)


def write_catalog(path: Path, catalog) -> None:
    from babel.messages.pofile import write_po

    with path.open("wb") as po_file:
        write_po(po_file, catalog, width=0, include_previous=True)


def new_catalog(domain: str):
    from babel.messages.catalog import Catalog

    return Catalog(locale=LOCALE, project="course", domain=domain)


@dataclass
class TwinReport:
    """What the builder found for one lesson."""

    lesson: str
    cells: int = 0
    untranslated: list[str] = field(default_factory=list)  # cell ids, code texts' contexts
    problems: list[str] = field(default_factory=list)  # lost LaTeX, code, placeholders
    code_texts: int = 0  # docstrings and comments

    def untranslated_cells(self) -> int:
        return sum(":" not in context for context in self.untranslated)

    def line(self) -> str:
        done = self.cells - self.untranslated_cells()
        text = f"{self.lesson}: {done}/{self.cells} markdown cells translated"
        if self.code_texts:
            left = len(self.untranslated) - self.untranslated_cells()
            text += f", {self.code_texts - left}/{self.code_texts} docstrings and comments"
        if self.untranslated:
            shown = ", ".join(self.untranslated[:8])
            more = f" and {len(self.untranslated) - 8} more" if len(self.untranslated) > 8 else ""
            text += f"; untranslated: {shown}{more}"
        return text


def translation(catalog, cell_id: str, source: str) -> str | None:
    """The cell's Chinese, or None when the catalog has none for this exact source."""
    if catalog is None:
        return None
    message = catalog.get(source, context=cell_id)
    if message is None or message.fuzzy or not message.string:
        return None
    return message.string


def translation_problems(cell_id: str, english: str, chinese: str) -> list[str]:
    """How ``chinese`` fails to keep ``english``'s LaTeX, code spans, links and HTML tags."""
    problems = []
    wanted = Counter(TRANSLATED_ANCHORS.get(span, span) for span in kept_spans(english))
    # A sentence may put the formulas in another order: the same spans, counted. It may also
    # mark more as code or math than the English does (a name the Chinese writes as `addColor`,
    # a vertex as $A$); a link or a tag it adds is not the English's.
    given = Counter(kept_spans(chinese))
    lost = sorted((wanted - given).elements())
    added = sorted(span for span in (given - wanted).elements() if not _MARKED.fullmatch(span))
    if lost or added:
        problems.append(f"cell {cell_id}: LaTeX/code/links differ: lost {lost}, added {added}")
    return problems


def build_twin(english_path: Path, catalog) -> tuple[dict, TwinReport]:
    """The twin of the English lesson at ``english_path``, outputs cleared, and its report."""
    notebook = copy.deepcopy(read_notebook(english_path))
    report = TwinReport(english_path.stem)
    first_code = True
    for cell in notebook["cells"]:
        source = cell_source(cell)
        if cell["cell_type"] == "code":
            texts = len(code_texts(cell["id"], source))
            if texts:
                report.code_texts += texts
                source, untranslated, problems = translated_code(cell["id"], source, catalog)
                report.untranslated += untranslated
                report.problems += problems
            if first_code:
                source = LANGUAGE_LINES + source
                first_code = False
            cell["source"] = source
            cell["outputs"] = []
            cell["execution_count"] = None
        elif cell["cell_type"] == "markdown" and source.strip():
            report.cells += 1
            chinese = translation(catalog, cell["id"], source)
            if chinese is None:
                report.untranslated.append(cell["id"])
            else:
                report.problems += translation_problems(cell["id"], source, chinese)
                cell["source"] = chinese
    return notebook, report


def english_code(twin: dict) -> list[str]:
    """The twin's code cells as the English lesson has them: the language lines removed.

    Raises
    ------
    ValueError
        If the twin's first code cell does not start with the language lines.
    """
    sources = [cell_source(cell) for cell in twin["cells"] if cell["cell_type"] == "code"]
    if not sources or not sources[0].startswith(LANGUAGE_LINES):
        raise ValueError(_("twin: the first code cell must start with the language lines"))
    sources[0] = sources[0][len(LANGUAGE_LINES) :]
    return sources


def update_catalog(english_path: Path, po_path: Path) -> tuple[int, int]:
    """Merge the English markdown, docstrings and comments into the catalog at ``po_path``;
    (new, obsolete) counts.

    A cell (a docstring, a comment) whose source changed gets a new untranslated message (its
    old translation is kept as obsolete, for the translator to reuse).
    """
    catalog = read_catalog(po_path) if po_path.exists() else new_catalog(english_path.stem)
    notebook = read_notebook(english_path)
    wanted = markdown_messages(notebook) + code_messages(notebook)
    wanted_keys = {(cell_id, source) for cell_id, source in wanted}
    new = 0
    for cell_id, source in wanted:
        if catalog.get(source, context=cell_id) is None:
            catalog.add(source, "", context=cell_id)
            new += 1
    obsolete = 0
    for message in list(catalog):
        if not message.id or (message.context, message.id) in wanted_keys:
            continue
        catalog.delete(message.id, context=message.context)
        catalog.obsolete[(message.id, message.context)] = message
        obsolete += 1
    po_path.parent.mkdir(parents=True, exist_ok=True)
    write_catalog(po_path, catalog)
    return new, obsolete


def same_cells(notebook: dict, other: dict) -> bool:
    """Whether two notebooks have the same cells (ids, kinds, sources), whatever their outputs."""

    def cells(book: dict) -> list[tuple]:
        return [(cell.get("id"), cell["cell_type"], cell_source(cell)) for cell in book["cells"]]

    return cells(notebook) == cells(other)


def write_twins(notebooks: Path, update_po: bool = False, check: bool = False) -> list[TwinReport]:
    """Write (or with ``check``, only check) each lesson's twin that changed; a report per lesson.

    A twin whose cells are already those its English lesson and catalog make is left alone,
    outputs included.
    """
    folder = notebooks / TWIN_FOLDER
    reports = []
    for english_path in english_lessons(notebooks):
        po_path = folder / f"{english_path.stem}.po"
        if update_po and not check:
            update_catalog(english_path, po_path)
        catalog = read_catalog(po_path) if po_path.exists() else None
        twin, report = build_twin(english_path, catalog)
        reports.append(report)
        twin_path = folder / english_path.name
        if check or catalog is None:
            continue
        if not twin_path.exists() or not same_cells(read_notebook(twin_path), twin):
            write_notebook(twin_path, twin)
    return reports


def run(notebooks: Path, update_po: bool, check: bool) -> int:
    """The ``twins`` command: print a line per lesson and the problems; 1 if any remain."""
    reports = write_twins(notebooks, update_po, check)
    failed = False
    for report in reports:
        print(report.line())
        for problem in report.problems:
            print(f"  {problem}")
        failed |= bool(report.untranslated or report.problems)
    total = sum(report.untranslated_cells() for report in reports)
    texts = sum(len(report.untranslated) for report in reports) - total
    print(f"untranslated markdown cells: {total}, docstrings and comments: {texts}")
    return 1 if (check and failed) else 0
