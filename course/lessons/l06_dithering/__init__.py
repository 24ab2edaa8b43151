"""Lesson 06 · Dithering: the chapter beside ``notebooks/06_dithering.ipynb``.

- :mod:`.lesson`: lesson 06, dithering: its registry entry, pictures, landmarks and printed lines;
- :mod:`.check`: lesson 06 exercises: the lab's ``DitheringOrdered`` and ``DitheringErrorDiffuse``;
- :mod:`.apps`: lesson 06 apps: dithering methods side by side, a gray-level slider,
  void-and-cluster;
- :mod:`.figures`: lesson 06's still pictures: every method side by side, the blue-noise mask and
  its spectrum, the wavefront order, and the left-edge slip;
- :mod:`.floyd_steinberg`: lesson 06's Floyd-Steinberg, one pixel at a time: where a pixel's error
  goes, and a 3 x 3 ramp diffused by hand, every value written.

The notebook imports its checkers as ``from course.lessons.l06_dithering import check``.
"""
