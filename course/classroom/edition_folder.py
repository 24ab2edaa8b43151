"""The student edition in its folder: written, and updated without losing a student's work.

Standard library only: ``python -m course student`` needs no numpy, matplotlib
or ipywidgets.

:func:`write_student_edition` writes every lesson's student edition
(:func:`course.classroom.release.student_notebook`) into a folder, and records
what it wrote in :data:`MANIFEST`: run again, it tells a notebook the student
edited from one only run, and never replaces the student's work
(:class:`EditionReport` says what it did). ``python -m course student``
(:mod:`course.classroom.cli`) calls it.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from course.classroom.edition import (
    cell_source,
    check_notebook,
    notebook_text,
    read_notebook,
)
from course.classroom.folders import (
    check_output_folder,
    loads_json,
    read_json_file,
    read_text_file,
)
from course.classroom.notebooks import LANGUAGES, NOTEBOOKS, notebooks
from course.classroom.release import student_notebook
from course.i18n import _

__all__ = ["MANIFEST", "EditionReport", "write_student_edition"]

#: The student edition's record of what it wrote: a digest of each notebook's sources.
MANIFEST = ".edition.json"


@dataclass(frozen=True)
class EditionReport:
    """What :func:`write_student_edition` did, notebook by notebook."""

    written: list[Path] = field(default_factory=list)
    unchanged: list[Path] = field(default_factory=list)
    #: Notebooks the student edited, left as they are: the lesson has not changed.
    kept: list[Path] = field(default_factory=list)
    #: (the student's edited notebook, the new edition written beside it).
    beside: list[tuple[Path, Path]] = field(default_factory=list)

    def lines(self) -> list[str]:
        """One line per notebook that needs the reader's attention, then a summary."""
        notes = [
            _(
                "{edited} has your work: the lesson changed, and its new edition is {new}, "
                "beside it (yours is untouched)"
            ).format(edited=edited.name, new=new.name)
            for edited, new in self.beside
        ]
        notes.append(
            _(
                "notebooks written: {written}; unchanged: {unchanged}; with your edits kept: {kept}"
            ).format(
                written=len(self.written),
                unchanged=len(self.unchanged),
                kept=len(self.kept) + len(self.beside),
            )
        )
        return notes


def _work(text: str) -> str:
    """A digest of what a student edits in a notebook: its cells' types and sources.

    Running cells changes outputs and counts, not the work: a notebook only run
    is replaced by a new edition; one whose sources differ is the student's.
    """
    try:
        notebook = loads_json(text)
        check_notebook(notebook)
        cells = [[cell["cell_type"], cell_source(cell)] for cell in notebook["cells"]]
    except ValueError:  # not JSON, nested too deep, not a notebook
        cells = ["unreadable", text]
    return hashlib.sha256(json.dumps(cells).encode("utf-8")).hexdigest()


def _read_manifest(out: Path) -> dict[str, str]:
    path = out / MANIFEST
    if not path.is_file():
        return {}
    try:
        manifest = read_json_file(path)
    except (OSError, ValueError):
        return {}
    if not isinstance(manifest, dict):
        return {}
    return {k: v for k, v in manifest.items() if isinstance(k, str) and isinstance(v, str)}


def _beside_name(out: Path, name: str, manifest: dict[str, str]) -> str:
    """The first ``NN_topic.new.ipynb`` (``.new2``, ...) that holds no edits of the student's."""
    stem = name.removesuffix(".ipynb")
    for number in range(1, 1000):
        candidate = f"{stem}.new{number if number > 1 else ''}.ipynb"
        path = out / candidate
        if not path.exists() or (
            path.is_file() and manifest.get(candidate) == _work(_read_text(path))
        ):
            return candidate
    raise ValueError(
        _("out: {out} holds 999 new editions of {name}; remove some").format(out=out, name=name)
    )


def _is_edition(out: Any) -> bool:
    """Whether ``out`` holds a student edition this function wrote (its manifest).

    A folder that holds only other languages' editions (``student/zh-CN/``, written
    before the English one) counts as one: the English edition goes beside them.
    """
    try:
        if not isinstance(out, (str, os.PathLike)):
            return False
        out = Path(out)
        if (out / MANIFEST).is_file():
            return True
        entries = list(out.iterdir()) if out.is_dir() else []
        return bool(entries) and all(
            entry.name in LANGUAGES and (entry / MANIFEST).is_file() for entry in entries
        )
    except OSError:
        return False


def _read_text(path: Path) -> str:
    try:
        return read_text_file(path)
    except (OSError, ValueError):  # ValueError: not UTF-8, or replaced by a pipe since checked
        return ""


def write_student_edition(
    out: str | Path, folder: str | Path = NOTEBOOKS, force: bool = False
) -> EditionReport:
    """Write or update the student edition of every notebook in ``folder`` in ``out``.

    A student's work is never lost. The edition records what it wrote in
    ``out/.edition.json``; run again, it writes new lessons, replaces the
    notebooks the student has not edited (running cells is not editing), and
    leaves every edited one alone: where that lesson changed, its new
    edition is written beside it as ``NN_topic.new.ipynb``.

    A non-empty ``out`` that is not an edition is refused unless ``force``;
    even then no file is replaced. Every notebook is read and every file
    checked before any is written, and each file is written whole (to a
    temporary file, then moved into place).
    """
    if not isinstance(force, bool):
        raise TypeError(
            _("force: expected True or False; got {force_type} {force:.60}").format(
                force_type=type(force).__name__, force=repr(force)
            )
        )
    check_output_folder(out, force or _is_edition(out))
    out = Path(out)
    editions = []
    for book in notebooks(folder, index=True):  # every notebook read before any is written
        notebook = read_notebook(book.path)
        try:
            edition = student_notebook(notebook)
        except ValueError as error:
            raise ValueError(_("{path}: {error}").format(path=book.path, error=error)) from None
        editions.append((book.path.name, notebook_text(edition)))
    manifest = _read_manifest(out)
    report = EditionReport()
    plan: list[tuple[str, str]] = []
    for name, text in editions:
        path = out / name
        work = _work(text)
        if path.is_dir():
            raise ValueError(
                _("out: {path} is a folder; the edition needs that name for a notebook").format(
                    path=path
                )
            )
        if path.exists() and not path.is_file():
            raise ValueError(
                _(
                    "out: {path} is not a regular file but a pipe, a device or a socket; the "
                    "edition needs that name for a notebook"
                ).format(path=path)
            )
        if not path.exists():
            plan.append((name, text))
            report.written.append(path)
            continue
        current = _work(_read_text(path))
        if current == work:
            report.unchanged.append(path)
        elif manifest.get(name) == current:  # as the edition wrote it: no work of the student's
            plan.append((name, text))
            report.written.append(path)
        elif manifest.get(name) == work:  # the student's, and the lesson has not changed
            report.kept.append(path)
        else:
            beside = _beside_name(out, name, manifest)
            plan.append((beside, text))
            report.beside.append((path, out / beside))
            report.written.append(out / beside)
        manifest[name] = work
    for name, text in plan:
        manifest[name] = _work(text)
    out.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=".edition-", dir=out))
    try:
        for name, text in plan:
            (staging / name).write_text(text, encoding="utf-8")
        (staging / MANIFEST).write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n")
        for name, _edition in plan:
            os.replace(staging / name, out / name)
        os.replace(staging / MANIFEST, out / MANIFEST)
    except OSError as error:
        raise ValueError(
            _("out: cannot write into {out} ({reason})").format(
                out=out, reason=error.strerror or error
            )
        ) from None
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return report
