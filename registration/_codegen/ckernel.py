"""Calling one compiled generated function through ctypes (the library it lives in:
:mod:`registration._codegen.cbackend`).

Values cross the boundary in CasADi's layout: float64, column-major per point, passed by pointer
with a stride per input and output (0 broadcasts one value to every point). :class:`CKernel`
evaluates at many points, in sequence (a scan) or in independent runs of scans; :class:`PointCall`
at one point with preallocated buffers.
"""

from __future__ import annotations

import ctypes
import functools
import math

import numpy as np

from registration._codegen.cbackend import library

__all__ = ["CKernel", "PointCall"]


def _pointer(a: np.ndarray) -> ctypes.c_void_p:
    return a.ctypes.data_as(ctypes.c_void_p)


def _work_args(work: tuple) -> tuple:
    """The work space of :meth:`CKernel.work_buffers` as ctypes arguments."""
    arg, res, iw, w = work
    return arg, res, _pointer(iw), _pointer(w)


def _column_major(prepared) -> list[np.ndarray]:
    """Contiguous float64 copies (or views) of prepared inputs, matrices column-major per point."""
    out = []
    for a, _batched, core in prepared:
        if len(core) == 2:
            a = np.swapaxes(a, -1, -2)
        out.append(np.ascontiguousarray(a))
    return out


class CKernel:
    """One compiled generated function with its CasADi work buffers (from :func:`library`, or
    from ``lib``, e.g. a :func:`library_of` build).

    ``prepared`` inputs are ``(array, batched, core shape)`` triples; outputs are returned as flat
    ``(points, r * c)`` float64 buffers, column-major per point.
    """

    def __init__(self, name: str, work: dict, lib: ctypes.CDLL | None = None):
        lib = library() if lib is None else lib
        self.name = name
        self._fptr = ctypes.cast(getattr(lib, name), ctypes.c_void_p)
        self._batch = lib.registration_batch
        self._scan = lib.registration_scan
        self._scan_runs = lib.registration_scan_runs
        self.work = work

    def work_buffers(self) -> tuple:
        """Fresh work space for one evaluation (arg, res, iw, w): calls never share it, so
        threads may evaluate the same function at once."""
        work = self.work
        return (
            (ctypes.c_void_p * max(work["sz_arg"], 1))(),
            (ctypes.c_void_p * max(work["sz_res"], 1))(),
            np.zeros(max(work["sz_iw"], 1), dtype=np.int64),
            np.zeros(max(work["sz_w"], 1), dtype=np.float64),
        )

    def call(self, prepared, n: int, output_shapes) -> list[np.ndarray]:
        """Evaluate at ``n`` points (unbatched inputs broadcast with stride 0)."""
        arrays = _column_major(prepared)  # kept alive until the call returns
        in_ptr = (ctypes.c_void_p * len(prepared))(*[a.ctypes.data for a in arrays])
        in_stride = (ctypes.c_longlong * len(prepared))(
            *[math.prod(core) if batched else 0 for _a, batched, core in prepared]
        )
        outs = [np.empty((n, r * c), dtype=np.float64) for r, c in output_shapes]
        out_ptr = (ctypes.c_void_p * len(outs))(*[b.ctypes.data for b in outs])
        out_stride = (ctypes.c_longlong * len(outs))(*[r * c for r, c in output_shapes])
        work = self.work_buffers()  # referenced until the call returns
        flag = self._batch(
            self._fptr,
            ctypes.c_longlong(n),
            len(prepared),
            in_ptr,
            in_stride,
            len(outs),
            out_ptr,
            out_stride,
            *_work_args(work),
        )
        if flag:
            raise RuntimeError(f"generated function {self.name} failed with flag {flag}")
        return outs

    def scan(self, prepared, n: int, k: int, last_only: list[bool], output_shapes) -> list[np.ndarray]:
        """Evaluate ``n`` steps in sequence, the first ``k`` inputs carried from the first ``k``
        outputs of the previous step; outputs flagged in ``last_only`` keep only the last step."""
        n_in, n_out = len(prepared), len(output_shapes)
        arrays = _column_major(prepared)
        sizes = [math.prod(core) for _a, _b, core in prepared]
        in_ptr = (ctypes.c_void_p * n_in)(*[a.ctypes.data for a in arrays])
        in_stride = (ctypes.c_longlong * n_in)(*[s if b else 0 for s, (_a, b, _c) in zip(sizes, prepared)])
        in_size = (ctypes.c_longlong * n_in)(*sizes)
        carry_from = (ctypes.c_int * n_in)(*[j if j < k else -1 for j in range(n_in)])
        outs = [
            np.empty((1 if last else n, r * c), dtype=np.float64)
            for last, (r, c) in zip(last_only, output_shapes)
        ]
        out_ptr = (ctypes.c_void_p * n_out)(*[b.ctypes.data for b in outs])
        out_stride = (ctypes.c_longlong * n_out)(
            *[0 if last else r * c for last, (r, c) in zip(last_only, output_shapes)]
        )
        scratch = np.empty(max(1, sum(sizes[:k])), dtype=np.float64)
        work = self.work_buffers()
        failed = self._scan(
            self._fptr,
            ctypes.c_longlong(n),
            n_in,
            in_ptr,
            in_stride,
            carry_from,
            in_size,
            n_out,
            out_ptr,
            out_stride,
            *_work_args(work),
            _pointer(scratch),
        )
        if failed:
            raise RuntimeError(f"generated function {self.name} failed at step {failed - 1}")
        return outs

    def scan_runs(
        self, inputs, runs: int, n: int, k: int, last_only: list[bool], output_shapes
    ) -> list[np.ndarray]:
        """``runs`` independent scans of ``n`` steps in one compiled call (see :meth:`scan`).

        ``inputs``: per input ``(array, run stride, step stride, size)``: a contiguous float64
        array (matrices column-major), its strides in doubles (0 broadcasts) and the number of
        doubles of one value. Outputs are flat ``(runs, n, r * c)`` buffers, or
        ``(runs, 1, r * c)`` for those flagged in ``last_only``."""
        n_in, n_out = len(inputs), len(output_shapes)
        sizes = [r * c for r, c in output_shapes]
        in_size = (ctypes.c_longlong * n_in)(*[size for *_rest, size in inputs])
        in_ptr = (ctypes.c_void_p * n_in)(*[a.ctypes.data for a, *_rest in inputs])
        in_run = (ctypes.c_longlong * n_in)(*[rs for _a, rs, _s, _z in inputs])
        in_step = (ctypes.c_longlong * n_in)(*[ss for _a, _r, ss, _z in inputs])
        carry_from = (ctypes.c_int * n_in)(*[j if j < k else -1 for j in range(n_in)])
        outs = [np.empty((runs, 1 if last else n, size)) for last, size in zip(last_only, sizes)]
        out_ptr = (ctypes.c_void_p * n_out)(*[b.ctypes.data for b in outs])
        out_run = (ctypes.c_longlong * n_out)(*[b.shape[1] * b.shape[2] for b in outs])
        out_step = (ctypes.c_longlong * n_out)(*[0 if last else size for last, size in zip(last_only, sizes)])
        scratch = np.empty(max(1, sum(in_size[:k])), dtype=np.float64)
        work = self.work_buffers()
        failed = self._scan_runs(
            self._fptr,
            ctypes.c_longlong(runs),
            ctypes.c_longlong(n),
            n_in,
            in_ptr,
            in_run,
            in_step,
            carry_from,
            in_size,
            n_out,
            out_ptr,
            out_run,
            out_step,
            (ctypes.c_void_p * n_in)(),
            (ctypes.c_void_p * n_out)(),
            *_work_args(work),
            _pointer(scratch),
        )
        if failed:
            run, step = divmod(int(failed) - 1, n)
            raise RuntimeError(f"generated function {self.name} failed at step {step} of run {run}")
        return outs

    def point_caller(self, input_shapes, output_shapes) -> "PointCall":
        """A single-point caller of this function with preallocated buffers."""
        call = functools.partial(self._batch, self._fptr, ctypes.c_longlong(1))
        work = self.work_buffers()
        return PointCall(self.name, call, input_shapes, output_shapes, work, *_work_args(work))


class PointCall:
    """Evaluate one compiled function at one point: inputs at their core shapes are copied into
    preallocated column-major buffers, one ctypes call, outputs returned as new arrays of their
    core shapes (floats for scalars)."""

    def __init__(self, name, call, input_shapes, output_shapes, work, arg, res, iw, w):
        self.name = name
        self._work = work  # kept alive: the call holds pointers into it
        self._input_shapes, self._output_shapes = list(input_shapes), list(output_shapes)
        self._in = [np.zeros(r * c) for r, c in self._input_shapes]
        self._out = [np.zeros(r * c) for r, c in self._output_shapes]
        n_in, n_out = len(self._in), len(self._out)
        in_ptr = (ctypes.c_void_p * n_in)(*[a.ctypes.data for a in self._in])
        in_stride = (ctypes.c_longlong * n_in)(*([0] * n_in))
        out_ptr = (ctypes.c_void_p * n_out)(*[a.ctypes.data for a in self._out])
        out_stride = (ctypes.c_longlong * n_out)(*([0] * n_out))
        self._call = functools.partial(
            call, n_in, in_ptr, in_stride, n_out, out_ptr, out_stride, arg, res, iw, w
        )

    def __call__(self, *inputs) -> tuple:
        for buf, (r, c), value in zip(self._in, self._input_shapes, inputs):
            if c == 1:
                buf[:] = np.ravel(value)
            else:
                buf[:] = np.asarray(value, dtype=np.float64).T.ravel()  # column-major
        flag = self._call()
        if flag:
            raise RuntimeError(f"generated function {self.name} failed with flag {flag}")
        outs = []
        for buf, (r, c) in zip(self._out, self._output_shapes):
            if (r, c) == (1, 1):
                outs.append(float(buf[0]))
            elif c == 1:
                outs.append(buf.copy())
            else:
                outs.append(buf.reshape(c, r).T.copy())
        return tuple(outs)
