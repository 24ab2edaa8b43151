# The course's JupyterHub: one JupyterLab per student on one machine, for a class.
#
# `make hub` runs it on this machine for a trial class (127.0.0.1, any username, one
# shared password). A teacher copies this file to a university's server (for example
# to /etc/jupyterhub/) and starts JupyterHub in the folder that is to hold the class's
# data; the COURSE_HUB_* environment variables, or the lines below them, change the
# rest. docs/hub.md says how, and how the same settings read on Zero to JupyterHub.
#
# What it sets up:
# - the data: in COURSE_HUB_DATA, by default the folder JupyterHub is started in (where
#   JupyterHub keeps its own database by default): the database, the cookie secret, the
#   student edition, every student's folder (homes/) and nbgrader's exchange (exchange/);
# - the proxy: configurable-http-proxy, the one COURSE_HUB_PROXY names, else `npm ci`'s in
#   hub/ (beside this file, or in the course's checkout, which the hub's Python has
#   installed), else the one on PATH;
# - every student's server is JupyterLab, from the same lock as the course
#   (requirements/hub.txt), started as a local process (SimpleLocalProcessSpawner:
#   one Unix user runs them all, each in its own folder);
# - the lessons, one copy per student, in one of two ways:
#   - by default, the student edition (`python -m course student`, built by the hub the
#     first time a student starts, if it is not there) is copied into the student's
#     student/ folder, file by file, never over what is there; the start page is its
#     course map;
#   - with COURSE_HUB_LESSONS_REPO (the student edition's git repository, the address
#     `python -m course link --repo` is given), the start page is nbgitpuller's pull of it,
#     into the folder the link pulls into, then the course map: the link and the hub give
#     a student the same folder;
# - nbgrader's exchange: students submit from JupyterLab's Assignments panel the lessons
#   they work in (linked into assignments/) and fetch other assignments; the teacher (an
#   admin user) releases and collects, with the course id of `python -m course nbgrader`'s;
# - limits, enforced by the kernel on each student's processes: an address space per
#   process (RLIMIT_AS, so a runaway array raises MemoryError instead of taking the
#   machine's memory), a CPU-time budget per process (RLIMIT_CPU), one BLAS/OpenMP
#   thread, and a lower priority than the hub (nice); the hub also passes the limits to
#   the server as MEM_LIMIT and CPU_LIMIT, which Jupyter's resource display shows;
# - idle servers are stopped (jupyterhub-idle-culler, a hub service);
# - an optional admin service token (COURSE_HUB_ADMIN_TOKEN), for scripts such as
#   benchmarks/bench_hub.py that create students and start their servers.
#
# The trial authenticator lets anyone in who knows the shared password: fine on
# 127.0.0.1, never on a server others can reach. A real class uses the university's
# login (an OAuthenticator or LTI authenticator), set in the "Who may log in" block.
# ruff: noqa: F821 (`c` is the configuration object JupyterHub passes in)

import asyncio
import importlib.util
import json
import os
import resource
import shutil
import signal
import sys
from pathlib import Path

from jupyterhub.app import JupyterHub
from jupyterhub.spawner import SimpleLocalProcessSpawner

from course.classroom.link import lessons_folder, pull_path

# Where the hub keeps its state: its database, cookie secret, proxy pid, the built
# student edition, every student's folder and nbgrader's exchange.
DATA = Path(os.environ.get("COURSE_HUB_DATA", ".")).resolve()
IP = os.environ.get("COURSE_HUB_IP", "127.0.0.1")
PORT = int(os.environ.get("COURSE_HUB_PORT", "8000"))
HUB_PORT = int(os.environ.get("COURSE_HUB_API_PORT", str(PORT + 81)))
PROXY_API_PORT = int(os.environ.get("COURSE_HUB_PROXY_API_PORT", str(PORT + 1)))
# The student edition each folder is seeded from: built on the first start if missing
# (`python -m course student`, in $COURSE_LANG's language, English by default).
EDITION = Path(os.environ.get("COURSE_HUB_EDITION", DATA / "student-edition")).resolve()
# Or the lessons from git: the student edition's repository, pulled by nbgitpuller.
LESSONS_REPO = os.environ.get("COURSE_HUB_LESSONS_REPO", "")
LESSONS_BRANCH = os.environ.get("COURSE_HUB_LESSONS_BRANCH", "main")
# Where each student's folder is, and the folder the lessons go to inside it: the one
# `python -m course link` pulls into when the lessons come from git.
HOMES = DATA / "homes"
LESSONS_FOLDER = lessons_folder(LESSONS_REPO) if LESSONS_REPO else "student"
if LESSONS_REPO:  # every start merges the teacher's new lessons in, as the link does
    START = "/" + pull_path(LESSONS_REPO, LESSONS_BRANCH, folder=LESSONS_FOLDER)
else:
    START = f"/lab/tree/{LESSONS_FOLDER}/00_index.ipynb"
# nbgrader's exchange, and the course id of `python -m course nbgrader`'s nbgrader_config.py.
EXCHANGE = DATA / "exchange"
COURSE_ID = "course"
# Jupyter configuration the hub writes for the servers (on their JUPYTER_CONFIG_PATH):
# nbgrader's settings for everyone, and what students do not see (the grader's panels).
CLASS_CONFIG = DATA / "jupyter" / "class"
STUDENT_CONFIG = DATA / "jupyter" / "students"
# The teacher's nbgrader course folder, inside their own folder: `python -m course nbgrader
# --out nbgrader` there, and the formgrader finds it.
GRADING_FOLDER = "nbgrader"
# A student's nbgrader assignments (Exchange.assignment_dir), inside their own folder. Each
# lesson is there already, as <lesson>/<lesson>.ipynb, a link to the lesson the student
# works in: once the teacher releases it, the Assignments panel shows it fetched, and Submit
# hands in that very notebook. Other assignments are fetched there.
ASSIGNMENTS_FOLDER = "assignments"
# Per student process: address space and CPU-seconds (see the header).
MEMORY_LIMIT_GIB = float(os.environ.get("COURSE_HUB_MEMORY_GIB", "2"))
CPU_SECONDS = int(os.environ.get("COURSE_HUB_CPU_SECONDS", str(4 * 3600)))
NICENESS = 5
# A server with no activity (no kernel busy, no browser tab) for this long is stopped.
IDLE_SECONDS = int(os.environ.get("COURSE_HUB_IDLE_SECONDS", "3600"))
# The hub's Python and its scripts (jupyterhub-singleuser, nbgrader, python): a venv's bin.
BIN = Path(sys.executable).parent

HOMES.mkdir(parents=True, exist_ok=True)
# Every student's server writes its submissions here and reads the releases: nbgrader asks
# for rwx for everyone (it resets any other mode when the teacher releases).
EXCHANGE.mkdir(exist_ok=True)
EXCHANGE.chmod(0o777)

# --- The hub and its proxy ----------------------------------------------------------
c.JupyterHub.ip = IP
c.JupyterHub.port = PORT
c.JupyterHub.hub_bind_url = f"http://127.0.0.1:{HUB_PORT}"
c.ConfigurableHTTPProxy.api_url = f"http://127.0.0.1:{PROXY_API_PORT}"
c.ConfigurableHTTPProxy.pid_file = str(DATA / "proxy.pid")


def find_proxy() -> str | None:
    """configurable-http-proxy: COURSE_HUB_PROXY, `npm ci`'s in hub/, or the one on PATH."""
    if os.environ.get("COURSE_HUB_PROXY"):
        return os.environ["COURSE_HUB_PROXY"]
    folders = [Path(__file__).resolve().parent]  # npm ci beside this file
    course = importlib.util.find_spec("course")
    if course and course.origin:  # the course's checkout: `npm ci` in its hub/
        folders.append(Path(course.origin).resolve().parent.parent / "hub")
    for folder in folders:
        proxy = folder / "node_modules" / ".bin" / "configurable-http-proxy"
        if proxy.exists():
            return str(proxy)
    return shutil.which("configurable-http-proxy")


PROXY = find_proxy()
if PROXY:
    c.ConfigurableHTTPProxy.command = [PROXY]
else:
    print(
        "jupyterhub_config.py: configurable-http-proxy not found: run `npm ci` in hub/ of the "
        "course's checkout, put it on PATH, or name it with COURSE_HUB_PROXY",
        file=sys.stderr,
    )
c.JupyterHub.db_url = f"sqlite:///{DATA / 'jupyterhub.sqlite'}"
c.JupyterHub.cookie_secret_file = str(DATA / "jupyterhub_cookie_secret")
# A whole class logs in at the start of a lesson: let the servers queue, not fail.
c.JupyterHub.concurrent_spawn_limit = 100
c.JupyterHub.active_server_limit = int(os.environ.get("COURSE_HUB_MAX_SERVERS", "60"))


def stop_once(hub: JupyterHub) -> None:
    """Make a second Ctrl-C (or SIGTERM) during the hub's shutdown wait for the first one.

    JupyterHub starts its whole shutdown again at each signal: the second stops the same
    servers a second time ("Failed to stop user: ''", once per server) and ends the event
    loop under the first ("Task was destroyed but it is pending!").
    """
    shutdown = hub.shutdown_cancel_tasks
    stopping = []

    async def shutdown_once(sig=None):
        if stopping:
            hub.log.info("Already stopping the hub and the students' servers: one moment.")
            return
        stopping.append(sig)
        await shutdown(sig)

    hub.shutdown_cancel_tasks = shutdown_once


if JupyterHub.initialized():  # the hub itself, not a command such as `jupyterhub token`
    stop_once(JupyterHub.instance())

# --- Who may log in -----------------------------------------------------------------
c.JupyterHub.authenticator_class = "dummy"
c.DummyAuthenticator.password = os.environ.get("COURSE_HUB_PASSWORD", "")
c.Authenticator.allow_all = True
# Admins are the class's graders: they release and collect (nbgrader's formgrader).
c.Authenticator.admin_users = {os.environ.get("COURSE_HUB_TEACHER", "teacher")}

# --- nbgrader's exchange --------------------------------------------------------------
# Read by every server's nbgrader (the Assignments panel, the formgrader, the nbgrader
# command in a terminal). The hub rewrites it at each start: change it here.
NBGRADER_CONFIG = f'''"""nbgrader on the course's hub: written by hub/jupyterhub_config.py."""

import os

c = get_config()  # noqa: F821 (nbgrader defines it)
c.CourseDirectory.course_id = {COURSE_ID!r}
c.Exchange.root = {str(EXCHANGE)!r}
if os.environ.get("COURSE_HUB_STUDENT"):
    # A student's server: one Unix account runs every student's, so nbgrader is told who
    # submits; the lessons are their assignments (see ASSIGNMENTS_FOLDER in the hub's file).
    c.CourseDirectory.student_id = os.environ["COURSE_HUB_STUDENT"]
    c.Exchange.assignment_dir = os.path.join(os.environ["HOME"], {ASSIGNMENTS_FOLDER!r})
else:
    # A grader's: the nbgrader course folder in their own folder.
    c.CourseDirectory.root = os.path.join(os.environ["HOME"], {GRADING_FOLDER!r})
    # One Unix account owns every submission (the spawner below): nbgrader would take each
    # for a student's cheating attempt. With an account per student, remove this line.
    c.CollectApp.check_owner = False
'''
# Students see the Assignments panel, not the grader's panels and their server handlers.
STUDENTS_HIDDEN = ("formgrader", "course-list", "create-assignment")
CLASS_CONFIG.mkdir(parents=True, exist_ok=True)
(CLASS_CONFIG / "nbgrader_config.py").write_text(NBGRADER_CONFIG)
(STUDENT_CONFIG / "labconfig").mkdir(parents=True, exist_ok=True)
(STUDENT_CONFIG / "labconfig" / "page_config.json").write_text(
    json.dumps(
        {"disabledExtensions": {f"@jupyter/nbgrader:{name}": True for name in STUDENTS_HIDDEN}},
        indent=1,
    )
)
(STUDENT_CONFIG / "jupyter_server_config.json").write_text(
    json.dumps(
        {
            "ServerApp": {
                "jpserver_extensions": {
                    f"nbgrader.server_extensions.{name.replace('-', '_')}": False
                    for name in ("formgrader", "course-list")
                }
            }
        },
        indent=1,
    )
)

# --- Each student's server ----------------------------------------------------------


class CourseSpawner(SimpleLocalProcessSpawner):
    """A local JupyterLab per student, under the per-process limits, in a seeded folder."""

    def make_preexec_fn(self, name):
        enter_home = super().make_preexec_fn(name)
        memory = int(MEMORY_LIMIT_GIB * 2**30)

        def limit():
            enter_home()
            # In the child before it runs the server: inherited by its kernels.
            resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
            resource.setrlimit(resource.RLIMIT_CPU, (CPU_SECONDS, CPU_SECONDS))
            os.nice(NICENESS)
            # A hub started in the background (nohup, `&`) ignores Ctrl-C, and its children
            # would too: the server must stop at the hub's SIGINT, not 10 s later at SIGTERM.
            signal.signal(signal.SIGINT, signal.SIG_DFL)

        return limit

    def get_env(self):
        env = super().get_env()
        folders = [str(CLASS_CONFIG)]
        if not self.user.admin:
            env["COURSE_HUB_STUDENT"] = self.user.name
            folders.insert(0, str(STUDENT_CONFIG))
        env["JUPYTER_CONFIG_PATH"] = os.pathsep.join(folders)
        return env


# One build of the edition at a time: a class logs in at once.
EDITION_BUILT = asyncio.Lock()


async def build_edition(log) -> None:
    """Write the student edition into EDITION if it is not there (the first start)."""
    async with EDITION_BUILT:
        if EDITION.is_dir():
            return
        partial = EDITION.with_name(EDITION.name + ".partial")
        shutil.rmtree(partial, ignore_errors=True)
        log.info("Building the student edition in %s", EDITION)
        build = await asyncio.create_subprocess_exec(
            sys.executable,
            "-m",
            "course",
            "student",
            "--out",
            str(partial),
            stdout=asyncio.subprocess.PIPE,
            stderr=asyncio.subprocess.STDOUT,
        )
        output, _ = await build.communicate()
        if build.returncode:
            raise RuntimeError(
                f"python -m course student failed ({build.returncode}): {output.decode()}"
            )
        partial.rename(EDITION)  # whole or not at all: a half-built edition is never seeded


async def seed_folder(spawner):
    """Copy the student edition into the student's folder: only the files not there yet.

    Then link each lesson into the student's nbgrader assignments (ASSIGNMENTS_FOLDER).
    With LESSONS_REPO, the start page pulls the lessons instead (nbgitpuller), and the
    lessons already pulled are linked.
    """
    lessons = Path(spawner.home_dir) / LESSONS_FOLDER
    if not LESSONS_REPO:
        await build_edition(spawner.log)
        for source in sorted(EDITION.rglob("*")):
            target = lessons / source.relative_to(EDITION)
            if source.is_dir():
                target.mkdir(parents=True, exist_ok=True)
            elif not target.exists():  # a student's edited notebook is never replaced
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(source, target)
    if not spawner.user.admin:
        link_assignments(lessons, Path(spawner.home_dir) / ASSIGNMENTS_FOLDER)


def link_assignments(lessons: Path, assignments: Path) -> None:
    """assignments/<lesson>/<lesson>.ipynb: a link to lessons/<lesson>.ipynb, for each lesson.

    nbgrader's assignment is a folder named as the assignment: the lessons' names are those
    of `python -m course nbgrader`'s assignments. A folder already there is left alone.
    """
    for lesson in sorted(lessons.glob("[0-9][0-9]_*.ipynb")):
        if lesson.name == "00_index.ipynb":
            continue
        folder = assignments / lesson.stem
        if not folder.exists():
            folder.mkdir(parents=True)
            (folder / lesson.name).symlink_to(os.path.relpath(lesson, folder))


c.JupyterHub.spawner_class = CourseSpawner
c.SimpleLocalProcessSpawner.home_dir_template = str(HOMES / "{username}")
c.Spawner.pre_spawn_hook = seed_folder
# The single-user server beside the hub's Python (a venv), else the one on PATH.
c.Spawner.cmd = [shutil.which("jupyterhub-singleuser", path=str(BIN)) or "jupyterhub-singleuser"]
c.Spawner.default_url = START
c.Spawner.args = [
    # Each drag step's picture sent at once (course.classroom.serving).
    "--ServerApp.kernel_websocket_connection_class=course.classroom.serving.PromptConnection",
    *(["--allow-root"] if os.geteuid() == 0 else []),
]
c.Spawner.environment = {
    # A terminal's python, nbgrader and git-pull are the hub's set, as the server's are.
    "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', os.defpath)}",
    "OPENBLAS_NUM_THREADS": "1",
    "OMP_NUM_THREADS": "1",
    "MKL_NUM_THREADS": "1",
    "PYDEVD_DISABLE_FILE_VALIDATION": "1",
    # glibc's malloc reserves 64 MiB of address space per thread otherwise: RLIMIT_AS
    # would count reservations, not memory.
    "MALLOC_ARENA_MAX": "2",
}
c.Spawner.mem_limit = f"{MEMORY_LIMIT_GIB}G"
c.Spawner.cpu_limit = 1.0
# Thirty servers starting at once on two cores take minutes, not JupyterHub's default 60 s.
c.Spawner.start_timeout = 600
c.Spawner.http_timeout = 600

# --- Services: the idle culler, and an admin token for scripts ----------------------
c.JupyterHub.services = [
    {
        "name": "idle-culler",
        "command": [
            sys.executable,
            "-m",
            "jupyterhub_idle_culler",
            f"--timeout={IDLE_SECONDS}",
            "--cull-every=300",
        ],
    }
]
c.JupyterHub.load_roles = [
    {
        "name": "idle-culler",
        "scopes": ["list:users", "read:users:activity", "read:servers", "delete:servers"],
        "services": ["idle-culler"],
    }
]
if os.environ.get("COURSE_HUB_ADMIN_TOKEN"):
    c.JupyterHub.services.append(
        {"name": "course-admin", "api_token": os.environ["COURSE_HUB_ADMIN_TOKEN"]}
    )
    c.JupyterHub.load_roles.append(
        {
            "name": "course-admin",
            "scopes": ["admin:users", "admin:servers", "tokens", "access:servers", "list:users"],
            "services": ["course-admin"],
        }
    )
