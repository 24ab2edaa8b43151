"""Command line: ``python -m course gallery --out DIR``, ``student --out DIR`` and ``map``.

Standard library only: ``student`` is a JSON transform and runs without numpy,
matplotlib or ipywidgets; ``gallery`` loads them when the lesson modules draw.

The lessons' notebooks are found beside the package in the course's repository (or in
``$COURSE_NOTEBOOKS``, or ``./notebooks``; ``--notebooks DIR`` says where). An installed
package without them still draws the gallery, every registered lesson's pictures; the
student edition and the map need the notebooks, and say so.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from course.classroom import edition, gallery
from course.classroom.course_map import course_map, update_readme
from course.classroom.notebooks import NOTEBOOKS_VARIABLE, find_notebooks
from course.classroom.registry import lessons

NOT_FOUND = (
    "the lessons' notebooks are not beside the installed package, nor in ./notebooks: "
    "pass --notebooks DIR, the notebooks/ folder of the course's repository "
    f"(or set {NOTEBOOKS_VARIABLE}=DIR)"
)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m course", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    gallery_command = commands.add_parser(
        "gallery", help="render every lesson's key figures to PNG files, without Jupyter"
    )
    student_command = commands.add_parser(
        "student", help="write the notebooks with solutions replaced by stubs, outputs cleared"
    )
    for command in (gallery_command, student_command):
        command.add_argument("--out", required=True, type=Path, help="the folder to write")
        command.add_argument(
            "--force",
            action="store_true",
            help="write into a non-empty folder (files of the same names are replaced; "
            "nothing is deleted)",
        )
        command.add_argument(
            "--notebooks",
            type=Path,
            help="the lessons' folder (default: the repository's notebooks/)",
        )
    gallery_command.add_argument(
        "--only",
        action="append",
        metavar="NAME",
        help="render only the picture of this name (repeatable), e.g. the README's",
    )
    map_command = commands.add_parser(
        "map", help="print the course map: a Markdown table of the lessons (the README's)"
    )
    map_command.add_argument(
        "--notebooks", type=Path, help="the lessons' folder (default: the repository's notebooks/)"
    )
    map_command.add_argument(
        "--link-prefix",
        default="",
        help="what goes before each notebook's file name in its link",
    )
    map_command.add_argument(
        "--readme",
        type=Path,
        help="rewrite the lesson table between this README's markers instead of printing it",
    )
    twins_command = commands.add_parser(
        "twins", help="write the Chinese lessons notebooks/zh-CN/*.ipynb from their catalogs"
    )
    twins_command.add_argument("--notebooks", type=Path, help="the English lessons' folder")
    twins_command.add_argument("--update-po", action="store_true", help="merge new English first")
    twins_command.add_argument("--check", action="store_true", help="write nothing; fail on gaps")
    args = parser.parse_args(argv)
    args.notebooks = args.notebooks or find_notebooks()
    if args.notebooks is None and args.command != "gallery":
        print(f"python -m course {args.command}: {NOT_FOUND}", file=sys.stderr)
        return 2
    if args.command == "twins":
        from course.classroom import twins

        return twins.run(args.notebooks, args.update_po, args.check)
    try:
        if args.command == "map" and args.readme:
            changed = update_readme(args.readme, args.notebooks)
            print(f"{args.readme}: lesson table {'rewritten' if changed else 'unchanged'}")
            return 0
        if args.command == "map":
            print(course_map(args.notebooks, args.link_prefix))
            return 0
        if args.command == "gallery":
            if args.notebooks is None:  # an installed package: every registered picture
                pictures = [p for lesson in lessons().values() for p in lesson.pictures]
            else:
                pictures = gallery.gallery_pictures(args.notebooks)
            if args.only:
                pictures = gallery.named_pictures(pictures, args.only)
            written = gallery.write_gallery(args.out, args.force, pictures)
        else:
            written = edition.write_student_edition(args.out, args.notebooks, args.force)
    except (FileExistsError, FileNotFoundError, NotADirectoryError, ValueError) as error:
        print(f"python -m course {args.command}: {error}", file=sys.stderr)
        return 2
    print(f"wrote {len(written)} files to {args.out}", file=sys.stderr)
    return 0
