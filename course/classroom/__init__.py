"""The classroom: the lessons as a course.

The third of the package's three layers (``design.md``): algorithms in the topic packages
(``course/curves/``, ``course/raster/``, ...), apps and checkers in :mod:`course.widgets`,
:mod:`course.check` and the lessons' chapters (:mod:`course.lessons`), and here what turns
them into a course:

- the lessons: :mod:`~course.classroom.notebooks` (found on disk),
  :mod:`~course.classroom.registry` (their registry entries and chapters),
  :mod:`~course.classroom.course_map` (the course map's table),
  :mod:`~course.classroom.lesson_shape` (teaching.md's budgets, measured),
  :mod:`~course.classroom.twins` (the Chinese lessons, from their catalogs),
  :mod:`~course.classroom.chinese_review` (what a Chinese student sees, against the
  glossary and the allow-list of Latin words);
- the editions: :mod:`~course.classroom.edition` (what they share),
  :mod:`~course.classroom.stubs` (an answer's stub), :mod:`~course.classroom.release` (the
  student edition, which is nbgrader's release), :mod:`~course.classroom.edition_folder`
  (written without losing a student's work);
- grading: :mod:`~course.classroom.exercise_list` (the declared exercises),
  :mod:`~course.classroom.nbgrader` (the nbgrader course folder),
  :mod:`~course.classroom.class_mistakes` (the class's named mistakes, after autograde);
- serving: :mod:`~course.classroom.cli` (``python -m course``),
  :mod:`~course.classroom.foreground` (a server run in the foreground, Ctrl-C to stop),
  :mod:`~course.classroom.serving` (kernel messages sent at once),
  :mod:`~course.classroom.link` (the nbgitpuller link), :mod:`~course.classroom.folders`
  (output folders, never clobbered unasked);
- for the lessons and their tests: :mod:`~course.classroom.source` (the library's source as
  "Going further" shows it), :mod:`~course.classroom.gallery` (key pictures as PNG files),
  :mod:`~course.classroom.pictures` and :mod:`~course.classroom.sliders` (how the lessons
  draw their pictures, and what a browser test predicts of a slider).

The plumbing (``tests/test_course.py`` lists it) uses the standard library only, so that
``python -m course student`` (a JSON transform) starts without numpy, matplotlib or
ipywidgets. Nothing here is imported by the layers below.
"""
