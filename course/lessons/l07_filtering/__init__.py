"""Lesson 07 · Filtering: the chapter beside ``notebooks/07_filtering.ipynb``.

- :mod:`.lesson`: the registry entry ``LESSON`` and the printing and landmark helpers;
- :mod:`.check`: the exercises' checkers, imported as
  ``from course.lessons.l07_filtering import check``;
- :mod:`.apps`: the interactive apps;
- :mod:`.figures`: the still pictures.
"""
