"""The classroom: the lessons as a course.

The third of the package's three layers (``design.md``): algorithms in
``course/*.py``, apps and checkers in :mod:`course.widgets` and
:mod:`course.check`, and here, beside the one-module-per-lesson registry in
:mod:`course.lessons`, what turns them into a course:

- :mod:`~course.classroom.notebooks`: the lesson notebooks found on disk;
- :mod:`~course.classroom.registry`: the registry's types, and the lesson
  modules found in :mod:`course.lessons`;
- :mod:`~course.classroom.course_map`: the course map's table;
- :mod:`~course.classroom.gallery`: every lesson's key pictures as PNG files;
- :mod:`~course.classroom.edition`: the student edition;
- :mod:`~course.classroom.cli`: ``python -m course``;
- :mod:`~course.classroom.link`: the nbgitpuller link that brings the lessons to a hub;
- :mod:`~course.classroom.folders`: output folders, never clobbered unasked;
- :mod:`~course.classroom.source`: the library's source as "Going further" shows it;
- :mod:`~course.classroom.pictures` and :mod:`~course.classroom.sliders`:
  how the lesson modules draw their pictures and how the browser tests
  predict a slider.

All but the last two use the standard library only, so that ``python -m
course student`` (a JSON transform) starts without numpy, matplotlib or
ipywidgets. Nothing here is imported by the layers below.
"""
