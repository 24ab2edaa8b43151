"""Lesson 03 · Lines and triangles: the chapter beside ``notebooks/03_lines_and_triangles.ipynb``.

- :mod:`.lesson`: lesson 03, lines and triangles: its registry entry, pictures, landmarks and
  printed lines;
- :mod:`.check`: checkers for lesson 03: the lab's ``DrawLine`` and ``DrawTriangleFilled``;
- :mod:`.apps`: lesson 03's apps: Bresenham against the report's staircase, and filled triangles;
- :mod:`.figures`: lesson 03's still pictures: a line's pixels, the report's staircase, a scanline
  fill, the edge rules on a shared edge, a mesh's cracks, and colour across a triangle;
- :mod:`.curve_segments`: the lab's Task 7 as an app: a cubic drawn as Bresenham segments, against
  the curve itself;
- :mod:`.grid`: the zoomed pixel grid lesson 03's apps draw on, in image space (y down);
- :mod:`.line_mistakes`: the wrong lines lesson 03's draw_line checker names, each reproduced on
  its cases;
- :mod:`.mistakes`: the wrong fills lesson 03's draw_triangle_filled checker names, each
  reproduced on the checker's cases.

The notebook imports its checkers as ``from course.lessons.l03_lines_and_triangles import check``.
"""
