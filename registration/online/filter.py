"""Online ECEF registration of two ship radars (SPEC section 2; Wang et al. 2011, eqs. 18-23).

Each row of the data holds one synchronous pair of plots of a common target by radar A and
radar B, with each ship's navigation (geodetic, exact) and measured attitude. The filter
estimates the 12 registration errors (:data:`registration.state.STATE_NAMES`): per ship the
heading, pitch and roll errors and the radar's range, bearing and elevation biases. Every
model evaluation runs in the generated Kalman step (derive/kalman.py); a batch run with fixed Q
is one compiled loop.

Conventions: SI units and radians; measured = true + error; corrected = measured - estimate.
"""

from __future__ import annotations

from collections import deque
from dataclasses import asdict, dataclass, field
from typing import Mapping

import numpy as np

from registration import _codegen as _loader
from registration.core.observability import ObservabilityReport, observability_report
from registration.online.contract import DATA_COLUMNS, N_STATE, SENSOR_COLUMNS, STATE_LABELS, STATE_NAMES, STATE_UNITS

__all__ = ["RegistrationConfig", "RegistrationResult", "OnlineRegistrar", "register", "validate_data", "difference_statistics"]

LINEARIZATIONS = ("paper", "relinearized", "fitted")
DEFAULT_LINEARIZATION = "fitted"
Q_MODES = ("fixed", "adaptive")
T_VARIANTS = ("standard", "paper")
_CARRY = {"x": "x_new", "P": "P_new", "info": "info_new"}
_DEG = np.pi / 180


@dataclass
class RegistrationConfig:
    """Filter settings. All sigmas are standard deviations in SI units (m, rad).

    sigma0: measurement noise ``[sr_A, sq_A, se_A, sr_B, sq_B, se_B]`` (R0 of eq. 19).
    prior_sigma: initial state standard deviations (P0 = diag(prior_sigma^2)), STATE_NAMES order.
    x0: initial estimate (default zeros).
    q_mode: ``fixed`` (Q = diag(q_sigma^2) per step) or ``adaptive`` (eqs. 21-22: the sample
        covariance of the last ``q_window`` estimates, plus the fixed Q as a floor).
    linearization: ``paper`` (H, Z at the raw measurements, as printed), ``relinearized`` (at
        the measurements corrected by the current estimate: an extended Kalman filter) or
        ``fitted`` (the default: at the most probable noise-free plots given the row and the
        current estimate with its covariance; the plots of one fused target once the
        registration is well known. Removes the paper filter's range-bias errors at 0.5 deg
        noise; like any EKF it needs a prior within the model's linear range;
        derive/kalman.py and the README).
    t_variant: ``standard`` (orthonormal ENU->ECEF) or ``paper`` (eq. 4 as printed).
    """

    sigma0: tuple = (50.0, 0.5 * _DEG, 0.5 * _DEG, 50.0, 0.5 * _DEG, 0.5 * _DEG)
    prior_sigma: tuple = (0.5 * _DEG, 0.2 * _DEG, 0.2 * _DEG, 2000.0, 1.0 * _DEG, 1.0 * _DEG) * 2
    x0: tuple | None = None
    q_mode: str = "fixed"
    q_sigma: tuple = (1e-6, 1e-6, 1e-6, 0.01, 1e-6, 1e-6) * 2
    q_window: int = 20
    linearization: str = DEFAULT_LINEARIZATION
    t_variant: str = "standard"

    def __post_init__(self):
        self.sigma0 = tuple(float(v) for v in self.sigma0)
        self.prior_sigma = tuple(float(v) for v in self.prior_sigma)
        self.q_sigma = tuple(float(v) for v in self.q_sigma)
        if len(self.sigma0) != 6 or not all(np.isfinite(self.sigma0)) or min(self.sigma0) <= 0:
            raise ValueError("sigma0: expected 6 finite values > 0 [m, rad, rad, m, rad, rad]")
        if max(self.sigma0[i] for i in (1, 2, 4, 5)) > 0.35:
            raise ValueError("sigma0: angle sigmas above 20 deg; pass radians, not degrees")
        if len(self.prior_sigma) != N_STATE or min(self.prior_sigma) <= 0 or not all(np.isfinite(self.prior_sigma)):
            raise ValueError(f"prior_sigma: expected {N_STATE} finite values > 0 (rad or m, STATE_NAMES order)")
        if len(self.q_sigma) != N_STATE or min(self.q_sigma) < 0 or not all(np.isfinite(self.q_sigma)):
            raise ValueError(f"q_sigma: expected {N_STATE} finite values >= 0 (rad or m per step)")
        if self.x0 is not None:
            self.x0 = tuple(float(v) for v in self.x0)
            if len(self.x0) != N_STATE or not all(np.isfinite(self.x0)):
                raise ValueError(f"x0: expected {N_STATE} finite values")
        if self.q_mode not in Q_MODES:
            raise ValueError(f"q_mode: expected one of {Q_MODES}, got {self.q_mode!r}")
        if self.linearization not in LINEARIZATIONS:
            raise ValueError(f"linearization: expected one of {LINEARIZATIONS}, got {self.linearization!r}")
        if self.t_variant not in T_VARIANTS:
            raise ValueError(f"t_variant: expected one of {T_VARIANTS}, got {self.t_variant!r}")
        if int(self.q_window) < 2:
            raise ValueError("q_window: need at least 2 estimates")

    @property
    def step_name(self) -> str:
        return f"kalman_step_{self.linearization}_{self.t_variant}"

    def to_json(self) -> dict:
        return asdict(self)


# --------------------------------------------------------------------------- data checks
_LIMITS = {
    "lat": (-np.pi / 2, np.pi / 2, "rad (latitude, [-pi/2, pi/2])"),
    "lon": (-2 * np.pi, 2 * np.pi, "rad"),
    "alt": (-1.2e4, 1.0e6, "m above the WGS-84 ellipsoid"),
    "heading": (-2 * np.pi, 2 * np.pi, "rad"),
    "pitch": (-np.pi / 2, np.pi / 2, "rad"),
    "roll": (-np.pi / 2, np.pi / 2, "rad"),
    "bearing": (-2 * np.pi, 2 * np.pi, "rad"),
    "elevation": (-np.pi / 2, np.pi / 2, "rad"),
}


def _row_error(row: int, column: str, value, expected: str) -> ValueError:
    return ValueError(f"row {row}, column {column!r}: value {value!r} {expected}")


#: Problem codes of :func:`cell_problems`, in the order of precedence within one cell.
PROBLEM_OK, PROBLEM_NON_FINITE, PROBLEM_OUT_OF_RANGE, PROBLEM_NON_POSITIVE = 0, 1, 2, 3
#: Contract names of the 18 row columns (``time`` excluded), in ``row`` order.
ROW_COLUMNS = tuple(f"{p}_{c}" for p in ("a", "b") for c in SENSOR_COLUMNS)


_COL_IS_RANGE = np.array([SENSOR_COLUMNS[j % 9] == "range" for j in range(18)])
_COL_LO = np.array([-np.inf if SENSOR_COLUMNS[j % 9] == "range" else _LIMITS[SENSOR_COLUMNS[j % 9]][0] for j in range(18)])
_COL_HI = np.array([np.inf if SENSOR_COLUMNS[j % 9] == "range" else _LIMITS[SENSOR_COLUMNS[j % 9]][1] for j in range(18)])


def cell_problems(block: np.ndarray) -> np.ndarray:
    """Problem code of every cell of a (K, 18) block in contract order (SI units, radians).

    0: fine; 1: not finite; 2: outside the column's limits (:data:`_LIMITS`: latitude and angles,
    altitude); 3: a range that is not > 0. A non-finite cell is reported as non-finite only.
    Shared by :func:`validate_data`, :meth:`OnlineRegistrar.update` and the file reader
    (:mod:`registration.rowcheck`), so every entry point applies the same rules.
    """
    block = np.asarray(block, dtype=np.float64)
    with np.errstate(invalid="ignore"):
        out_of_range = (block < _COL_LO) | (block > _COL_HI)
        non_positive = _COL_IS_RANGE & (block <= 0)
    codes = np.where(non_positive, PROBLEM_NON_POSITIVE, np.where(out_of_range, PROBLEM_OUT_OF_RANGE, PROBLEM_OK)).astype(np.int8)
    codes[~np.isfinite(block)] = PROBLEM_NON_FINITE
    return codes


def _check_block(block: np.ndarray, first_row: int = 0) -> None:
    """Check a (K, 18) block of rows in contract order; raise naming the first bad row/column."""
    codes = cell_problems(block)
    if not codes.any():
        return
    r, c = (int(v) for v in np.argwhere(codes)[0])  # first bad cell in row-major order
    code = codes[r, c]
    if code == PROBLEM_NON_FINITE:
        msg = "is not finite; expected a number"
    elif code == PROBLEM_NON_POSITIVE:
        msg = "must be > 0 m (slant range)"
    else:
        lo, hi, unit = _LIMITS[SENSOR_COLUMNS[c % 9]]
        msg = f"is outside [{lo:g}, {hi:g}] {unit}"
        with np.errstate(invalid="ignore"):
            if unit.startswith("rad") and np.nanmax(np.abs(block[:, c])) <= 360:
                msg += " (looks like degrees: convert with numpy.radians)"
    raise _row_error(first_row + r, ROW_COLUMNS[c], float(block[r, c]), msg)


def validate_data(data: Mapping) -> tuple[np.ndarray, np.ndarray]:
    """Check a data mapping (dict of arrays or DataFrame); return ``time (K,)`` and ``rows (K, 18)``.

    Raises ValueError naming the row and column of the first problem: a missing column, a
    non-finite value, a latitude or angle out of range, a non-positive range, or a timestamp that
    does not increase.
    """
    missing = [c for c in DATA_COLUMNS if c not in data]
    if missing:
        raise ValueError(f"missing column(s) {missing}; expected {list(DATA_COLUMNS)} (SI units, radians)")
    try:
        cols = [np.asarray(data[c], dtype=np.float64) for c in DATA_COLUMNS]
    except (TypeError, ValueError) as exc:
        raise ValueError(f"non-numeric column in data: {exc}") from exc
    k = cols[0].shape
    for name, col in zip(DATA_COLUMNS, cols):
        if col.ndim != 1 or col.shape != k:
            raise ValueError(f"column {name!r}: shape {col.shape}, expected {k} like 'time' (one value per row)")
    if k[0] == 0:
        raise ValueError("data has no rows")
    time = cols[0]
    if not np.isfinite(time).all():
        r = int(np.argmax(~np.isfinite(time)))
        raise _row_error(r, "time", float(time[r]), "is not finite; expected seconds")
    steps = np.diff(time)
    if (steps <= 0).any():
        r = int(np.argmax(steps <= 0)) + 1
        raise _row_error(r, "time", float(time[r]), f"does not increase (previous row: {time[r - 1]!r}); timestamps must be strictly increasing")
    rows = np.stack(cols[1:], axis=1)
    _check_block(rows)
    return time, rows


def _row_from_mapping(row: Mapping | np.ndarray) -> np.ndarray:
    if isinstance(row, np.ndarray) or isinstance(row, (list, tuple)):
        arr = np.asarray(row, dtype=np.float64)
        if arr.shape != (18,):
            raise ValueError(f"row: expected 18 values in contract order (a_lat ... b_elevation), got shape {arr.shape}")
        return arr
    missing = [c for c in DATA_COLUMNS[1:] if c not in row]
    if missing:
        raise ValueError(f"row: missing column(s) {missing}")
    return np.array([float(row[c]) for c in DATA_COLUMNS[1:]])


# --------------------------------------------------------------------------- results
def difference_statistics(diff: np.ndarray) -> dict:
    """max |.|, mean and standard deviation per ECEF axis of a (K, 3) difference, in metres."""
    diff = np.asarray(diff)
    return {
        "max": np.abs(diff).max(axis=0).tolist(),
        "mean": diff.mean(axis=0).tolist(),
        "std": diff.std(axis=0, ddof=1).tolist() if len(diff) > 1 else [0.0, 0.0, 0.0],
    }


@dataclass
class RegistrationResult:
    """Everything a run produced. Shapes: K rows; 12 states in :data:`STATE_NAMES` order."""

    config: RegistrationConfig
    time: np.ndarray
    estimates: np.ndarray  # (K, 12) posterior estimate after each row
    covariances: np.ndarray  # (K, 12, 12)
    innovations: np.ndarray  # (K, 3) m
    innovation_covariances: np.ndarray  # (K, 3, 3) m^2
    nis: np.ndarray  # (K,)
    information: np.ndarray  # (12, 12) sum H^T R^-1 H as the filter accumulated it (at its linearisation points)
    information_at_estimate: np.ndarray  # (12, 12) the same sum re-evaluated at the final estimate (observability)
    raw_difference_ecef: np.ndarray  # (K, 3) X_A - X_B from the measured values
    corrected_difference_ecef: np.ndarray  # (K, 3) X_A - X_B corrected with the estimate after each row
    corrected_a_ecef: np.ndarray  # (K, 3) corrected target position from radar A
    corrected_b_ecef: np.ndarray  # (K, 3)
    observability: ObservabilityReport
    state_names: tuple = STATE_NAMES

    @property
    def final(self) -> np.ndarray:
        return self.estimates[-1]

    @property
    def final_sigma(self) -> np.ndarray:
        return np.sqrt(np.diag(self.covariances[-1]))

    def statistics(self) -> dict:
        """The Table-1-style before/after statistics (metres)."""
        return {"before": difference_statistics(self.raw_difference_ecef), "after": difference_statistics(self.corrected_difference_ecef)}

    def identifiable_combinations(self) -> list[dict]:
        """Estimates of the sums that are identifiable when the parts are not (e.g. dC_a + dq_a)."""
        out = []
        P, x = self.covariances[-1], self.final
        for a, b in self.observability.identifiable_sums:
            i, j = STATE_NAMES.index(a), STATE_NAMES.index(b)
            var = P[i, i] + P[j, j] + 2 * P[i, j]
            out.append({"name": f"{a} + {b}", "indices": [i, j], "estimate": float(x[i] + x[j]), "sigma": float(np.sqrt(max(var, 0.0)))})
        return out


# --------------------------------------------------------------------------- filter
class OnlineRegistrar:
    """Streaming registration: call :meth:`update` with one row at a time.

    A row is a mapping with the data-contract columns (without ``time``) or an array of the
    18 values in contract order. The row is validated before the state is touched, so a bad row
    raises ValueError and leaves the filter exactly as it was.
    """

    def __init__(self, config: RegistrationConfig | None = None):
        self.config = config or RegistrationConfig()
        self._step = _loader.get(self.config.step_name)
        self._bound = None  # single-row caller with preallocated buffers, made on first update()
        self.x = np.array(self.config.x0 if self.config.x0 is not None else np.zeros(N_STATE))
        self.P = np.diag(np.square(self.config.prior_sigma))
        self.info = np.zeros((N_STATE, N_STATE))
        self._q_fixed = np.diag(np.square(self.config.q_sigma))
        self._sigma0 = np.array(self.config.sigma0)
        self._window: deque = deque(maxlen=int(self.config.q_window))
        self.n_updates = 0
        self.last_time: float | None = None

    def process_noise(self) -> np.ndarray:
        """Q for the next step: fixed, or eqs. 21-22 (sample covariance of the last N estimates)."""
        if self.config.q_mode == "fixed" or len(self._window) < 2:
            return self._q_fixed
        est = np.array(self._window)
        dev = est - est.mean(axis=0)
        return dev.T @ dev / len(est) + self._q_fixed

    def update(self, row, time: float | None = None) -> dict:
        """Process one row; return {'x', 'P', 'nu', 'S', 'nis'} after the update."""
        values = _row_from_mapping(row)
        _check_block(values[None, :], first_row=self.n_updates)
        if time is not None:
            if not np.isfinite(time):
                raise _row_error(self.n_updates, "time", time, "is not finite; expected seconds")
            if self.last_time is not None and time <= self.last_time:
                raise _row_error(self.n_updates, "time", time, f"does not increase (previous: {self.last_time}); timestamps must be strictly increasing")
        if self._bound is None:
            self._bound = self._step.bind()
        x, P, info, nu, S, nis = self._bound(self.x, self.P, self.info, self.process_noise(), values, self._sigma0)
        if not (np.isfinite(x).all() and np.isfinite(P).all()):
            raise RuntimeError(f"row {self.n_updates}: the filter step produced non-finite values; state left unchanged")
        self.x, self.P, self.info = x, P, info
        self._window.append(self.x.copy())
        self.n_updates += 1
        self.last_time = time if time is not None else self.last_time
        return {"x": self.x, "P": self.P, "nu": nu, "S": S, "nis": nis}

    def update_block(self, rows: np.ndarray, times: np.ndarray | None = None, *, partial: bool = False) -> dict:
        """Process a (K, 18) block of rows in contract order; the same arithmetic as K calls of :meth:`update`.

        With fixed Q the block runs as one compiled loop (the scan of :func:`register`), carrying
        x, P and the information from the state the filter is in, so a run split into blocks is
        bit-for-bit the run in one piece. The block is validated before the state is touched.
        Returns ``x (K, 12)``, ``P (K, 12, 12)``, ``nu``, ``S``, ``nis`` and ``n``, the rows taken.

        A step whose result is not finite is never committed. With ``partial=False`` it raises
        RuntimeError and the state is left as it was before the block; with ``partial=True`` the
        rows before it are committed and returned (``n`` < K), so the caller can set that row aside.
        """
        rows = np.ascontiguousarray(rows, dtype=np.float64)
        if rows.ndim != 2 or rows.shape[1] != 18:
            raise ValueError(f"rows: expected shape (K, 18) in contract order, got {rows.shape}")
        k = rows.shape[0]
        _check_block(rows, first_row=self.n_updates)
        if times is not None:
            times = np.asarray(times, dtype=np.float64)
            if times.shape != (k,):
                raise ValueError(f"times: expected shape ({k},), got {times.shape}")
            if not np.isfinite(times).all():
                r = int(np.argmax(~np.isfinite(times)))
                raise _row_error(self.n_updates + r, "time", float(times[r]), "is not finite; expected seconds")
            prev = np.concatenate([[-np.inf if self.last_time is None else self.last_time], times[:-1]])
            if (times <= prev).any():
                r = int(np.argmax(times <= prev))
                raise _row_error(self.n_updates + r, "time", float(times[r]), f"does not increase (previous: {prev[r]}); timestamps must be strictly increasing")
        if k == 0:
            return {"x": np.empty((0, N_STATE)), "P": np.empty((0, N_STATE, N_STATE)), "nu": np.empty((0, 3)),
                    "S": np.empty((0, 3, 3)), "nis": np.empty(0), "n": 0}
        if self.config.q_mode == "fixed":
            out = self._step.scan(
                k, _CARRY,
                {"x": self.x, "P": self.P, "info": self.info, "Q": self._q_fixed, "row": rows, "sigma0": self._sigma0},
            )
            x, P, info = out["x_new"], out["P_new"], out["info_new"]
            nu, S, nis = out["nu"], out["S"], out["nis"]
            ok = np.isfinite(x).all(axis=1) & np.isfinite(P).all(axis=(1, 2)) & np.isfinite(info).all(axis=(1, 2))
            n = k if ok.all() else int(np.argmax(~ok))
            if n < k and not partial:
                raise RuntimeError(f"row {self.n_updates + n}: the filter step produced non-finite values; state left unchanged")
            if n:
                self.x, self.P, self.info = x[n - 1].copy(), P[n - 1].copy(), info[n - 1].copy()
                for i in range(max(0, n - self._window.maxlen), n):
                    self._window.append(x[i].copy())
                self.n_updates += n
                if times is not None:
                    self.last_time = float(times[n - 1])
            return {"x": x[:n], "P": P[:n], "nu": nu[:n], "S": S[:n], "nis": nis[:n], "n": n}
        saved = self.state_dict()
        xs, Ps = np.empty((k, N_STATE)), np.empty((k, N_STATE, N_STATE))
        nus, Ss, niss = np.empty((k, 3)), np.empty((k, 3, 3)), np.empty(k)
        n = k
        for i in range(k):
            try:
                r = self.update(rows[i], time=None if times is None else float(times[i]))
            except RuntimeError:
                if not partial:
                    self.load_state_dict(saved)
                    raise
                n = i
                break
            xs[i], Ps[i], nus[i], Ss[i], niss[i] = r["x"], r["P"], r["nu"], r["S"], r["nis"]
        return {"x": xs[:n], "P": Ps[:n], "nu": nus[:n], "S": Ss[:n], "nis": niss[:n], "n": n}

    def state_dict(self) -> dict:
        """Everything that determines the next steps (plain numpy arrays and numbers; copies)."""
        return {
            "x": self.x.copy(), "P": self.P.copy(), "info": self.info.copy(),
            "window": np.array(self._window).reshape(-1, N_STATE),
            "n_updates": int(self.n_updates), "last_time": self.last_time,
        }

    def load_state_dict(self, state: dict) -> None:
        """Restore a :meth:`state_dict` (shapes are checked; values must be finite)."""
        x = np.array(state["x"], dtype=np.float64)
        P = np.array(state["P"], dtype=np.float64)
        info = np.array(state["info"], dtype=np.float64)
        window = np.array(state["window"], dtype=np.float64).reshape(-1, N_STATE)
        if x.shape != (N_STATE,) or P.shape != (N_STATE, N_STATE) or info.shape != (N_STATE, N_STATE):
            raise ValueError("state: x must be (12,), P and info (12, 12)")
        if len(window) > self._window.maxlen:
            raise ValueError(f"state: window holds {len(window)} estimates, more than q_window = {self._window.maxlen}")
        if not (np.isfinite(x).all() and np.isfinite(P).all() and np.isfinite(info).all() and np.isfinite(window).all()):
            raise ValueError("state: non-finite values")
        self.x, self.P, self.info = x, P, info
        self._window.clear()
        self._window.extend(w.copy() for w in window)
        self.n_updates = int(state["n_updates"])
        last = state.get("last_time")
        self.last_time = None if last is None else float(last)

    @classmethod
    def from_state_dict(cls, state: dict, config: RegistrationConfig | None = None) -> "OnlineRegistrar":
        reg = cls(config)
        reg.load_state_dict(state)
        return reg

    def observability(self) -> ObservabilityReport:
        """From the information accumulated at the filter's own linearisation points (streaming)."""
        return observability_report(self.info, np.array(self.config.prior_sigma), STATE_NAMES, STATE_LABELS, STATE_UNITS)


def information_matrix(H: np.ndarray, R: np.ndarray) -> np.ndarray:
    """sum_k H_k^T R_k^-1 H_k for H (K, 3, 12) and R (K, 3, 3), by Cholesky solves.

    W_k = L_k^-1 H_k by forward substitution written over the whole batch (numpy's batched
    ``solve`` pays a LAPACK call per 3x3 system, ~10x slower here), then J = W^T W in one
    matrix product over the stacked rows.
    """
    L = np.linalg.cholesky(R)
    W = np.empty(np.shape(H), dtype=float)
    W[:, 0] = H[:, 0] / L[:, 0, 0, None]
    W[:, 1] = (H[:, 1] - L[:, 1, 0, None] * W[:, 0]) / L[:, 1, 1, None]
    W[:, 2] = (H[:, 2] - L[:, 2, 0, None] * W[:, 0] - L[:, 2, 1, None] * W[:, 1]) / L[:, 2, 2, None]
    W = W.reshape(-1, H.shape[-1])
    J = W.T @ W
    return 0.5 * (J + J.T)


def information_skipping_bad_rows(H: np.ndarray, R: np.ndarray) -> tuple[np.ndarray, int]:
    """sum H^T R^-1 H over the rows, leaving out rows whose R is not positive definite or whose term
    is not finite (possible only for extreme accepted values); returns (J, rows used)."""
    try:
        J = information_matrix(H, R)
        if np.isfinite(J).all() and np.abs(J).max() < 1e200:
            return J, len(H)
    except np.linalg.LinAlgError:
        pass
    J, used = np.zeros((N_STATE, N_STATE)), 0
    for k in range(len(H)):
        try:
            Jk = information_matrix(H[k:k + 1], R[k:k + 1])
        except np.linalg.LinAlgError:
            continue
        if np.isfinite(Jk).all() and np.abs(Jk).max() < 1e200 and np.isfinite(J + Jk).all():
            J, used = J + Jk, used + 1
    return J, used



def information_at_estimate(rows: np.ndarray, x: np.ndarray, config: RegistrationConfig) -> tuple[np.ndarray, int]:
    """sum_k H_k^T R_k^-1 H_k with H, R at the rows (K, 18) corrected by one estimate x (12,).

    One compiled loop of the generated ``information_step``. If any row makes the sum
    non-finite (possible only for extreme accepted values), the NumPy path recomputes it and
    leaves such rows out. Returns (J, rows used).
    """
    if len(rows) == 0:
        return np.zeros((N_STATE, N_STATE)), 0
    step = _loader.get(f"information_step_{config.t_variant}")
    out = step.scan(len(rows), {"info": "info_new"},
                    {"info": np.zeros((N_STATE, N_STATE)), "x": np.asarray(x, dtype=float), "row": rows,
                     "sigma0": np.array(config.sigma0)}, keep_last=("info_new",))
    J = out["info_new"]
    if np.isfinite(J).all() and np.abs(J).max() < 1e200:
        return J, len(rows)
    pair = _pair_outputs(_corrected_rows(rows, np.broadcast_to(x, (len(rows), N_STATE))), config)
    return information_skipping_bad_rows(pair["H"], pair["R"])


def _corrected_rows(rows: np.ndarray, estimates: np.ndarray) -> np.ndarray:
    corr = np.zeros_like(rows)
    corr[:, 3:9] = estimates[:, 0:6]
    corr[:, 12:18] = estimates[:, 6:12]
    out = rows - corr
    for j in (7, 16):  # bearings back into (-pi, pi]
        out[:, j] = np.angle(np.exp(1j * out[:, j]))
    return out


def _target_positions(rows: np.ndarray, config: RegistrationConfig) -> tuple[np.ndarray, np.ndarray]:
    """Target ECEF (K, 3) seen by radar A and by radar B (eq. 3), from rows in the step's layout.

    Two calls of the generated plot2ecef: about half the cost of the pair model, which also
    builds H, M and R."""
    fn = _loader.get(f"plot2ecef_{config.t_variant}")
    p_a = fn(*(rows[:, j] for j in range(9)))[0]
    p_b = fn(*(rows[:, 9 + j] for j in range(9)))[0]
    return np.asarray(p_a).reshape(-1, 3), np.asarray(p_b).reshape(-1, 3)


def _pair_outputs(rows: np.ndarray, config: RegistrationConfig):
    fn = _loader.get(f"pseudo_measurement_{config.t_variant}")
    args = [rows[:, 0:3], rows[:, 3:6], rows[:, 6:9], rows[:, 9:12], rows[:, 12:15], rows[:, 15:18], np.array(config.sigma0)]
    return dict(zip(fn.output_names, fn(*args)))


def register(data: Mapping, config: RegistrationConfig | None = None, *, progress: bool = False) -> RegistrationResult:
    """Run the registration filter over a whole data set (batch).

    ``data``: dict of arrays or pandas DataFrame following the data contract (``time`` in s and
    for prefixes ``a_``/``b_``: lat, lon, alt, heading, pitch, roll, range, bearing, elevation;
    SI units, radians). The data are validated before any estimation. With ``q_mode='fixed'``
    the whole run is one compiled loop; the adaptive mode steps row by row.
    """
    config = config or RegistrationConfig()
    time, rows = validate_data(data)
    k = len(time)
    registrar = OnlineRegistrar(config)
    if config.q_mode == "fixed":
        out = registrar._step.scan(
            k,
            _CARRY,
            {"x": registrar.x, "P": registrar.P, "info": registrar.info, "Q": registrar._q_fixed, "row": rows, "sigma0": registrar._sigma0},
            keep_last=("info_new",),
        )
        estimates, covs, info = out["x_new"], out["P_new"], out["info_new"]
        nu, S, nis = out["nu"], out["S"], out["nis"]
        if not (np.isfinite(estimates).all() and np.isfinite(covs).all()):
            raise RuntimeError("the filter produced non-finite values; check the data and the configuration")
    else:
        estimates, covs = np.empty((k, N_STATE)), np.empty((k, N_STATE, N_STATE))
        nu, S, nis = np.empty((k, 3)), np.empty((k, 3, 3)), np.empty(k)
        iterator = range(k)
        if progress:
            from tqdm import tqdm

            iterator = tqdm(iterator, desc="registering", unit="row")
        for i in iterator:
            r = registrar.update(rows[i], time=float(time[i]))
            estimates[i], covs[i], nu[i], S[i], nis[i] = r["x"], r["P"], r["nu"], r["S"], r["nis"]
        info = registrar.info

    raw_a, raw_b = _target_positions(rows, config)
    corrected_a, corrected_b = _target_positions(_corrected_rows(rows, estimates), config)
    info_final, _ = information_at_estimate(rows, estimates[-1], config)
    report = observability_report(info_final, np.array(config.prior_sigma), STATE_NAMES, STATE_LABELS, STATE_UNITS)
    return RegistrationResult(
        config=config, time=time, estimates=estimates, covariances=covs, innovations=nu,
        innovation_covariances=S, nis=nis, information=info, information_at_estimate=info_final,
        raw_difference_ecef=raw_a - raw_b, corrected_difference_ecef=corrected_a - corrected_b,
        corrected_a_ecef=corrected_a, corrected_b_ecef=corrected_b,
        observability=report,
    )
