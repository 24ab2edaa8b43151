"""Lesson 05 · Anti-aliasing a curve: the chapter beside ``notebooks/05_antialiasing.ipynb``.

- :mod:`.lesson`: the registry entry ``LESSON`` and the printing and landmark helpers;
- :mod:`.check`: the exercises' checkers, imported as
  ``from course.lessons.l05_antialiasing import check``;
- :mod:`.apps`: the interactive apps;
- :mod:`.figures`: the still pictures.
"""
