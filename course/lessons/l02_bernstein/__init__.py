"""Lesson 02 · The Bernstein form: the chapter beside ``notebooks/02_bernstein.ipynb``.

- :mod:`.lesson`: the registry entry ``LESSON`` and the printing and landmark helpers;
- :mod:`.check`: the exercises' checkers, imported as
  ``from course.lessons.l02_bernstein import check``;
- :mod:`.apps`: the interactive apps;
- :mod:`.figures`: the still pictures.
"""
