"""The slider apps the notebooks show, one module per lesson.

Every app is a :class:`~course.widgets.base.SliderApp`: a figure rendered to
an image widget beside its controls, redrawn by changing artists.
"""

from course.widgets.base import FigureView, SliderApp

# lessons 04-05
from course.widgets.lines import LineApp, TriangleApp
from course.widgets.supersampling import SupersampleApp

__all__ = ["FigureView", "SliderApp"]
# lessons 04-05
__all__ += ["LineApp", "SupersampleApp", "TriangleApp"]
