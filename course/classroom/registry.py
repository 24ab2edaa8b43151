"""What a notebook cannot say about itself: one registry entry per lesson chapter.

A lesson is a notebook ``notebooks/NN_topic.ipynb`` and a chapter, the package
``course/lessons/lNN_topic/``, whose module ``lesson.py`` defines ``LESSON``, a :class:`Lesson`:
the handout task it answers, what it teaches in one line, its key pictures
(for ``python -m course gallery`` and the course map) and the sliders and
drags that the browser tests make like a student, with the pixels the
picture must then show. The modules are discovered, not listed: adding a lesson is adding its
files. For example, ``course/lessons/l03_lines_and_triangles/lesson.py`` holds::

    LESSON = Lesson(
        handout="Lab 1 report (seed 001), Task 4 (line drawing) and Task 5 (triangles)",
        teaches="one line on what the lesson teaches",
        pictures=(Picture("03_name", "caption", lambda: app_picture(LineApp())),),
        sliders=(
            SliderMove(
                build=LineApp,  # exactly as the notebook's cell builds the app
                control="y1",  # a key of app.controls: a slider
                moves=(("ArrowRight", "ArrowRight"), ("End",)),
                landmarks=line_landmarks,  # app -> [Landmark], by the library
                app=0,  # the notebook's first slider app
            ),
        ),
    )

where ``line_landmarks(app)``, in the same module, computes with the
library (``course.raster.line``), not from the app's artists, pixels whose
colour is then known, using :func:`course.classroom.pictures.landmark_at` to
map data coordinates to the picture. Standard library only: the types here
hold the callables, the lesson modules import what they draw with.

Classroom tooling for the course's authors and its browser tests: its
inputs come from the lesson registry, never from a student, so this module
checks none (``UNCHECKED = True``; the fuzz test skips it).
"""

from __future__ import annotations

import dataclasses
import importlib
import pkgutil
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from course.i18n import _

__all__ = [
    "ENTRY_MODULE",
    "LESSONS_PACKAGE",
    "LESSON_MODULE",
    "DragMove",
    "Landmark",
    "Lesson",
    "Picture",
    "SliderMove",
    "lesson_modules",
    "lessons",
]

UNCHECKED = True  # see the module docstring

#: The package the lesson chapters are found in, their names in it, and the module of
#: each chapter that holds its ``LESSON``.
LESSONS_PACKAGE = "course.lessons"
LESSON_MODULE = re.compile(r"^l(\d\d)_(\w+)$")
ENTRY_MODULE = "lesson"


@dataclass(frozen=True)
class Landmark:
    """A pixel of an app's picture whose colour the library determines.

    ``row`` and ``column`` index the picture (row 0 at the top); the pixel
    must be within ``tolerance`` of ``color`` in every RGB channel (0-255).
    """

    what: str
    row: int
    column: int
    color: tuple[int, int, int]
    tolerance: int = 40


@dataclass(frozen=True)
class SliderMove:
    """How a student moves one slider of a lesson's app, and what must follow.

    ``app`` counts the notebook's slider apps from 0 in the order the
    notebook shows them. ``build`` makes that app (a
    :class:`course.widgets.base.SliderApp`) exactly as the notebook's cell
    does, so that a test can set ``control`` to the value the browser shows
    and render the picture the kernel should have sent. ``moves`` are key
    sequences pressed on the slider's focused handle (Playwright key names);
    the picture is checked after each one, so each must end on a value the
    slider's readout shows unambiguously. ``landmarks(app)`` names pixels
    whose colour the library computes for the app's current control values
    (for lesson 01, the red dot at the point ``de_casteljau`` returns).
    """

    build: Callable[[], Any]
    control: str
    moves: tuple[tuple[str, ...], ...]
    landmarks: Callable[[Any], list[Landmark]]
    app: int = 0


@dataclass(frozen=True)
class DragMove:
    """How a student drags one thing on a lesson's app, and what must follow.

    ``build`` makes the app (a :class:`course.widgets.base.SliderApp`) as the
    notebook's cell does; ``handle`` names what is grabbed (the first of the
    app's handles of that name, :meth:`~course.widgets.base.SliderApp.handles`),
    pressed where it is drawn. ``path`` lists the pointer's moves as offsets
    in picture pixels from that press; it is released at the last one.
    ``landmarks(app)`` names pixels whose colour the library computes for
    the app after the drag (for lesson 01, B(t) for the moved points).
    ``app`` counts the notebook's apps from 0, as in :class:`SliderMove`.
    """

    build: Callable[[], Any]
    handle: str
    path: tuple[tuple[float, float], ...]
    landmarks: Callable[[Any], list[Landmark]]
    app: int = 0


@dataclass(frozen=True)
class Picture:
    """One key figure of a lesson: a file name (no suffix), a caption, a PNG renderer."""

    name: str
    caption: str
    render: Callable[[], bytes]


@dataclass(frozen=True)
class Lesson:
    """A lesson's registry entry: what its notebook cannot say about itself.

    ``outcomes`` says what a student will be able to do after the lesson,
    ``minutes`` about how long it takes, and ``preview`` is one legible,
    single-panel picture for the course map. ``handout``, ``teaches`` and
    ``outcomes`` are English, marked with :func:`course.i18n.N_` in the
    lesson module; :func:`lessons` gives them in the current language.
    """

    handout: str
    teaches: str
    pictures: tuple[Picture, ...] = ()
    sliders: tuple[SliderMove, ...] = ()
    drags: tuple[DragMove, ...] = ()
    outcomes: tuple[str, ...] = ()
    minutes: int = 0
    preview: Picture | None = None


def lesson_modules() -> dict[str, str]:
    """The lesson modules ``lNN_topic`` of :mod:`course.lessons`: number -> module name.

    Examples
    --------
    >>> lesson_modules()["01"]
    'course.lessons.l01_de_casteljau.lesson'
    """
    package = importlib.import_module(LESSONS_PACKAGE)
    found: dict[str, str] = {}
    for module in pkgutil.iter_modules(package.__path__):
        match = LESSON_MODULE.match(module.name)
        if not match:
            continue
        if not module.ispkg:
            raise TypeError(
                _("{name}: a lesson is a chapter, a folder {name}/ with its lesson.py").format(
                    name=module.name
                )
            )
        number = match.group(1)
        name = f"{LESSONS_PACKAGE}.{module.name}.{ENTRY_MODULE}"
        if number in found:
            raise ValueError(
                _("lesson {number}: two chapters claim it, {found} and {name}").format(
                    number=number, found=found[number], name=name
                )
            )
        found[number] = name
    return dict(sorted(found.items()))


def lessons() -> dict[str, Lesson]:
    """Every lesson module's ``LESSON``, by lesson number, in lesson order.

    The entries' texts (``handout``, ``teaches``, ``outcomes``) are in the
    language :func:`course.use_language` set, so that the course map, and any
    notebook cell that reads an entry, speaks it; in English they are the
    modules' own entries. Importing the modules imports what they draw with
    (numpy, matplotlib, the apps); call this only where the pictures or the
    sliders are needed.
    """
    entries = {}
    for number, name in lesson_modules().items():
        lesson = getattr(importlib.import_module(name), "LESSON", None)
        if not isinstance(lesson, Lesson):
            raise TypeError(
                _("{name}: expected a module-level LESSON = Lesson(...); got {lesson_type}").format(
                    name=name, lesson_type=type(lesson).__name__
                )
            )
        entries[number] = dataclasses.replace(
            lesson,
            handout=_(lesson.handout),
            teaches=_(lesson.teaches),
            outcomes=tuple(_(outcome) for outcome in lesson.outcomes),
        )
    return entries
