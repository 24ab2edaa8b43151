"""The course's website (``make site``) in Chromium: every page, picture and internal link.

The built site (``build/site/``, or ``$SITE``) is served over HTTP on 127.0.0.1, and the
browser may fetch nothing else: a request that leaves the site is aborted, so the test
sees what a reader offline would: formulas must be typeset by the MathJax the site ships.
No page may show three consecutive lines of an exercise's solution. Every HTML page of the
build must load, every picture on it decode, and every link that stays inside the site
reach a file, and an anchor the element it names. The landing page must be the course
map, linking every lesson. A screenshot of the landing page and of lesson 01 goes to
``docs/browser/``, and one of the Chinese landing page. The Chinese site, in ``zh-CN/``,
is held to the same, and every page of either language links its twin in the other,
which must exist.
"""

from __future__ import annotations

import functools
import http.server
import json
import os
import re
import threading
from collections.abc import Iterator
from html import unescape
from pathlib import Path
from urllib.parse import urldefrag, urlparse

import pytest
from playwright.sync_api import Browser, Page

from course.classroom.stubs import stub_line
from tests_browser.conftest import REPOSITORY, free_port

SITE = Path(os.environ.get("SITE", REPOSITORY / "build" / "site")).resolve()
DOCS = REPOSITORY / "docs" / "browser"
LESSON_PAGES = sorted(SITE.glob("[0-9][0-9]_*.html"))
#: The Chinese site's folder: the same page names as the English one's.
CHINESE = SITE / "zh-CN"
CHINESE_LESSON_PAGES = sorted(CHINESE.glob("[0-9][0-9]_*.html"))
#: Every page of both languages.
PAGES = sorted(SITE.glob("*.html")) + sorted(CHINESE.glob("*.html"))

# For every <img>: whether it decoded, and its natural size.
IMAGES = """async () => Promise.all([...document.images].map(async (image) => {
    try { await image.decode(); } catch (error) { return [image.src, false, 0]; }
    return [image.src, image.complete, image.naturalWidth * image.naturalHeight];
}))"""
LINKS = "() => [...document.querySelectorAll('a[href]')].map((link) => link.href)"


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args) -> None:
        pass


@pytest.fixture(scope="module")
def site() -> Iterator[str]:
    if not (SITE / "index.html").is_file():
        pytest.fail(f"{SITE}/index.html is missing: build the website first with `make site`")
    port = free_port()
    handler = functools.partial(QuietHandler, directory=str(SITE))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", port), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{port}/"
    finally:
        httpd.shutdown()
        httpd.server_close()


@pytest.fixture
def offline_page(browser: Browser, site: str) -> Iterator[Page]:
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    context.set_default_timeout(60_000)
    context.route(
        "**/*",
        lambda route: route.continue_() if route.request.url.startswith(site) else route.abort(),
    )
    page = context.new_page()
    yield page
    context.close()


def visit(page: Page, url: str) -> tuple[list, list[str]]:
    """Load ``url``; its pictures (src, decoded, pixels) and its links."""
    response = page.goto(url, wait_until="load")
    assert response is not None and response.ok, f"{url}: {response and response.status}"
    return page.evaluate(IMAGES), page.evaluate(LINKS)


def test_the_site_has_the_course_map_and_every_lesson_in_both_languages():
    assert (SITE / "index.html").is_file() and (CHINESE / "index.html").is_file()
    lessons = sorted(path.stem for path in (REPOSITORY / "notebooks").glob("[0-9][0-9]_*.ipynb"))
    assert [page.stem for page in LESSON_PAGES] == [name for name in lessons if name[:2] != "00"]
    assert [page.stem for page in CHINESE_LESSON_PAGES] == [page.stem for page in LESSON_PAGES]


SWITCH = re.compile(r'<nav class="language-switch"[^>]*>(.*?)</nav>', re.DOTALL)


def test_every_page_of_both_languages_links_its_twin_in_the_other():
    """Read off the built files: the switch is in the page's HTML, whatever a script does."""
    assert len(PAGES) >= 2 * (len(LESSON_PAGES) + 1)
    for path in PAGES:
        switches = SWITCH.findall(path.read_text(encoding="utf-8"))
        assert len(switches) == 1, f"{path.relative_to(SITE)}: {len(switches)} language switches"
        targets = re.findall(r'<a href="([^"]+)" hreflang="([^"]+)"', switches[0])
        chinese = path.parent == CHINESE
        assert [language for _, language in targets] == ["en" if chinese else "zh-CN"]
        twin = (path.parent / targets[0][0]).resolve()
        assert twin == (SITE if chinese else CHINESE).resolve() / path.name, path
        assert twin.is_file(), f"{path.relative_to(SITE)} links {targets[0][0]}, which is missing"
    chinese_page = (CHINESE / "01_de_casteljau.html").read_text(encoding="utf-8")
    assert '<html class="no-js" lang="zh-CN"' in chinese_page
    assert re.search(r"<h1>[^<]*[\u4e00-\u9fff]", chinese_page), "lesson 01's title in Chinese"


def test_every_page_loads_every_picture_decodes_and_no_internal_link_is_broken(
    offline_page: Page, site: str
):
    links: set[str] = set()
    pictures = 0
    for path in PAGES:
        images, found = visit(offline_page, site + path.relative_to(SITE).as_posix())
        broken = [src for src, decoded, size in images if not (decoded and size > 0)]
        assert not broken, f"{path.name}: pictures that do not decode: {broken}"
        pictures += len(images)
        links.update(link for link in found if link.startswith(site))
    assert pictures >= len(LESSON_PAGES) * 6, f"only {pictures} pictures on the whole site"

    anchors: dict[str, set[str]] = {}
    missing = []
    for link in sorted(links):
        address, fragment = urldefrag(link)
        relative = urlparse(address).path.lstrip("/") or "index.html"
        target = SITE / relative
        if relative.endswith("/"):
            target = target / "index.html"
        if not target.is_file():
            missing.append(link)
            continue
        if fragment and target.suffix == ".html":
            if address not in anchors:
                offline_page.goto(address, wait_until="load")
                anchors[address] = set(
                    offline_page.evaluate(
                        "() => [...document.querySelectorAll('[id]')].map(e => e.id)"
                    )
                )
            if fragment not in anchors[address]:
                missing.append(link)
    assert not missing, f"internal links to nothing: {missing}"


def test_the_landing_page_is_the_course_map_and_links_every_lesson(offline_page: Page, site: str):
    images, links = visit(offline_page, site)
    assert offline_page.locator("h1").first.inner_text().startswith("Course map")
    for lesson in LESSON_PAGES:
        assert site + lesson.name in links, f"the course map does not link {lesson.name}"
    assert len(images) >= len(LESSON_PAGES), "the course map shows one picture per lesson"
    DOCS.mkdir(parents=True, exist_ok=True)
    offline_page.screenshot(path=str(DOCS / "site_course_map.png"))
    images, links = visit(offline_page, site + "zh-CN/")
    assert offline_page.locator("h1").first.inner_text().startswith("课程地图")
    for lesson in CHINESE_LESSON_PAGES:
        assert f"{site}zh-CN/{lesson.name}" in links, f"the Chinese map does not link {lesson.name}"
    assert len(images) >= len(CHINESE_LESSON_PAGES), "the Chinese map shows a picture per lesson"
    # The Chinese text is drawn in the font the site ships: Chromium here has no Chinese font.
    loaded = offline_page.evaluate(
        """async () => (await document.fonts.load('16px "Course CJK"', '课程地图'))
            .map((face) => face.status)"""
    )
    assert loaded == ["loaded"], loaded
    offline_page.screenshot(path=str(DOCS / "site_course_map_zh-CN.png"))


def test_a_lesson_page_shows_its_apps_still_pictures_with_the_gallerys_captions(
    offline_page: Page, site: str
):
    images, _ = visit(offline_page, site + "01_de_casteljau.html")
    assert images, "lesson 01 shows its pictures"
    alts = offline_page.evaluate("() => [...document.images].map((image) => image.alt)")
    assert all(alts), "every picture has alt text"
    # The app's still picture, captioned as the gallery captions it (docs/ shows the same).
    assert "de Casteljau's levels for 4 control points at t = 0.50" in alts
    assert (
        offline_page.locator("script[type='application/vnd.jupyter.widget-view+json']").count() == 0
    )
    offline_page.locator("img").first.scroll_into_view_if_needed()
    offline_page.screenshot(path=str(DOCS / "site_lesson01.png"))


def solution_triples() -> set[tuple[str, ...]]:
    """Every three consecutive lines the student edition's stubs take out of the solutions."""
    from course.classroom.edition import cell_source, solution_cells
    from course.classroom.stubs import exercise_stub

    triples = set()
    for path in (REPOSITORY / "notebooks").glob("[0-9][0-9]_*.ipynb"):
        notebook = json.loads(path.read_text(encoding="utf-8"))
        for index in solution_cells(notebook):
            source = cell_source(notebook["cells"][index])
            kept = {line.strip() for line in exercise_stub(source).splitlines()}
            removed = [line.strip() for line in source.splitlines() if line.strip()]
            removed = [line for line in removed if line not in kept]
            triples |= {tuple(removed[i : i + 3]) for i in range(len(removed) - 2)}
    return triples


def page_lines(path: Path) -> list[str]:
    """The text of a page's code and outputs, line by line, as a reader sees it."""
    markup = path.read_text(encoding="utf-8")
    markup = re.sub(r"<(script|style)\b.*?</\1>", "", markup, flags=re.DOTALL)
    plain = unescape(re.sub(r"<[^>]+>", "", markup))
    return [line.strip() for line in plain.splitlines() if line.strip()]


def test_no_page_of_the_published_site_shows_a_solution():
    answers = solution_triples()
    assert len(answers) > 30, "the solutions have lines to look for"
    leaking = []
    for path in PAGES:
        lines = page_lines(path)
        shown = {tuple(lines[i : i + 3]) for i in range(len(lines) - 2)}
        if answers & shown:
            leaking.append(path.relative_to(SITE).as_posix())
    print(f"\npages of {SITE.name}/ (both languages) containing a solution line: {len(leaking)}")
    assert leaking == []
    # Every exercise shows its stub instead, in the page's language.
    for pages, language in ((LESSON_PAGES, "en"), (CHINESE_LESSON_PAGES, "zh-CN")):
        says = stub_line(language).split('"')[1]  # "your code here", «在这里写你的代码»
        assert any(says in " ".join(page_lines(page)) for page in pages), says


def test_formulas_render_offline_from_the_sites_own_mathjax(offline_page: Page, site: str):
    """The browser may fetch nothing outside the site: MathJax must come from it."""
    for path in PAGES:
        markup = path.read_text(encoding="utf-8")
        sources = re.findall(r"<script[^>]*\bsrc=\"([^\"]+)\"", markup)
        assert all(not urlparse(source).netloc for source in sources), (path.name, sources)
        assert "cdn.jsdelivr" not in markup and "cdnjs" not in markup, path.name
    assert (SITE / "_static" / "mathjax" / "tex-mml-chtml.js").is_file()
    assert (CHINESE / "_static" / "mathjax" / "tex-mml-chtml.js").is_file()
    visit(offline_page, site + "01_de_casteljau.html")
    offline_page.wait_for_function(
        "() => document.querySelectorAll('mjx-container').length > 0", timeout=60_000
    )
    typeset = offline_page.locator("mjx-container").count()
    raw = offline_page.evaluate(
        "() => [...document.querySelectorAll('.math')].filter(e => /\\\\\\(|\\$/.test("
        "e.textContent) && !e.querySelector('mjx-container')).length"
    )
    assert typeset > 5 and raw == 0, (typeset, raw)
