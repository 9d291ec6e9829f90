"""Generated functions as numpy callables, on the backend chosen once per process.

Backends (environment variable ``REGISTRATION_BACKEND``): ``c``, the compiled C sources
(:mod:`registration._codegen.cbackend`, called through :mod:`registration._codegen.ckernel`);
``casadi``, the serialized functions (:mod:`registration._codegen.casadi_backend`, no compiler
needed); ``auto`` (default), ``c`` if a C compiler works, otherwise ``casadi`` with one warning.
"""

from __future__ import annotations

import os
import threading
import warnings

import numpy as np

from registration._codegen.artifacts import ArtifactError, manifest
from registration._codegen.casadi_backend import CasadiKernel
from registration._codegen.cbackend import library
from registration._codegen.ckernel import CKernel, PointCall
from registration._codegen.cstepper import CStepper
from registration._codegen.stepper import PyStepper

__all__ = ["BoundCall", "GeneratedFunction", "backend", "get"]

_LOCK = threading.RLock()
_backend_cache: dict = {}
_functions: dict = {}


def backend() -> str:
    """The backend in use: 'c' or 'casadi' (decided once per process)."""
    with _LOCK:
        if "name" in _backend_cache:
            return _backend_cache["name"]
        wanted = os.environ.get("REGISTRATION_BACKEND", "auto").lower()
        if wanted not in {"auto", "c", "casadi"}:
            raise ValueError(f"REGISTRATION_BACKEND must be auto, c or casadi, got {wanted!r}")
        name = "casadi"
        if wanted in {"auto", "c"}:
            try:
                library()
                name = "c"
            except (ArtifactError, OSError) as exc:
                if wanted == "c":
                    raise
                warnings.warn(
                    f"compiled C backend unavailable ({exc}); using the serialized CasADi functions (slower)",
                    RuntimeWarning,
                    stacklevel=2,
                )
        _backend_cache["name"] = name
        return name


def get(name: str) -> "GeneratedFunction":
    """The generated function ``name``, loaded once per process (thread-safe)."""
    with _LOCK:
        fn = _functions.get(name)
        if fn is None:
            fn = _functions[name] = GeneratedFunction(name)
        return fn


def shape_outputs(buf: np.ndarray, n: int, shape: tuple[int, int]) -> np.ndarray:
    """A flat ``(n, r * c)`` column-major buffer as (n,), (n, r) or (n, r, c)."""
    r, c = shape
    if (r, c) == (1, 1):
        return buf.reshape(n)
    if c == 1:
        return buf.reshape(n, r)
    return buf.reshape(n, c, r).swapaxes(1, 2)


class GeneratedFunction:
    """One generated function, vectorised over a leading axis of N points.

    Each input is given either at its core shape (broadcast to every point) or with one extra
    leading axis of length N: a scalar input as () or (N,), a vector (r,) or (N, r), a matrix
    (r, c) or (N, r, c). Outputs always have the leading axis: (N,), (N, r) or (N, r, c).
    """

    def __init__(self, name: str, force_backend: str | None = None):
        meta = manifest()["functions"][name]
        self.name = name
        self.doc = meta["doc"]
        self.input_names = [p["name"] for p in meta["inputs"]]
        self.output_names = [p["name"] for p in meta["outputs"]]
        self.input_shapes = [tuple(p["shape"]) for p in meta["inputs"]]
        self.output_shapes = [tuple(p["shape"]) for p in meta["outputs"]]
        self._backend = force_backend or backend()
        self._casadi = CasadiKernel(name)
        self._c = CKernel(name, meta["work"]) if self._backend == "c" else None
        self.__doc__ = self.doc

    @property
    def backend_name(self) -> str:
        """The backend this function evaluates on: 'c' or 'casadi'."""
        return self._backend

    @property
    def casadi(self):
        """The serialized ``casadi.Function`` (hash-checked), e.g. for automatic differentiation."""
        return self._casadi.function()

    def __repr__(self) -> str:
        ins = ", ".join(f"{n}{list(s)}" for n, s in zip(self.input_names, self.input_shapes))
        outs = ", ".join(f"{n}{list(s)}" for n, s in zip(self.output_names, self.output_shapes))
        return f"<generated {self.name}({ins}) -> ({outs}) [{self._backend}]>"

    def _prepare(self, args):
        if len(args) != len(self.input_names):
            raise TypeError(
                f"{self.name} takes {len(self.input_names)} inputs {self.input_names}, got {len(args)}"
            )
        prepared, n = [], None
        for name, shape, arg in zip(self.input_names, self.input_shapes, args):
            a = np.asarray(arg, dtype=np.float64)
            core = () if shape == (1, 1) else ((shape[0],) if shape[1] == 1 else shape)
            if a.shape == core:
                batched = False
            elif a.ndim == len(core) + 1 and a.shape[1:] == core:
                batched = True
                if n is None:
                    n = a.shape[0]
                elif a.shape[0] != n:
                    raise ValueError(
                        f"{self.name}: input {name!r} has {a.shape[0]} points but an earlier input has {n}"
                    )
            else:
                raise ValueError(
                    f"{self.name}: input {name!r} must have shape {core} or (N, *{core}), got {a.shape}"
                )
            prepared.append((a, batched, core))
        return prepared, (1 if n is None else n)

    def __call__(self, *args):
        prepared, n = self._prepare(args)
        if self._c is None:
            return self._casadi.call(prepared, n, self.output_shapes)
        outs = self._c.call(prepared, n, self.output_shapes)
        return tuple(shape_outputs(buf, n, shape) for buf, shape in zip(outs, self.output_shapes))

    def bind(self) -> "BoundCall":
        """A single-point caller with preallocated buffers: a few microseconds of Python per call."""
        return BoundCall(self)

    def point_caller(self) -> PointCall | None:
        """The compiled single-point caller with preallocated buffers; None on the CasADi backend."""
        return None if self._c is None else self._c.point_caller(self.input_shapes, self.output_shapes)

    def stepper(
        self,
        carry: dict[str, str],
        feed: str,
        *,
        low=None,
        high=None,
        finite: tuple[str, ...] = (),
        deliver: tuple[str, ...] = (),
    ) -> CStepper | PyStepper:
        """Single steps with a carried state kept in persistent buffers (a streaming filter).

        ``carry`` as in :meth:`scan`; ``feed`` the input written at every step; ``low``/``high``
        element-wise bounds of the fed input, checked before evaluating; ``finite`` the outputs
        that must be finite for the new state to be committed; ``deliver`` the outputs
        ``results()`` returns. See :mod:`registration._codegen.stepper`.
        """
        if self._c is None:
            return PyStepper(self, carry, feed, low, high, finite, deliver)
        return CStepper(self, self._c, library(), carry, feed, low, high, finite, deliver)

    def scan(self, n: int, carry: dict[str, str], inputs: dict, keep_last: tuple[str, ...] = ()) -> dict:
        """Evaluate the function ``n`` times in sequence, feeding outputs back as inputs.

        ``carry`` maps an input name to the output name it takes from the previous step; the
        given value of that input is the initial one. Every other input is given either at its
        core shape (the same every step) or with a leading axis of length ``n`` (one per step).
        Returns every output with a leading axis of length ``n`` except those in ``keep_last``,
        returned for the last step only. In the C backend the whole loop runs in compiled code.
        Carried inputs must be the first inputs, paired with the first outputs in the same order
        (CasADi's ``mapaccum`` convention, used by the serialized backend).
        """
        names_in, names_out = self.input_names, self.output_names
        k = len(carry)
        if list(carry) != names_in[:k] or list(carry.values()) != names_out[:k]:
            raise ValueError(
                f"{self.name}: carried inputs must be the first {k} inputs paired with the first outputs"
            )
        args = []
        for name in names_in:
            if name not in inputs:
                raise ValueError(f"{self.name}: missing input {name!r}")
            args.append(inputs[name])
        prepared, _ = self._prepare(args)
        for (a, batched, _core), name in zip(prepared, names_in):
            if name in carry and batched:
                raise ValueError(f"{self.name}: carried input {name!r} takes one initial value")
            if batched and a.shape[0] != n:
                raise ValueError(f"{self.name}: input {name!r} has {a.shape[0]} steps, expected {n}")
        if self._c is not None:
            outs = self._c.scan(prepared, n, k, [name in keep_last for name in names_out], self.output_shapes)
        else:
            outs = self._casadi.scan(prepared, n, k, self.output_shapes)
            outs = [o[-1:] if name in keep_last else o for o, name in zip(outs, names_out)]
        result = {}
        for name, buf, shape in zip(names_out, outs, self.output_shapes):
            m = buf.shape[0]
            arr = shape_outputs(buf.reshape(m, -1), m, shape)
            result[name] = arr[0] if name in keep_last else arr
        return result

    def scan_runs(
        self, runs: int, n: int, carry: dict[str, str], inputs: dict, keep_last: tuple[str, ...] = ()
    ) -> dict:
        """``runs`` independent scans of ``n`` steps each (e.g. Monte Carlo runs), as :meth:`scan`.

        Each input is given at its core shape (the same in every run and step), with one leading
        axis of length ``runs`` (one value per run, the same at every step; for a carried input,
        each run's initial value) or with two, ``(runs, n, *core)`` (one value per run and step).
        Returns every output as ``(runs, n, *core)``, those in ``keep_last`` as ``(runs, *core)``
        (each run's last step). Run ``r`` gives bit for bit what :meth:`scan` gives with run
        ``r``'s inputs. In the C backend all runs are one compiled call.
        """
        names_in, names_out = self.input_names, self.output_names
        k = len(carry)
        if list(carry) != names_in[:k] or list(carry.values()) != names_out[:k]:
            raise ValueError(
                f"{self.name}: carried inputs must be the first {k} inputs paired with the first outputs"
            )
        if runs < 1 or n < 1:
            raise ValueError(f"{self.name}: need at least one run and one step, got runs={runs}, n={n}")
        lead = [self._runs_input(name, inputs, runs, n, name in carry) for name in names_in]
        last = [name in keep_last for name in names_out]
        if self._c is not None:
            outs = self._c.scan_runs(
                [_strided(a, core) for a, core in lead], runs, n, k, last, self.output_shapes
            )
        else:
            outs = [np.stack(o) for o in zip(*(self._casadi_run(lead, r, n, k) for r in range(runs)))]
            outs = [o[:, -1:] if flag else o for o, flag in zip(outs, last)]
        result = {}
        for name, buf, shape, flag in zip(names_out, outs, self.output_shapes, last):
            m = buf.shape[1]
            arr = shape_outputs(buf.reshape(runs * m, -1), runs * m, shape)
            arr = arr.reshape(runs, m, *arr.shape[1:])
            result[name] = arr[:, 0] if flag else arr
        return result

    def _runs_input(self, name: str, inputs: dict, runs: int, n: int, carried: bool):
        """Input ``name`` as a ``(runs or 1, n or 1, *core)`` float64 array, and its core shape."""
        if name not in inputs:
            raise ValueError(f"{self.name}: missing input {name!r}")
        shape = self.input_shapes[self.input_names.index(name)]
        core = () if shape == (1, 1) else ((shape[0],) if shape[1] == 1 else shape)
        a = np.asarray(inputs[name], dtype=np.float64)
        lead = a.shape[: a.ndim - len(core)]
        allowed = [(), (runs,)] + ([] if carried else [(runs, n)])
        if a.shape[len(lead) :] != core or lead not in allowed:
            kinds = " or ".join(str((*lo, *core)) for lo in allowed)
            raise ValueError(f"{self.name}: input {name!r} must have shape {kinds}, got {a.shape}")
        lead = lead + (1,) * (2 - len(lead))
        return a.reshape(*lead, *core), core

    def _casadi_run(self, lead, r: int, n: int, k: int) -> list[np.ndarray]:
        """Run ``r`` of :meth:`scan_runs` on the CasADi backend: flat ``(n, r * c)`` outputs."""
        prepared = []
        for a, core in lead:
            one = a[r if a.shape[0] > 1 else 0]
            prepared.append((one, True, core) if one.shape[0] > 1 else (one[0], False, core))
        return self._casadi.scan(prepared, n, k, self.output_shapes)


def _strided(a: np.ndarray, core: tuple) -> tuple:
    """A ``(runs or 1, n or 1, *core)`` input as the compiled scan takes it: a contiguous
    column-major array, its run and step strides in doubles (0 where broadcast) and its size."""
    size = int(np.prod(core, dtype=int))
    if len(core) == 2:
        a = np.swapaxes(a, -1, -2)
    a = np.ascontiguousarray(a)
    return a, size * a.shape[1] if a.shape[0] > 1 else 0, size if a.shape[1] > 1 else 0, size


class BoundCall:
    """Evaluate one generated function at one point with preallocated input and output buffers.

    ``call(*inputs)`` copies each input (core shape, numpy-convertible) into its buffer and
    returns the outputs as new arrays of their core shapes. In the C backend that is one ctypes
    call with pointer arrays built once; otherwise it falls back to the vectorised call.
    """

    def __init__(self, fn: GeneratedFunction):
        self.fn = fn
        self._point = fn.point_caller()

    def __call__(self, *inputs) -> tuple:
        if self._point is None:
            return tuple(o[0] for o in self.fn(*inputs))
        return self._point(*inputs)
