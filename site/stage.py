"""Stage the committed notebooks as the website's source: ``python site/stage.py OUT``.

Nothing is executed: the pages show the outputs committed in ``notebooks/``. The site is
the student edition, safe to publish: each exercise shows its stub, without the solution's
output, and a cell that reveals a solution another way shows the student edition's note
instead (``course.classroom.edition``); ``--teacher`` keeps the answers, for a teacher's
own copy. Staging

- copies every ``NN_topic.ipynb``, the course map ``00_index.ipynb`` as ``index.ipynb``
  (the landing page), its links rewritten, and a hidden table of contents added to it;
- drops each app's live-widget output, so that the app's still picture shows, as on GitHub;
- writes ``alt.json``: for each picture (by the SHA-256 of its bytes, which names the file
  myst-nb writes) its alt text: the gallery's caption when the picture is one of the gallery's
  (``python -m course gallery``, same pixels), else the output's own text, else a description
  from the lesson's title. ``site/conf.py`` sets it on the page's ``<img>``;
- with ``--language zh-CN``, stages the Chinese twins of ``notebooks/zh-CN/`` instead, and
  takes the gallery's captions in Chinese, as the twins' pictures are drawn. ``make site``
  builds that source into the English site's ``zh-CN/`` folder, so that each page's twin is
  the same file name one folder down or up: ``site/_templates/page.html`` links them, on
  every page;
- copies MathJax (``--mathjax``: the ``es5`` folder of npm's ``mathjax`` package, which
  ``make site`` fetches with ``npm pack``) into ``_mathjax/``, what a page loads to typeset
  its formulas and nothing more, so that formulas render offline.
"""

from __future__ import annotations

import argparse
import base64
import hashlib
import io
import json
import re
import shutil
import sys
from pathlib import Path

from course.classroom.edition import (
    EXERCISE_TAG,
    SOLUTION_TAG,
    hidden_cell,
    reveals,
)
from course.classroom.notebooks import DEFAULT_LANGUAGE, LANGUAGES, language_folder
from course.classroom.release import without_source_import
from course.classroom.stubs import exercise_stub

REPOSITORY = Path(__file__).resolve().parent.parent
#: What a page needs of MathJax's es5 folder: the combined TeX component, the TeX
#: extensions it loads on demand, its fonts, and the menu's and accessibility's parts.
MATHJAX_PARTS = (
    "tex-mml-chtml.js",
    "input/tex/extensions",
    "output/chtml/fonts/woff-v2",
    "a11y",
    "ui",
)
NOTEBOOKS = REPOSITORY / "notebooks"
LESSON_FILE = re.compile(r"^(\d\d)_\w+\.ipynb$")
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"
IMAGES = ("image/png", "image/jpeg")
HEADING = re.compile(r"^#+\s+(.+?)\s*$", re.MULTILINE)
# A repr that says nothing about the picture: IPython's, or an app's constructor call.
UNINFORMATIVE = re.compile(r"^<.*object>$|^\w+App\(")


def myst_anchors(markdown: str) -> str:
    """Links to a heading as JupyterLab spells its anchor (``#The-handouts``), as MyST does.

    JupyterLab keeps the heading's case; MyST's heading anchors are lower case.

    >>> myst_anchors("[the handouts](index.ipynb#The-handouts)")
    '[the handouts](index.ipynb#the-handouts)'
    """
    return re.sub(
        r"(\]\([^)#\s]*\.ipynb#)([^)\s]+)\)",
        lambda link: f"{link.group(1)}{link.group(2).lower()})",
        markdown,
    )


def text(value: str | list[str]) -> str:
    return value if isinstance(value, str) else "".join(value)


def pixels_key(data: bytes) -> str:
    """A picture's identity by its pixels, whatever its encoding."""
    from PIL import Image

    with Image.open(io.BytesIO(data)) as image:
        rgb = image.convert("RGB")
        return hashlib.sha256(repr(rgb.size).encode() + rgb.tobytes()).hexdigest()


def gallery_captions(language: str = DEFAULT_LANGUAGE) -> dict[str, str]:
    """The gallery's captions, by the pixels of the picture each one describes.

    The pictures are drawn in ``language``, as a twin's pictures are, with that language's
    titles and legends. A caption the library's catalog does not translate is left out
    (the page's own text describes that picture), so that no English reaches another
    language's pages.
    """
    from course.classroom.registry import lessons
    from course.i18n import _
    from course.i18n import language as shown_in

    captions = {}
    with shown_in(language):
        for lesson in lessons().values():
            for picture in lesson.pictures:
                caption = _(picture.caption)
                if language == DEFAULT_LANGUAGE or caption != picture.caption:
                    captions[pixels_key(picture.render())] = caption
    return captions


def in_language(words: str, language: str) -> bool:
    """Whether ``words`` can describe a picture on a page in ``language``.

    A Chinese page's picture is not described in English: an output's text that has no
    Chinese character (a caption the library does not translate) is not used there.

    >>> in_language("B(t) = (5/4, 3/2)", "zh-CN"), in_language("贝塞尔曲线 B(t)", "zh-CN")
    (False, True)
    """
    if language == DEFAULT_LANGUAGE:
        return True
    return any("\u4e00" <= letter <= "\u9fff" for letter in words)


def plain_heading(markdown: str) -> str | None:
    """A markdown heading's text without its link syntax."""
    found = HEADING.search(markdown)
    return re.sub(r"\[([^]]*)\]\([^)]*\)", r"\1", found.group(1)) if found else None


def student_cells(cells: list[dict], language: str = DEFAULT_LANGUAGE) -> list[dict]:
    """The cells as the student edition shows them, the other cells' outputs kept.

    An exercise shows its stub and no output (the solution's check said PASS); a cell
    that reveals a solution is the student edition's note, in ``language``.
    """
    shown = []
    for number, cell in enumerate(cells):
        tags = cell.get("metadata", {}).get("tags", [])
        if reveals(cell):
            cell = hidden_cell(cell, number, language)
        elif cell["cell_type"] == "code" and without_source_import(cell) is None:
            continue
        elif cell["cell_type"] == "code" and SOLUTION_TAG in tags:
            cell = dict(cell, source=exercise_stub(text(cell["source"]), language), outputs=[])
            cell["execution_count"] = None
            cell["metadata"] = dict(
                cell["metadata"], tags=[EXERCISE_TAG if t == SOLUTION_TAG else t for t in tags]
            )
        elif cell["cell_type"] == "code":
            cell = without_source_import(cell)
        shown.append(cell)
    return shown


def bundle_mathjax(es5: Path, out: Path) -> None:
    """Copy what a page needs of MathJax's ``es5`` folder into ``out``."""
    if not (es5 / MATHJAX_PARTS[0]).is_file():
        raise SystemExit(
            f"site/stage.py: no MathJax in {es5}: pass --mathjax, the es5 folder of npm's "
            "mathjax package (make site fetches it with npm pack)"
        )
    for part in MATHJAX_PARTS:
        source, target = es5 / part, out / part
        target.parent.mkdir(parents=True, exist_ok=True)
        if source.is_dir():
            shutil.copytree(source, target)
        else:
            shutil.copy2(source, target)


def stage(
    out: Path,
    notebooks: Path = NOTEBOOKS,
    captions: dict[str, str] | None = None,
    teacher: bool = False,
    mathjax: Path | None = None,
    language: str = DEFAULT_LANGUAGE,
) -> int:
    """Write the website's source to ``out``; return the number of pictures.

    The student edition unless ``teacher``; MathJax bundled from ``mathjax`` if given.
    ``language`` is the lessons' (``notebooks`` holds its twins): on its pages a picture is
    described only by words in that language (:func:`in_language`), else by its page's.
    """
    captions = gallery_captions() if captions is None else captions
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    books = sorted(path for path in notebooks.iterdir() if LESSON_FILE.match(path.name))
    alt: dict[str, str] = {}
    for path in books:
        notebook = json.loads(path.read_text(encoding="utf-8"))
        title = next(
            (
                plain_heading(text(cell["source"]))
                for cell in notebook["cells"]
                if cell["cell_type"] == "markdown" and plain_heading(text(cell["source"]))
            ),
            path.stem,
        )
        count = 0
        if not teacher:
            notebook["cells"] = student_cells(notebook["cells"], language)
        # nbformat 4.5 cells carry ids; the committed ones are normalised without.
        notebook["nbformat_minor"] = max(notebook.get("nbformat_minor", 0), 5)
        for number, cell in enumerate(notebook["cells"]):
            cell.setdefault("id", f"cell-{number}")
            if cell["cell_type"] == "markdown":
                cell["source"] = myst_anchors(
                    text(cell["source"]).replace("00_index.ipynb", "index.ipynb")
                )
            described = title
            for output in cell.get("outputs", []):
                data = output.get("data", {})
                data.pop(WIDGET_VIEW, None)
                if "text/markdown" in data:
                    markdown = text(data["text/markdown"])
                    markdown = markdown.replace("](00_index.ipynb", "](index.ipynb")
                    data["text/markdown"] = markdown
                    described = plain_heading(markdown) or described
                for mime in IMAGES:
                    if mime not in data:
                        continue
                    count += 1
                    raw = base64.b64decode(text(data[mime]))
                    said = text(data.get("text/plain", "")).strip().strip("'\"")
                    if pixels_key(raw) in captions:
                        description = captions[pixels_key(raw)]
                    elif said and not UNINFORMATIVE.match(said) and in_language(said, language):
                        description = said
                    elif language != DEFAULT_LANGUAGE:
                        description = f"{described} ({count})"
                    elif described != title:
                        description = f"{described}: one panel of the lesson"
                    else:
                        description = f"{title}, picture {count}"
                    alt[hashlib.sha256(raw).hexdigest()] = description
        name = "index.ipynb" if path.name.startswith("00_") else path.name
        if name == "index.ipynb":
            pages = "\n".join(book.stem for book in books if not book.name.startswith("00_"))
            notebook["cells"].append(
                {
                    "cell_type": "markdown",
                    "id": "table-of-contents",
                    "metadata": {},
                    "source": f"```{{toctree}}\n:hidden:\n\n{pages}\n```\n",
                }
            )
        (out / name).write_text(json.dumps(notebook, ensure_ascii=False, indent=1), "utf-8")
    (out / "alt.json").write_text(json.dumps(alt, ensure_ascii=False, indent=1), "utf-8")
    if mathjax is not None:
        bundle_mathjax(mathjax, out / "_mathjax" / "mathjax")
    return len(alt)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path, help="the folder to write (replaced)")
    parser.add_argument("--notebooks", type=Path, default=NOTEBOOKS)
    parser.add_argument(
        "--teacher", action="store_true", help="keep the answers: never publish this build"
    )
    parser.add_argument(
        "--mathjax", type=Path, help="the es5 folder of npm's mathjax package, bundled"
    )
    parser.add_argument(
        "--language",
        choices=LANGUAGES,
        default=DEFAULT_LANGUAGE,
        help="the lessons' language: another than English stages notebooks/<language>/",
    )
    args = parser.parse_args(argv)
    pictures = stage(
        args.out,
        language_folder(args.notebooks, args.language),
        gallery_captions(args.language),
        teacher=args.teacher,
        mathjax=args.mathjax,
        language=args.language,
    )
    print(f"site/stage.py: {pictures} pictures staged in {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
