"""The Chinese lessons: ``python -m course twins`` writes each twin from its catalog.

The translation of ``notebooks/NN_topic.ipynb`` is the gettext catalog
``notebooks/zh-CN/NN_topic.po``: one message per markdown cell, ``msgctxt`` the cell's id,
``msgid`` its source, ``msgstr`` the Chinese. The twin ``notebooks/zh-CN/NN_topic.ipynb`` is
the English lesson with each markdown cell replaced by its translation, the code cells copied,
and :data:`course.i18n.LANGUAGE_LINES` put before the first code cell. Its outputs come from
executing it (``make notebooks``); the builder writes a twin only when its cells changed (their
ids, kinds or sources), and then with the English outputs cleared: the other twins, and their
outputs, stay as they are.

Cell ids are stable (nbformat 4.5, kept by ``nbstripout --keep-id``), so inserting, moving or
deleting a cell leaves every other cell's message, and its translation, where it was. A message
is found by its exact id and source only: a cell whose English changed is untranslated until a
translator looks at it, never filled from a near match.

``--update-po`` merges the English markdown into the catalogs: a new or changed cell becomes
an untranslated message, a message no cell has any more becomes obsolete (``#~``). ``--check``
writes nothing and fails when a message is untranslated or a translation lost the LaTeX, code
spans, links' targets or HTML tags of its English.

Needs Babel (a dependency of the course) and the standard library only. A command-line tool
over the course's own files, never given a student's input: it checks none
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import copy
import json
import re
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
    untranslated: list[str] = field(default_factory=list)  # cell ids
    problems: list[str] = field(default_factory=list)  # lost LaTeX, code, placeholders

    def line(self) -> str:
        done = self.cells - len(self.untranslated)
        text = f"{self.lesson}: {done}/{self.cells} markdown cells translated"
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
    wanted = [TRANSLATED_ANCHORS.get(span, span) for span in kept_spans(english)]
    # A sentence may put the formulas in another order: the same spans, counted.
    if sorted(kept_spans(chinese)) != sorted(wanted):
        lost = sorted(set(wanted) - set(kept_spans(chinese)))
        added = sorted(set(kept_spans(chinese)) - set(wanted))
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
    """Merge the English markdown into the catalog at ``po_path``; (new, obsolete) counts.

    A cell whose source changed gets a new untranslated message (its old translation is kept
    as obsolete, for the translator to reuse).
    """
    catalog = read_catalog(po_path) if po_path.exists() else new_catalog(english_path.stem)
    wanted = markdown_messages(read_notebook(english_path))
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
    total = sum(len(report.untranslated) for report in reports)
    print(f"untranslated markdown cells: {total}")
    return 1 if (check and failed) else 0
