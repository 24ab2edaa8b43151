"""course: Jupyter lessons for an introductory computer-graphics course.

One module per concept; the notebooks in ``notebooks/`` import them.
"""

from importlib.metadata import PackageNotFoundError, version

try:
    #: Written once, in pyproject.toml.
    __version__ = version("course")
except PackageNotFoundError:  # the package imported from a folder, not installed
    __version__ = "0+unknown"

from course.i18n import current_language, use_language

__all__ = ["__version__", "current_language", "use_language"]
