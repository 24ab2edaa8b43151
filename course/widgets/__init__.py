"""The apps' shared machinery: the picture widget, the app base, the browser's drawing.

Every app is a :class:`~course.widgets.base.SliderApp`: a figure rendered to a picture
widget beside its controls, redrawn by changing artists. A lesson's apps live in its
chapter (``course/lessons/lNN_topic/apps.py``, its still pictures in ``figures.py``).
"""
