"""The gallery: every lesson's key figures as PNG files, without Jupyter.

For slides and for readers without Jupyter: ``python -m course gallery --out
DIR`` renders the pictures registered by the lesson modules whose notebooks
exist. It refuses to write into a folder that already holds anything unless
told ``force=True``, and it never deletes a file: with ``force`` it adds its
own files, replacing only files of the same names.
"""

from __future__ import annotations

import os
import secrets
import sys
from pathlib import Path
from typing import TextIO

from course.classroom.folders import check_output_folder, inside_folder, require_inside
from course.classroom.notebooks import NOTEBOOKS, notebooks
from course.classroom.registry import Picture, lessons
from course.i18n import _

__all__ = ["ProgressBar", "gallery_pictures", "named_pictures", "write_gallery"]


class ProgressBar:
    """A one-line text progress bar, redrawn in place on a terminal.

    Examples
    --------
    >>> import io
    >>> stream = io.StringIO()
    >>> bar = ProgressBar(4, stream, length=8)
    >>> bar.advance("first.png")
    >>> stream.getvalue()
    '\\r[##------] 1/4 first.png'
    """

    def __init__(self, total: int, stream: TextIO | None = None, length: int = 30) -> None:
        for name, value, most in (("total", total, 10**6), ("length", length, 200)):
            if isinstance(value, bool) or not isinstance(value, int):
                raise TypeError(
                    _("{name}: expected an integer; got {value_type} {value}").format(
                        name=name, value_type=type(value).__name__, value=repr(value)
                    )
                )
            if not 0 <= value <= most:
                raise ValueError(
                    _("{name}: expected an integer from 0 to {most}; got {value}").format(
                        name=name, most=most, value=value
                    )
                )
        if stream is not None and not callable(getattr(stream, "write", None)):
            raise TypeError(
                _("stream: expected a text stream or None; got {stream_type}").format(
                    stream_type=type(stream).__name__
                )
            )
        self.total, self.done, self.length = total, 0, length
        self.stream = sys.stderr if stream is None else stream
        self._last_length = 0

    def advance(self, label: str) -> None:
        self.done += 1
        filled = round(self.length * self.done / max(self.total, 1))
        line = f"[{'#' * filled}{'-' * (self.length - filled)}] {self.done}/{self.total} {label}"
        # Pad over a longer previous label, since "\r" only moves the cursor.
        self.stream.write("\r" + line.ljust(self._last_length))
        self._last_length = len(line)
        self.stream.flush()

    def close(self) -> None:
        self.stream.write("\n")
        self.stream.flush()


def gallery_pictures(folder: str | Path = NOTEBOOKS) -> list[Picture]:
    """The registered pictures of every lesson notebook in ``folder``, in lesson order."""
    registered = lessons()
    return [
        picture
        for book in notebooks(folder)
        if book.number in registered
        for picture in registered[book.number].pictures
    ]


def named_pictures(pictures: list[Picture], names: list[str]) -> list[Picture]:
    """The pictures of these names, in the order asked; ValueError names an unknown one.

    Examples
    --------
    >>> shown = [Picture("a", "first", bytes), Picture("b", "second", bytes)]
    >>> [picture.name for picture in named_pictures(shown, ["b"])]
    ['b']
    >>> named_pictures(shown, ["c"])
    Traceback (most recent call last):
    ...
    ValueError: no picture named 'c'; the pictures are: a, b
    """
    by_name = {picture.name: picture for picture in _as_pictures(pictures)}
    if not isinstance(names, (list, tuple)) or not all(isinstance(name, str) for name in names):
        raise TypeError(
            _("names: expected a list of picture names; got {names:.60}").format(names=repr(names))
        )
    for name in names:
        if name not in by_name:
            raise ValueError(
                _("no picture named {name}; the pictures are: {names}").format(
                    name=repr(name), names=", ".join(by_name)
                )
            )
    return [by_name[name] for name in names]


def write_gallery(
    out: str | Path,
    force: bool = False,
    pictures: list[Picture] | None = None,
    stream: TextIO | None = None,
) -> list[Path]:
    """Render ``pictures`` (default: :func:`gallery_pictures`) as ``out/<name>.png``.

    Parameters
    ----------
    out : path
        The folder to write; created if missing.
    force : bool
        Write into a folder that is not empty. Files of other names are left
        alone; a file of the same name as a picture is replaced.
    pictures : list of Picture, optional
    stream : text stream, optional
        Where the progress bar goes (default standard error).

    Returns
    -------
    list of Path
        The files written, in order.

    Raises
    ------
    FileExistsError
        If ``out`` holds anything and ``force`` is false, before anything is written.
    NotADirectoryError
        If ``out`` exists and is not a folder.
    ValueError
        If a symbolic link under ``out`` (a PNG of a picture's name) leads outside it,
        before anything is written.
    """
    check_output_folder(out, force)
    out = Path(out)
    pictures = gallery_pictures() if pictures is None else _as_pictures(pictures)
    names = [picture.name for picture in pictures]
    if len(set(names)) != len(names):
        raise ValueError(_("pictures: expected distinct names; got {names}").format(names=names))
    paths = [inside_folder(out, name, ".png") for name in names]  # all, before writing any
    require_inside(out, paths)  # a PNG of that name may be a link that leads out
    out.mkdir(parents=True, exist_ok=True)
    bar = ProgressBar(len(pictures), stream)
    written = []
    for picture, path in zip(pictures, paths, strict=True):
        _write_whole(path, picture.render())
        written.append(path)
        bar.advance(path.name)
    bar.close()
    return written


def _write_whole(path: Path, data: bytes) -> None:
    """Write ``data`` to a temporary file beside ``path``, then move it into place.

    A file of that name is replaced whole, never written through: not a pipe (whose
    opening would wait for a reader), nor a symbolic link.
    """
    temporary = path.with_name(f".{path.name}.{secrets.token_hex(4)}.writing")
    # A new file (O_EXCL: not a link nor a pipe planted there), with the umask's permissions.
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0)
    descriptor = os.open(temporary, flags, 0o666)
    try:
        with open(descriptor, "wb") as file:
            file.write(data)
        os.replace(temporary, path)
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise


def _as_pictures(pictures: object) -> list[Picture]:
    if not isinstance(pictures, (list, tuple)) or not all(
        isinstance(picture, Picture) for picture in pictures
    ):
        raise TypeError(
            _("pictures: expected a list of registry Pictures; got {pictures:.60}").format(
                pictures=repr(pictures)
            )
        )
    return list(pictures)
