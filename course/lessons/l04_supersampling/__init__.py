"""Lesson 04 · Sampling and supersampling: the chapter beside ``notebooks/04_supersampling.ipynb``.

- :mod:`.lesson`: lesson 04, sampling and supersampling: its registry entry, pictures, landmarks and
  printed lines;
- :mod:`.check`: checker for lesson 04: the lab's supersampling (Task 6);
- :mod:`.apps`: lesson 04's app: shrinking an image by supersampling, rate by rate;
- :mod:`.figures`: lesson 04's still pictures: folding in one dimension, the box filter's response,
  the zone plate shrunk, the error at every rate, the report's shift and the photograph.
- :mod:`.mistakes`: the known mistakes lesson 04's checkers name, each reproduced on the checker's
  cases.

The notebook imports its checkers as ``from course.lessons.l04_supersampling import check``.
"""
