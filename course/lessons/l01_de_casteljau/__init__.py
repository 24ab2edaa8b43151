"""Lesson 01 · de Casteljau's algorithm: the chapter beside ``notebooks/01_de_casteljau.ipynb``.

- :mod:`.lesson`: lesson 01, de Casteljau's algorithm: its registry entry, pictures, landmarks and
  printed lines;
- :mod:`.drawn`: lesson 01's graded cases, drawn per submission from the fixed cases' families;
- :mod:`.check`: lesson 01's checkers: one de Casteljau level, ``recursive_bezier`` and the drawing
  loop;
- :mod:`.apps`: lesson 01's app: de Casteljau's construction, level by level, as t moves;
- :mod:`.figures`: lesson 01's still pictures: the construction by hand, and each handout pitfall;
- :mod:`.drawing_loop`: lesson 01's drawing loop, ``bezier(control_points, window)``: what its
  checker runs;
- :mod:`.mistakes`: lesson 01's drawing loop: the handouts' mistakes its checker names, and how it
  tells them;
- :mod:`.pixel_views`: the pieces lesson 01's pixel figures are built from, and the yellow check's
  overview.

The notebook imports its checkers as ``from course.lessons.l01_de_casteljau import check``.
"""
