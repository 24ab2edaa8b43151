"""The slider apps the notebooks show, one module per lesson.

Every app is a :class:`~course.widgets.base.SliderApp`: a figure rendered to
an image widget beside its controls, redrawn by changing artists.
"""

from course.widgets.antialias import StepApp, ZoomApp
from course.widgets.base import FigureView, SliderApp
from course.widgets.bernstein import BernsteinBasisApp
from course.widgets.de_casteljau import DeCasteljauApp
from course.widgets.dithering import DitherComparisonApp, GrayLevelApp, VoidAndClusterApp
from course.widgets.filtering import RepeatedBlurApp
from course.widgets.lines import LineApp, TriangleApp
from course.widgets.poisson import PoissonIterationApp
from course.widgets.supersampling import SupersampleApp

__all__ = [
    "BernsteinBasisApp",
    "DeCasteljauApp",
    "DitherComparisonApp",
    "FigureView",
    "GrayLevelApp",
    "LineApp",
    "PoissonIterationApp",
    "RepeatedBlurApp",
    "SliderApp",
    "StepApp",
    "SupersampleApp",
    "TriangleApp",
    "VoidAndClusterApp",
    "ZoomApp",
]
