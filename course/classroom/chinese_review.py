"""What a Chinese student sees, gathered from the committed files, and the controls it names.

A Chinese student should see no English, one term per concept, Chinese punctuation between
Chinese words, and, where a lesson's prose names a control, that control under that name
(issue 36). This module gathers what a student sees; the tests run the rules on it
(``tests/test_chinese_review.py``, ``tests/test_chinese_text.py``, ``tests/test_glossary.py``).

What a student sees, gathered as :class:`~course.classroom.chinese_text.Shown` texts, each
with where it is:

* :func:`twin_outputs`: the executed outputs of the twins ``notebooks/zh-CN/NN_topic.ipynb``
  (stream, error, and the form JupyterLab shows of a result: HTML, markdown or plain text;
  a widget's or a picture's plain text is not shown, the widget's labels are read from the
  app itself);
* :func:`catalog_messages`: every ``msgstr`` of ``course/locale/zh_CN/LC_MESSAGES/course.po``,
  and of a lesson's ``notebooks/zh-CN/NN_topic.po`` (its markdown);
* :func:`figure_texts`: every text artist of the figures a chapter's figure functions draw
  (the functions of ``course/lessons/lNN_topic/*.py`` that return a ``Still`` or a
  ``Figure``), drawn in Chinese; a parameter without a default is given the sample of
  :func:`sample_arguments` by its name;
* :func:`app_texts`: every app of a chapter (a ``SliderApp`` subclass defined in it) built in
  Chinese with its defaults (or :func:`sample_arguments`): its controls' descriptions,
  options' labels, buttons and labels, and the text artists of its picture.

Chapters are found as :func:`course.classroom.registry.lesson_modules` finds them, so a new
chapter is reviewed without a change here.

What it says of them: :mod:`course.classroom.chinese_text` (Latin words, punctuation) and
:mod:`course.classroom.glossary` (terms); and here, :func:`control_mentions`: the prose's
names of controls (emphasised after a verb that sets a control, or quoted after one that
picks an option), to be found among the labels of the lesson's apps (:func:`app_labels`),
in English for the English lesson and in Chinese for its twin.

Classroom tooling over the course's own files, never given a student's input: it checks none
(``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import ast
import html
import importlib
import inspect
import json
import pkgutil
import re
import tokenize
from collections.abc import Callable, Iterable, Iterator
from io import StringIO
from pathlib import Path
from typing import Any

from course.classroom.chinese_text import CATALOG, NOTEBOOKS, Shown
from course.i18n import language

UNCHECKED = True  # see the module docstring

__all__ = [
    "app_classes",
    "app_labels",
    "app_texts",
    "by_lesson",
    "catalog_messages",
    "chapter_modules",
    "code_listing_text",
    "control_mentions",
    "english_markdown",
    "figure_texts",
    "lesson_numbers",
    "output_text",
    "sample_arguments",
    "twin_markdown",
    "twin_outputs",
    "unknown_controls",
    "widget_labels",
]


def lesson_numbers() -> list[str]:
    """The lessons' numbers, as the registry finds their chapters."""
    from course.classroom.registry import lesson_modules

    return list(lesson_modules())


def _twins(notebooks: Path) -> list[tuple[str, dict]]:
    found = []
    for path in sorted((notebooks / "zh-CN").glob("[0-9][0-9]_*.ipynb")):
        found.append((path.name[:2], json.loads(path.read_text(encoding="utf-8"))))
    return found


def _source(value: Any) -> str:
    return value if isinstance(value, str) else "".join(value)


def twin_markdown(notebooks: Path = NOTEBOOKS) -> list[Shown]:
    """Every markdown cell of every twin, in order, as ``NN cell i``."""
    return [
        Shown(number, f"cell {index}", _source(cell["source"]))
        for number, notebook in _twins(notebooks)
        for index, cell in enumerate(notebook["cells"])
        if cell["cell_type"] == "markdown"
    ]


def _html_text(markup: str) -> str:
    return html.unescape(re.sub(r"<[^>]+>", " ", markup))


def output_text(output: dict) -> str:
    """What JupyterLab shows of one output as text ("" for a picture or a widget).

    Examples
    --------
    >>> output_text({"output_type": "stream", "name": "stdout", "text": ["通过\\n"]})
    '通过\\n'
    >>> output_text({"output_type": "display_data",
    ...              "data": {"image/png": "", "text/plain": "ZoomApp(k=3)"}})
    ''
    >>> output_text({"output_type": "error", "ename": "ValueError", "evalue": "坏"})
    'ValueError: 坏'
    """
    kind = output["output_type"]
    if kind == "stream":
        return _source(output["text"])
    if kind == "error":
        return f"{output['ename']}: {output['evalue']}"
    data = output.get("data", {})
    if any(key.startswith(("image/", "application/vnd.jupyter.widget")) for key in data):
        return ""  # the picture or the live widget is shown, not its text form
    if "text/html" in data:
        return _html_text(_source(data["text/html"]))
    if "text/markdown" in data:
        return _source(data["text/markdown"])
    return _source(data.get("text/plain", ""))


def code_listing_text(text: str) -> str | None:
    """The comments and docstrings of ``text`` when it is a Python listing, else None.

    A printed listing (``inspect.getsource``) is code; its words are its comments and
    docstrings.

    Examples
    --------
    >>> code_listing_text('def f(x):\\n    \"\"\"Twice x.\"\"\"\\n    return 2 * x  # doubled\\n')
    'Twice x.\\n# doubled'
    >>> code_listing_text("通过：全部 4 个用例") is None
    True
    """
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError):
        return None
    definitions = [
        node
        for node in ast.walk(tree)
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))
    ]
    if not definitions:
        return None
    words = [ast.get_docstring(node) or "" for node in definitions]
    try:
        tokens = tokenize.generate_tokens(StringIO(text).readline)
        words += [token.string for token in tokens if token.type == tokenize.COMMENT]
    except (tokenize.TokenError, IndentationError):
        pass
    return "\n".join(word for word in words if word)


def twin_outputs(notebooks: Path = NOTEBOOKS) -> list[Shown]:
    """The text every twin's executed outputs show, as ``cell i output``."""
    shown = []
    for number, notebook in _twins(notebooks):
        for index, cell in enumerate(notebook["cells"]):
            for output in cell.get("outputs", []):
                text = output_text(output)
                listing = code_listing_text(text) if text else None
                if listing is not None:
                    text = listing
                markup = "text/markdown" in output.get("data", {})
                if text.strip():
                    where = f"cell {index} output"
                    shown.append(Shown(number, where, text, loose=True, markup=markup))
    return shown


def _read_po(path: Path):
    from babel.messages.pofile import read_po

    with path.open("rb") as po_file:
        return read_po(po_file, locale="zh_CN")


_CHAPTER = re.compile(r"course/lessons/l(\d\d)_")


def catalog_messages(catalog: Path = CATALOG, notebooks: Path = NOTEBOOKS) -> list[Shown]:
    """Every translation of the library's catalog and of the lessons' catalogs.

    A library message belongs to the lesson whose chapter its source is in (``""`` when it
    is shared); a lesson's message, to its lesson, where ``NN_topic.po`` and its cell id.
    """
    shown = []
    for message in _read_po(catalog):
        if not message.id:
            continue
        lessons = {
            found.group(1)
            for file, _line in message.locations
            for found in [_CHAPTER.match(file)]
            if found
        }
        lesson = min(lessons) if len(lessons) == 1 else ""
        where = f"course.po {message.id if isinstance(message.id, str) else message.id[0]!r}"
        strings = message.string if isinstance(message.string, (tuple, list)) else [message.string]
        shown += [Shown(lesson, where, text, loose=True) for text in strings if text]
    for path in sorted((notebooks / "zh-CN").glob("[0-9][0-9]_*.po")):
        for message in _read_po(path):
            if message.id and message.string:
                where = f"{path.name} {message.context}"
                shown.append(Shown(path.name[:2], where, message.string))
    return shown


# --- figures and apps, drawn in Chinese --------------------------------------------------


def chapter_modules(number: str) -> list[Any]:
    """Every module of lesson ``number``'s chapter, imported."""
    from course.classroom.registry import lesson_modules

    package = importlib.import_module(lesson_modules()[number].rsplit(".", 1)[0])
    return [
        importlib.import_module(f"{package.__name__}.{module.name}")
        for module in pkgutil.iter_modules(package.__path__)
    ]


def sample_arguments() -> dict[str, Any]:
    """An argument by parameter name, for a figure or an app whose parameter has no default.

    A new name fails the review with a message naming it: give the parameter a default, or
    a sample here.
    """
    import numpy as np

    from course.images import SEED_000_CUBIC

    ramp = np.tile(np.linspace(0.0, 1.0, 96), (96, 1))
    return {
        "points": SEED_000_CUBIC,
        "t": 0.25,
        "seed": "000",
        "gray": ramp,
        "image": ramp,
        "images": {"阈值": (ramp > 0.5).astype(float), "蓝噪声": ramp},
        "centre": (48.0, 48.0),
    }


def _call(function: Callable, samples: dict[str, Any]) -> Any:
    arguments = {}
    for name, parameter in inspect.signature(function).parameters.items():
        if parameter.default is not inspect.Parameter.empty or parameter.kind in (
            parameter.VAR_POSITIONAL,
            parameter.VAR_KEYWORD,
        ):
            continue
        if name not in samples:
            raise LookupError(
                f"{function.__module__}.{function.__qualname__}: no sample for parameter "
                f"{name!r}; give it a default or add one to sample_arguments()"
            )
        arguments[name] = samples[name]
    return function(**arguments)


def _returns(function: Callable, names: tuple[str, ...]) -> bool:
    annotation = inspect.signature(function).return_annotation
    return any(name == str(getattr(annotation, "__name__", annotation)) for name in names)


def _texts(figure: Any) -> list[str]:
    from matplotlib.text import Text

    return [text.get_text() for text in figure.findobj(Text) if text.get_text().strip()]


def figure_texts(number: str) -> list[Shown]:
    """The texts of every figure lesson ``number``'s figure functions draw, in Chinese.

    A figure function is a public function of a chapter module that returns a ``Still``
    or a ``Figure``; every figure a ``Still`` is made of is read, not rendered (its text
    artists are all there before it is drawn).
    """
    import matplotlib.pyplot as plt

    from course.widgets.picture import Still

    samples = sample_arguments()
    shown: list[Shown] = []
    of = Still.of.__func__
    seen: list[str] = []

    def recording(cls, figure, caption):
        seen.extend(_texts(figure))
        plt.close(figure)
        return cls(b"\x89PNG", caption)

    with language("zh-CN"):
        Still.of = classmethod(recording)
        try:
            for module in chapter_modules(number):
                for name, function in vars(module).items():
                    if (
                        name.startswith("_")
                        or not inspect.isfunction(function)
                        or function.__module__ != module.__name__
                        or not _returns(function, ("Still", "Figure"))
                    ):
                        continue
                    seen.clear()
                    result = _call(function, samples)
                    if isinstance(result, Still):
                        seen.append(result.caption)
                    elif result is not None:
                        seen.extend(_texts(result))
                        plt.close(result)
                    where = f"figure {module.__name__.rsplit('.', 1)[1]}.{name}"
                    shown += [Shown(number, where, text) for text in seen]
        finally:
            Still.of = classmethod(of)
    return shown


def app_classes(number: str) -> list[type]:
    """The apps lesson ``number``'s chapter defines: its ``SliderApp`` subclasses."""
    from course.widgets.base import SliderApp

    return [
        value
        for module in chapter_modules(number)
        for value in vars(module).values()
        if inspect.isclass(value)
        and issubclass(value, SliderApp)
        and value.__module__ == module.__name__
    ]


def widget_labels(widget: Any) -> list[str]:
    """Every label a widget tree shows: descriptions, options, tooltips, labels, buttons."""
    import ipywidgets as widgets

    labels: list[str] = []
    stack = [widget]
    while stack:
        item = stack.pop()
        for attribute in ("description", "tooltip", "placeholder"):
            value = getattr(item, attribute, None)
            if isinstance(value, str) and value.strip("\u200b \n"):
                labels.append(value)
        if isinstance(item, (widgets.Label, widgets.HTML, widgets.HTMLMath)) and item.value:
            labels.append(_html_text(item.value))
        option_labels = getattr(item, "_options_labels", None)
        if option_labels:
            labels += [str(label) for label in option_labels]
        labels += [str(tip) for tip in getattr(item, "tooltips", None) or () if tip]
        stack += list(getattr(item, "children", ()))
    return labels


def _build(app_class: type, samples: dict[str, Any]) -> Any:
    return _call(app_class, samples)


def app_labels(number: str, code: str) -> set[str]:
    """The controls' names and options of lesson ``number``'s apps, in language ``code``."""
    samples = sample_arguments()
    labels: set[str] = set()
    with language(code):
        for app_class in app_classes(number):
            app = _build(app_class, samples)
            for control in app.controls.values():
                labels.update(_label_key(label) for label in widget_labels(control))
    return labels


def app_texts(number: str) -> list[Shown]:
    """Lesson ``number``'s apps built in Chinese: their widgets' labels and picture texts."""
    import matplotlib.pyplot as plt

    samples = sample_arguments()
    shown = []
    with language("zh-CN"):
        for app_class in app_classes(number):
            app = _build(app_class, samples)
            app.refresh()
            where = f"app {app_class.__name__}"
            shown += [Shown(number, where, label) for label in widget_labels(app.widget)]
            shown += [Shown(number, f"{where} picture", text) for text in _texts(app.figure)]
            plt.close(app.figure)
    return shown


# --- the prose's names of controls -----------------------------------------------------------

_SETS_EN = r"(?:set|raise|lower|move|switch|turn|slide|pick|change|increase|decrease|put)"
_MENTIONS = {
    "en": (re.compile(rf"\b{_SETS_EN}\s+(?:the\s+)?\*([^*\n]+)\*", re.IGNORECASE),),
    "zh-CN": (
        re.compile(r"[把将]\s*\*([^*\n]+)\*\s*(?:调|设|切换|拖|改|换|选|移|增|减|拉)"),
        re.compile(r"(?:调整|调节|拖动|移动|切换|改变|增大|减小|拉动)\s*\*([^*\n]+)\*"),
        re.compile(r"(?:切换成|切换到|换成|设为|选成|选择|选)\s*[“«]([^”»\n]+)[”»]"),
        # The Chinese edition's convention: a control or an option is named in 「」, as
        # Chinese software manuals name buttons and menus (Chinese fonts have no italics).
        re.compile(r"「([^」\n]+)」"),
    ),
}


def control_mentions(text: str, code: str) -> list[str]:
    """The names of controls that prose in language ``code`` gives, in order.

    Examples
    --------
    >>> control_mentions("Drag the points and move *segments*. * Set *segments* to 1.", "en")
    ['segments', 'segments']
    >>> control_mentions("把 *控制点数* 调到 10，再把 *采样方式* 切换成“报告的采样”。", "zh-CN")
    ['控制点数', '采样方式', '报告的采样']
    >>> control_mentions("把「规则」切换成「左上规则」，再看「线段数」的读数。", "zh-CN")
    ['规则', '左上规则', '线段数']
    >>> control_mentions("the *gap* is two points", "en")
    []
    """
    found = []
    for pattern in _MENTIONS[code]:
        found += [(hit.start(), hit.group(1).strip()) for hit in pattern.finditer(text)]
    return [name for _start, name in sorted(found)]


def _label_key(label: str) -> str:
    return re.sub(r"[\s:：。.]+$", "", label.strip()).casefold()


def unknown_controls(mentions: Iterable[str], labels: set[str]) -> list[str]:
    """The mentions that name no label (compared without case and trailing punctuation).

    Examples
    --------
    >>> unknown_controls(["points", "t"], {"控制点数", "t"})
    ['points']
    """
    keys = {_label_key(label) for label in labels}
    return [name for name in mentions if _label_key(name) not in keys]


def english_markdown(notebooks: Path = NOTEBOOKS) -> list[Shown]:
    """Every markdown cell of every English lesson, as ``cell i``."""
    shown = []
    for path in sorted(notebooks.glob("[0-9][0-9]_*.ipynb")):
        notebook = json.loads(path.read_text(encoding="utf-8"))
        shown += [
            Shown(path.name[:2], f"cell {index}", _source(cell["source"]))
            for index, cell in enumerate(notebook["cells"])
            if cell["cell_type"] == "markdown"
        ]
    return shown


def by_lesson(texts: Iterable[Shown]) -> Iterator[tuple[str, str]]:
    """``(lesson, prose)``: each lesson's texts joined in order."""
    joined: dict[str, list[str]] = {}
    for shown in texts:
        joined.setdefault(shown.lesson, []).append(shown.text)
    for number, parts in joined.items():
        yield number, "\n\n".join(parts)
