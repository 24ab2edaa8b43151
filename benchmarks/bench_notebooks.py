"""How long a student waits for Run All: each lesson notebook, top to bottom, in a fresh kernel.

Each notebook is run by nbclient as JupyterLab's Run All does: one kernel,
started before the clock starts (a kernel starts in about a second, whatever
the lesson), then every code cell in order. The time printed is from the
first cell sent to the last cell's result, the best of ``--runs`` runs (the
least disturbed by other processes), with the notebook's own outputs
discarded. The notebooks on disk are not changed.

Goals (issues 12, 13 and 14): Run All of notebooks 00-08 at most 15 s each on this 2-core
machine. The other lessons are printed for information.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient

NOTEBOOKS = Path(__file__).resolve().parent.parent / "notebooks"
GOALS = {f"{number:02d}": 15.0 for number in range(9)}


def run_all_seconds(path: Path) -> float:
    """Seconds from the first cell sent to the last cell done, in a kernel already started."""
    notebook = nbformat.read(path, as_version=4)
    client = NotebookClient(
        notebook,
        timeout=600,
        kernel_name="python3",
        resources={"metadata": {"path": str(path.parent)}},
    )
    with client.setup_kernel():
        start = time.perf_counter()
        for index, cell in enumerate(notebook.cells):
            if cell.cell_type == "code":
                client.execute_cell(cell, index)
        return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=2, help="runs per notebook; the best counts")
    parser.add_argument("notebooks", nargs="*", help="notebook files (default: every lesson)")
    args = parser.parse_args()
    paths = [Path(name) for name in args.notebooks] or sorted(NOTEBOOKS.glob("[0-9][0-9]_*.ipynb"))
    for path in paths:
        seconds = min(run_all_seconds(path) for _ in range(args.runs))
        number = path.name[:2]
        line = f"Run All {path.stem}: {seconds:.1f} s"
        if number in GOALS:
            verdict = "met" if seconds <= GOALS[number] else "NOT met"
            line += f" (goal <= {GOALS[number]:g} s, {verdict})"
        else:
            line += " (no goal)"
        print(line, flush=True)


if __name__ == "__main__":
    main()
