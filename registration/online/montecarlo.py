"""Monte Carlo evaluation of the online filter on the paper scenario: RMSE against the filter's
sigma and the Cramér-Rao bound, and NEES/NIS against their chi-square intervals (docs/online.md).

Seeds ``seed0 .. seed0 + runs - 1`` change only the noise; a state (or sum) is evaluated when the
observability report calls it identifiable in every run. Memory: about 1.2 kB per row and run.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.online.batch import register
from registration.core.consistency import nees_interval
from registration.online.crlb import crlb_from_information, crlb_information, nees_series
from registration.online.config import RegistrationConfig
from registration.online.scenario import paper_scenario
from registration.online.contract import IS_ANGLE, N_STATE, STATE_LABELS, STATE_NAMES

__all__ = ["Quantity", "MonteCarloResult", "run_montecarlo", "crlb_information", "nees_interval", "nees_series", "parse_sum"]



def parse_sum(text: str) -> tuple[str, str]:
    """``"dC_a+dq_a"`` -> ``("dC_a", "dq_a")`` (two state names of the same unit)."""
    parts = [p.strip() for p in str(text).split("+")]
    if len(parts) != 2 or any(p not in STATE_NAMES for p in parts):
        raise ValueError(f"sum {text!r}: expected NAME+NAME with names from {list(STATE_NAMES)}")
    i, j = (STATE_NAMES.index(p) for p in parts)
    if i == j:
        raise ValueError(f"sum {text!r}: the two states must differ")
    if IS_ANGLE[i] != IS_ANGLE[j]:
        raise ValueError(f"sum {text!r}: cannot add an angle and a range")
    return tuple(STATE_NAMES[k] for k in sorted((i, j)))


# --------------------------------------------------------------------------- result
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
        if self.nees is None:
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
        return {"dof_per_run": 3, "chi2_dof": 3 * self.runs, "interval_95": [lo, hi], "time_mean": float(np.mean(self.nis)),
                "fraction_of_steps_inside": float(np.mean(inside))}

    def final_rows(self) -> list[dict]:
        """Per quantity at the last step: RMSE, filter sigma, 2 sigma, sqrt(CRLB), bias (SI units)."""
        rows = []
        for j, q in enumerate(self.quantities):
            rows.append({
                "name": q.name, "kind": q.kind, "unit_si": "rad" if q.angle else "m",
                "rmse": float(self.rmse[-1, j]), "filter_sigma": float(self.filter_sigma[-1, j]),
                "filter_two_sigma_mean": float(self.filter_two_sigma_mean[-1, j]),
                "crlb_sigma": float(self.crlb_sigma[-1, j]), "mean_error": float(self.mean_error[-1, j]),
                "rmse_over_crlb": float(self.rmse[-1, j] / self.crlb_sigma[-1, j]),
                "rmse_over_filter_sigma": float(self.rmse[-1, j] / self.filter_sigma[-1, j]),
            })
        return rows

    def table(self) -> str:
        cfg = self.config
        motion = self.scenario.get("ship_motion")
        lines = [
            f"Monte Carlo: {self.runs} runs of the paper scenario (seeds {self.seed0}..{self.seed0 + self.runs - 1}), "
            f"{len(self.time)} rows each; ships {'level (paper)' if motion is None else 'pitching/rolling'}; "
            f"angle noise {np.degrees(self.scenario['angle_sigma_rad']):.3g} deg; "
            f"filter: linearization {cfg.linearization}, Q {cfg.q_mode}, T {cfg.t_variant} "
            f"(data simulated with T {self.scenario.get('t_variant', 'standard')})",
            "Final step. RMSE over runs; filter sigma = rms over runs of the filter's own sigma, 2σ = its mean 2-sigma;",
            "CRLB = Cramér-Rao bound with the prior, from H, R at the true values; bias = mean error over runs.",
        ]
        head = f"  {'quantity':<16}{'unit':<5}{'RMSE':>10}{'σ filter':>10}{'2σ filter':>11}{'√CRLB':>10}{'RMSE/√CRLB':>11}{'bias':>10}  kind"
        lines.append(head)
        for row, q in zip(self.final_rows(), self.quantities):
            k = q.scale
            lines.append(
                f"  {q.name:<16}{q.unit:<5}{row['rmse'] * k:10.4g}{row['filter_sigma'] * k:10.4g}"
                f"{row['filter_two_sigma_mean'] * k:11.4g}{row['crlb_sigma'] * k:10.4g}{row['rmse_over_crlb']:11.2f}"
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
                f"NEES of the identifiable part ({', '.join(ns['quantities'])}; m = {ns['dof_per_run']} per run): "
                f"final {ns['final']:.3g}, time mean {ns['time_mean']:.3g}; 95% interval [{lo:.3g}, {hi:.3g}] "
                f"(M avgNEES ~ chi2({ns['chi2_dof']})); inside at {100 * ns['fraction_of_steps_inside']:.0f}% of steps -> {ns['verdict']}"
            )
        else:
            lines.append("NEES: no identifiable quantity, nothing to test")
        nis = self.nis_summary()
        lo, hi = nis["interval_95"]
        lines.append(
            f"NIS (3 per run): time mean {nis['time_mean']:.3g}; 95% interval [{lo:.3g}, {hi:.3g}] (chi2({nis['chi2_dof']})); "
            f"inside at {100 * nis['fraction_of_steps_inside']:.0f}% of steps"
        )
        return "\n".join(lines)

    def to_json(self) -> dict:
        series = []
        for j, q in enumerate(self.quantities):
            series.append({
                "name": q.name, "kind": q.kind, "unit": "rad" if q.angle else "m",
                "direction": {STATE_NAMES[i]: float(q.direction[i]) for i in np.flatnonzero(q.direction)},
                "rmse": self.rmse[:, j].tolist(), "mean_error": self.mean_error[:, j].tolist(),
                "filter_sigma": self.filter_sigma[:, j].tolist(),
                "filter_two_sigma_mean": self.filter_two_sigma_mean[:, j].tolist(),
                "crlb_sigma": self.crlb_sigma[:, j].tolist(),
            })
        return {
            "runs": self.runs, "seeds": [self.seed0, self.seed0 + self.runs - 1],
            "units": "SI (rad, m)",
            "config": self.config.to_json(), "scenario": self.scenario, "scenario_kwargs": self.scenario_kwargs,
            "final": self.final_rows(),
            "nees": None if self.nees is None else {**self.nees_summary(), "series": self.nees.tolist()},
            "nis": {**self.nis_summary(), "series": self.nis.tolist()},
            "observability": {"status_counts": self.status_counts, "identifiable_combination_counts": self.combination_counts,
                              "excluded": self.excluded, "rule": "reported when identifiable in every run"},
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
        fig, axes = plt.subplots(nrows, ncols, figsize=(5.2 * ncols, 3.9 * nrows), squeeze=False, layout="constrained")
        axes = axes.ravel()
        t = self.time
        for ax, q, j in zip(axes, self.quantities, range(len(self.quantities))):
            k = q.scale
            ax.semilogy(t, self.rmse[:, j] * k, color="k", lw=1.8, label=f"RMSE ({self.runs} runs)")
            ax.semilogy(t, self.filter_sigma[:, j] * k, color="tab:blue", lw=1.5, ls="--", label="filter σ (rms)")
            ax.semilogy(t, self.filter_two_sigma_mean[:, j] * k, color="tab:blue", lw=1.0, ls=":", label="filter 2σ (mean)")
            ax.semilogy(t, self.crlb_sigma[:, j] * k, color="tab:red", lw=1.5, ls="-.", label="√CRLB (with prior)")
            ax.semilogy(t, np.abs(self.mean_error[:, j]) * k, color="0.55", lw=0.9, label="|mean error| (bias)")
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
        if self.nees is not None:
            lo, hi = self.nees_interval
            ax.plot(t, self.nees, color="k", lw=1.2, label=f"avg NEES (m = {self.nees_dof} per run)")
            ax.axhspan(lo, hi, color="tab:green", alpha=0.15, label=f"NEES 95% interval [{lo:.2f}, {hi:.2f}]")
            ax.axhline(self.nees_dof, color="tab:green", lw=0.8)
        lo, hi = self.nis_interval
        ax.plot(t, self.nis, color="tab:purple", lw=0.8, alpha=0.8, label="avg NIS (3 per run)")
        ax.axhspan(lo, hi, color="tab:purple", alpha=0.08, label=f"NIS 95% interval [{lo:.2f}, {hi:.2f}]")
        top = max(np.percentile(self.nis, 99), self.nees_dof + 1, *(np.percentile(self.nees, 99),) if self.nees is not None else ())
        ax.set_ylim(0, 1.15 * top)
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


# --------------------------------------------------------------------------- runner
def _collect_runs(runs: int, seed0: int, config, progress: bool, scenario_kwargs: dict) -> dict:
    """Register every seed's scenario; keep errors, covariances, NIS, the mean CRLB and status counts."""
    iterator = range(runs)
    if progress:
        from tqdm import tqdm

        iterator = tqdm(iterator, desc="Monte Carlo", unit="run")
    out: dict = {"status_counts": {n: {} for n in STATE_NAMES}, "combo_counts": {}}
    for r in iterator:
        sc = paper_scenario(seed=seed0 + r, **scenario_kwargs)
        cfg = config if config is not None else RegistrationConfig(sigma0=tuple(sc.sigma0))
        res = register(sc.data, cfg)
        if r == 0:
            k = len(res.time)
            out.update(time=res.time, description=dict(sc.description), err=np.empty((runs, k, N_STATE)),
                       P=np.empty((runs, k, N_STATE, N_STATE)), nis=np.empty((runs, k)),
                       crlb=np.zeros((k, N_STATE, N_STATE)))
        out["err"][r] = res.estimates - sc.truth_state
        out["P"][r] = res.covariances
        out["nis"][r] = res.nis
        out["crlb"] += crlb_from_information(crlb_information(sc), cfg.prior_sigma)
        for name, status in res.observability.status.items():
            counts = out["status_counts"][name]
            counts[status] = counts.get(status, 0) + 1
        for comb in res.identifiable_combinations():
            pair = tuple(STATE_NAMES[i] for i in sorted(comb["indices"]))
            out["combo_counts"][pair] = out["combo_counts"].get(pair, 0) + 1
    out["config"] = cfg
    out["crlb"] = out["crlb"] / runs
    return out


def _direction(names) -> np.ndarray:
    d = np.zeros(N_STATE)
    d[[STATE_NAMES.index(n) for n in names]] = 1.0
    return d


def _select_quantities(runs, status_counts, combo_counts, include_weak, sums_requested) -> tuple[list, dict]:
    """Identifiable (in every run) states, then identifiable sums, then flagged weak states and requested sums."""
    quantities: list[Quantity] = []
    excluded = {}
    for i, name in enumerate(STATE_NAMES):
        counts = status_counts[name]
        if counts.get("identifiable", 0) == runs:
            quantities.append(Quantity(name, _direction([name]), "identifiable", bool(IS_ANGLE[i])))
        elif include_weak and counts.get("not identifiable", 0) == 0:
            quantities.append(Quantity(name, _direction([name]), "weak", bool(IS_ANGLE[i])))
        else:
            excluded[name] = ", ".join(f"{s}: {c}" for s, c in sorted(counts.items()))
    for (a, b), count in sorted(combo_counts.items(), key=lambda t: (STATE_NAMES.index(t[0][0]), STATE_NAMES.index(t[0][1]))):
        if count == runs:
            quantities.append(Quantity(f"{a} + {b}", _direction([a, b]), "identifiable combination", bool(IS_ANGLE[STATE_NAMES.index(a)])))
    have = {q.name for q in quantities}
    for a, b in sums_requested:
        name = f"{a} + {b}"
        if name not in have:
            quantities.append(Quantity(name, _direction([a, b]), "requested sum", bool(IS_ANGLE[STATE_NAMES.index(a)])))
            have.add(name)
    return quantities, excluded


def run_montecarlo(
    runs: int = 100,
    seed0: int = 0,
    config: RegistrationConfig | None = None,
    *,
    include_weak: bool = False,
    extra_sums=(),
    progress: bool = False,
    **scenario_kwargs,
) -> MonteCarloResult:
    """Run the paper scenario with seeds ``seed0 .. seed0 + runs - 1`` and collect the statistics.

    ``config``: the filter settings; by default :class:`RegistrationConfig` with ``sigma0`` set
    to the noise the scenario is simulated with. ``scenario_kwargs`` go to
    :func:`paper_scenario` (e.g. ``angle_sigma``, ``ship_motion``, ``n_steps``; ``seed`` is set
    here). ``include_weak`` also reports states that are weak (never ``not identifiable``) in
    every run; ``extra_sums`` adds requested sums such as ``"dC_a+dq_a"``. Both are flagged and
    stay out of the NEES.
    """
    runs = int(runs)
    if runs < 2:
        raise ValueError(f"runs: need at least 2 Monte Carlo runs, got {runs}")
    if "seed" in scenario_kwargs:
        raise ValueError("pass the first seed as seed0, not in the scenario arguments")
    sums_requested = [parse_sum(s) if isinstance(s, str) else parse_sum("+".join(s)) for s in extra_sums]
    runs_data = _collect_runs(runs, seed0, config, progress, scenario_kwargs)
    quantities, excluded = _select_quantities(runs, runs_data["status_counts"], runs_data["combo_counts"],
                                              include_weak, sums_requested)
    err, P, crlb = runs_data["err"], runs_data["P"], runs_data["crlb"]
    m = len(quantities)
    T = np.array([q.direction for q in quantities]).reshape(m, N_STATE)
    e_q = err @ T.T  # (runs, K, m)
    var_q = np.einsum("qi,rkij,qj->rkq", T, P, T, optimize=True)
    in_nees = np.array([q.in_nees for q in quantities], dtype=bool)
    m_nees = int(in_nees.sum())
    if m_nees:
        nees = nees_series(err, P, T[in_nees]).mean(axis=0)
        interval = nees_interval(runs, m_nees)
    else:
        nees, interval = None, None
    description = runs_data["description"]
    combo_counts = runs_data["combo_counts"]
    description.pop("seed", None)
    return MonteCarloResult(
        runs=runs, seed0=seed0, config=runs_data["config"], scenario=description,
        scenario_kwargs={k: (v.__dict__ if hasattr(v, "__dict__") else v) for k, v in scenario_kwargs.items()},
        time=runs_data["time"], quantities=quantities, rmse=np.sqrt(np.mean(e_q**2, axis=0)),
        mean_error=np.mean(e_q, axis=0), filter_sigma=np.sqrt(np.mean(var_q, axis=0)),
        filter_two_sigma_mean=np.mean(2.0 * np.sqrt(np.clip(var_q, 0.0, None)), axis=0),
        crlb_sigma=np.sqrt(np.clip(np.einsum("qi,kij,qj->kq", T, crlb, T), 0.0, None)),
        nees=nees, nees_dof=m_nees, nees_interval=interval,
        nis=runs_data["nis"].mean(axis=0), nis_interval=nees_interval(runs, 3),
        status_counts=runs_data["status_counts"], combination_counts={f"{a} + {b}": c for (a, b), c in combo_counts.items()},
        excluded=excluded,
    )
