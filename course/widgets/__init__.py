"""The slider apps the notebooks show, one module per lesson.

Every app is a :class:`~course.widgets.base.SliderApp`: a figure rendered to
an image widget beside its controls, redrawn by changing artists.
"""

from course.widgets.antialias import StepApp, ZoomApp  # lesson 03
from course.widgets.base import FigureView, SliderApp

__all__ = ["FigureView", "SliderApp"]
# lesson 03
__all__ += ["StepApp", "ZoomApp"]
