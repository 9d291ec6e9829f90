"""The compiled carried-state stepper :class:`CStepper` (what a step does and returns:
:mod:`registration._codegen.stepper`).

A :class:`CStepper` keeps every input of the function in a persistent column-major buffer. The
compiled ``registration_step`` of ``_batch.c`` checks the fed input against its bounds, evaluates
the function, checks the chosen outputs are finite and only then commits the new state; it also
copies the delivered outputs into the caller's next row of a block (so that a streaming loop
returns views, not per-row copies) and, if asked, one output into a ring of its last values (a
window of estimates).
"""

from __future__ import annotations

import ctypes
import functools

import numpy as np

from registration._codegen.stepper import (
    StepLayout,
    column_major,
    from_column_major,
    kept_output,
    kept_values,
)

__all__ = ["BLOCK_ROWS", "CStepper"]


class _StepperStruct(ctypes.Structure):
    """Mirror of ``registration_stepper`` in ``_batch.c``."""

    _fields_ = [
        ("f", ctypes.c_void_p),
        ("n_in", ctypes.c_int),
        ("n_out", ctypes.c_int),
        ("n_carry", ctypes.c_int),
        ("check_in", ctypes.c_int),
        ("n_finite", ctypes.c_int),
        ("in_ptr", ctypes.c_void_p),
        ("out_ptr", ctypes.c_void_p),
        ("in_size", ctypes.c_void_p),
        ("out_size", ctypes.c_void_p),
        ("low", ctypes.c_void_p),
        ("high", ctypes.c_void_p),
        ("finite_out", ctypes.c_void_p),
        ("arg", ctypes.c_void_p),
        ("res", ctypes.c_void_p),
        ("iw", ctypes.c_void_p),
        ("w", ctypes.c_void_p),
        ("n_deliver", ctypes.c_int),
        ("deliver_out", ctypes.c_void_p),
        ("deliver_ptr", ctypes.c_void_p),
        ("ring_out", ctypes.c_int),
        ("ring_len", ctypes.c_int),
        ("ring", ctypes.c_void_p),
        ("ring_count", ctypes.c_longlong),
    ]


def _results_function(views: list[np.ndarray], keys: tuple[str, ...] | None):
    """``f()``: a new copy of each view (of an output buffer, at its core shape), a float for a
    one-element view; a tuple, or a dict under ``keys``. Written out for the views, so a step's
    results cost one copy per output."""
    return functools.partial(_results_template(tuple(v.shape == (1,) for v in views), keys), *views)


@functools.lru_cache(maxsize=None)
def _results_template(scalars: tuple[bool, ...], keys: tuple[str, ...] | None):
    """``f(*views)`` for views of which those flagged in ``scalars`` become floats, returning a
    tuple or (``keys`` given) a dict; compiled once per pattern."""
    names = [f"v{i}" for i in range(len(scalars))]
    parts = [f"{n}.item()" if scalar else f"{n}.copy()" for n, scalar in zip(names, scalars)]
    return _compiled("results", names, parts, keys)


def _compiled(name: str, params: list[str], parts: list[str], keys: tuple[str, ...] | None):
    """A function ``name(*params)`` returning the expressions ``parts`` as a tuple, or as a dict
    under ``keys``: built once per pattern, so a call costs no per-field Python loop."""
    if keys is not None:
        body = "{" + ", ".join(f"{k!r}: {p}" for k, p in zip(keys, parts)) + "}"
    else:
        body = f"({', '.join(parts)},)" if parts else "()"
    namespace: dict = {}
    exec(f"def {name}({', '.join(params)}):\n    return {body}\n", namespace)  # noqa: S102
    return namespace[name]


class CStepper:
    """Compiled carried-state steps of one generated function (see the module docstring).

    ``set(name, value)`` writes an input (core shape), ``get(name)`` reads one back (a copy),
    ``step(value)`` writes the fed input and evaluates; after :data:`OK`, ``results()`` returns
    the delivered outputs as new arrays of their core shapes (floats for scalars): a tuple, or a
    dict when ``deliver`` maps result keys to output names. ``advance(value)`` is ``step`` then
    ``results`` in one call, for a streaming loop: the results, or the step's code (an int) if
    it was not :data:`OK`. Its arrays are the caller's too, but cheaper: the compiled step copies
    the delivered outputs into rows of blocks of :data:`BLOCK_ROWS` steps, and ``advance``
    returns views of one row (a block is freed when no row of it is referenced any more).
    ``keep(name, length)`` keeps the last ``length`` values of output ``name`` of the successful
    steps (copied by the compiled step into a ring), ``kept()`` returns them, ``set_kept`` loads them.
    """

    def __init__(
        self, fn, kernel, library, carry: dict, feed: str, low=None, high=None, finite=(), deliver=()
    ):
        lay = self._layout = StepLayout(fn, carry, feed, low, high, finite, deliver)
        self._in = [np.zeros(r * c) for r, c in lay.in_shapes]
        sizes = [r * c for r, c in lay.out_shapes]
        self._out = [np.zeros(size) for size in sizes]
        views = [
            self._out[j] if lay.out_shapes[j][1] == 1 else self._out[j].reshape(lay.out_shapes[j][::-1]).T
            for j in lay.deliver
        ]  # matrices are column-major
        #: results() -> the delivered outputs of the last successful step, as new arrays (floats for scalars)
        self.results = _results_function(views, lay.keys)
        self._feed = self._in[lay.feed]
        work = kernel.work
        keep = self._keep = {
            "in_ptr": (ctypes.c_void_p * len(self._in))(*[a.ctypes.data for a in self._in]),
            "out_ptr": (ctypes.c_void_p * len(self._out))(*[a.ctypes.data for a in self._out]),
            "in_size": (ctypes.c_longlong * len(self._in))(*[a.size for a in self._in]),
            "out_size": (ctypes.c_longlong * len(sizes))(*sizes),
            "finite_out": (ctypes.c_int * max(1, len(lay.finite)))(*lay.finite),
            "arg": (ctypes.c_void_p * max(work["sz_arg"], 1))(),
            "res": (ctypes.c_void_p * max(work["sz_res"], 1))(),
            "iw": np.zeros(max(work["sz_iw"], 1), dtype=np.int64),
            "w": np.zeros(max(work["sz_w"], 1)),
            "low": lay.low if lay.low is not None else np.zeros(1),
            "high": lay.high if lay.high is not None else np.zeros(1),
            "deliver_out": (ctypes.c_int * max(1, len(lay.deliver)))(*lay.deliver),
            "deliver_ptr": (ctypes.c_void_p * max(1, len(lay.deliver)))(),
        }
        addr = {
            k: (v.ctypes.data if isinstance(v, np.ndarray) else ctypes.addressof(v)) for k, v in keep.items()
        }
        self._struct = _StepperStruct(
            f=ctypes.cast(getattr(library, fn.name), ctypes.c_void_p).value,
            n_in=len(self._in),
            n_out=len(self._out),
            n_carry=lay.n_carry,
            check_in=lay.feed if lay.low is not None else -1,
            n_finite=len(lay.finite),
            n_deliver=len(lay.deliver),
            ring_out=-1,
            **addr,
        )
        self._ring: np.ndarray | None = None
        call = functools.partial(library.registration_step, ctypes.byref(self._struct))
        blocks = _Blocks(keep["deliver_ptr"], [lay.out_shapes[j] for j in lay.deliver])
        self.step, self.advance = _step_functions(self._feed, call, self._unchecked(call), blocks, lay.keys)

    def _unchecked(self, call):
        """``call`` with the bounds check of the fed input switched off for once."""
        struct = self._struct

        def unchecked():
            saved, struct.check_in = struct.check_in, -1
            try:
                return call()
            finally:
                struct.check_in = saved

        return unchecked

    def set(self, name: str, value) -> None:
        """Write input ``name`` (its core shape; a carried input sets the state)."""
        j = self._layout.inputs.index(name)
        self._in[j][:] = column_major(value, self._layout.in_shapes[j], name)

    def keep(self, name: str, length: int) -> None:
        """From now on keep the last ``length`` (>= 1) values of vector output ``name``; none kept yet."""
        j, size = kept_output(self._layout, name, length)
        self._ring = np.zeros((length, size))
        self._struct.ring = self._ring.ctypes.data
        self._struct.ring_out, self._struct.ring_len, self._struct.ring_count = j, length, 0

    def kept(self) -> np.ndarray:
        """The kept values, oldest first: a new (m, size) array, m <= length (see :meth:`keep`)."""
        if self._ring is None:
            raise ValueError("nothing is kept: call keep() first")
        count, length = self._struct.ring_count, len(self._ring)
        if count <= length:
            return self._ring[:count].copy()
        return np.roll(self._ring, -(count % length), axis=0)

    def set_kept(self, values) -> None:
        """Replace the kept values by ``values`` ((m, size), oldest first, m <= length)."""
        if self._ring is None:
            raise ValueError("nothing is kept: call keep() first")
        values = kept_values(values, self._ring.shape)
        self._ring[: len(values)] = values
        self._struct.ring_count = len(values)

    def get(self, name: str):
        """A copy of input ``name`` at its core shape (a carried input: the committed state)."""
        j = self._layout.inputs.index(name)
        out = from_column_major(self._in[j], self._layout.in_shapes[j])
        return out if isinstance(out, float) else out.copy()


#: Steps per block of delivered results (see :class:`CStepper`): 64 rows of the Kalman step's
#: x, P, nu, S, nis are 86 kB.
BLOCK_ROWS = 64


class _Blocks:
    """Blocks of :data:`BLOCK_ROWS` rows into which the compiled step copies the delivered outputs;
    ``new()`` allocates one, points the step's ``deliver_ptr`` at its first row and returns its
    arrays: per output (rows,), (rows, r) or (rows, r, c) (column-major rows seen transposed)."""

    def __init__(self, deliver_ptr, shapes: list[tuple[int, int]]):
        self._ptr, self._shapes = deliver_ptr, shapes
        sizes = [r * c for r, c in shapes]
        self._offsets = [BLOCK_ROWS * sum(sizes[:m]) for m in range(len(sizes) + 1)]

    def new(self) -> tuple:
        block = np.empty(self._offsets[-1])
        base = block.ctypes.data
        arrays = []
        for m, (r, c) in enumerate(self._shapes):
            self._ptr[m] = base + block.itemsize * self._offsets[m]
            part = block[self._offsets[m] : self._offsets[m + 1]]
            arrays.append(
                part
                if (r, c) == (1, 1)
                else part.reshape(BLOCK_ROWS, r)
                if c == 1
                else part.reshape(BLOCK_ROWS, c, r).swapaxes(1, 2)
            )
        return tuple(arrays)


def _step_functions(feed: np.ndarray, call, unchecked, blocks: _Blocks, keys: tuple[str, ...] | None):
    """``step(value, check=True)`` and ``advance(value)`` of a :class:`CStepper` (closures: the names
    are bound once, as these run once per row of a stream). Both count the successful steps, whose
    results the compiled step has copied to the next row of the current block."""
    rows = blocks.new()
    row = 0
    scalars = tuple(a.ndim == 1 for a in rows)
    pick = _row_template(scalars, keys)

    def step(value, check: bool = True) -> int:
        """Write the fed input (flat, in its column-major order) and evaluate one step; a code.

        ``check=False`` skips the bounds of the fed input (for values a detailed check accepted)."""
        nonlocal rows, row
        feed[:] = value
        code = call() if check else unchecked()
        if not code:
            row += 1
            if row == BLOCK_ROWS:
                rows, row = blocks.new(), 0
        return code

    def advance(value):
        """``step(value)``, then the results as views of their row of the block; the code if not OK."""
        nonlocal rows, row
        feed[:] = value
        code = call()
        if code:
            return code
        out = pick(row, *rows)
        row += 1
        if row == BLOCK_ROWS:
            rows, row = blocks.new(), 0
        return out

    return step, advance


@functools.lru_cache(maxsize=None)
def _row_template(scalars: tuple[bool, ...], keys: tuple[str, ...] | None):
    """``f(i, *arrays)``: row ``i`` of each array (a float for those flagged in ``scalars``), as a
    tuple or a dict under ``keys``; compiled once per pattern."""
    names = [f"a{m}" for m in range(len(scalars))]
    parts = [f"{n}.item(i)" if scalar else f"{n}[i]" for n, scalar in zip(names, scalars)]
    return _compiled("pick", ["i", *names], parts, keys)
