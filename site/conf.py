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
# Furo shows its announcement bar when this is set: _templates/page.html fills the bar with
# the language switch, so the text here is never shown.
html_theme_options = {"announcement": "English · 中文"}
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


def setup(app):
    app.connect("config-inited", _bundle_mathjax)
    app.connect("config-inited", _chinese_title)
    app.connect("doctree-read", _set_alt_text)
    return {"parallel_read_safe": True}
