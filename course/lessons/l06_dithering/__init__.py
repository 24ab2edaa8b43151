"""Lesson 06 · Dithering: the chapter beside ``notebooks/06_dithering.ipynb``.

- :mod:`.lesson`: the registry entry ``LESSON`` and the printing and landmark helpers;
- :mod:`.check`: the exercises' checkers, imported as
  ``from course.lessons.l06_dithering import check``;
- :mod:`.apps`: the interactive apps;
- :mod:`.figures`: the still pictures.
"""
