"""Carried-state single steps of a generated function (a streaming filter): what a step does and
returns, the layout of a stepped function's inputs and outputs, and the stepper of the serialized
CasADi backend (:class:`PyStepper`); the compiled one is :mod:`registration._codegen.cstepper`.

A stepper keeps every input of the function: the constant inputs are written once, the carried
state (the first inputs, fed from the first outputs) stays between steps, and a step writes only
the one input that changes (``feed``). A step checks that input against element-wise bounds,
evaluates the function, checks the chosen outputs are finite and only then commits the new state;
it can also keep one output's last values (a window of estimates).

Codes returned by ``step``: :data:`OK`, :data:`OUT_OF_BOUNDS` (the fed input is outside its
bounds or NaN; nothing evaluated), :data:`NON_FINITE` (a checked output is not finite; the state
is left as it was), :data:`FAILED` (the generated function returned a non-zero flag).
"""

from __future__ import annotations

import enum
from collections import deque

import numpy as np

__all__ = [
    "StepCode",
    "OK",
    "OUT_OF_BOUNDS",
    "NON_FINITE",
    "FAILED",
    "StepLayout",
    "PyStepper",
    "column_major",
    "core_shape",
    "from_column_major",
    "kept_output",
    "kept_values",
]


class StepCode(enum.IntEnum):
    """What one step did (the return codes of ``registration_step`` in ``_batch.c``)."""

    OK = 0
    OUT_OF_BOUNDS = 1
    NON_FINITE = 2
    FAILED = 3


OK, OUT_OF_BOUNDS, NON_FINITE, FAILED = (int(c) for c in StepCode)


def core_shape(shape: tuple[int, int]) -> tuple:
    """The numpy shape of one value of a (rows, cols) port: (), (rows,) or (rows, cols)."""
    r, c = shape
    return () if (r, c) == (1, 1) else ((r,) if c == 1 else (r, c))


def column_major(value, shape: tuple[int, int], name: str) -> np.ndarray:
    """``value`` at its core shape as a flat column-major float64 array."""
    a = np.asarray(value, dtype=np.float64)
    if a.shape != core_shape(shape):
        raise ValueError(f"input {name!r}: expected shape {core_shape(shape)}, got {a.shape}")
    return a.T.ravel() if a.ndim == 2 else a.ravel()


def from_column_major(buf: np.ndarray, shape: tuple[int, int]):
    """A flat column-major buffer at its core shape (a view; a float for a scalar)."""
    r, c = shape
    if (r, c) == (1, 1):
        return float(buf[0])
    return buf if c == 1 else buf.reshape(c, r).T


class StepLayout:
    """Names, shapes and which inputs are carried, fed, bounded; which outputs are checked and delivered."""

    def __init__(self, fn, carry: dict, feed: str, low, high, finite, deliver):
        self.fn_name = fn.name
        self.inputs, self.outputs = list(fn.input_names), list(fn.output_names)
        self.in_shapes, self.out_shapes = list(fn.input_shapes), list(fn.output_shapes)
        k = len(carry)
        if list(carry) != self.inputs[:k] or list(carry.values()) != self.outputs[:k]:
            raise ValueError(
                f"{fn.name}: carried inputs must be the first {k} inputs paired with the first outputs"
            )
        if self.in_shapes[:k] != self.out_shapes[:k]:
            raise ValueError(
                f"{fn.name}: a carried input and its output differ in shape "
                f"({self.in_shapes[:k]} vs {self.out_shapes[:k]})"
            )
        if feed not in self.inputs[k:]:
            raise ValueError(f"{fn.name}: the fed input must be a non-carried input, got {feed!r}")
        self.n_carry, self.feed = k, self.inputs.index(feed)
        size = self.in_shapes[self.feed][0] * self.in_shapes[self.feed][1]
        self.low = None if low is None else np.broadcast_to(np.asarray(low, dtype=np.float64), (size,)).copy()
        self.high = (
            None if high is None else np.broadcast_to(np.asarray(high, dtype=np.float64), (size,)).copy()
        )
        if (self.low is None) != (self.high is None):
            raise ValueError("give both low and high bounds, or neither")
        self.finite = [self.outputs.index(n) for n in finite]
        #: the keys of results() as a dict (``deliver`` a mapping key -> output name), or None for a tuple
        self.keys = tuple(deliver) if isinstance(deliver, dict) else None
        self.deliver = [
            self.outputs.index(n) for n in (deliver.values() if isinstance(deliver, dict) else deliver)
        ]


def kept_output(lay: StepLayout, name: str, length: int) -> tuple[int, int]:
    """Index and size of vector output ``name`` to keep ``length`` values of; ValueError if not one."""
    if name not in lay.outputs or lay.out_shapes[lay.outputs.index(name)][1] != 1:
        raise ValueError(f"{lay.fn_name}: keep() takes a vector output, got {name!r}")
    if int(length) < 1:
        raise ValueError(f"keep(): length must be at least 1, got {length}")
    j = lay.outputs.index(name)
    return j, lay.out_shapes[j][0]


def kept_values(values, shape: tuple[int, int]) -> np.ndarray:
    """``values`` as an (m, size) float64 array with m <= the ring's length; ValueError otherwise."""
    a = np.asarray(values, dtype=np.float64)
    if a.ndim != 2 or a.shape[1] != shape[1] or len(a) > shape[0]:
        raise ValueError(
            f"set_kept(): expected at most {shape[0]} values of size {shape[1]}, got shape {a.shape}"
        )
    return a


class PyStepper:
    """:class:`CStepper` on the serialized CasADi backend: the same checks, in NumPy."""

    def __init__(self, fn, carry: dict, feed: str, low=None, high=None, finite=(), deliver=()):
        self._fn = fn
        self._layout = StepLayout(fn, carry, feed, low, high, finite, deliver)
        self._values = [np.zeros(core_shape(s)) for s in self._layout.in_shapes]
        self._last: list | None = None
        self._ring: deque | None = None
        self._ring_out = -1

    def keep(self, name: str, length: int) -> None:
        self._ring_out, size = kept_output(self._layout, name, length)
        self._ring = deque(maxlen=int(length))
        self._ring_len, self._ring_size = int(length), size

    def kept(self) -> np.ndarray:
        if self._ring is None:
            raise ValueError("nothing is kept: call keep() first")
        return np.array(self._ring).reshape(-1, self._ring_size)

    def set_kept(self, values) -> None:
        if self._ring is None:
            raise ValueError("nothing is kept: call keep() first")
        self._ring.clear()
        self._ring.extend(kept_values(values, (self._ring_len, self._ring_size)).copy())

    def set(self, name: str, value) -> None:
        j = self._layout.inputs.index(name)
        column_major(value, self._layout.in_shapes[j], name)  # shape check
        self._values[j] = np.array(value, dtype=np.float64)

    def get(self, name: str):
        v = self._values[self._layout.inputs.index(name)]
        return float(v) if v.ndim == 0 else v.copy()

    def step(self, value, check: bool = True) -> int:
        lay = self._layout
        flat = np.asarray(value, dtype=np.float64).ravel()
        low, high = lay.low, lay.high  # both or neither (StepLayout)
        if check and low is not None and high is not None and not ((flat >= low) & (flat <= high)).all():
            return OUT_OF_BOUNDS
        r, c = lay.in_shapes[lay.feed]
        self._values[lay.feed] = flat.reshape(c, r).T if c > 1 else flat.reshape(core_shape((r, c)))
        outs = [o[0] for o in self._fn(*self._values)]
        if not all(np.isfinite(outs[j]).all() for j in lay.finite):
            return NON_FINITE
        for j in range(lay.n_carry):
            self._values[j] = np.array(outs[j])
        if self._ring is not None:
            self._ring.append(np.array(outs[self._ring_out], dtype=np.float64).ravel())
        self._last = outs
        return OK

    def results(self) -> tuple | dict:
        last = self._last
        if last is None and self._layout.deliver:
            raise ValueError(f"{self._layout.fn_name}: results() before a successful step")
        out = tuple(
            float(last[j]) if np.ndim(last[j]) == 0 else np.array(last[j])
            for j in self._layout.deliver
            if last is not None
        )
        return out if self._layout.keys is None else dict(zip(self._layout.keys, out))

    def advance(self, value) -> tuple | dict | int:
        code = self.step(value)
        return code if code else self.results()
