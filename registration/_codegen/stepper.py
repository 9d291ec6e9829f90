"""Carried-state single steps of a generated function (a streaming filter), at compiled speed.

A :class:`CStepper` keeps every input of the function in a persistent column-major buffer: the
constant inputs are written once, the carried state (the first inputs, fed from the first
outputs) stays in the buffers between steps, and a step writes only the one input that changes
(``feed``). The compiled ``registration_step`` of ``_batch.c`` checks that input against
element-wise bounds, evaluates the function, checks the chosen outputs are finite and only then
commits the new state. :class:`PyStepper` does the same on the serialized CasADi backend.

Codes returned by ``step``: :data:`OK`, :data:`OUT_OF_BOUNDS` (the fed input is outside its
bounds or NaN; nothing evaluated), :data:`NON_FINITE` (a checked output is not finite; the state
is left as it was), :data:`FAILED` (the generated function returned a non-zero flag).
"""

from __future__ import annotations

import ctypes
import enum
import functools

import numpy as np

__all__ = ["StepCode", "OK", "OUT_OF_BOUNDS", "NON_FINITE", "FAILED", "CStepper", "PyStepper"]


class StepCode(enum.IntEnum):
    """What one step did (the return codes of ``registration_step`` in ``_batch.c``)."""

    OK = 0
    OUT_OF_BOUNDS = 1
    NON_FINITE = 2
    FAILED = 3


OK, OUT_OF_BOUNDS, NON_FINITE, FAILED = (int(c) for c in StepCode)


class _StepperStruct(ctypes.Structure):
    """Mirror of ``registration_stepper`` in ``_batch.c``."""

    _fields_ = [
        ("f", ctypes.c_void_p), ("n_in", ctypes.c_int), ("n_out", ctypes.c_int), ("n_carry", ctypes.c_int),
        ("check_in", ctypes.c_int), ("n_finite", ctypes.c_int),
        ("in_ptr", ctypes.c_void_p), ("out_ptr", ctypes.c_void_p), ("in_size", ctypes.c_void_p),
        ("out_size", ctypes.c_void_p), ("low", ctypes.c_void_p), ("high", ctypes.c_void_p),
        ("finite_out", ctypes.c_void_p), ("arg", ctypes.c_void_p), ("res", ctypes.c_void_p),
        ("iw", ctypes.c_void_p), ("w", ctypes.c_void_p),
    ]


def _core(shape: tuple[int, int]) -> tuple:
    r, c = shape
    return () if (r, c) == (1, 1) else ((r,) if c == 1 else (r, c))


def _column_major(value, shape: tuple[int, int], name: str) -> np.ndarray:
    """``value`` at its core shape as a flat column-major float64 array."""
    a = np.asarray(value, dtype=np.float64)
    if a.shape != _core(shape):
        raise ValueError(f"input {name!r}: expected shape {_core(shape)}, got {a.shape}")
    return a.T.ravel() if a.ndim == 2 else a.ravel()


def _from_column_major(buf: np.ndarray, shape: tuple[int, int]):
    """A flat column-major buffer at its core shape (a view; a float for a scalar)."""
    r, c = shape
    if (r, c) == (1, 1):
        return float(buf[0])
    return buf if c == 1 else buf.reshape(c, r).T


def _results_function(views: list[np.ndarray]):
    """``f()``: a new copy of each view (of an output buffer, at its core shape), a float for a
    one-element view. Written out for the views, so a step's results cost one copy per output."""
    return functools.partial(_results_template(tuple(v.shape == (1,) for v in views)), *views)


@functools.lru_cache(maxsize=None)
def _results_template(scalars: tuple[bool, ...]):
    """``f(*views)`` for views of which those flagged in ``scalars`` become floats (compiled once per pattern)."""
    names = [f"v{i}" for i in range(len(scalars))]
    parts = [f"float({n}[0])" if scalar else f"{n}.copy()" for n, scalar in zip(names, scalars)]
    body = f"({', '.join(parts)},)" if parts else "()"
    namespace: dict = {}
    exec(f"def results({', '.join(names)}):\n    return {body}\n", namespace)  # noqa: S102
    return namespace["results"]


class _Layout:
    """Names, shapes and which inputs are carried, fed, bounded; which outputs are checked and delivered."""

    def __init__(self, fn, carry: dict, feed: str, low, high, finite, deliver):
        self.fn_name = fn.name
        self.inputs, self.outputs = list(fn.input_names), list(fn.output_names)
        self.in_shapes, self.out_shapes = list(fn.input_shapes), list(fn.output_shapes)
        k = len(carry)
        if list(carry) != self.inputs[:k] or list(carry.values()) != self.outputs[:k]:
            raise ValueError(f"{fn.name}: carried inputs must be the first {k} inputs paired with the first outputs")
        if self.in_shapes[:k] != self.out_shapes[:k]:
            raise ValueError(f"{fn.name}: a carried input and its output differ in shape "
                             f"({self.in_shapes[:k]} vs {self.out_shapes[:k]})")
        if feed not in self.inputs[k:]:
            raise ValueError(f"{fn.name}: the fed input must be a non-carried input, got {feed!r}")
        self.n_carry, self.feed = k, self.inputs.index(feed)
        size = self.in_shapes[self.feed][0] * self.in_shapes[self.feed][1]
        self.low = None if low is None else np.broadcast_to(np.asarray(low, dtype=np.float64), (size,)).copy()
        self.high = None if high is None else np.broadcast_to(np.asarray(high, dtype=np.float64), (size,)).copy()
        if (self.low is None) != (self.high is None):
            raise ValueError("give both low and high bounds, or neither")
        self.finite = [self.outputs.index(n) for n in finite]
        self.deliver = [self.outputs.index(n) for n in deliver]


class CStepper:
    """Compiled carried-state steps of one generated function (see the module docstring).

    ``set(name, value)`` writes an input (core shape), ``get(name)`` reads one back (a copy),
    ``step(value)`` writes the fed input and evaluates; after :data:`OK`, ``results()`` returns
    the delivered outputs as new arrays of their core shapes (floats for scalars).
    """

    def __init__(self, fn, kernel, library, carry: dict, feed: str, low=None, high=None, finite=(), deliver=()):
        lay = self._layout = _Layout(fn, carry, feed, low, high, finite, deliver)
        self._in = [np.zeros(r * c) for r, c in lay.in_shapes]
        sizes = [r * c for r, c in lay.out_shapes]
        self._out = [np.zeros(size) for size in sizes]
        views = [self._out[j] if lay.out_shapes[j][1] == 1 else self._out[j].reshape(lay.out_shapes[j][::-1]).T
                 for j in lay.deliver]  # matrices are column-major
        #: results() -> the delivered outputs of the last successful step, as new arrays (floats for scalars)
        self.results = _results_function(views)
        self._feed = self._in[lay.feed]
        work = kernel.work
        keep = self._keep = {
            "in_ptr": (ctypes.c_void_p * len(self._in))(*[a.ctypes.data for a in self._in]),
            "out_ptr": (ctypes.c_void_p * len(self._out))(*[a.ctypes.data for a in self._out]),
            "in_size": (ctypes.c_longlong * len(self._in))(*[a.size for a in self._in]),
            "out_size": (ctypes.c_longlong * len(sizes))(*sizes),
            "finite_out": (ctypes.c_int * max(1, len(lay.finite)))(*lay.finite),
            "arg": (ctypes.c_void_p * max(work["sz_arg"], 1))(), "res": (ctypes.c_void_p * max(work["sz_res"], 1))(),
            "iw": np.zeros(max(work["sz_iw"], 1), dtype=np.int64), "w": np.zeros(max(work["sz_w"], 1)),
            "low": lay.low if lay.low is not None else np.zeros(1), "high": lay.high if lay.high is not None else np.zeros(1),
        }
        addr = {k: (v.ctypes.data if isinstance(v, np.ndarray) else ctypes.addressof(v)) for k, v in keep.items()}
        self._struct = _StepperStruct(
            f=ctypes.cast(getattr(library, fn.name), ctypes.c_void_p).value, n_in=len(self._in), n_out=len(self._out),
            n_carry=lay.n_carry, check_in=lay.feed if lay.low is not None else -1, n_finite=len(lay.finite), **addr,
        )
        self._call = functools.partial(library.registration_step, ctypes.byref(self._struct))

    def set(self, name: str, value) -> None:
        """Write input ``name`` (its core shape; a carried input sets the state)."""
        j = self._layout.inputs.index(name)
        self._in[j][:] = _column_major(value, self._layout.in_shapes[j], name)

    def get(self, name: str):
        """A copy of input ``name`` at its core shape (a carried input: the committed state)."""
        j = self._layout.inputs.index(name)
        out = _from_column_major(self._in[j], self._layout.in_shapes[j])
        return out if isinstance(out, float) else out.copy()

    def step(self, value, check: bool = True) -> int:
        """Write the fed input (flat, in its column-major order) and evaluate one step; a code.

        ``check=False`` skips the bounds of the fed input (for values a detailed check accepted)."""
        self._feed[:] = value
        if check:
            return self._call()
        saved, self._struct.check_in = self._struct.check_in, -1
        try:
            return self._call()
        finally:
            self._struct.check_in = saved


class PyStepper:
    """:class:`CStepper` on the serialized CasADi backend: the same checks, in NumPy."""

    def __init__(self, fn, carry: dict, feed: str, low=None, high=None, finite=(), deliver=()):
        self._fn = fn
        self._layout = _Layout(fn, carry, feed, low, high, finite, deliver)
        self._values = [np.zeros(_core(s)) for s in self._layout.in_shapes]
        self._last: list | None = None

    def set(self, name: str, value) -> None:
        j = self._layout.inputs.index(name)
        _column_major(value, self._layout.in_shapes[j], name)  # shape check
        self._values[j] = np.array(value, dtype=np.float64)

    def get(self, name: str):
        v = self._values[self._layout.inputs.index(name)]
        return float(v) if v.ndim == 0 else v.copy()

    def step(self, value, check: bool = True) -> int:
        lay = self._layout
        flat = np.asarray(value, dtype=np.float64).ravel()
        if check and lay.low is not None and not ((flat >= lay.low) & (flat <= lay.high)).all():
            return OUT_OF_BOUNDS
        r, c = lay.in_shapes[lay.feed]
        self._values[lay.feed] = flat.reshape(c, r).T if c > 1 else flat.reshape(_core((r, c)))
        outs = [o[0] for o in self._fn(*self._values)]
        if not all(np.isfinite(outs[j]).all() for j in lay.finite):
            return NON_FINITE
        for j in range(lay.n_carry):
            self._values[j] = np.array(outs[j])
        self._last = outs
        return OK

    def results(self) -> tuple:
        return tuple(float(self._last[j]) if np.ndim(self._last[j]) == 0 else np.array(self._last[j])
                     for j in self._layout.deliver)
