"""Lesson 05 · Anti-aliasing a curve: the chapter beside ``notebooks/05_antialiasing.ipynb``.

- :mod:`.lesson`: lesson 05, anti-aliasing a curve: its registry entry, pictures, landmarks and
  printed lines;
- :mod:`.check`: lesson 05's exercises: the bilinear splat about pixel centres, and the arc-length
  weights;
- :mod:`.apps`: lesson 05's apps: zoomed pixel views of anti-aliased curves;
- :mod:`.figures`: lesson 05's still pictures: a curve with and without anti-aliasing, a pixel as a
  small area, one splat, the brightness along the curve, the report's half-pixel offset, stroked
  text;
- :mod:`.measurements`: lesson 05's measurements of the handouts' curve (seed 000's cubic on its 700
  x 700 canvas);
- :mod:`.mistakes`: the known mistakes lesson 05's checkers name, each reproduced on the checker's
  cases;
- :mod:`.splat_pictures`: the splat checker's pictures: a wrong splat beside the right one, its
  pixels numbered;
- :mod:`.splat_tables`: a splat as a table: rows (x, y, weight), the one form lesson 05's splat
  checker compares;
- :mod:`.zoom_panel`: zoomed pixel views of a rendered curve: where the window sits, one panel, a
  still grid.

The notebook imports its checkers as ``from course.lessons.l05_antialiasing import check``.
"""
