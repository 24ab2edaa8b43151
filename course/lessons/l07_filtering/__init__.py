"""Lesson 07 · Filtering: the chapter beside ``notebooks/07_filtering.ipynb``.

- :mod:`.lesson`: lesson 07, filtering: its registry entry, pictures, landmarks and printed lines;
- :mod:`.check`: lesson 07 exercises: the lab's ``Blur`` and ``Edge``;
- :mod:`.mistakes`: the known mistakes lesson 07's checkers name, each reproduced on the checker's
  cases;
- :mod:`.apps`: lesson 07's apps: any 3 x 3 kernel on the photograph, and repeated blurs at the
  border;
- :mod:`.border_names`: the border rules by the names a student reads, in the lesson's language;
- :mod:`.figures`: lesson 07's still pictures: blur and edges on the photograph, one output pixel's
  window, the border after many blurs, and the false edges zero padding draws.

The notebook imports its checkers as ``from course.lessons.l07_filtering import check``.
"""
