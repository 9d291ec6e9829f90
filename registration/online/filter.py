"""The online registration filter (:class:`OnlineRegistrar`): one row or one block at a time.

Every model evaluation runs in the generated Kalman step (``derive/kalman.py``); a block with
fixed Q is one compiled loop that carries x, P and the information, so a run split into blocks
is bit for bit the run in one piece. Wang et al. 2011, the filter of eqs. (18)-(23).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from registration import _codegen
from registration.core.observability import ObservabilityReport, observability_report
from registration.online.config import RegistrationConfig
from registration.online.contract import (
    LIMITS,
    N_ROW,
    N_STATE,
    SENSOR_COLUMNS,
    SENSORS,
    STATE_LABELS,
    STATE_NAMES,
    STATE_UNITS,
    check_rows,
    check_times,
    row_error,
    row_from_mapping,
)

__all__ = ["OnlineRegistrar", "ROW_LOW", "ROW_HIGH", "STEP_CARRY"]

_OK, _OUT_OF_BOUNDS, _FAILED = (int(_codegen.StepCode[c]) for c in ("OK", "OUT_OF_BOUNDS", "FAILED"))
_ROW_SHAPE, _F64, _INF = (N_ROW,), np.dtype(np.float64), float("inf")

#: The Kalman step's carried inputs and the outputs they take from the previous step.
STEP_CARRY = {"x": "x_new", "P": "P_new", "info": "info_new"}
#: What update() returns (its keys) from the Kalman step's outputs.
_DELIVER = {"x": "x_new", "P": "P_new", "nu": "nu", "S": "S", "nis": "nis"}
#: Element-wise bounds of a row for the compiled pre-check of :meth:`OnlineRegistrar.update`: the
#: contract's LIMITS, and for ranges [smallest normal float, largest finite float] so that NaN, inf
#: and ranges <= 0 fail. A row it rejects goes to the detailed check_rows (which names the problem,
#: or accepts a positive subnormal range).
_KINDS = SENSOR_COLUMNS * len(SENSORS)
ROW_LOW = np.array([np.finfo(np.float64).tiny if k == "range" else LIMITS[k][0] for k in _KINDS])
ROW_HIGH = np.array([np.finfo(np.float64).max if k == "range" else LIMITS[k][1] for k in _KINDS])


def _empty_block() -> dict:
    return {
        "x": np.empty((0, N_STATE)),
        "P": np.empty((0, N_STATE, N_STATE)),
        "nu": np.empty((0, 3)),
        "S": np.empty((0, 3, 3)),
        "nis": np.empty(0),
        "n": 0,
    }


def _frozen(a) -> np.ndarray:
    """A float64 copy that cannot be written (the filter's state is replaced, never mutated)."""
    a = np.array(a, dtype=np.float64)
    a.flags.writeable = False
    return a


def _seconds(time, row: int) -> float:
    """``time`` as a float (s); a string, None-like or other non-number raises, naming the row."""
    if isinstance(time, (str, bytes, bool, np.bool_)):
        raise row_error(row, "time", time, "is not a number; expected seconds")
    try:
        return float(time)
    except (TypeError, ValueError) as exc:
        raise row_error(row, "time", time, "is not a number; expected seconds") from exc


def _time_follows(t: float, last) -> bool:
    """True if ``t`` (s) is finite and after ``last`` (None: any finite time); plain float tests."""
    return -_INF < t < _INF and (last is None or t > last)


class OnlineRegistrar:
    """Streaming registration: :meth:`update` takes one row, :meth:`update_block` a (K, 18) block.

    A row is a mapping with the data-contract columns (without ``time``) or an array of the
    18 values in contract order (SI units, radians). Rows are validated before the state is
    touched, so a bad row raises ValueError and leaves the filter exactly as it was.
    Attributes: ``x`` (12,) estimate, ``P`` (12, 12) covariance, ``info`` (12, 12) the information
    the filter accumulated at its linearisation points (read-only arrays: assign new values, or use
    :meth:`load_state_dict`), ``n_updates``, ``last_time`` (s).
    """

    def __init__(self, config: RegistrationConfig | None = None):
        self.config = config or RegistrationConfig()
        self._step = _codegen.get(self.config.step_name)
        # The compiled single-row stepper holding the state, made on first update(): the generated
        # module's CStepper or PyStepper (the generated callables are untyped, hence Any).
        self._stepper: Any = None
        self._advance = None  # its advance(), bound once
        # The state as read-only arrays; None after update(), when it lives in the stepper's buffers.
        self._held: dict | None = {
            "x": _frozen(self.config.x0 if self.config.x0 is not None else np.zeros(N_STATE)),
            "P": _frozen(np.diag(np.square(self.config.prior_sigma))),
            "info": _frozen(np.zeros((N_STATE, N_STATE))),
            "window": _frozen(np.empty((0, N_STATE))),  # the last q_window estimates, oldest first
        }
        self._q_window = int(self.config.q_window)
        self._q_fixed = np.diag(np.square(self.config.q_sigma))
        self._adaptive = self.config.q_mode != "fixed"
        self._sigma0 = np.array(self.config.sigma0)
        self.n_updates = 0
        self.last_time: float | None = None

    def _state(self, name: str) -> np.ndarray:
        """State ``name`` (x, P, info or window): the held array, else read back (once) from the stepper."""
        held = self._held
        if held is None:
            held = self._held = {}
        value = held.get(name)
        if value is None:
            value = held[name] = _frozen(
                self._stepper.kept() if name == "window" else self._stepper.get(name)
            )
        return value

    def _set_state(self, name: str, value) -> None:
        value = _frozen(value)
        if self._held is None:  # the state is in the stepper; the rest stays there
            self._held = {}
        self._held[name] = value
        if self._stepper is not None and name == "window":
            self._stepper.set_kept(value)
        elif self._stepper is not None:
            self._stepper.set(name, value)

    def __getstate__(self) -> dict:
        """For pickle and copy: the state as arrays, without the compiled functions (found again on load)."""
        state = dict(self.__dict__)
        state.update(
            _held={k: self._state(k) for k in ("x", "P", "info", "window")},
            _stepper=None,
            _advance=None,
            _step=None,
        )
        return state

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._step = _codegen.get(self.config.step_name)

    x = property(lambda self: self._state("x"), lambda self, v: self._set_state("x", v), doc="(12,) estimate")
    P = property(
        lambda self: self._state("P"), lambda self, v: self._set_state("P", v), doc="(12, 12) covariance"
    )
    info = property(
        lambda self: self._state("info"),
        lambda self, v: self._set_state("info", v),
        doc="(12, 12) information accumulated at the filter's linearisation points",
    )

    def process_noise(self) -> np.ndarray:
        """Q for the next step: fixed, or eqs. (21)-(22) (sample covariance of the last N estimates)."""
        if self.config.q_mode == "fixed":
            return self._q_fixed
        est = self._state("window")
        if len(est) < 2:
            return self._q_fixed
        dev = est - est.mean(axis=0)
        return dev.T @ dev / len(est) + self._q_fixed

    def _make_stepper(self):
        """The compiled stepper, loaded with the state; returns its ``advance``."""
        stepper = self._step.stepper(
            STEP_CARRY, "row", low=ROW_LOW, high=ROW_HIGH, finite=("x_new", "P_new"), deliver=_DELIVER
        )
        for name, value in (
            ("x", self.x),
            ("P", self.P),
            ("info", self.info),
            ("Q", self._q_fixed),
            ("sigma0", self._sigma0),
        ):
            stepper.set(name, value)
        stepper.keep("x_new", self._q_window)  # the window of estimates, kept by the compiled step
        stepper.set_kept(self._state("window"))
        self._stepper, self._advance = stepper, stepper.advance
        return stepper.advance

    def update(self, row, time: float | None = None) -> dict:
        """Process one row; return {'x', 'P', 'nu', 'S', 'nis'} after the update (nu in m, S in m^2).

        The returned arrays are new and the caller's: changing them does not change the filter.
        One compiled call checks the row's bounds, steps the filter and commits the state only if
        the new x and P are finite; the detailed checks run only to name a problem.
        """
        if type(row) is not np.ndarray or row.shape != _ROW_SHAPE or row.dtype is not _F64:
            row = row_from_mapping(row)
        if time is not None and not (type(time) is float and _time_follows(time, self.last_time)):
            time = self._checked_time(row, time)  # a non-float, or one that does not follow: convert or raise
        advance = self._advance or self._make_stepper()
        if self._adaptive:
            self._stepper.set("Q", self.process_noise())
        out = advance(row)
        if type(out) is int:
            out = self._refused(out, row)
        self._held = None  # the new state (and window) is in the stepper's buffers
        self.n_updates += 1
        if time is not None:
            self.last_time = time
        return out

    def _checked_time(self, row: np.ndarray, time) -> float:
        """``time`` (s) as a float after ``last_time``; else ValueError, naming a bad row first."""
        n = self.n_updates
        try:
            time = _seconds(time, n)
        except ValueError:
            check_rows(row[None, :], first_row=n)  # a bad row is named before a bad time
            raise
        if not _time_follows(time, self.last_time):
            check_rows(row[None, :], first_row=n)
            check_times(np.array([time], dtype=float), n, self.last_time)
        return time

    def _refused(self, code: int, values: np.ndarray) -> dict:
        """After a step the stepper refused: raise, naming the problem, or step again when only its
        conservative bounds objected (a subnormal range the detailed check accepts); the results."""
        n, stepper = self.n_updates, self._stepper
        if code == _OUT_OF_BOUNDS:
            check_rows(values[None, :], first_row=n)  # raises, naming the row and column
            code = stepper.step(values, check=False)
        if code == _FAILED:
            raise RuntimeError(
                f"row {n}: the generated step {self.config.step_name} returned an error; state left unchanged"
            )
        if code != _OK:
            raise RuntimeError(f"row {n}: the filter step produced non-finite values; state left unchanged")
        return stepper.results()

    def update_block(
        self, rows: np.ndarray, times: np.ndarray | None = None, *, partial: bool = False
    ) -> dict:
        """Process a (K, 18) block of rows; the same arithmetic as K calls of :meth:`update`.

        Returns ``x (K, 12)``, ``P (K, 12, 12)``, ``nu (K, 3)``, ``S (K, 3, 3)``, ``nis (K,)`` and
        ``n``, the rows taken. A step whose result is not finite is never committed: with
        ``partial=False`` it raises RuntimeError and the state is left as it was before the block;
        with ``partial=True`` the rows before it are committed and returned (``n`` < K).
        """
        rows = np.ascontiguousarray(rows, dtype=np.float64)
        if rows.ndim != 2 or rows.shape[1] != N_ROW:
            raise ValueError(f"rows: expected shape (K, {N_ROW}) in contract order, got {rows.shape}")
        k = rows.shape[0]
        check_rows(rows, first_row=self.n_updates)
        if times is not None:
            times = np.asarray(times, dtype=np.float64)
            if times.shape != (k,):
                raise ValueError(f"times: expected shape ({k},), got {times.shape}")
            check_times(times, self.n_updates, self.last_time)
        if k == 0:
            return _empty_block()
        if self.config.q_mode == "fixed":
            return self._scan_block(rows, times, partial)
        return self._step_block(rows, times, partial)

    def _scan_block(self, rows: np.ndarray, times, partial: bool) -> dict:
        """Fixed Q: one compiled loop; only the last information matrix is kept unless a row fails."""
        k = len(rows)
        inputs = {
            "x": self.x,
            "P": self.P,
            "info": self.info,
            "Q": self._q_fixed,
            "row": rows,
            "sigma0": self._sigma0,
        }
        out = self._step.scan(k, STEP_CARRY, inputs, keep_last=("info_new",))
        x, P = out["x_new"], out["P_new"]
        ok = np.isfinite(x).all(axis=1) & np.isfinite(P).all(axis=(1, 2))
        if ok.all() and np.isfinite(out["info_new"]).all():
            n, info = k, out["info_new"]
        else:  # rare: find the first failing row with every step's information
            out = self._step.scan(k, STEP_CARRY, inputs)
            ok &= np.isfinite(out["info_new"]).all(axis=(1, 2))
            n = int(np.argmax(~ok))
            info = out["info_new"][n - 1] if n else self.info
            if not partial:
                raise RuntimeError(
                    f"row {self.n_updates + n}: the filter step produced non-finite values; state left "
                    "unchanged"
                )
        if n:
            window = np.concatenate([self._state("window"), x[:n]])[-self._q_window :]
            self.x, self.P, self.info = x[n - 1].copy(), P[n - 1].copy(), np.array(info)
            self._set_state("window", window)
            self.n_updates += n
            if times is not None:
                self.last_time = float(times[n - 1])
        return {"x": x[:n], "P": P[:n], "nu": out["nu"][:n], "S": out["S"][:n], "nis": out["nis"][:n], "n": n}

    def _step_block(self, rows: np.ndarray, times, partial: bool) -> dict:
        """Adaptive Q: Q depends on the previous estimates, so the rows go one compiled step at a time."""
        k = len(rows)
        saved = self.state_dict()
        res = {
            "x": np.empty((k, N_STATE)),
            "P": np.empty((k, N_STATE, N_STATE)),
            "nu": np.empty((k, 3)),
            "S": np.empty((k, 3, 3)),
            "nis": np.empty(k),
        }
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
            for key, arr in res.items():
                arr[i] = r[key]
        return {**{key: arr[:n] for key, arr in res.items()}, "n": n}

    def state_dict(self) -> dict:
        """Everything that determines the next steps (plain numpy arrays and numbers; copies)."""
        return {
            "x": self.x.copy(),
            "P": self.P.copy(),
            "info": self.info.copy(),
            "window": self._state("window").copy(),
            "n_updates": int(self.n_updates),
            "last_time": self.last_time,
        }

    def load_state_dict(self, state: dict) -> None:
        """Restore a :meth:`state_dict` (shapes are checked; values must be finite)."""
        x = np.array(state["x"], dtype=np.float64)
        P = np.array(state["P"], dtype=np.float64)
        info = np.array(state["info"], dtype=np.float64)
        window = np.array(state["window"], dtype=np.float64).reshape(-1, N_STATE)
        if x.shape != (N_STATE,) or P.shape != (N_STATE, N_STATE) or info.shape != (N_STATE, N_STATE):
            raise ValueError("state: x must be (12,), P and info (12, 12)")
        if len(window) > self._q_window:
            raise ValueError(
                f"state: window holds {len(window)} estimates, more than q_window = {self._q_window}"
            )
        if not (
            np.isfinite(x).all()
            and np.isfinite(P).all()
            and np.isfinite(info).all()
            and np.isfinite(window).all()
        ):
            raise ValueError("state: non-finite values")
        self.x, self.P, self.info = x, P, info
        self._set_state("window", window)
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
        return observability_report(
            self.info, np.array(self.config.prior_sigma), STATE_NAMES, STATE_LABELS, STATE_UNITS
        )
