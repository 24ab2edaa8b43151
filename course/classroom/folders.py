"""The files and folders the classroom commands read and write. Standard library only.

A folder is never clobbered unasked (:func:`check_output_folder`), nothing is written
outside it (:func:`inside_folder`, :func:`require_inside`), and what is read is a regular
file of JSON a reader can hold (:func:`read_text_file`, :func:`read_json_file`,
:func:`loads_json`): a pipe is never waited on, and JSON nested deeper than
:data:`MAX_JSON_DEPTH` is refused, not recursed into until Python gives up.
"""

from __future__ import annotations

import json
import os
import stat
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from course.i18n import _

__all__ = [
    "MAX_JSON_DEPTH",
    "check_output_folder",
    "inside_folder",
    "loads_json",
    "read_json_file",
    "read_text_file",
    "require_inside",
]

# The longest file or folder name most file systems take (NAME_MAX).
_NAME_MAX = 255

#: How deep the JSON the commands read may nest: a notebook nests 5 deep (its outputs' data
#: and its widgets' state a few more); a deeper file is refused before anything recurses.
MAX_JSON_DEPTH = 100


def check_output_folder(out: str | Path, force: bool) -> None:
    """Refuse a file, or a folder that holds anything unless ``force``: nothing is deleted.

    Also refuses, with a ValueError naming ``out``, a name too long for the
    file system and a folder (or the nearest existing parent of one to be
    made) that cannot be written.
    """
    if isinstance(out, bool) or not isinstance(out, (str, os.PathLike)):
        raise TypeError(
            _("out: expected a folder path; got {out_type} {out:.60}").format(
                out_type=type(out).__name__, out=repr(out)
            )
        )
    if not isinstance(force, bool):
        raise TypeError(
            _("force: expected True or False; got {force_type} {force:.60}").format(
                force_type=type(force).__name__, force=repr(force)
            )
        )
    out = Path(out)
    if not str(out) or "\0" in str(out):
        raise ValueError(_("out: expected a folder path; got {out}").format(out=repr(str(out))))
    long = [part for part in out.parts if len(os.fsencode(part)) > _NAME_MAX]
    if long:
        raise ValueError(
            _(
                "out: the name {start}... has {length} characters; folder names may have at "
                "most {most}"
            ).format(start=repr(long[0][:40]), length=len(long[0]), most=_NAME_MAX)
        )
    try:
        existing = out
        while not existing.exists() and existing != existing.parent:
            existing = existing.parent
        if existing != out and not existing.is_dir():
            raise NotADirectoryError(
                _("out: {existing}, a parent of {out}, is a file, not a folder").format(
                    existing=existing, out=out
                )
            )
        if existing.is_dir() and not os.access(existing, os.W_OK | os.X_OK):
            raise ValueError(
                _(
                    "out: cannot write into {existing} (permission denied); choose another folder"
                ).format(existing=existing)
            )
        if out.exists() and not out.is_dir():
            raise NotADirectoryError(
                _("out: expected a folder; got the file {out}").format(out=out)
            )
        holds_files = out.is_dir() and any(out.iterdir())
    except OSError as error:  # a parent the user may not enter, say
        if isinstance(error, NotADirectoryError) and error.errno is None:
            raise  # one of the two above (the system's own carry an errno)
        raise ValueError(
            _("out: cannot use {out} ({reason}); choose another folder").format(
                out=out, reason=error.strerror or error
            )
        ) from None
    if holds_files and not force:
        raise FileExistsError(
            _(
                "out: {out} is not empty; choose an empty folder, or pass force=True "
                "(--force) to add these files to it (files of the same names are replaced, "
                "nothing is deleted)"
            ).format(out=out)
        )


def inside_folder(folder: Path, name: str, suffix: str) -> Path:
    """``folder / (name + suffix)``, refusing a name that would leave ``folder``.

    Examples
    --------
    >>> inside_folder(Path("out"), "a", ".png").as_posix()
    'out/a.png'
    >>> inside_folder(Path("out"), "../x", ".png")
    Traceback (most recent call last):
    ...
    ValueError: name: expected a plain file name inside out; got '../x'
    >>> inside_folder(Path("out"), "a", "/../../x")
    Traceback (most recent call last):
    ...
    ValueError: suffix: expected a file name ending such as '.png'; got '/../../x'
    """
    if not isinstance(suffix, str) or not _plain(suffix) or suffix == ".":
        raise ValueError(
            _("suffix: expected a file name ending such as '.png'; got {suffix:.60}").format(
                suffix=repr(suffix)
            )
        )
    if (
        not isinstance(name, str)
        or not name
        or not _plain(name)
        or name + suffix in (".", "..")
        or len(os.fsencode(name + suffix)) > _NAME_MAX
    ):
        raise ValueError(
            _("name: expected a plain file name inside {folder}; got {name}").format(
                folder=folder, name=repr(name)
            )
        )
    return folder / f"{name}{suffix}"


def _plain(text: str) -> bool:
    """No separator nor NUL: ``text`` cannot lead out of a folder."""
    return text not in (".", "..") and not any(mark in text for mark in ("/", "\\", "\0"))


def require_inside(out: str | Path, targets: Iterable[Path]) -> None:
    """Refuse, with a ValueError naming it, a target that a symbolic link leads out of ``out``.

    ``out`` itself may be a link: the user named it. Below it, a link (a folder on the way,
    or the file itself) is followed only when it leads to a place inside ``out``. Every
    target is checked before any is written.

    Examples
    --------
    >>> import tempfile
    >>> out = Path(tempfile.mkdtemp())
    >>> (out / "source").symlink_to("/tmp")
    >>> require_inside(out, [out / "a.png"])
    >>> require_inside(out, [out / "source" / "a.ipynb"])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: out: .../source/a.ipynb leads outside ..., to /tmp/a.ipynb, through a symbolic \
link; remove the link or choose another folder
    """
    root = Path(out).resolve()
    for target in targets:
        try:
            resolved = Path(target).resolve()
        except (OSError, RuntimeError) as error:  # a loop of links
            raise ValueError(
                _("out: cannot follow the links to {target} ({reason})").format(
                    target=target, reason=error
                )
            ) from None
        if resolved != root and root not in resolved.parents:
            raise ValueError(
                _(
                    "out: {target} leads outside {out}, to {resolved}, through a symbolic link; "
                    "remove the link or choose another folder"
                ).format(target=target, out=out, resolved=resolved)
            )


def read_text_file(path: str | Path) -> str:
    """The UTF-8 text of the regular file at ``path``, never waiting on a pipe.

    The file is opened without waiting (opening a FIFO to read waits for a writer) and read
    only when it is a regular file: a FIFO, a device or a socket of that name is a
    ValueError (the caller names the file). OSError and UnicodeDecodeError as reading
    raises them.

    Examples
    --------
    >>> import tempfile
    >>> folder = Path(tempfile.mkdtemp())
    >>> _ = (folder / "a.json").write_text("[1]")
    >>> read_text_file(folder / "a.json")
    '[1]'
    >>> read_text_file(folder)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    IsADirectoryError: ...
    """
    if isinstance(path, bool) or not isinstance(path, (str, os.PathLike)):
        raise TypeError(
            _("path: expected a file's path; got {path_type}").format(path_type=type(path).__name__)
        )
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    descriptor = os.open(path, flags)
    with open(descriptor, "rb") as file:
        mode = os.fstat(descriptor).st_mode
        if stat.S_ISDIR(mode):
            raise IsADirectoryError(21, os.strerror(21), str(path))
        if not stat.S_ISREG(mode):
            raise ValueError(_("not a regular file but a pipe, a device or a socket"))
        data = file.read()
    return data.decode("utf-8")


def read_json_file(path: str | Path) -> Any:
    """The JSON value in the regular file at ``path``: :func:`read_text_file`, :func:`loads_json`.

    A ValueError when it is not a regular file, not UTF-8, not JSON, or nests deeper than
    :data:`MAX_JSON_DEPTH` (the caller names the file); OSError as reading raises it.
    """
    return loads_json(read_text_file(path))


def loads_json(text: str) -> Any:
    """``json.loads(text)``, refusing JSON nested deeper than :data:`MAX_JSON_DEPTH`.

    A ValueError for text that is not JSON, or nests too deep (where ``json.loads`` alone
    raises RecursionError, or returns what every reader after it would recurse into).

    Examples
    --------
    >>> loads_json('{"cells": [[1]]}')
    {'cells': [[1]]}
    >>> loads_json("[" * 100_000 + "]" * 100_000)
    Traceback (most recent call last):
    ...
    ValueError: JSON nested deeper than 100 levels
    """
    if not isinstance(text, str):
        raise TypeError(
            _("text: expected JSON text, a str; got {text_type}").format(
                text_type=type(text).__name__
            )
        )
    try:
        value = json.loads(text)
        deep = _nested_deeper_than(value, MAX_JSON_DEPTH)
    except RecursionError:
        deep = True
    if deep:
        raise ValueError(_("JSON nested deeper than {most} levels").format(most=MAX_JSON_DEPTH))
    return value


def _nested_deeper_than(value: Any, most: int) -> bool:
    """Whether lists and objects in ``value`` nest more than ``most`` deep; no recursion."""
    waiting = [(value, 1)]
    while waiting:
        item, depth = waiting.pop()
        if isinstance(item, (dict, list)):
            if depth > most:
                return True
            children = item.values() if isinstance(item, dict) else item
            waiting.extend((child, depth + 1) for child in children)
    return False
