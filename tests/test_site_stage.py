"""site/stage.py: the website's source is the student edition, with MathJax bundled."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

from course.classroom.edition import HIDDEN_NOTE, STUB_LINE, exercise_stub, reveals
from course.classroom.notebooks import notebooks

REPOSITORY = Path(__file__).resolve().parent.parent
_spec = importlib.util.spec_from_file_location("stage", REPOSITORY / "site" / "stage.py")
stage = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(stage)


def text(value) -> str:
    return value if isinstance(value, str) else "".join(value)


def solution_triples(source: str) -> set[tuple[str, ...]]:
    """Every three consecutive lines the stub takes out of a solution."""
    kept = {line.strip() for line in exercise_stub(source).splitlines()}
    removed = [line.strip() for line in source.splitlines() if line.strip()]
    removed = [line for line in removed if line not in kept]
    return {tuple(removed[i : i + 3]) for i in range(len(removed) - 2)}


def shown_triples(notebook: dict) -> set[tuple[str, ...]]:
    """Every three consecutive lines a page shows: sources and text outputs."""
    parts = []
    for cell in notebook["cells"]:
        parts.append(text(cell["source"]))
        for output in cell.get("outputs", []):
            parts.append(text(output.get("text", "")))
            for kind, value in output.get("data", {}).items():
                if kind.startswith("text/"):
                    parts.append(text(value))
    lines = [line.strip() for part in parts for line in part.splitlines() if line.strip()]
    return {tuple(lines[i : i + 3]) for i in range(len(lines) - 2)}


def fake_mathjax(folder: Path) -> Path:
    for part in stage.MATHJAX_PARTS:
        path = folder / part if part.endswith(".js") else folder / part / "x.js"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(f"// {part}")
    (folder / "sre").mkdir()
    (folder / "sre" / "big.js").write_text("// not needed by a page")
    return folder


def test_the_published_source_shows_stubs_and_no_solution_and_the_teachers_keeps_them(tmp_path):
    stage.stage(tmp_path / "site", captions={}, mathjax=fake_mathjax(tmp_path / "es5"))
    stage.stage(tmp_path / "teacher", captions={}, teacher=True)
    leaking_pages = 0
    exercises = 0
    for book in notebooks(index=True):
        teacher = json.loads(book.path.read_text(encoding="utf-8"))
        name = "index.ipynb" if book.number == "00" else book.path.name
        page = json.loads((tmp_path / "site" / name).read_text(encoding="utf-8"))
        answers = set()
        for before, after in zip(teacher["cells"], page["cells"], strict=False):
            if "solution" in before.get("metadata", {}).get("tags", []):
                exercises += 1
                answers |= solution_triples(text(before["source"]))
                assert STUB_LINE in after["source"] and after["outputs"] == []
            elif reveals(before):
                assert after["source"] == HIDDEN_NOTE
        if answers & shown_triples(page):
            leaking_pages += 1
        kept = json.loads((tmp_path / "teacher" / name).read_text(encoding="utf-8"))
        assert answers <= shown_triples(kept), "the teacher's build keeps the solutions"
    assert exercises > 0
    assert leaking_pages == 0
    bundled = tmp_path / "site" / "_mathjax" / "mathjax"
    assert (bundled / "tex-mml-chtml.js").is_file()
    assert (bundled / "output" / "chtml" / "fonts" / "woff-v2" / "x.js").is_file()
    assert not (bundled / "sre").exists()
