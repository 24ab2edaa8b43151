"""Lesson 03 · Lines and triangles: the chapter beside ``notebooks/03_lines_and_triangles.ipynb``.

- :mod:`.lesson`: the registry entry ``LESSON`` and the printing and landmark helpers;
- :mod:`.check`: the exercises' checkers, imported as
  ``from course.lessons.l03_lines_and_triangles import check``;
- :mod:`.apps`: the interactive apps;
- :mod:`.figures`: the still pictures.
"""
