# The course's JupyterHub: one JupyterLab per student on one machine, for a class.
#
# `make hub` runs it on this machine for a trial class (127.0.0.1, any username, one
# shared password). A teacher copies this file to a university's server and changes
# what the COURSE_HUB_* environment variables set, or the lines below them; docs/hub.md
# says how, and how the same settings read on Zero to JupyterHub (Kubernetes).
#
# What it sets up:
# - every student's server is JupyterLab, from the same lock as the course
#   (requirements/hub.txt), started as a local process (SimpleLocalProcessSpawner:
#   one Unix user runs them all, each in its own folder);
# - each student's folder is seeded from the student edition the first time, file by
#   file, never overwriting what is there; the start page is its course map;
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

import os
import resource
import shutil
import sys
from pathlib import Path

from jupyterhub.spawner import SimpleLocalProcessSpawner

REPOSITORY = Path(__file__).resolve().parent.parent
# Where the hub keeps its state: its database, cookie secret, proxy pid, the built
# student edition and every student's folder.
DATA = Path(os.environ.get("COURSE_HUB_DATA", REPOSITORY / "build" / "hub")).resolve()
IP = os.environ.get("COURSE_HUB_IP", "127.0.0.1")
PORT = int(os.environ.get("COURSE_HUB_PORT", "8000"))
HUB_PORT = int(os.environ.get("COURSE_HUB_API_PORT", str(PORT + 81)))
PROXY_API_PORT = int(os.environ.get("COURSE_HUB_PROXY_API_PORT", str(PORT + 1)))
# The student edition (python -m course student --out ...) each folder is seeded from.
EDITION = Path(os.environ.get("COURSE_HUB_EDITION", DATA / "student-edition"))
# Where each student's folder is, and the folder the edition goes to inside it.
HOMES = DATA / "homes"
LESSONS_FOLDER = "student"
# Per student process: address space and CPU-seconds (see the header).
MEMORY_LIMIT_GIB = float(os.environ.get("COURSE_HUB_MEMORY_GIB", "2"))
CPU_SECONDS = int(os.environ.get("COURSE_HUB_CPU_SECONDS", str(4 * 3600)))
NICENESS = 5
# A server with no activity (no kernel busy, no browser tab) for this long is stopped.
IDLE_SECONDS = int(os.environ.get("COURSE_HUB_IDLE_SECONDS", "3600"))

DATA.mkdir(parents=True, exist_ok=True)
HOMES.mkdir(parents=True, exist_ok=True)

# --- The hub and its proxy ----------------------------------------------------------
c.JupyterHub.ip = IP
c.JupyterHub.port = PORT
c.JupyterHub.hub_bind_url = f"http://127.0.0.1:{HUB_PORT}"
c.ConfigurableHTTPProxy.api_url = f"http://127.0.0.1:{PROXY_API_PORT}"
c.ConfigurableHTTPProxy.pid_file = str(DATA / "proxy.pid")
# configurable-http-proxy from npm: `make hub` installs the pinned one (hub/package-lock.json).
PROXY = DATA / "node_modules" / ".bin" / "configurable-http-proxy"
if PROXY.exists():
    c.ConfigurableHTTPProxy.command = [str(PROXY)]
c.JupyterHub.db_url = f"sqlite:///{DATA / 'jupyterhub.sqlite'}"
c.JupyterHub.cookie_secret_file = str(DATA / "jupyterhub_cookie_secret")
# A whole class logs in at the start of a lesson: let the servers queue, not fail.
c.JupyterHub.concurrent_spawn_limit = 100
c.JupyterHub.active_server_limit = int(os.environ.get("COURSE_HUB_MAX_SERVERS", "60"))

# --- Who may log in -----------------------------------------------------------------
c.JupyterHub.authenticator_class = "dummy"
c.DummyAuthenticator.password = os.environ.get("COURSE_HUB_PASSWORD", "")
c.Authenticator.allow_all = True
c.Authenticator.admin_users = {os.environ.get("COURSE_HUB_TEACHER", "teacher")}

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

        return limit


def seed_folder(spawner):
    """Copy the student edition into the student's folder: only the files not there yet."""
    lessons = Path(spawner.home_dir) / LESSONS_FOLDER
    for source in sorted(EDITION.rglob("*")) if EDITION.is_dir() else []:
        target = lessons / source.relative_to(EDITION)
        if source.is_dir():
            target.mkdir(parents=True, exist_ok=True)
        elif not target.exists():  # a student's edited notebook is never replaced
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target)


c.JupyterHub.spawner_class = CourseSpawner
c.SimpleLocalProcessSpawner.home_dir_template = str(HOMES / "{username}")
c.Spawner.pre_spawn_hook = seed_folder
# The single-user server beside the hub's Python (a venv), else the one on PATH.
c.Spawner.cmd = [
    shutil.which("jupyterhub-singleuser", path=str(Path(sys.executable).parent))
    or "jupyterhub-singleuser"
]
c.Spawner.default_url = f"/lab/tree/{LESSONS_FOLDER}/00_index.ipynb"
c.Spawner.args = [
    # Each drag step's picture sent at once (course.classroom.serving).
    "--ServerApp.kernel_websocket_connection_class=course.classroom.serving.PromptConnection",
    *(["--allow-root"] if os.geteuid() == 0 else []),
]
c.Spawner.environment = {
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
