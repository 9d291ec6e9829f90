"""The association's per-sensor tracker loop in compiled code (``registration_tracks`` of
``_tracker.c``), on the generated constant-velocity filter ``cv_start``, ``cv_predict``,
``cv_gate`` and ``cv_update``.

What the loop does, and its reference implementation in numpy:
:func:`registration.fleet.association.grouping.tracks.sensor_tracks`. On the C backend only (the
caller checks :func:`registration._codegen.backend`).
"""

from __future__ import annotations

import ctypes
from dataclasses import dataclass

import numpy as np

from registration._codegen.artifacts import manifest
from registration._codegen.cbackend import library

__all__ = ["FILTER_FUNCTIONS", "CompiledTracks", "compiled_assignment", "compiled_tracks"]

#: The generated functions the loop calls, in the order it takes them.
FILTER_FUNCTIONS = ("cv_start", "cv_predict", "cv_gate", "cv_update")


@dataclass(frozen=True)
class CompiledTracks:
    """The loop's result: ``track`` (N,) the track id of each plot (ids in the order the tracks
    opened), and the time ``seconds_assignment`` (s) and number ``assignments`` of the
    assignments it solved."""

    track: np.ndarray
    seconds_assignment: float
    assignments: int


def _pointer(a: np.ndarray) -> ctypes.c_void_p:
    return a.ctypes.data_as(ctypes.c_void_p)


def _check(bounds, step_plots, p_ecef, cov, time, sensor) -> None:
    """ValueError unless the arrays fit together (the C loop trusts them)."""
    n = np.shape(time)[0] if np.ndim(time) == 1 else -1
    if n < 0 or np.shape(sensor) != (n,) or np.shape(p_ecef) != (n, 3) or np.shape(cov) != (n, 3, 3):
        raise ValueError(
            f"time (N,), sensor (N,), p_ecef (N, 3) and cov (N, 3, 3) must agree, got {np.shape(time)}, "
            f"{np.shape(sensor)}, {np.shape(p_ecef)}, {np.shape(cov)}"
        )
    b, steps = np.asarray(bounds), np.asarray(step_plots)
    if b.ndim != 1 or b.size < 1 or b[0] != 0 or b[-1] != steps.size or (np.diff(b) < 0).any():
        raise ValueError("bounds must rise from 0 to the number of step plots")
    if steps.size and (steps.min() < 0 or steps.max() >= n):
        raise ValueError(f"step plots must be plot indices in [0, {n})")
    if n and np.min(sensor) < 0:
        raise ValueError("sensor indices must be >= 0")
    within = np.ones(max(steps.size - 1, 0), dtype=bool)
    within[b[1:-1][(b[1:-1] > 0) & (b[1:-1] < steps.size)] - 1] = False  # pairs across a step boundary
    if (np.diff(np.asarray(sensor)[steps]) < 0)[within].any():
        raise ValueError("each step's plots must be sorted by sensor")


def compiled_tracks(
    bounds: np.ndarray,
    step_plots: np.ndarray,
    p_ecef: np.ndarray,
    cov: np.ndarray,
    time: np.ndarray,
    sensor: np.ndarray,
    *,
    gate: float,
    forbidden: float,
    accel_sigma: float,
    max_speed: float,
    max_missed: int,
) -> CompiledTracks:
    """Run the tracker over the steps ``step_plots[bounds[s]:bounds[s + 1]]`` (plot indices, each
    step sorted by sensor) of plots at ``p_ecef`` (N, 3) m with covariances ``cov`` (N, 3, 3) m^2,
    times ``time`` (N,) s and sensor indices ``sensor`` (N,); ``gate`` the chi-square bound on the
    squared distance, ``forbidden`` the assignment's cost of a pair not allowed (above any real
    cost), ``accel_sigma`` m/s^2/sqrt(Hz), ``max_speed`` m/s, ``max_missed`` scans.
    RuntimeError if the loop fails (out of memory, or a generated function's error flag)."""
    _check(bounds, step_plots, p_ecef, cov, time, sensor)
    lib = library()
    functions = manifest()["functions"]
    work = [functions[name]["work"] for name in FILTER_FUNCTIONS]
    arg = (ctypes.c_void_p * max(max(w["sz_arg"] for w in work), 4))()
    res = (ctypes.c_void_p * max(max(w["sz_res"] for w in work), 2))()
    iw = np.zeros(max(1, max(w["sz_iw"] for w in work)), dtype=np.int64)
    w = np.zeros(max(1, max(w["sz_w"] for w in work)), dtype=np.float64)
    n = time.size
    p = np.ascontiguousarray(p_ecef, dtype=np.float64)
    cov_cm = np.ascontiguousarray(np.swapaxes(cov, 1, 2), dtype=np.float64)  # column-major per plot
    trace = np.ascontiguousarray(np.trace(cov, axis1=1, axis2=2), dtype=np.float64)
    t = np.ascontiguousarray(time, dtype=np.float64)
    s = np.ascontiguousarray(sensor, dtype=np.int64)
    b = np.ascontiguousarray(bounds, dtype=np.int64)
    steps = np.ascontiguousarray(step_plots, dtype=np.int64)
    track = np.full(n, -1, dtype=np.int64)
    seconds, calls = ctypes.c_double(0.0), ctypes.c_longlong(0)
    fptr = [ctypes.cast(getattr(lib, name), ctypes.c_void_p) for name in FILTER_FUNCTIONS]
    status = lib.registration_tracks(
        *fptr,
        arg,
        res,
        _pointer(iw),
        _pointer(w),
        ctypes.c_longlong(b.size - 1),
        _pointer(b),
        _pointer(steps),
        _pointer(p),
        _pointer(cov_cm),
        _pointer(trace),
        _pointer(t),
        _pointer(s),
        ctypes.c_longlong(int(s.max()) + 1 if n else 1),
        ctypes.c_double(gate),
        ctypes.c_double(forbidden),
        ctypes.c_double(accel_sigma),
        ctypes.c_double(max_speed),
        ctypes.c_longlong(max_missed),
        _pointer(track),
        ctypes.byref(seconds),
        ctypes.byref(calls),
    )
    if status == -1:
        raise RuntimeError("the compiled tracker ran out of memory")
    if status == -2:
        raise RuntimeError("the compiled tracker: an assignment had no finite cost")
    if status:
        raise RuntimeError(f"the compiled tracker: generated {FILTER_FUNCTIONS[status - 1]} failed")
    return CompiledTracks(track, float(seconds.value), int(calls.value))


def compiled_assignment(cost: np.ndarray) -> np.ndarray:
    """The loop's assignment alone: (R,) the column of each row minimising the sum of ``cost``
    (R, C), R <= C, finite (the rows and columns of :func:`scipy.optimize.linear_sum_assignment`,
    whose algorithm, column order and tie rule it follows). For tests against scipy."""
    a = np.ascontiguousarray(cost, dtype=np.float64)
    if a.ndim != 2 or a.shape[0] > a.shape[1] or not np.isfinite(a).all():
        raise ValueError(f"cost must be a finite (R, C) matrix with R <= C, got shape {a.shape}")
    col4row = np.full(a.shape[0], -1, dtype=np.int64)
    status = library().registration_assign(
        ctypes.c_longlong(a.shape[0]), ctypes.c_longlong(a.shape[1]), _pointer(a), _pointer(col4row)
    )
    if status:
        raise RuntimeError("the compiled assignment ran out of memory")  # finite costs: always feasible
    return col4row
