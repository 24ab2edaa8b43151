"""The slider apps the notebooks show, one module per lesson.

Every app is a :class:`~course.widgets.base.SliderApp`: a figure rendered to
an image widget beside its controls, redrawn by changing artists.
"""

from course.widgets.base import FigureView, SliderApp

__all__ = ["FigureView", "SliderApp"]

# Lesson 08: Poisson image editing.
from course.widgets.poisson import PoissonIterationApp

__all__ += ["PoissonIterationApp"]
