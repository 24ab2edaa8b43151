"""The library's own messages: English untouched, every Chinese translation present and sound."""

from __future__ import annotations

import ast
import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest
from babel.messages.extract import extract_from_dir
from babel.messages.pofile import read_po
from matplotlib.figure import Figure

import course
import course.curves.handout_loops
import course.curves.paths
import course.filters
import course.metrics
import course.poisson.problem
import course.raster
import course.raster.canvas
import course.raster.triangles
from course import i18n
from course.classroom.folders import check_output_folder
from course.classroom.twins import placeholders
from course.lessons.l04_supersampling import figures as supersampling_figures
from course.lessons.l04_supersampling.apps import SupersampleApp
from course.lessons.l07_filtering.apps import KernelApp
from course.widgets.base import parse_points

ROOT = Path(__file__).resolve().parents[1]
POT = ROOT / "course" / "locale" / "course.pot"
PO = ROOT / "course" / "locale" / "zh_CN" / "LC_MESSAGES" / "course.po"


def catalog(path: Path):
    with path.open("rb") as file:
        return read_po(file)


def message_ids(messages) -> set[str]:
    return {m.id if isinstance(m.id, str) else m.id[0] for m in messages if m.id}


@pytest.fixture(autouse=True)
def english_after():
    yield
    course.use_language("en")


def test_the_template_holds_every_marked_message():
    extracted = {
        message if isinstance(message, str) else message[0]
        for _, _, message, _, _ in extract_from_dir(
            str(ROOT / "course"),
            method_map=[("**.py", "python")],
            # Babel skips folders named _* by default: course/_validate holds messages too.
            directory_filter=lambda path: Path(path).name != "__pycache__",
        )
    }
    assert extracted, "nothing is marked"
    assert message_ids(catalog(POT)) == extracted, "run: make messages"


def test_every_message_is_translated_and_none_is_left_over():
    template, chinese = catalog(POT), catalog(PO)
    assert message_ids(chinese) == message_ids(template)
    untranslated = [m.id for m in chinese if m.id and (m.fuzzy or not m.string)]
    assert untranslated == [], f"untranslated in {PO.name} (translate them there): {untranslated}"


def test_a_translation_keeps_the_placeholders_of_its_english():
    for message in catalog(PO):
        if message.id:
            assert placeholders(message.string) == placeholders(message.id), message.id


def test_english_shows_the_source_strings_and_chinese_the_catalog():
    assert course.current_language() == "en"
    for message in catalog(PO):
        if message.id:
            assert i18n._(message.id) == message.id
    course.use_language("zh-CN")
    assert course.current_language() == "zh-CN"
    for message in catalog(PO):
        if message.id:
            assert i18n._(message.id) == message.string


def test_a_truth_value_is_shown_as_yes_or_no_in_the_current_language():
    import numpy as np

    assert [i18n.yes_no(value) for value in (True, False, np.bool_(True), 0)] == [
        "yes",
        "no",
        "yes",
        "no",
    ]
    with i18n.message_language("zh-CN"):
        assert (i18n.yes_no(True), i18n.yes_no(np.float64(0.0) < 1e-10)) == ("是", "是")
        assert i18n.yes_no(False) == "否"
    assert i18n.yes_no(True) == "yes"


def test_a_missing_mo_is_compiled_from_the_po_in_memory(tmp_path, monkeypatch):
    folder = tmp_path / "zh_CN" / "LC_MESSAGES"
    folder.mkdir(parents=True)
    shutil.copy(PO, folder / "course.po")
    monkeypatch.setattr(i18n, "LOCALE_DIR", tmp_path)
    monkeypatch.setattr(i18n, "_loaded", {})
    assert i18n.gettext_catalog("zh_CN").gettext("RMS error") == "均方根误差"
    assert not (folder / "course.mo").exists()
    monkeypatch.setattr(i18n, "_loaded", {})
    (folder / "course.po").unlink()
    with pytest.raises(FileNotFoundError, match="zh_CN"):
        i18n.gettext_catalog("zh_CN")


def test_a_stale_mo_gives_way_to_a_newer_po(tmp_path, monkeypatch):
    folder = tmp_path / "zh_CN" / "LC_MESSAGES"
    folder.mkdir(parents=True)
    (folder / "course.mo").write_bytes(b"not a catalog")
    shutil.copy(PO, folder / "course.po")
    stale = (folder / "course.po").stat().st_mtime - 10
    import os

    os.utime(folder / "course.mo", (stale, stale))
    monkeypatch.setattr(i18n, "LOCALE_DIR", tmp_path)
    monkeypatch.setattr(i18n, "_loaded", {})
    assert i18n.gettext_catalog("zh_CN").gettext("RMS error") == "均方根误差"


@pytest.mark.parametrize("code", ["zh", "zh_CN", "EN", ""])
def test_an_unknown_language_is_refused_by_name(code):
    with pytest.raises(ValueError, match="code must be one of"):
        course.use_language(code)
    assert course.current_language() == "en"


def test_a_language_is_a_string():
    with pytest.raises(TypeError, match="code must be a str"):
        course.use_language(None)


def test_every_translation_renders_without_a_missing_glyph(caplog):
    import matplotlib as mpl

    english_fonts = list(mpl.rcParams["font.family"])
    course.use_language("zh-CN")
    assert mpl.rcParams["font.family"][: len(english_fonts)] == english_fonts
    texts = [m.string for m in catalog(PO) if m.id]
    figure = Figure(figsize=(8, 0.3 * len(texts)))
    for row, text in enumerate(texts):
        figure.text(0.01, 1 - (row + 0.5) / len(texts), text, fontsize=8)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        figure.savefig(__import__("io").BytesIO(), format="png", dpi=10)  # glyphs, not pixels
    missing = [str(w.message) for w in caught if "missing from font" in str(w.message)]
    # Mathtext ($...$) has no fallback font: it logs its missing glyphs instead of warning.
    missing += [r.getMessage() for r in caplog.records if "does not have a glyph" in r.getMessage()]
    assert missing == []
    course.use_language("en")
    assert list(mpl.rcParams["font.family"]) == english_fonts


def test_bold_chinese_needs_no_bold_face_and_logs_nothing(caplog):
    # The font package has only a regular face: without the stand-in, matplotlib logs
    # "findfont: Failed to find font weight bold for Noto Sans SC" under every bold title.
    with i18n.language("zh-CN"):
        figure = Figure()
        figure.suptitle("贝塞尔曲线", weight="bold")
        figure.text(0.5, 0.5, "x", weight="bold")
        with caplog.at_level("INFO", logger="matplotlib.font_manager"):
            figure.savefig(__import__("io").BytesIO(), format="png")
    assert [r.getMessage() for r in caplog.records if "findfont" in r.getMessage()] == []


def test_english_without_the_font_shows_chinese_as_missing_glyphs():
    # The check above can fail: the English fonts lack these glyphs.
    figure = Figure()
    figure.text(0.1, 0.5, "均方根误差")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        figure.savefig(__import__("io").BytesIO(), format="png")
    assert any("missing from font" in str(w.message) for w in caught)


def test_a_figure_speaks_the_language_and_english_is_unchanged():
    english = supersampling_figures.box_response_figure().caption
    with i18n.language("zh-CN"):
        chinese = supersampling_figures.box_response_figure().caption
    assert chinese == "在奈奎斯特频率 0.5 处，盒式滤波保留 0.637；在 1、2 和 3 周期/像素处为零"
    assert supersampling_figures.box_response_figure().caption == english
    assert english == (
        "at the Nyquist frequency 0.5 the box keeps 0.637; zero at 1, 2 and 3 cycles per pixel"
    )


def test_no_english_message_holds_chinese_but_a_quoted_handout():
    # English is the source's own strings: Chinese there would show in English, except the
    # handouts' own words quoted in parentheses, "the basic part (基础部分)".
    import re

    def chinese(text: str) -> bool:
        return any("\u4e00" <= c <= "\u9fff" for c in re.sub(r"\([^()]*\)", "", text))

    assert [m.id for m in catalog(POT) if m.id and chinese(m.id)] == []
    assert chinese("the basic part 基础部分") and not chinese("the basic part (基础部分)")


def _binds_underscore(function: ast.AST) -> bool:
    """Whether ``function`` assigns the name ``_`` in its own scope (not a comprehension's)."""
    stack = list(ast.iter_child_nodes(function))
    while stack:
        node = stack.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
            continue
        if isinstance(node, (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)):
            continue
        if isinstance(node, ast.Name) and node.id == "_" and isinstance(node.ctx, ast.Store):
            return True
        stack.extend(ast.iter_child_nodes(node))
    return False


def _calls_underscore(function: ast.AST) -> bool:
    return any(
        isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "_"
        for node in ast.walk(function)
    )


def test_no_function_hides_the_translation_function_behind_a_throwaway_name():
    # `_, density = ...` then `_("...")` calls the first value: a TypeError where a
    # message was meant (one hid in a checker's pass picture, one in a new message).
    hiding = [
        f"{path.relative_to(ROOT)}:{node.lineno} {node.name}"
        for path in sorted((ROOT / "course").rglob("*.py"))
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
        and _binds_underscore(node)
        and _calls_underscore(node)
    ]
    assert hiding == []


@pytest.mark.parametrize(
    ("call", "english"),
    [
        (lambda: course.raster.nearest_pixels([[1, 2, 3]]), "points must have shape (K, 2)"),
        (
            lambda: course.filters.convolve(np.zeros((4, 4)), np.ones((2, 2))),
            "must be a 3 x 3 array",
        ),
        (lambda: course.metrics.rmse(np.zeros((2, 2)), np.zeros((3, 3))), "same shape"),
        (lambda: parse_points(None), "text must be a string such as"),
        (lambda: SupersampleApp(size=1000, out_size=1), "out_size must be at least"),
        (lambda: check_output_folder(3, False), "out: expected a folder path"),
    ],
)
def test_an_error_raised_to_a_student_speaks_their_language(call, english):
    with pytest.raises((ValueError, TypeError)) as raised:
        call()
    assert english in str(raised.value)
    course.use_language("zh-CN")
    with pytest.raises(type(raised.value)) as translated:
        call()
    shown = str(translated.value)
    assert english not in shown and any("\u4e00" <= c <= "\u9fff" for c in shown), shown


def _cjk(text: str) -> bool:
    return any("\u4e00" <= c <= "\u9fff" for c in text)


@pytest.mark.parametrize(
    ("call", "english", "chinese"),
    [
        (
            lambda: course.poisson.problem.inpaint_problem(np.zeros((5, 5)), np.ones((4, 4))),
            "mask must have shape (5, 5), the image's (H, W); got shape (4, 4)",
            "mask 的形状必须是 (5, 5)，即图像的 (H, W)；实际形状为 (4, 4)",
        ),
        (
            lambda: course.curves.paths.as_path([]),
            "points must be a 2-D array of shape (N, d), one row per point; got shape (0,)",
            "points 必须是形状为 (N, d) 的二维数组，每行一个点；实际形状为 (0,)",
        ),
        (
            lambda: course.raster.canvas.blank((4, 2.5)),
            "shape[1] (width) must be an integer; got float 2.5",
            "shape[1]（宽） 必须是整数；实际得到 float 2.5",
        ),
        (
            lambda: course.curves.handout_loops.loop_pixels([[0, 0], [1, 1]], "003"),
            "loop must be a HandoutLoop, e.g. HANDOUT_LOOPS['003'] or NAIVE_LOOP; got str '003'",
            "loop 必须是 HandoutLoop，例如 HANDOUT_LOOPS['003'] 或 NAIVE_LOOP；实际为 str '003'",
        ),
        (
            lambda: course.raster.triangles.triangle((0, 0), (2**40, 0), (0, 5)),
            "p1 coordinates must lie within +-1048576; got [1099511627776.0, 0.0]",
            "p1 的坐标必须在 +-1048576 以内；实际为 [1099511627776.0, 0.0]",
        ),
        (
            lambda: KernelApp(image=np.zeros((20, 20)), window=(1.5, 3)),
            "window[0] (row) must be an integer; got float 1.5",
            "window[0]（行） 必须是整数；实际得到 float 1.5",
        ),
        (
            lambda: course.use_language(3),
            "code must be a str such as 'zh-CN', not int",
            "code 必须是像 'zh-CN' 这样的字符串，而不是 int",
        ),
    ],
)
def test_a_students_error_is_the_catalogs_chinese_and_english_is_unchanged(call, english, chinese):
    # The whole message: a piece passed in (a name's gloss, what a shape is) is Chinese too.
    with pytest.raises((ValueError, TypeError)) as raised:
        call()
    assert str(raised.value) == english
    with i18n.language("zh-CN"), pytest.raises(type(raised.value)) as translated:
        call()
    assert str(translated.value) == chinese
    assert _cjk(chinese) and english.split()[0] in chinese  # it names the parameter
    assert course.current_language() == "en"


# Raised messages left in English on purpose, by module and function: each is shown to
# no student.
ENGLISH_RAISES = {
    # The catalog of that language is missing: nothing to translate the message with.
    ("course/i18n.py", "gettext_catalog"),
    # An app written without a handle it lists: for the course's developers.
    ("course/widgets/pointer.py", "drag"),
    # The browser tests' own landmarks, asked of the zone plate only.
    ("course/lessons/l04_supersampling/lesson.py", "supersample_landmarks"),
    # Lesson 01 prints this function's source (English, byte for byte) and prints its message
    # through lesson.print_recursion_error, which reads the English numbers and says them in
    # the student's language.
    ("course/curves/bezier.py", "de_casteljau_recursive"),
    # The Chinese edition's scanners, about the course's own files (a malformed glossary.tsv,
    # a lesson function with no sample argument): for the course's authors, never a student.
    ("course/classroom/glossary.py", "load_glossary"),
    ("course/classroom/chinese_review.py", "_call"),
}
# Exceptions caught inside the course, whose message no one reads: browser_drawing's
# NotDrawable only tells FigureView to draw with Agg instead.
UNSEEN_EXCEPTIONS = {"NotDrawable"}


def _prose_outside_underscore(node: ast.AST, names: dict[str, list[ast.AST]]) -> bool:
    """Whether the message ``node`` holds words not passed through ``_()``.

    Calls are not entered (``_()``, ``repr()``, a helper's result), except the receiver of a
    method (``"...".format()``, ``message.format()``); a name is followed to its assignments.
    """
    if isinstance(node, ast.Constant):
        return isinstance(node.value, str) and any(c.isalpha() for c in node.value)
    if isinstance(node, ast.JoinedStr):
        return any(_prose_outside_underscore(part, names) for part in node.values)
    if isinstance(node, ast.FormattedValue):
        return _prose_outside_underscore(node.value, names)
    if isinstance(node, ast.Call):
        method = node.func
        return isinstance(method, ast.Attribute) and _prose_outside_underscore(method.value, names)
    if isinstance(node, ast.Name):
        values = names.pop(node.id, [])  # popped: a name assigned from itself is seen once
        return any(_prose_outside_underscore(value, names) for value in values)
    return any(_prose_outside_underscore(child, names) for child in ast.iter_child_nodes(node))


def _english_raises() -> list[str]:
    """``path:line function`` of each raise (or ``parser.error``) whose message is English."""
    found = []
    for path in sorted((ROOT / "course").rglob("*.py")):
        relative = path.relative_to(ROOT).as_posix()
        tree = ast.parse(path.read_text(encoding="utf-8"))
        scopes = [tree, *(n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef))]
        for scope in scopes:
            body = list(ast.walk(scope)) if scope is not tree else list(ast.iter_child_nodes(tree))
            assigned: dict[str, list[ast.AST]] = {}
            for node in body:
                if isinstance(node, ast.Assign):
                    for target in node.targets:
                        if isinstance(target, ast.Name):
                            assigned.setdefault(target.id, []).append(node.value)
            for node in body:
                if isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call):
                    call = node.exc
                elif (
                    isinstance(node, ast.Call)
                    and isinstance(node.func, ast.Attribute)
                    and node.func.attr == "error"
                    and ast.unparse(node.func.value) == "parser"
                ):
                    call = node
                else:
                    continue
                messages = call.args[:1] or [keyword.value for keyword in call.keywords]
                name = getattr(scope, "name", "")
                unseen = ast.unparse(call.func) in UNSEEN_EXCEPTIONS
                if unseen or (relative, name) in ENGLISH_RAISES:
                    continue
                if any(_prose_outside_underscore(m, dict(assigned)) for m in messages):
                    found.append(f"{relative}:{node.lineno} {name}")
    return sorted(set(found))


def test_every_raised_message_goes_through_the_translation_function():
    # A student's error follows their language: an f-string or a literal raised without
    # _() stays English in the Chinese edition.
    assert _english_raises() == []


def test_the_raise_finder_finds_english_and_passes_marked_messages():
    def english(source: str) -> bool:
        tree = ast.parse(source)
        (call,) = [n.exc for n in ast.walk(tree) if isinstance(n, ast.Raise)]
        assigned = {
            t.id: [n.value]
            for n in ast.walk(tree)
            if isinstance(n, ast.Assign)
            for t in n.targets
            if isinstance(t, ast.Name)
        }
        return _prose_outside_underscore(call.args[0], assigned)

    assert english('raise ValueError(f"x must be positive; got {x}")')
    assert english('raise ValueError("got {x}".format(x=x))')
    assert english('message = "bad"\nraise ValueError(message)')
    assert english('raise ValueError(name + "bad")')
    assert not english('raise ValueError(_("got {x}").format(x=repr(x)))')
    assert not english('name = f"{name}: "\nraise ValueError(name + _("bad"))')
    assert not english('raise ValueError(f"{message}\\n{hint(m)}")')
    assert not english("raise ValueError(str(error))")
