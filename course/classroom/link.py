"""``python -m course link``: the nbgitpuller link that brings the lessons to a class's hub.

A teacher publishes the student edition (``python -m course student --out
DIR``) as a git repository, and sends the class one link. Opened on the
class's JupyterHub, nbgitpuller clones that repository into the student's
folder the first time; every later click merges the teacher's new lessons in
and keeps what the student wrote (a file the student changed keeps the
student's lines where both changed it). The link then opens the course map.

The link names the folder it pulls into (nbgitpuller's ``targetpath``): the
repository's name without ``.git``, so that ``https://.../cg-student`` and
``https://.../cg-student.git`` (what a Clone button gives) both pull into
``cg-student/`` and open ``cg-student/00_index.ipynb``. The course's hub
(``hub/jupyterhub_config.py``) opens the same pull as its start page when it is
given the repository, so that a student has one copy of the lessons.

Standard library only, like the rest of ``python -m course``: the teacher
runs it anywhere.
"""

from __future__ import annotations

import argparse
import posixpath
import re
from urllib.parse import quote, urlencode, urlsplit

from course.i18n import _

# The command-line helpers (add_command, run) are for cli.py only.
__all__ = [
    "add_command",
    "lessons_folder",
    "nbgitpuller_link",
    "pull_path",
    "run",
]

#: The notebook the link opens, at the top of the student edition.
START_NOTEBOOK = "00_index.ipynb"
#: What a branch or folder name may hold: no spaces, no "..", nothing a URL would mangle.
_NAME = re.compile(r"^[A-Za-z0-9._/-]+$")


def nbgitpuller_link(
    hub: str,
    repository: str,
    branch: str = "main",
    notebook: str = START_NOTEBOOK,
    folder: str | None = None,
) -> str:
    """The link that pulls ``repository``'s ``branch`` into a student's folder on ``hub``.

    ``hub`` is the hub's address (``https://hub.example.edu``, or with the
    prefix the hub is served under); ``repository`` the student edition's
    git repository, cloned over http(s). The link opens ``notebook`` in
    JupyterLab, inside ``folder`` (by default :func:`lessons_folder`: the
    repository's name without ``.git``).

    Examples
    --------
    >>> print(nbgitpuller_link("https://hub.example.edu/", "https://github.com/u/cg-student.git"))
    https://hub.example.edu/hub/user-redirect/git-pull?repo=https%3A%2F%2Fgithub.com%2Fu%2Fcg-student.git&branch=main&targetpath=cg-student&urlpath=lab%2Ftree%2Fcg-student%2F00_index.ipynb
    """
    hub = _web_address(hub, "hub").rstrip("/")
    return f"{hub}/hub/user-redirect/{pull_path(repository, branch, notebook, folder)}"


def pull_path(
    repository: str,
    branch: str = "main",
    notebook: str = START_NOTEBOOK,
    folder: str | None = None,
) -> str:
    """nbgitpuller's address on a student's own server: the link without the hub's part.

    The hub's start page (``Spawner.default_url``) is ``"/" + pull_path(...)``:
    every start merges the teacher's new lessons in, like the link, into the
    same folder. The arguments are :func:`nbgitpuller_link`'s.

    Examples
    --------
    >>> print(pull_path("https://github.com/u/cg-student", folder="lessons"))
    git-pull?repo=https%3A%2F%2Fgithub.com%2Fu%2Fcg-student&branch=main&targetpath=lessons&urlpath=lab%2Ftree%2Flessons%2F00_index.ipynb
    """
    repository = _web_address(repository, "repository")
    branch = _name(branch, "branch")
    notebook = _name(notebook, "notebook")
    folder = lessons_folder(repository) if folder is None else _name(folder, "folder")
    query = {
        "repo": repository,
        "branch": branch,
        "targetpath": folder,
        "urlpath": f"lab/tree/{folder}/{notebook}",
    }
    return f"git-pull?{urlencode(query, quote_via=quote, safe='')}"


def lessons_folder(repository: str) -> str:
    """The folder a student's lessons are pulled into: the repository's name, without ``.git``.

    Examples
    --------
    >>> lessons_folder("https://github.com/u/cg-student.git")
    'cg-student'
    >>> lessons_folder("https://git.example.edu/cg/lessons/")
    'lessons'
    """
    repository = _web_address(repository, "repository")
    name = posixpath.basename(urlsplit(repository).path.rstrip("/")).removesuffix(".git")
    if not name or not _NAME.match(name) or name in (".", ".."):
        raise ValueError(
            _("repository must end in the repository's name; got {repository}").format(
                repository=repr(repository)
            )
        )
    return name


def _web_address(value: object, name: str) -> str:
    if not isinstance(value, str):
        raise TypeError(
            _("{name} must be an http(s) address as a string; got {value_type}").format(
                name=name, value_type=type(value).__name__
            )
        )
    parts = urlsplit(value)
    if parts.scheme not in ("http", "https") or not parts.netloc or parts.query or parts.fragment:
        raise ValueError(
            _(
                "{name} must be an http(s) address with a host, no query or fragment; got {value}"
            ).format(name=name, value=repr(value))
        )
    return value


def _name(value: object, name: str) -> str:
    if not isinstance(value, str):
        raise TypeError(
            _("{name} must be a string; got {value_type}").format(
                name=name, value_type=type(value).__name__
            )
        )
    parts = value.split("/")
    if not _NAME.match(value) or ".." in parts or "" in parts:
        raise ValueError(
            _(
                "{name} must be a relative name of letters, digits, '.', '_', '-' and '/' (no "
                "'..'); got {value}"
            ).format(name=name, value=repr(value))
        )
    return value


def add_command(commands: argparse._SubParsersAction) -> None:
    """Add ``link`` to ``python -m course``'s commands."""
    command = commands.add_parser(
        "link", help="print the nbgitpuller link that brings the student edition to a hub"
    )
    command.add_argument("--hub", required=True, help="the hub's address, e.g. https://hub.uni.edu")
    command.add_argument(
        "--repo",
        required=True,
        help="the student edition's git repository (python -m course student --out DIR, "
        "committed and pushed), cloned over https",
    )
    command.add_argument("--branch", default="main", help="its branch (default: main)")
    command.add_argument(
        "--notebook",
        default=START_NOTEBOOK,
        help=f"what the link opens (default: {START_NOTEBOOK})",
    )
    command.add_argument("--folder", help="the student's folder (default: the repository's name)")


def run(args: argparse.Namespace) -> str:
    """The link ``python -m course link`` prints for its parsed arguments."""
    return nbgitpuller_link(args.hub, args.repo, args.branch, args.notebook, args.folder)
