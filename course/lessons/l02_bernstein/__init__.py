"""Lesson 02 · The Bernstein form: the chapter beside ``notebooks/02_bernstein.ipynb``.

- :mod:`.lesson`: lesson 02, the Bernstein form: its registry entry, pictures, landmarks and printed
  lines;
- :mod:`.drawn`: lesson 02's graded cases, drawn per submission from the fixed cases' families;
- :mod:`.check`: lesson 02's checkers: binomial coefficients by Pascal's rule, and ``naive_bezier``;
- :mod:`.code_reading`: what a student's code does, read from its source: a product in ``comb``,
  and whether ``naive_bezier`` calls it;
- :mod:`.apps`: lesson 02's app: the Bernstein basis polynomials of one degree, and their values at
  t;
- :mod:`.figures`: lesson 02's still pictures: end tangents, the hodograph, the binomials' cost,
  accuracy.

The notebook imports its checkers as ``from course.lessons.l02_bernstein import check``.
"""
