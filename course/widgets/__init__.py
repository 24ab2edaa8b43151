"""The slider apps the notebooks show, one module per lesson.

Every app is a :class:`~course.widgets.base.SliderApp`: a figure rendered to
an image widget beside its controls, redrawn by changing artists.
"""

from course.widgets.base import FigureView, SliderApp

__all__ = ["FigureView", "SliderApp"]

# Lessons 06-07: dithering and filtering.
from course.widgets.dithering import (
    DitherComparisonApp,
    GrayLevelApp,
    VoidAndClusterApp,
)
from course.widgets.filtering import RepeatedBlurApp

__all__ += ["DitherComparisonApp", "GrayLevelApp", "RepeatedBlurApp", "VoidAndClusterApp"]
