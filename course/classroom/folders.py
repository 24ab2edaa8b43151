"""The folders the classroom commands write: never clobbered unasked. Standard library only."""

from __future__ import annotations

import os
from pathlib import Path

from course.i18n import _

__all__ = ["check_output_folder", "inside_folder"]

# The longest file or folder name most file systems take (NAME_MAX).
_NAME_MAX = 255


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
