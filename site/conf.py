"""Sphinx configuration of the course's website: ``make site``.

The source is ``build/site-source/``, written by ``site/stage.py`` from the committed
notebooks; myst-nb renders their outputs as committed (nothing is executed), and the
build needs no network. Formulas are typeset by the MathJax that ``site/stage.py`` bundled
into the source's ``_mathjax/`` (from npm's ``mathjax`` package): the pages load it from
the site itself, never from a CDN, so they render offline.

Two languages, two builds of this configuration: the English site from ``build/site-source/``
into ``build/site/``, the Chinese from ``build/site-source-zh-CN/`` (``site/stage.py
--language zh-CN``) into ``build/site/zh-CN/``, with ``-D language=zh_CN`` (Sphinx's and
Furo's own words in Chinese, Chinese search). ``_templates/page.html`` puts a link to the
page's twin at the top of every page.
"""

from __future__ import annotations

import json
import logging
from importlib import metadata
from pathlib import Path

project = "course"
author = "the course's authors"
copyright = "the course's authors. Code: MIT licence; lesson text and pictures: CC BY 4.0"
release = version = metadata.version("course")
html_title = "Computer graphics: Bézier curves, pixels and the 2D lab"

extensions = ["myst_nb"]
root_doc = "index"
exclude_patterns = ["_build", "**.ipynb_checkpoints", "alt.json", "_mathjax"]
# Relative to _static/, where _bundle_mathjax copies the staged MathJax.
mathjax_path = "mathjax/tex-mml-chtml.js"

# The committed outputs are the pages' pictures: never re-execute.
nb_execution_mode = "off"
# No widget JavaScript from a CDN: the apps show their still picture.
nb_ipywidgets_js: dict = {}
myst_enable_extensions = ["dollarmath", "amsmath"]
myst_heading_anchors = 3
# Markdown outputs (the course map's table) are MyST, as cells are: tables and page links.
nb_render_markdown_format = "myst"

html_theme = "furo"
templates_path = ["_templates"]
html_static_path = ["_static"]
html_css_files = ["cjk.css"]
# Furo's font stacks, then the Chinese font _static/cjk.css declares (see _subset_cjk_font).
_FONTS = {
    "font-stack": "-apple-system, BlinkMacSystemFont, Segoe UI, Helvetica, Arial, sans-serif, "
    'Apple Color Emoji, Segoe UI Emoji, "Course CJK"',
    "font-stack--monospace": '"SFMono-Regular", Menlo, Consolas, Monaco, Liberation Mono, '
    'Lucida Console, monospace, "Course CJK"',
}
# Furo shows its announcement bar when "announcement" is set: _templates/page.html fills the
# bar with the language switch, so the text here is never shown.
html_theme_options = {
    "announcement": "English · 中文",
    "light_css_variables": _FONTS,
    "dark_css_variables": _FONTS,
}
#: What _static/cjk.css's unicode-range covers: the characters the subset must hold.
CJK_RANGES = (
    (0x2E80, 0x2FFF),
    (0x3000, 0x303F),
    (0x3400, 0x4DBF),
    (0x4E00, 0x9FFF),
    (0xF900, 0xFAFF),
    (0xFF00, 0xFFEF),
)
html_show_sourcelink = False
html_copy_source = False


def _set_alt_text(app, doctree) -> None:
    """Each picture's alt text, from site/stage.py's alt.json (by the file's SHA-256)."""
    alt = json.loads((Path(app.srcdir) / "alt.json").read_text(encoding="utf-8"))
    for node in doctree.findall(lambda node: node.tagname == "image"):
        described = alt.get(Path(node["uri"]).stem)
        if described and not node.get("alt"):
            node["alt"] = described


def _bundle_mathjax(app, config) -> None:
    """Serve the MathJax that site/stage.py staged, from the site's own _static/."""
    bundled = Path(app.srcdir) / "_mathjax"
    if not (bundled / mathjax_path).is_file():
        raise RuntimeError(
            f"{bundled / mathjax_path} is missing: stage the site with --mathjax (make site)"
        )
    config.html_static_path = [*config.html_static_path, str(bundled)]


def _chinese_title(app, config) -> None:
    """The Chinese site's title, in Chinese (its pages' own titles come from the twins)."""
    if config.language == "zh_CN":
        config.html_title = "计算机图形学：贝塞尔曲线、像素与二维实验"


def _subset_cjk_font(app, exception) -> None:
    """Write _static/cjk-sans.otf: Noto Sans SC cut to the Chinese characters the build shows.

    The characters are read off the built pages and scripts (the search's and the theme's
    translated words included), so the font holds every one and nothing more: a few
    hundred kilobytes instead of the package's 8 MB.
    """
    if exception is not None or app.builder.format != "html":
        return
    from fontTools import subset

    from course.i18n import cjk_font_path

    logging.getLogger("fontTools").setLevel(logging.WARNING)  # its per-table notes

    out = Path(app.outdir)
    shown = set()
    for path in out.rglob("*"):
        # Another language's site may be built inside this one's (zh-CN/): not its pages.
        other = path.relative_to(out).parts[0] in ("zh-CN",) and out.name != "zh-CN"
        if (
            path.suffix in (".html", ".js")
            and "mathjax" not in path.parts
            and not other
            and path.is_file()
        ):
            text = path.read_text(encoding="utf-8", errors="ignore")
            shown |= {
                ord(letter)
                for letter in set(text)
                if any(low <= ord(letter) <= high for low, high in CJK_RANGES)
            }
    options = subset.Options()
    options.name_IDs = ["*"]  # keep the font's names and its OFL licence text
    font = subset.load_font(str(cjk_font_path()), options)
    subsetter = subset.Subsetter(options)
    subsetter.populate(unicodes=sorted(shown))
    subsetter.subset(font)
    subset.save_font(font, str(out / "_static" / "cjk-sans.otf"), options)


def setup(app):
    app.connect("build-finished", _subset_cjk_font)
    app.connect("config-inited", _bundle_mathjax)
    app.connect("config-inited", _chinese_title)
    app.connect("doctree-read", _set_alt_text)
    return {"parallel_read_safe": True}
