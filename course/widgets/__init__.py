"""The slider apps the notebooks show, one module per lesson.

Every app is a :class:`~course.widgets.base.SliderApp`: a figure rendered to
an image widget beside its controls, redrawn by changing artists.
"""

from course.widgets.base import FigureView, SliderApp

__all__ = ["FigureView", "SliderApp"]

# Lessons 01-02: Bézier curves.
from course.widgets.bernstein import BernsteinBasisApp
from course.widgets.de_casteljau import DeCasteljauApp

__all__ += ["BernsteinBasisApp", "DeCasteljauApp"]
