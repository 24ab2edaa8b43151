"""Single-slip mutants of every exercise's reference solution, and each checker's verdict on them.

An exercise is a code cell of a lesson's notebook tagged ``solution`` that
ends with ``check.<checker>(<function>)``. Its reference solution is that
function; a mutant changes one thing in its body (or, where the cell marks it
with ``### BEGIN SOLUTION`` / ``### END SOLUTION``, one thing between the
markers), the way a student slips:

- an arithmetic operator swapped for its usual partner (+ -, * /, / //, ** *,
  % //), in an expression or an augmented assignment;
- a comparison swapped (< <=, < >, > >=, <= >=, == !=, in / not in, is / is not);
- an integer constant plus or minus one (so 0 becomes 1 and 1 becomes 0), a
  float 0.0 or 1.0 swapped for the other;
- ``and`` swapped for ``or`` and back;
- a unary minus or ``not`` dropped, or a minus put before an operand of an
  arithmetic operator;
- a statement replaced by ``pass`` (a dropped line; the code stays valid);
- an index, a slice bound or a ``range`` argument that is not a constant,
  plus or minus one (constants are covered above).

Mutants whose source is the original's, or another mutant's, are dropped.

Each mutant is checked in a process of its own, forked from a server that has
imported the checkers once (multiprocessing's ``forkserver``), under a hard
timeout and an address-space limit, so that a mutant that loops forever or
grows without bound cannot stall or sink the harness whatever the checker does.
The outcome is one of :data:`OUTCOMES`.

The exercise's namespace is rebuilt cheaply: of the notebook's earlier code
cells, only the top-level imports, definitions and assignments the exercise
needs (by name, transitively) are run, so ``recursive_bezier`` gets the
reference ``next_level`` and lesson 06 its ``M``; no figure or app is built.
"""

from __future__ import annotations

import ast
import copy
import io
import json
import multiprocessing
import multiprocessing.connection
import os
import re
import time
import traceback
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import redirect_stderr, redirect_stdout
from dataclasses import dataclass
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOKS = ROOT / "notebooks"

TIMEOUT = 20.0  # seconds a mutant's check may take before the harness kills it
MEMORY = 3 * 2**30  # bytes of address space a mutant's check may add
WORKERS = 2  # the machine's two cores are shared

OUTCOMES = (
    "failed",  # the checker returned a falsy result
    "stopped",  # ... saying its own budget stopped the case (a kind of failed)
    "named",  # ... naming a known mistake (a kind of failed)
    "survived",  # the checker returned a truthy result: the mutant passes
    "memory",  # the mutant hit the harness's memory limit: the checker did not stop it
    "hang",  # the harness's timeout: the checker did not stop it
    "crash",  # the checker raised instead of returning a result
)
FAILED = ("failed", "stopped", "named")  # outcomes that count as the checker failing the mutant

BEGIN, END = "### BEGIN SOLUTION", "### END SOLUTION"


@dataclass(frozen=True)
class Exercise:
    """One exercise: its checker, the reference function's source and what it needs to run."""

    checker: str  # the checker's name in its module, ``check.<checker>``
    function: str  # the reference function's name
    notebook: str  # the notebook's file name
    cell: int  # the cell's index in the notebook
    source: str  # the cell's code without its final check call
    setup: str  # the earlier cells' statements the cell needs, in order
    call: str  # the check call, ``check.<checker>(<function>)``
    lines: tuple[int, int]  # the cell's lines (1-based, inclusive) that mutants may change


@dataclass(frozen=True)
class Mutant:
    """One slip in one exercise's reference solution."""

    exercise: str  # the checker's name
    kind: str  # which slip, e.g. "operator", "comparison", "constant", "statement"
    line: int  # the line of the cell the slip is on
    original: str  # that statement (its header, for a compound one), as ast.unparse writes it
    mutated: str  # the same with the slip
    source: str  # the whole mutated cell code, without the check call

    @property
    def diff(self) -> str:
        """The slip, short: ``line N: x < x1 -> x <= x1``, a word of context either side.

        Where the statement holds the changed words more than once, the column
        of the change follows the line (``line 7:12``), so each diff names one mutant.
        """
        before, after = self.original, self.mutated
        start = 0
        while start < min(len(before), len(after)) and before[start] == after[start]:
            start += 1
        end = 0
        while (
            end < min(len(before), len(after)) - start
            and before[len(before) - 1 - end] == after[len(after) - 1 - end]
        ):
            end += 1
        # Widen to a word of context either side, cut at spaces.
        left = before.rfind(" ", 0, max(0, before.rfind(" ", 0, start)))
        left = 0 if left < 0 else left + 1
        right_before = _word_end(before, len(before) - end)
        right_after = _word_end(after, len(after) - end)
        old, new = before[left:right_before].strip(), after[left:right_after].strip()
        where = f"{self.line}" if before.count(old) == 1 else f"{self.line}:{left}"
        return f"line {where}: {old or '(nothing)'}  ->  {new or '(nothing)'}"


def _word_end(text: str, position: int) -> int:
    """Past the next space-delimited word after ``position`` (or the text's end)."""
    first = text.find(" ", position + 1)
    if first < 0:
        return len(text)
    second = text.find(" ", first + 1)
    return len(text) if second < 0 else second


@dataclass(frozen=True)
class Outcome:
    """What the checker made of one mutant."""

    mutant: Mutant
    outcome: str  # one of OUTCOMES
    detail: str  # the report's first lines, or the error
    seconds: float


# --- finding the exercises ------------------------------------------------------------


def _code_cells(notebook: Path) -> list[tuple[int, list[str], str]]:
    cells = json.loads(notebook.read_text(encoding="utf-8"))["cells"]
    return [
        (index, cell.get("metadata", {}).get("tags", []), "".join(cell["source"]))
        for index, cell in enumerate(cells)
        if cell["cell_type"] == "code"
    ]


def _defined_names(statement: ast.stmt) -> set[str]:
    if isinstance(statement, (ast.Import, ast.ImportFrom)):
        return {(alias.asname or alias.name).split(".")[0] for alias in statement.names}
    if isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return {statement.name}
    if isinstance(statement, (ast.Assign, ast.AnnAssign)):
        targets = statement.targets if isinstance(statement, ast.Assign) else [statement.target]
        return {
            node.id
            for target in targets
            for node in ast.walk(target)
            if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store)
        }
    return set()


def _used_names(node: ast.AST) -> set[str]:
    return {n.id for n in ast.walk(node) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}


def _setup(earlier: Sequence[ast.stmt], needed: set[str]) -> str:
    """The earlier statements that define ``needed`` names, and what those need, in order."""
    chosen: set[int] = set()
    wanted = set(needed)
    changed = True
    while changed:
        changed = False
        for index, statement in enumerate(earlier):
            if index not in chosen and _defined_names(statement) & wanted:
                chosen.add(index)
                wanted |= _used_names(statement)
                changed = True
    return "\n".join(ast.unparse(earlier[index]) for index in sorted(chosen))


def _checked_call(tree: ast.Module) -> ast.Call | None:
    """The cell's last statement if it is ``check.<checker>(<function>)``."""
    last = tree.body[-1] if tree.body else None
    call = last.value if isinstance(last, ast.Expr) else None
    if (
        isinstance(call, ast.Call)
        and isinstance(call.func, ast.Attribute)
        and isinstance(call.func.value, ast.Name)
        and call.func.value.id == "check"
        and len(call.args) == 1
        and isinstance(call.args[0], ast.Name)
    ):
        return call
    return None


def find_exercises(notebooks: Iterable[Path] | None = None) -> list[Exercise]:
    """Every exercise of the lessons' notebooks, in the notebooks' order."""
    found = []
    for notebook in sorted(notebooks or NOTEBOOKS.glob("[0-9]*.ipynb")):
        earlier: list[ast.stmt] = []
        for index, tags, text in _code_cells(notebook):
            try:
                tree = ast.parse(text)
            except SyntaxError:  # IPython magics: never an exercise's dependency here
                continue
            definitions = [
                statement
                for statement in tree.body
                if isinstance(
                    statement,
                    (ast.Import, ast.ImportFrom, ast.FunctionDef, ast.ClassDef, ast.Assign),
                )
            ]
            checked = _checked_call(tree) if "solution" in tags else None
            if checked is not None:
                last, function = tree.body[-1], checked.args[0].id  # type: ignore[attr-defined]
                body = tree.body[:-1]
                text_lines = text.splitlines()
                marked = [i + 1 for i, line in enumerate(text_lines) if line.strip() == BEGIN]
                ends = [i + 1 for i, line in enumerate(text_lines) if line.strip() == END]
                definition = next(
                    s for s in body if isinstance(s, ast.FunctionDef) and s.name == function
                )
                if marked and ends:
                    lines = (marked[0] + 1, ends[0] - 1)
                else:
                    first = definition.body[0]
                    if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                        first = definition.body[1]  # the docstring stays
                    lines = (first.lineno, definition.end_lineno or first.lineno)
                source = "\n".join(text_lines[: last.lineno - 1]).rstrip()
                needed = _used_names(ast.Module(body=body, type_ignores=[])) | {"check"}
                needed -= {n for s in body for n in _defined_names(s)}
                found.append(
                    Exercise(
                        checker=checked.func.attr,  # type: ignore[attr-defined]
                        function=function,
                        notebook=notebook.name,
                        cell=index,
                        source=source,
                        setup=_setup(earlier, needed),
                        call=ast.unparse(last),
                        lines=lines,
                    )
                )
            earlier.extend(definitions)
    return found


# --- the slips ------------------------------------------------------------------------

ARITHMETIC: dict[type[ast.operator], tuple[type[ast.operator], ...]] = {
    ast.Add: (ast.Sub,),
    ast.Sub: (ast.Add,),
    ast.Mult: (ast.Div,),
    ast.Div: (ast.Mult, ast.FloorDiv),
    ast.FloorDiv: (ast.Div,),
    ast.Mod: (ast.FloorDiv,),
    ast.Pow: (ast.Mult,),
}
COMPARISON: dict[type[ast.cmpop], tuple[type[ast.cmpop], ...]] = {
    ast.Lt: (ast.LtE, ast.Gt),
    ast.LtE: (ast.Lt, ast.GtE),
    ast.Gt: (ast.GtE, ast.Lt),
    ast.GtE: (ast.Gt, ast.LtE),
    ast.Eq: (ast.NotEq,),
    ast.NotEq: (ast.Eq,),
    ast.In: (ast.NotIn,),
    ast.NotIn: (ast.In,),
    ast.Is: (ast.IsNot,),
    ast.IsNot: (ast.Is,),
}
SYMBOLS = {
    ast.Add: "+",
    ast.Sub: "-",
    ast.Mult: "*",
    ast.Div: "/",
    ast.FloorDiv: "//",
    ast.Mod: "%",
    ast.Pow: "**",
}

Path_ = tuple[tuple[str, int | None], ...]  # from the module down to a node: (field, index)


def _get(root: ast.AST, path: Path_) -> Any:
    node: Any = root
    for field, index in path:
        node = getattr(node, field)
        if index is not None:
            node = node[index]
    return node


def _set(root: ast.AST, path: Path_, value: Any) -> None:
    parent = _get(root, path[:-1])
    field, index = path[-1]
    if index is None:
        setattr(parent, field, value)
    else:
        getattr(parent, field)[index] = value


def _walk(node: ast.AST, path: Path_ = ()) -> Iterator[tuple[Path_, ast.AST]]:
    yield path, node
    for field, value in ast.iter_fields(node):
        if isinstance(value, list):
            for index, item in enumerate(value):
                if isinstance(item, ast.AST):
                    yield from _walk(item, (*path, (field, index)))
        elif isinstance(value, ast.AST):
            yield from _walk(value, (*path, (field, None)))


def _plus(node: ast.expr, step: int) -> ast.expr:
    return ast.BinOp(copy.deepcopy(node), ast.Add() if step > 0 else ast.Sub(), ast.Constant(1))


def _is_number(node: ast.AST) -> bool:
    return (
        isinstance(node, ast.Constant)
        and isinstance(node.value, (int, float))
        and not isinstance(node.value, bool)
    )


def _adds_a_constant(node: ast.AST) -> bool:
    """``i + 1`` and the like: their ±1 slips are the constant's own."""
    return (
        isinstance(node, ast.BinOp)
        and isinstance(node.op, (ast.Add, ast.Sub))
        and _is_number(node.right)
    )


def _off_by_one_targets(node: ast.AST) -> Iterator[tuple[Path_, ast.expr]]:
    """The index, slice-bound and range-argument expressions below ``node`` to shift by one."""

    def shiftable(expr: ast.AST | None) -> bool:
        return (
            isinstance(expr, ast.expr)
            and not isinstance(expr, (ast.Slice, ast.Tuple))
            and not _is_number(expr)
            and not (isinstance(expr, ast.UnaryOp) and _is_number(expr.operand))
            and not _adds_a_constant(expr)
        )

    if isinstance(node, ast.Subscript):
        if isinstance(node.slice, ast.Tuple):
            for index, element in enumerate(node.slice.elts):
                if shiftable(element):
                    yield (("slice", None), ("elts", index)), element
        elif shiftable(node.slice):
            yield (("slice", None),), node.slice
    elif isinstance(node, ast.Slice):
        for field in ("lower", "upper"):
            value = getattr(node, field)
            if shiftable(value):
                yield ((field, None),), value
    elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "range":
        for index, argument in enumerate(node.args):
            if shiftable(argument):
                yield (("args", index),), argument


def _slips(node: ast.AST, parent: ast.AST | None) -> Iterator[tuple[str, Callable[[], Any]]]:
    """(kind, a function making the replacement node) for each slip at ``node``."""
    if isinstance(node, (ast.BinOp, ast.AugAssign)):
        for other in ARITHMETIC.get(type(node.op), ()):

            def swap(node: Any = node, other: Any = other) -> Any:
                new = copy.deepcopy(node)
                new.op = other()
                return new

            yield "operator", swap
    if isinstance(node, ast.Compare):
        for position, op in enumerate(node.ops):
            for other in COMPARISON.get(type(op), ()):

                def compare(node: Any = node, position: int = position, other: Any = other) -> Any:
                    new = copy.deepcopy(node)
                    new.ops[position] = other()
                    return new

                yield "comparison", compare
    if _is_number(node):
        assert isinstance(node, ast.Constant)
        value = node.value
        if isinstance(value, int):
            for step in (1, -1):
                yield "constant", lambda value=value, step=step: ast.Constant(value + step)
        elif value in (0.0, 1.0):
            yield "constant", lambda value=value: ast.Constant(1.0 - value)
    if isinstance(node, ast.BoolOp):

        def boolean(node: Any = node) -> Any:
            new = copy.deepcopy(node)
            new.op = ast.Or() if isinstance(node.op, ast.And) else ast.And()
            return new

        yield "boolean", boolean
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.Not)):
        yield "unary", lambda node=node: copy.deepcopy(node.operand)
    if (
        isinstance(parent, ast.BinOp)
        and isinstance(parent.op, tuple(ARITHMETIC))
        and isinstance(node, (ast.Name, ast.Subscript, ast.Attribute, ast.Constant, ast.Call))
        and not (isinstance(node, ast.Constant) and node.value == 0)
    ):
        yield "unary", lambda node=node: ast.UnaryOp(ast.USub(), copy.deepcopy(node))


def _statement_text(statement: ast.stmt) -> str:
    """A statement on one line: a compound statement's header, a simple one whole."""
    if isinstance(statement, (ast.For, ast.While, ast.If, ast.With, ast.FunctionDef)):
        header = copy.copy(statement)
        header.body = [ast.Pass()]  # type: ignore[attr-defined]
        if hasattr(header, "orelse"):
            header.orelse = []  # type: ignore[attr-defined]
        return ast.unparse(header).splitlines()[0]
    return " ".join(ast.unparse(statement).split())


def mutants(exercise: Exercise) -> list[Mutant]:
    """Every distinct single-slip mutant of ``exercise``'s reference solution."""
    tree = ast.parse(exercise.source)
    original = ast.unparse(tree)
    first, last = exercise.lines
    seen = {original}
    made = []
    nodes = list(_walk(tree))
    parents = {id(child): node for _, node in nodes for child in ast.iter_child_nodes(node)}

    def enclosing_statement(path: Path_) -> Path_:
        for cut in range(len(path), -1, -1):
            if isinstance(_get(tree, path[:cut]), ast.stmt):
                return path[:cut]
        return ()

    def inside(node: ast.AST) -> bool:
        line = getattr(node, "lineno", None)
        end = getattr(node, "end_lineno", line)
        return line is not None and first <= line and (end or line) <= last

    def add(kind: str, path: Path_, replacement: Any) -> None:
        new_tree = ast.parse(exercise.source)  # a fresh tree: far cheaper than a deep copy
        _set(new_tree, path, replacement)
        source = ast.unparse(new_tree)
        if source in seen:
            return
        compile(source, "<mutant>", "exec")
        seen.add(source)
        at = enclosing_statement(path)
        statement = _get(tree, at)
        made.append(
            Mutant(
                exercise=exercise.checker,
                kind=kind,
                line=statement.lineno,
                original=_statement_text(statement),
                mutated=_statement_text(_get(new_tree, at)),
                source=source,
            )
        )

    for path, node in nodes:
        if not path:
            continue
        statement = _get(tree, enclosing_statement(path))
        if not inside(node) and not (isinstance(node, ast.expr) and inside(statement)):
            continue
        if isinstance(node, ast.stmt) and not isinstance(node, ast.Pass):
            docstring = isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant)
            if inside(node) and not docstring:
                add("statement", path, ast.Pass())
        for kind, make in _slips(node, parents.get(id(node))):
            add(kind, path, make())
        for below, target in _off_by_one_targets(node):
            for step in (1, -1):
                add("off by one", (*path, *below), _plus(target, step))
    return made


# --- running the checkers -------------------------------------------------------------

PRELOAD = [
    "numpy",
    "matplotlib",
    "matplotlib.pyplot",
    "course.lessons.l01_de_casteljau.check",
    "course.lessons.l02_bernstein.check",
    "course.lessons.l03_lines_and_triangles.check",
    "course.lessons.l04_supersampling.check",
    "course.lessons.l05_antialiasing.check",
    "course.lessons.l06_dithering.check",
    "course.lessons.l07_filtering.check",
    "course.lessons.l08_poisson.check",
]


def _check(setup: str, source: str, call: str, memory: int, prelude: str, connection: Any) -> None:
    """In the mutant's own process: run the check and send back (outcome, detail)."""
    try:
        import resource

        _, hard = resource.getrlimit(resource.RLIMIT_AS)
        with open("/proc/self/statm") as statm:
            used = int(statm.read().split()[0]) * resource.getpagesize()
        resource.setrlimit(resource.RLIMIT_AS, (used + memory, hard))
    except (ImportError, OSError, ValueError):
        pass  # no address-space limit on this platform: the timeout still holds
    try:
        if os.nice(0) < 10:
            os.nice(10 - os.nice(0))
    except OSError:
        pass
    chatter = io.StringIO()
    try:
        namespace: dict[str, Any] = {"__name__": "__mutant__"}
        exec(compile(prelude, "<prelude>", "exec"), {})
        exec(compile(setup, "<setup>", "exec"), namespace)
        exec(compile(source, "<mutant>", "exec"), namespace)
        with redirect_stdout(chatter), redirect_stderr(chatter):
            result = eval(compile(call, "<check>", "eval"), namespace)
    except MemoryError:
        connection.send(("memory", "MemoryError raised out of the checker"))
        return
    except BaseException:  # the checker's own failure: the harness reports it
        lines = traceback.format_exc().strip().splitlines()
        connection.send(("crash", "\n".join(lines[-4:])))
        return
    connection.send(classify(result))


def classify(result: Any) -> tuple[str, str]:
    """The outcome of a checker's result, and the report's first lines."""
    if not hasattr(result, "passed") or not hasattr(result, "message"):
        return "crash", f"the checker returned {type(result).__name__}, not a CheckResult"
    message = str(result.message)
    detail = "\n".join(message.splitlines()[:6])[:1500]
    if result:
        return "survived", detail
    if "MemoryError" in message:
        return "memory", detail  # the harness's limit, not the checker's budget
    if getattr(result, "mistake", None) is not None:
        return "named", detail
    if re.search(r"was stopped|did not stop|memory", message, re.IGNORECASE):
        return "stopped", detail
    return "failed", detail


def _context() -> Any:
    os.environ.setdefault("MPLBACKEND", "Agg")
    for variable in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(variable, "1")  # one thread: forking is safe, the cores shared
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload([*PRELOAD, "mutation"])
    return context


def run(
    work: Sequence[tuple[Exercise, Mutant]],
    timeout: float = TIMEOUT,
    workers: int = WORKERS,
    memory: int = MEMORY,
    progress: Callable[[Outcome], None] | None = None,
    prelude: str = "",
) -> list[Outcome]:
    """Check each mutant in a process of its own, ``workers`` at a time; outcomes in order.

    ``prelude`` is code the process runs first, in a namespace of its own (to
    lengthen a checker's own budget, say).
    """
    context = _context()
    results: dict[int, Outcome] = {}
    pending = list(enumerate(work))[::-1]
    running: dict[Any, tuple[int, Any, Any, float]] = {}  # sentinel: (index, process, conn, t0)

    def finish(sentinel: Any, outcome: str, detail: str) -> None:
        index, process, connection, started = running.pop(sentinel)
        process.join(1)
        if process.is_alive():
            process.kill()
            process.join()
        connection.close()
        results[index] = Outcome(work[index][1], outcome, detail, time.monotonic() - started)
        if progress is not None:
            progress(results[index])

    while pending or running:
        while pending and len(running) < workers:
            index, (exercise, mutant) = pending.pop()
            receiver, sender = context.Pipe(duplex=False)
            process = context.Process(
                target=_check,
                args=(exercise.setup, mutant.source, exercise.call, memory, prelude, sender),
                daemon=True,
            )
            process.start()
            sender.close()
            running[process.sentinel] = (index, process, receiver, time.monotonic())
        now = time.monotonic()
        deadline = min(started + timeout for _, _, _, started in running.values())
        waitables = [*running, *(conn for _, _, conn, _ in running.values())]
        ready = multiprocessing.connection.wait(waitables, max(0.0, deadline - now))
        for sentinel, (_, _, connection, _) in list(running.items()):
            if connection in ready or sentinel in ready:
                try:
                    outcome, detail = connection.recv()
                except (EOFError, OSError):
                    code = running[sentinel][1].exitcode
                    outcome, detail = "crash", f"the check's process died (exit code {code})"
                finish(sentinel, outcome, detail)
        now = time.monotonic()
        for sentinel, (_, process, _, started) in list(running.items()):
            if now - started > timeout:
                process.kill()
                finish(sentinel, "hang", f"still running after {timeout:g} s")
    return [results[index] for index in range(len(work))]


def everything(exercises: Sequence[Exercise] | None = None) -> list[tuple[Exercise, Mutant]]:
    """Every (exercise, mutant) pair, in the notebooks' order."""
    return [(e, m) for e in exercises or find_exercises() for m in mutants(e)]


def reference_check(exercise: Exercise) -> tuple[str, str]:
    """The checker's verdict on the unmutated reference (in a process of its own)."""
    original = Mutant(exercise.checker, "none", 0, "", "", exercise.source)
    (outcome,) = run([(exercise, original)])
    return outcome.outcome, outcome.detail
