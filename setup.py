"""Compile the gettext catalogs (course/locale/*/LC_MESSAGES/*.po) into .mo files in wheels.

Everything else about the package is in pyproject.toml. The .mo files are build products,
not committed; course.i18n compiles a missing one in memory when an editable install runs.
"""

from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py


class BuildPyWithCatalogs(build_py):
    """build_py that first writes each catalog's .mo beside its .po, with Babel."""

    def run(self) -> None:
        from babel.messages.mofile import write_mo
        from babel.messages.pofile import read_po

        for po_path in Path("course/locale").glob("*/LC_MESSAGES/*.po"):
            with po_path.open("rb") as po_file:
                catalog = read_po(po_file)
            with po_path.with_suffix(".mo").open("wb") as mo_file:
                write_mo(mo_file, catalog, use_fuzzy=False)
        super().run()


setup(cmdclass={"build_py": BuildPyWithCatalogs})
