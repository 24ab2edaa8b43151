"""The slider apps the notebooks show, one module per lesson.

Every app is a :class:`~course.widgets.base.SliderApp`: a figure rendered to
an image widget beside its controls, redrawn by changing artists. A lesson's
notebook imports from its own module (``from course.widgets.de_casteljau
import DeCasteljauApp``), so a new lesson adds its module and edits nothing here.
"""
