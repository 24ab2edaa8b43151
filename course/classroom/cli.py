"""Command line: ``python -m course lab``, ``student``, ``nbgrader``, ``mistakes``, ``map``, ...

Standard library only: ``student`` and ``nbgrader`` are JSON transforms and run
without numpy, matplotlib or ipywidgets; ``gallery`` loads them when the lesson
modules draw. ``lab`` updates the student edition, then starts JupyterLab at its
course map (``--teacher``: the solved lessons), with ``--allow-root`` when run as
root, as in a container. ``lab`` and ``app`` leave Ctrl-C to the server they start:
JupyterLab asks before it stops, Voila stops; neither ends with a traceback.
``student`` writes into ``student/`` beside the lessons' folder unless ``--out`` says
where, as ``make student`` and ``lab`` do.

The lessons' notebooks are found beside the package in the course's repository (or in
``$COURSE_NOTEBOOKS``, or ``./notebooks``; ``--notebooks DIR`` says where). An installed
package without them still draws the gallery, every registered lesson's pictures; the
student edition and the map need the notebooks, and say so.

Every edition comes in each language of :data:`course.classroom.notebooks.LANGUAGES`:
``--language zh-CN`` (or ``$COURSE_LANG``; English by default) makes ``lab``, ``student``,
``nbgrader`` and ``app`` use the Chinese twins in ``notebooks/zh-CN/``; ``lab`` writes
their student edition into ``student/zh-CN/`` and opens its course map.
"""

from __future__ import annotations

import argparse
import os
import signal
import subprocess
import sys
from pathlib import Path

from course.classroom import class_mistakes, edition_folder, gallery, link, nbgrader
from course.classroom.course_map import course_map, update_readme
from course.classroom.notebooks import (
    DEFAULT_LANGUAGE,
    LANGUAGES,
    NOTEBOOKS_VARIABLE,
    find_notebooks,
    language_folder,
)
from course.classroom.registry import lessons
from course.i18n import N_, _, message_language

__all__ = ["app_command", "lab_command", "main"]

#: The environment variable that chooses the editions' language (``make lab COURSE_LANG=zh-CN``),
#: not ``LANG``, which every shell sets for its own messages.
LANGUAGE_VARIABLE = "COURSE_LANG"

#: Shown with ``_(NOT_FOUND).format(variable=NOTEBOOKS_VARIABLE)``.
NOT_FOUND = N_(
    "the lessons' notebooks are not beside the installed package, nor in ./notebooks: "
    "pass --notebooks DIR, the notebooks/ folder of the course's repository "
    "(or set {variable}=DIR)"
)


#: The connection class that sends the apps' messages at once (course.classroom.serving).
PROMPT = "course.classroom.serving.PromptConnection"

#: The module a server starts through: ``python -m MODULE``, without a traceback on Ctrl-C.
FOREGROUND = "course.classroom.foreground"


def lab_command(
    notebooks: str | Path, teacher: bool, extra: list[str], language: str = DEFAULT_LANGUAGE
) -> list[str]:
    """The ``jupyter lab`` command line: rooted at the repository, opening a course map.

    The student edition's map is ``student/00_index.ipynb``, the teacher's
    ``notebooks/00_index.ipynb``; another ``language`` than English opens the map of its
    folder, ``student/zh-CN/`` or ``notebooks/zh-CN/``.

    Examples
    --------
    >>> command = lab_command(Path("/course/notebooks"), False, ["--no-browser"])
    >>> command[1:4], command[-1]
    (['-m', 'jupyterlab', '--ServerApp.root_dir=/course'], '--no-browser')
    >>> command[4]
    '--LabApp.default_url=/lab/tree/student/00_index.ipynb'
    >>> lab_command(Path("/course/notebooks"), False, [], "zh-CN")[4]
    '--LabApp.default_url=/lab/tree/student/zh-CN/00_index.ipynb'
    """
    if isinstance(notebooks, bool) or not isinstance(notebooks, (str, os.PathLike)):
        raise TypeError(
            _("notebooks: expected a folder path; got {notebooks_type}").format(
                notebooks_type=type(notebooks).__name__
            )
        )
    if not isinstance(teacher, bool):
        raise TypeError(
            _("teacher: expected True or False; got {teacher_type}").format(
                teacher_type=type(teacher).__name__
            )
        )
    if not isinstance(extra, list) or not all(isinstance(option, str) for option in extra):
        raise TypeError(
            _("extra: expected a list of jupyter lab options; got {extra:.60}").format(
                extra=repr(extra)
            )
        )
    notebooks = Path(notebooks)
    root = notebooks.resolve().parent
    opened = language_folder(notebooks.resolve() if teacher else root / "student", language)
    command = [
        sys.executable,
        "-m",
        "jupyterlab",
        f"--ServerApp.root_dir={root}",
        f"--LabApp.default_url=/lab/tree/{opened.relative_to(root).as_posix()}/00_index.ipynb",
        f"--ServerApp.kernel_websocket_connection_class={PROMPT}",
    ]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        command.append("--allow-root")  # JupyterLab refuses root without it (containers)
    return command + extra


def app_command(notebooks: str | Path, port: int, extra: list[str]) -> list[str]:
    """The ``voila`` command line serving the lessons in ``notebooks`` as apps, code hidden.

    ``notebooks`` is a language's folder (:func:`course.classroom.notebooks.language_folder`):
    Voila's page lists its lessons, each opened at ``/voila/render/NN_topic.ipynb``.

    Examples
    --------
    >>> command = app_command(Path("/course/notebooks/zh-CN"), 8866, [])
    >>> command[1:4]
    ['-m', 'voila', '/course/notebooks/zh-CN']
    >>> command[-1]
    '--Voila.kernel_websocket_connection_class=course.classroom.serving.PromptConnection'
    """
    if isinstance(notebooks, bool) or not isinstance(notebooks, (str, os.PathLike)):
        raise TypeError(
            _("notebooks: expected a folder path; got {notebooks_type}").format(
                notebooks_type=type(notebooks).__name__
            )
        )
    if isinstance(port, bool) or not isinstance(port, int) or not 0 < port < 65536:
        raise ValueError(
            _("port: expected a TCP port, an int from 1 to 65535; got {port:.60}").format(
                port=repr(port)
            )
        )
    if not isinstance(extra, list) or not all(isinstance(option, str) for option in extra):
        raise TypeError(
            _("extra: expected a list of voila options; got {extra:.60}").format(extra=repr(extra))
        )
    return [
        sys.executable,
        "-m",
        "voila",
        str(notebooks),
        "--no-browser",
        "--Voila.ip=127.0.0.1",
        f"--port={port}",
        *extra,
        f"--Voila.kernel_websocket_connection_class={PROMPT}",
    ]


def _student_folder(notebooks: Path, language: str) -> Path:
    """The student edition's folder: ``student/`` beside the lessons' (``student/zh-CN/``)."""
    return language_folder(notebooks.resolve().parent / "student", language)


def _serve(command: list[str]) -> int:
    """Run a server, ``python -m MODULE ARGS``, until it stops; its exit status.

    The terminal sends Ctrl-C to its whole foreground process group, so the server gets it
    too and answers it its own way: JupyterLab asks "Shut down this Jupyter server
    (y/[n])?", and y or a second Ctrl-C stops it; Voila stops. This process only waits
    (``subprocess.call`` died at the first Ctrl-C with a traceback, and killed the server
    before its question could be answered). The server starts through :data:`FOREGROUND`,
    so a Ctrl-C that comes while it still imports ends it without a traceback too.
    """
    python, option, module, *rest = command
    with subprocess.Popen([python, option, FOREGROUND, module, *rest]) as server:
        while True:
            try:
                status = server.wait()
            except KeyboardInterrupt:
                continue  # the server's to answer
            if status == -signal.SIGINT:
                return _end_as_interrupted()
            return 128 - status if status < 0 else status


def _end_as_interrupted() -> int:
    """End this process as Ctrl-C ends a program, without a traceback; 130 where it cannot.

    On POSIX the process ends by SIGINT, as Python ends on a KeyboardInterrupt, so that the
    shell or make that waits for it reads it as interrupted, not as an error (make prints one
    line, ``make: *** [Makefile:NN: lab] Interrupt``). Elsewhere: status 130, the shells' own.
    """
    if os.name == "posix":
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        os.kill(os.getpid(), signal.SIGINT)
    return 128 + signal.SIGINT


def _language(value: str | None) -> str:
    """The ``--language`` asked for, else ``$COURSE_LANG``, else English; checked."""
    language = value if value is not None else os.environ.get(LANGUAGE_VARIABLE) or DEFAULT_LANGUAGE
    if language not in LANGUAGES:
        named = "--language" if value is not None else LANGUAGE_VARIABLE
        raise ValueError(
            _("{named}: expected one of {choices}; got {language:.60}").format(
                named=named, choices=", ".join(LANGUAGES), language=repr(language)
            )
        )
    return language


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m course", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    lab = commands.add_parser(
        "lab",
        help="update the student edition in student/, then open its course map in JupyterLab "
        "(other options go to jupyter lab)",
    )
    lab.add_argument(
        "--teacher", action="store_true", help="open the solved lessons in notebooks/ instead"
    )
    lab.add_argument(
        "--notebooks", type=Path, help="the lessons' folder (default: the repository's notebooks/)"
    )
    app = commands.add_parser(
        "app",
        help="serve the lessons as apps in Voila, code hidden (other options go to voila)",
    )
    app.add_argument("--port", type=int, default=8866, help="the port (default: 8866)")
    app.add_argument(
        "--notebooks", type=Path, help="the lessons' folder (default: the repository's notebooks/)"
    )
    grading = commands.add_parser(
        "nbgrader",
        help="write an nbgrader course folder: nbgrader_config.py and source/<lesson>/",
    )
    gallery_command = commands.add_parser(
        "gallery", help="render every lesson's key figures to PNG files, without Jupyter"
    )
    student_command = commands.add_parser(
        "student", help="write the notebooks with solutions replaced by stubs, outputs cleared"
    )
    for command in (gallery_command, student_command, grading):
        if command is student_command:  # as make student and lab write it
            command.add_argument(
                "--out",
                type=Path,
                help="the folder to write (default: student/ beside the lessons' folder; "
                "student/zh-CN/ in Chinese)",
            )
        else:
            command.add_argument("--out", required=True, type=Path, help="the folder to write")
        command.add_argument(
            "--force",
            action="store_true",
            help="write into a non-empty folder (gallery and nbgrader: files of the same "
            "names are replaced; student: a notebook with edits is never replaced; nothing "
            "is deleted)",
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
    for command in (lab, app, student_command, grading):
        command.add_argument(
            "--language",
            metavar="LANGUAGE",
            help=f"the edition's language: {', '.join(LANGUAGES)} (default: "
            f"${LANGUAGE_VARIABLE}, else {DEFAULT_LANGUAGE})",
        )
    link.add_command(commands)
    class_mistakes.add_mistakes_command(commands)
    args, extra = parser.parse_known_args(argv)
    language = DEFAULT_LANGUAGE
    if args.command in ("lab", "app", "student", "nbgrader"):
        try:
            language = _language(args.language)
        except ValueError as error:
            print(f"python -m course {args.command}: {error}", file=sys.stderr)
            return 2
    # The commands that make an edition speak its language, errors and reports included.
    try:
        with message_language(language):
            return _run(parser, args, extra, language)
    except KeyboardInterrupt:  # before a server started, or in a command without one
        return _end_as_interrupted()


def _run(
    parser: argparse.ArgumentParser, args: argparse.Namespace, extra: list[str], language: str
) -> int:
    """The command ``args`` asks for, its messages in the current language; the exit status."""
    if extra and args.command not in ("lab", "app"):
        parser.error(_("unrecognized arguments: {arguments}").format(arguments=" ".join(extra)))
    if args.command == "mistakes":
        return class_mistakes.run(args)
    if args.command == "link":
        try:
            print(link.run(args))
        except ValueError as error:
            print(f"python -m course link: {error}", file=sys.stderr)
            return 2
        return 0
    args.notebooks = args.notebooks or find_notebooks()
    if args.notebooks is None and args.command != "gallery":
        print(
            f"python -m course {args.command}: " + _(NOT_FOUND).format(variable=NOTEBOOKS_VARIABLE),
            file=sys.stderr,
        )
        return 2
    if args.command == "twins":
        from course.classroom import twins

        return twins.run(args.notebooks, args.update_po, args.check)
    try:
        if args.command in ("lab", "app", "student", "nbgrader"):
            lessons_folder = language_folder(args.notebooks, language)
        if args.command == "lab":
            if not args.teacher:
                # student/ is the edition's own folder: one written before the edition kept
                # a manifest is taken over (its notebooks count as the student's work).
                student = _student_folder(args.notebooks, language)
                report = edition_folder.write_student_edition(student, lessons_folder, force=True)
                shown = student.relative_to(args.notebooks.resolve().parent).as_posix()
                for line in report.lines():
                    print(f"{shown}/: {line}", file=sys.stderr)
            return _serve(lab_command(args.notebooks, args.teacher, extra, language))
        if args.command == "app":
            if not lessons_folder.is_dir():
                raise ValueError(
                    _("notebooks: no lessons in {lessons_folder}").format(
                        lessons_folder=lessons_folder
                    )
                )
            return _serve(app_command(lessons_folder, args.port, extra))
        if args.command == "map" and args.readme:
            changed = update_readme(args.readme, args.notebooks)
            done = _("lesson table rewritten") if changed else _("lesson table unchanged")
            print(f"{args.readme}: {done}")
            return 0
        if args.command == "map":
            print(course_map(args.notebooks, args.link_prefix, guide=False))
            return 0
        if args.command == "gallery":
            if args.notebooks is None:  # an installed package: every registered picture
                pictures = [p for lesson in lessons().values() for p in lesson.pictures]
            else:
                pictures = gallery.gallery_pictures(args.notebooks)
            if args.only:
                pictures = gallery.named_pictures(pictures, args.only)
            written = gallery.write_gallery(args.out, args.force, pictures)
        elif args.command == "nbgrader":
            written = nbgrader.write_nbgrader_course(args.out, lessons_folder, args.force)
        else:
            if args.out is None:
                args.out = _student_folder(args.notebooks, language)
            report = edition_folder.write_student_edition(args.out, lessons_folder, args.force)
            for line in report.lines():
                print(f"{args.out}: {line}", file=sys.stderr)
            return 0
    except (OSError, ValueError, TypeError) as error:
        message = " ".join(str(error).split()) if str(error) else type(error).__name__
        print(f"python -m course {args.command}: {message}", file=sys.stderr)
        return 2
    print(
        _("wrote {count} files to {out}").format(count=len(written), out=args.out),
        file=sys.stderr,
    )
    return 0
