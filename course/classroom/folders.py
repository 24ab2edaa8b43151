"""The folders the classroom commands write: never clobbered unasked. Standard library only."""

from __future__ import annotations

from pathlib import Path

__all__ = ["check_output_folder"]


def check_output_folder(out: Path, force: bool) -> None:
    """Refuse a file, or a folder that holds anything unless ``force``: nothing is deleted."""
    if out.exists() and not out.is_dir():
        raise NotADirectoryError(f"out: expected a folder; got the file {out}")
    if out.is_dir() and any(out.iterdir()) and not force:
        raise FileExistsError(
            f"out: {out} is not empty; choose an empty folder, or pass force=True "
            "(--force) to add these files to it (files of the same names are replaced, "
            "nothing is deleted)"
        )
