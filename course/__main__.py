"""Command line: ``python -m course gallery --out DIR`` and ``student --out DIR``."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from course.lessons import NOTEBOOKS


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m course", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    gallery = commands.add_parser(
        "gallery", help="render every lesson's key figures to PNG files, without Jupyter"
    )
    student = commands.add_parser(
        "student", help="write the notebooks with solutions replaced by stubs, outputs cleared"
    )
    for command in (gallery, student):
        command.add_argument("--out", required=True, type=Path, help="the folder to write")
        command.add_argument(
            "--force",
            action="store_true",
            help="write into a non-empty folder (files of the same names are replaced; "
            "nothing is deleted)",
        )
        command.add_argument(
            "--notebooks", type=Path, default=NOTEBOOKS, help="the lessons' folder"
        )
    args = parser.parse_args(argv)
    try:
        if args.command == "gallery":
            from course.gallery import gallery_pictures, write_gallery

            written = write_gallery(args.out, args.force, gallery_pictures(args.notebooks))
        else:
            from course.edition import write_student_edition

            written = write_student_edition(args.out, args.notebooks, args.force)
    except (FileExistsError, NotADirectoryError, ValueError) as error:
        print(f"python -m course {args.command}: {error}", file=sys.stderr)
        return 2
    print(f"wrote {len(written)} files to {args.out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
