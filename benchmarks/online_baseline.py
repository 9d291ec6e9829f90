"""The online registration filter in plain NumPy, the baseline of bench_online.py (not shipped).

It composes the generated pair model per row or vectorised, so the comparison measures the
compiled loop against NumPy glue, not a second derivation."""

from __future__ import annotations

import numpy as np

from registration import _codegen
from registration.online import RegistrationConfig
from registration.online.contract import N_STATE


class NumpyFilter:
    """The registration filter of derive/kalman.py in plain NumPy: linearisation ``paper`` or
    ``fitted``, fixed Q. Only the generated pair model is used; the model is never re-derived,
    and all the filter algebra is written out here."""

    def __init__(self, config: RegistrationConfig):
        if config.linearization not in ("paper", "fitted") or config.q_mode != "fixed":
            raise ValueError("the baseline implements linearization 'paper' or 'fitted' with a fixed Q")
        self.linearization = config.linearization
        self.model = _codegen.get(f"pseudo_measurement_{config.t_variant}")
        self.sigma0 = np.array(config.sigma0)
        self.R0 = np.diag(np.square(self.sigma0))
        self.var_a, self.var_b = np.square(self.sigma0[0:3]), np.square(self.sigma0[3:6])
        self.Q = np.diag(np.square(config.q_sigma))
        self.x0 = np.zeros(N_STATE) if config.x0 is None else np.array(config.x0)
        self.P0 = np.diag(np.square(config.prior_sigma))

    @property
    def flavours(self) -> tuple[bool, ...]:
        """``vectorised`` values this linearisation admits: the fitted point depends on the state."""
        return (True, False) if self.linearization == "paper" else (False,)

    def model_rows(self, rows: np.ndarray):
        """Z (K, 3), H (K, 3, 12), M (K, 3, 6) for all rows in one vectorised call."""
        out = dict(
            zip(
                self.model.output_names,
                self.model(
                    rows[:, 0:3],
                    rows[:, 3:6],
                    rows[:, 6:9],
                    rows[:, 9:12],
                    rows[:, 12:15],
                    rows[:, 15:18],
                    self.sigma0,
                ),
            )
        )
        return out["Z"], out["H"], out["M"]

    def fitted_row(self, x: np.ndarray, P_pred: np.ndarray, row: np.ndarray, pair):
        """Innovation nu (3,), H (3, 12), R (3, 3) of the fitted linearisation for one row.

        ``pair`` is a single-point caller of the generated pseudo-measurement. Same point as
        derive/kalman.py ``_fitted_linearisation``, written here."""
        c = row.copy()  # corrected row
        c[3:9] -= x[0:6]
        c[12:18] -= x[6:12]
        Z, H, M, R, _, _ = pair(c[0:3], c[3:6], c[6:9], c[9:12], c[12:15], c[15:18], self.sigma0)
        S = H @ P_pred @ H.T + R
        v = (self.R0 @ M.T) @ np.linalg.solve(0.5 * (S + S.T), Z)  # MAP noise of the plots
        t_a, t_b = c[6:9] - v[0:3], c[15:18] - v[3:6]
        Z, H, M, R, _, _ = pair(c[0:3], c[3:6], t_a, c[9:12], c[12:15], t_b, self.sigma0)
        return Z + M @ v, H, R

    def run(self, rows: np.ndarray, vectorised: bool) -> dict:
        if vectorised and self.linearization != "paper":
            raise ValueError("only the paper linearisation can evaluate its model up front")
        fitted = self.linearization == "fitted"
        k = len(rows)
        xs, Ps = np.empty((k, N_STATE)), np.empty((k, N_STATE, N_STATE))
        nus, Ss, niss = np.empty((k, 3)), np.empty((k, 3, 3)), np.empty(k)
        x, P, info = self.x0.copy(), self.P0.copy(), np.zeros((N_STATE, N_STATE))
        Q, R0, eye, sigma0 = self.Q, self.R0, np.eye(N_STATE), self.sigma0
        pair = self.model.bind()  # single-point caller, preallocated
        if vectorised:
            Zs, Hs, Ms = self.model_rows(rows)
        for i in range(k):
            row = rows[i]
            P_pred = P + Q
            if fitted:
                nu, H, R = self.fitted_row(x, P_pred, row, pair)
            else:
                if vectorised:
                    Z, H, M = Zs[i], Hs[i], Ms[i]
                else:
                    Z, H, M, _, _, _ = pair(
                        row[0:3], row[3:6], row[6:9], row[9:12], row[12:15], row[15:18], sigma0
                    )
                R = M @ R0 @ M.T
                nu = Z - H @ x
            HP = H @ P_pred
            S = HP @ H.T + R
            S = 0.5 * (S + S.T)
            K = np.linalg.solve(S, HP).T
            x = x + K @ nu
            IKH = eye - K @ H
            P = IKH @ P_pred @ IKH.T + K @ R @ K.T
            P = 0.5 * (P + P.T)
            info = info + H.T @ np.linalg.solve(R, H)
            info = 0.5 * (info + info.T)
            xs[i], Ps[i], nus[i], Ss[i] = x, P, nu, S
            niss[i] = nu @ np.linalg.solve(S, nu)
        return {"x": xs, "P": Ps, "nu": nus, "S": Ss, "nis": niss, "info": info}
