"""What a Monte Carlo evaluation of the online filter produced (:class:`MonteCarloResult`): RMSE
against the filter's sigma and the Cramér-Rao bound, NEES and NIS against their chi-square
intervals, as a table, JSON and a figure (all values in SI units: rad, m; docs/background/online.md).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.online.config import RegistrationConfig
from registration.online.contract import STATE_LABELS, STATE_NAMES

__all__ = ["Quantity", "MonteCarloResult"]


@dataclass
class Quantity:
    """A reported direction ``c^T x`` of the state: one state or the sum of two."""

    name: str
    direction: np.ndarray  # (12,)
    kind: str  # "identifiable", "identifiable combination", "weak", "requested sum"
    angle: bool

    @property
    def in_nees(self) -> bool:
        return self.kind in ("identifiable", "identifiable combination")

    @property
    def unit(self) -> str:
        return "deg" if self.angle else "m"

    @property
    def scale(self) -> float:
        """SI -> display (deg or m)."""
        return np.degrees(1.0) if self.angle else 1.0

    @property
    def label(self) -> str:
        idx = np.flatnonzero(self.direction)
        if len(idx) == 1:
            return f"{STATE_LABELS[idx[0]]} ({self.name})"
        return f"{' + '.join(STATE_LABELS[i] for i in idx)}"


@dataclass
class MonteCarloResult:
    """Monte Carlo statistics; series have a leading time axis K; all values in SI units (rad, m)."""

    runs: int
    seed0: int
    config: RegistrationConfig
    scenario: dict  # description of the seed0 scenario (without the seed-specific part)
    scenario_kwargs: dict
    time: np.ndarray  # (K,)
    quantities: list[Quantity]
    rmse: np.ndarray  # (K, m)
    mean_error: np.ndarray  # (K, m) mean over runs of estimate - truth (bias)
    filter_sigma: np.ndarray  # (K, m) sqrt(mean over runs of c^T P c)
    filter_two_sigma_mean: np.ndarray  # (K, m) mean over runs of 2 sqrt(c^T P c)
    crlb_sigma: np.ndarray  # (K, m) sqrt(c^T CRLB c)
    nees: np.ndarray | None  # (K,) run-averaged NEES of the identifiable part
    nees_dof: int  # m: identifiable dimensions per run
    nees_interval: tuple[float, float] | None
    nis: np.ndarray  # (K,) run-averaged NIS
    nis_interval: tuple[float, float]
    status_counts: dict  # state -> {status: number of runs}
    combination_counts: dict  # "a + b" -> number of runs listing it as identifiable
    excluded: dict = field(default_factory=dict)  # state -> why it is not reported

    # -- summaries
    @property
    def nees_quantities(self) -> list[Quantity]:
        return [q for q in self.quantities if q.in_nees]

    def nees_summary(self) -> dict | None:
        if self.nees is None or self.nees_interval is None:  # both None: no quantity in the NEES
            return None
        lo, hi = self.nees_interval
        final = float(self.nees[-1])
        inside = (self.nees >= lo) & (self.nees <= hi)
        if final > hi:
            verdict = "INCONSISTENT: optimistic (errors larger than the filter's covariance claims)"
        elif final < lo:
            verdict = "INCONSISTENT: pessimistic (filter covariance larger than the errors)"
        else:
            verdict = "consistent"
        return {
            "dof_per_run": self.nees_dof,
            "chi2_dof": self.runs * self.nees_dof,
            "interval_95": [lo, hi],
            "final": final,
            "time_mean": float(np.mean(self.nees)),
            "fraction_of_steps_inside": float(np.mean(inside)),
            "verdict": verdict,
            "quantities": [q.name for q in self.nees_quantities],
        }

    def nis_summary(self) -> dict:
        lo, hi = self.nis_interval
        inside = (self.nis >= lo) & (self.nis <= hi)
        return {
            "dof_per_run": 3,
            "chi2_dof": 3 * self.runs,
            "interval_95": [lo, hi],
            "time_mean": float(np.mean(self.nis)),
            "fraction_of_steps_inside": float(np.mean(inside)),
        }

    def final_rows(self) -> list[dict]:
        """Per quantity at the last step: RMSE, filter sigma, 2 sigma, sqrt(CRLB), bias (SI units)."""
        rows = []
        for j, q in enumerate(self.quantities):
            rows.append(
                {
                    "name": q.name,
                    "kind": q.kind,
                    "unit_si": "rad" if q.angle else "m",
                    "rmse": float(self.rmse[-1, j]),
                    "filter_sigma": float(self.filter_sigma[-1, j]),
                    "filter_two_sigma_mean": float(self.filter_two_sigma_mean[-1, j]),
                    "crlb_sigma": float(self.crlb_sigma[-1, j]),
                    "mean_error": float(self.mean_error[-1, j]),
                    "rmse_over_crlb": float(self.rmse[-1, j] / self.crlb_sigma[-1, j]),
                    "rmse_over_filter_sigma": float(self.rmse[-1, j] / self.filter_sigma[-1, j]),
                }
            )
        return rows

    def table(self) -> str:
        cfg = self.config
        motion = self.scenario.get("ship_motion")
        lines = [
            f"Monte Carlo: {self.runs} runs of the paper scenario (seeds "
            f"{self.seed0}..{self.seed0 + self.runs - 1}), {len(self.time)} rows each; ships "
            f"{'level (paper)' if motion is None else 'pitching/rolling'}; angle noise "
            f"{np.degrees(self.scenario['angle_sigma_rad']):.3g} deg; filter: linearization "
            f"{cfg.linearization}, Q {cfg.q_mode}, T {cfg.t_variant} (data simulated with T "
            f"{self.scenario.get('t_variant', 'standard')})",
            "Final step. RMSE over runs; filter sigma = rms over runs of the filter's own sigma, 2σ = its "
            "mean 2-sigma;",
            "CRLB = Cramér-Rao bound with the prior, from H, R at the true values; bias = mean error over "
            "runs.",
        ]
        head = (
            "  "
            f"{'quantity':<16}{'unit':<5}{'RMSE':>10}{'σ filter':>10}{'2σ filter':>11}{'√CRLB':>10}"
            f"{'RMSE/√CRLB':>11}{'bias':>10}  kind"
        )
        lines.append(head)
        for row, q in zip(self.final_rows(), self.quantities):
            k = q.scale
            lines.append(
                f"  {q.name:<16}{q.unit:<5}{row['rmse'] * k:10.4g}{row['filter_sigma'] * k:10.4g}"
                f"{row['filter_two_sigma_mean'] * k:11.4g}{row['crlb_sigma'] * k:10.4g}"
                f"{row['rmse_over_crlb']:11.2f}"
                f"{row['mean_error'] * k:10.3g}  {q.kind}"
            )
        if not self.quantities:
            lines.append("  (no quantity is identifiable in every run)")
        if self.excluded:
            lines.append("  not reported (not identifiable in every run; status counts over runs):")
            for name, why in self.excluded.items():
                lines.append(f"    {name:<10} {why}")
        ns = self.nees_summary()
        if ns is not None:
            lo, hi = ns["interval_95"]
            lines.append(
                f"NEES of the identifiable part ({', '.join(ns['quantities'])}; m = {ns['dof_per_run']} per "
                f"run): final {ns['final']:.3g}, time mean {ns['time_mean']:.3g}; 95% interval [{lo:.3g}, "
                f"{hi:.3g}] (M avgNEES ~ chi2({ns['chi2_dof']})); inside at "
                f"{100 * ns['fraction_of_steps_inside']:.0f}% of steps -> {ns['verdict']}"
            )
        else:
            lines.append("NEES: no identifiable quantity, nothing to test")
        nis = self.nis_summary()
        lo, hi = nis["interval_95"]
        lines.append(
            f"NIS (3 per run): time mean {nis['time_mean']:.3g}; 95% interval [{lo:.3g}, {hi:.3g}] "
            f"(chi2({nis['chi2_dof']})); inside at {100 * nis['fraction_of_steps_inside']:.0f}% of steps"
        )
        return "\n".join(lines)

    def to_json(self) -> dict:
        nees = self.nees_summary()
        series = []
        for j, q in enumerate(self.quantities):
            series.append(
                {
                    "name": q.name,
                    "kind": q.kind,
                    "unit": "rad" if q.angle else "m",
                    "direction": {STATE_NAMES[i]: float(q.direction[i]) for i in np.flatnonzero(q.direction)},
                    "rmse": self.rmse[:, j].tolist(),
                    "mean_error": self.mean_error[:, j].tolist(),
                    "filter_sigma": self.filter_sigma[:, j].tolist(),
                    "filter_two_sigma_mean": self.filter_two_sigma_mean[:, j].tolist(),
                    "crlb_sigma": self.crlb_sigma[:, j].tolist(),
                }
            )
        return {
            "runs": self.runs,
            "seeds": [self.seed0, self.seed0 + self.runs - 1],
            "units": "SI (rad, m)",
            "config": self.config.to_json(),
            "scenario": self.scenario,
            "scenario_kwargs": self.scenario_kwargs,
            "final": self.final_rows(),
            "nees": None if nees is None or self.nees is None else {**nees, "series": self.nees.tolist()},
            "nis": {**self.nis_summary(), "series": self.nis.tolist()},
            "observability": {
                "status_counts": self.status_counts,
                "identifiable_combination_counts": self.combination_counts,
                "excluded": self.excluded,
                "rule": "reported when identifiable in every run",
            },
            "time": self.time.tolist(),
            "series": series,
        }

    # -- plot
    def plot(self, path) -> None:
        """RMSE, filter sigma (rms and mean 2-sigma) and sqrt(CRLB) against time, one log panel
        per quantity, plus the run-averaged NEES and NIS with their 95 % intervals."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        n_panels = len(self.quantities) + 1
        ncols = min(3, n_panels)
        nrows = int(np.ceil(n_panels / ncols))
        fig, axes = plt.subplots(
            nrows, ncols, figsize=(5.2 * ncols, 3.9 * nrows), squeeze=False, layout="constrained"
        )
        axes = axes.ravel()
        t = self.time
        for ax, q, j in zip(axes, self.quantities, range(len(self.quantities))):
            k = q.scale
            ax.semilogy(t, self.rmse[:, j] * k, color="k", lw=1.8, label=f"RMSE ({self.runs} runs)")
            ax.semilogy(
                t, self.filter_sigma[:, j] * k, color="tab:blue", lw=1.5, ls="--", label="filter σ (rms)"
            )
            ax.semilogy(
                t,
                self.filter_two_sigma_mean[:, j] * k,
                color="tab:blue",
                lw=1.0,
                ls=":",
                label="filter 2σ (mean)",
            )
            ax.semilogy(
                t, self.crlb_sigma[:, j] * k, color="tab:red", lw=1.5, ls="-.", label="√CRLB (with prior)"
            )
            ax.semilogy(
                t, np.abs(self.mean_error[:, j]) * k, color="0.55", lw=0.9, label="|mean error| (bias)"
            )
            lows = np.concatenate([self.rmse[:, j], self.filter_sigma[:, j], self.crlb_sigma[:, j]]) * k
            highs = np.concatenate([self.rmse[:, j], self.filter_two_sigma_mean[:, j]]) * k
            ax.set_ylim(0.5 * np.min(lows[lows > 0]), 1.3 * np.max(highs))  # the bias line may dip to zero
            flag = "" if q.in_nees else f"  [{q.kind}]"
            ax.set_title(f"{q.name}{flag}", fontsize=11)
            ax.set_xlabel("time (s)")
            ax.set_ylabel(q.unit)
            ax.grid(True, which="both", alpha=0.3)
        if self.quantities:
            axes[0].legend(fontsize=8, loc="upper right", framealpha=0.9)
        ax = axes[len(self.quantities)]
        if self.nees is not None and self.nees_interval is not None:
            lo, hi = self.nees_interval
            ax.plot(t, self.nees, color="k", lw=1.2, label=f"avg NEES (m = {self.nees_dof} per run)")
            ax.axhspan(lo, hi, color="tab:green", alpha=0.15, label=f"NEES 95% interval [{lo:.2f}, {hi:.2f}]")
            ax.axhline(self.nees_dof, color="tab:green", lw=0.8)
        lo, hi = self.nis_interval
        ax.plot(t, self.nis, color="tab:purple", lw=0.8, alpha=0.8, label="avg NIS (3 per run)")
        ax.axhspan(lo, hi, color="tab:purple", alpha=0.08, label=f"NIS 95% interval [{lo:.2f}, {hi:.2f}]")
        top = max(
            np.percentile(self.nis, 99),
            self.nees_dof + 1,
            *(np.percentile(self.nees, 99),) if self.nees is not None else (),
        )
        ax.set_ylim(0, 1.7 * top)  # the upper part for the legend, clear of the curves
        ax.set_title("consistency (identifiable part)", fontsize=11)
        ax.set_xlabel("time (s)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, loc="upper right", framealpha=0.9)
        for extra in axes[n_panels:]:
            extra.set_visible(False)
        cfg = self.config
        motion = "level ships" if self.scenario.get("ship_motion") is None else "pitching/rolling ships"
        fig.suptitle(
            f"Monte Carlo, {self.runs} runs, {motion}: RMSE vs filter σ vs Cramér-Rao bound "
            f"(linearization {cfg.linearization}, Q {cfg.q_mode}, T {cfg.t_variant})",
            fontsize=12,
        )
        fig.savefig(path, dpi=110)
        plt.close(fig)
