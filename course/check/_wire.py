"""How values cross between the grader and its child (:mod:`course.check.outside`).

A message is one JSON document on a line, followed by the raw bytes of the numeric arrays
it holds (:func:`write_message`, :func:`read_message`): values cross as plain JSON
(numbers, text, lists) and arrays as their bytes, dtype and shape, never pickled
(:func:`encode`, :func:`decode`), so nothing a student's object does can run in the
grader's process. Raw bytes, not text: a lesson's 700 x 700 RGB window took a third of a
second each way as base64 in JSON, and a checker sends it, and gets it back, every case.

Standard library and numpy only: the child's program is this module's text followed by
:mod:`course.check._outside_child`'s, and the grader imports it (``UNCHECKED = True``: it
trusts its caller).
"""

from __future__ import annotations

import json
import math
from typing import IO, Any

UNCHECKED = True  # see the module docstring

#: Items an iterator or a list may hold before the answer is refused as too long.
MAX_ITEMS = 2_000_000
#: How deep nested lists may go.
MAX_DEPTH = 32
#: Why an answer could not cross (:class:`Unreadable`): the grader words each in the
#: student's language.
NESTED, ARRAY, LIST, ITERATOR, BYTES = range(1, 6)


class Unreadable(Exception):
    """The returned value cannot cross: why (:data:`NESTED`, :data:`ARRAY`, :data:`LIST`,
    :data:`ITERATOR`, or :data:`BYTES` for an array its bytes cannot make) and the count,
    which the grader words in the student's language."""


def encode(value: Any, buffers: list[Any], depth: int = 0) -> Any:
    """``value`` as plain JSON: None, bools, ints, floats (tagged when not finite), text,
    lists and tuples, numeric or boolean arrays; any other object as its type's name.

    An array's bytes are appended to ``buffers`` (they travel after the message's line);
    its JSON is its dtype, its shape and the buffer's index."""
    import numpy as np

    if depth > MAX_DEPTH:
        raise Unreadable(NESTED, MAX_DEPTH)
    if value is None or type(value) is bool or type(value) is str:
        return value
    if type(value) is int:
        return {"int": str(value)} if abs(value) > 2**53 else value
    if type(value) is float:
        return value if math.isfinite(value) else {"float": repr(value)}
    if type(value) is complex:
        return {
            "complex": [
                encode(value.real, buffers, depth + 1),
                encode(value.imag, buffers, depth + 1),
            ]
        }
    if isinstance(value, np.generic) and type(value).__module__ == "numpy":
        return encode(value.item(), buffers, depth + 1)
    if type(value) is np.ndarray:
        if value.dtype.kind not in "biufc":
            return {"object": f"ndarray[{value.dtype}]"}
        if value.size > MAX_ITEMS:
            raise Unreadable(ARRAY, int(value.size))
        buffers.append(np.ascontiguousarray(value).reshape(-1).view(np.uint8))
        return {"array": [value.dtype.str, list(value.shape), len(buffers) - 1]}
    if type(value) in (list, tuple):
        if len(value) > MAX_ITEMS:
            raise Unreadable(LIST, len(value))
        items = [encode(item, buffers, depth + 1) for item in value]
        return {"tuple": items} if type(value) is tuple else {"list": items}
    if type(value).__name__ in ("generator", "map", "zip", "filter") or (
        hasattr(type(value), "__next__") and hasattr(type(value), "__iter__")
    ):
        items = []
        for item in value:
            if len(items) >= MAX_ITEMS:
                raise Unreadable(ITERATOR, MAX_ITEMS)
            items.append(encode(item, buffers, depth + 1))
        return {"iterator": items}
    return {"object": type(value).__name__}


class Opaque:
    """An answer of a type that cannot cross (a set, a class of the student's, an array of
    objects): its type's name, ``kind``, which the grader words as any answer's type."""

    def __init__(self, kind: str) -> None:
        self.kind = kind

    def __repr__(self) -> str:
        return f"<{self.kind}>"


def decode(value: Any, buffers: list[bytearray]) -> Any:
    """The value :func:`encode` made, its arrays in ``buffers`` (writable, as the student's
    function may write into an argument): numbers, text, lists, tuples, arrays;
    :class:`Opaque` for an object that could not cross. An iterator arrives as the list of
    its items. :class:`Unreadable` for an array its buffer cannot hold."""
    if not isinstance(value, dict):
        return value
    if "array" in value:
        return _array(value["array"], buffers)
    if "list" in value or "iterator" in value:
        return [decode(item, buffers) for item in value.get("list", value.get("iterator"))]
    if "tuple" in value:
        return tuple(decode(item, buffers) for item in value["tuple"])
    if "int" in value:
        return int(value["int"])
    if "float" in value:
        return float(value["float"])
    if "complex" in value:
        return complex(decode(value["complex"][0], buffers), decode(value["complex"][1], buffers))
    return Opaque(str(value.get("object", "object")))


def _array(spec: Any, buffers: list[bytearray]) -> Any:
    """The numeric array ``[dtype, shape, index]`` describes, on its buffer (not copied).

    :class:`Unreadable` (:data:`BYTES`) for anything else: only a child that wrote to the
    grader's channel itself sends such an answer."""
    import numpy as np

    try:
        dtype_text, shape, index = spec
        dtype = np.dtype(str(dtype_text))
        shape = tuple(int(length) for length in shape)
        buffer = buffers[int(index)]
    except (TypeError, ValueError, IndexError) as error:
        raise Unreadable(BYTES, 0) from error
    if (
        dtype.kind not in "biufc"
        or dtype.fields is not None
        or min(shape, default=0) < 0
        or math.prod(shape) * dtype.itemsize != len(buffer)
    ):
        raise Unreadable(BYTES, 0)
    return np.frombuffer(buffer, dtype).reshape(shape)


def write_message(stream: IO[bytes], message: dict[str, Any], buffers: list[Any]) -> None:
    """``message`` as a JSON line, its ``"buffers"`` the byte sizes of the arrays' bytes
    (:func:`encode`'s ``buffers``), which follow it."""
    if buffers:
        message = {**message, "buffers": [buffer.nbytes for buffer in buffers]}
    stream.write(json.dumps(message).encode("utf-8") + b"\n")
    for buffer in buffers:
        stream.write(buffer)
    stream.flush()


def read_message(stream: IO[bytes], most: int) -> tuple[dict[str, Any], list[bytearray]] | None:
    """The next message on ``stream`` and its buffers; None when the stream ends.

    A line that is not a JSON object, or declares buffers that are not sizes or that hold
    more than ``most`` bytes in all, is skipped: what a student's code wrote to the channel
    itself. A line longer than ``most`` is read in pieces, each skipped."""
    while True:
        line = stream.readline(most + 1)
        if not line:
            return None
        try:
            message = json.loads(line)
        except ValueError:  # also for text that is not UTF-8
            continue
        if not isinstance(message, dict):
            continue
        sizes = message.get("buffers", [])
        if not (
            isinstance(sizes, list)
            and all(type(size) is int and size >= 0 for size in sizes)
            and sum(sizes) <= most
        ):
            continue
        buffers = []
        for size in sizes:
            buffer = bytearray(size)
            view, got = memoryview(buffer), 0
            while got < size:
                count = stream.readinto(view[got:])
                if not count:
                    return None
                got += count
            buffers.append(buffer)
        return message, buffers
