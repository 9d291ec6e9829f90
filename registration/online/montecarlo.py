"""Monte Carlo evaluation of the online filter on the paper scenario: RMSE against the filter's
sigma and the Cramér-Rao bound, and NEES/NIS against their chi-square intervals (docs/background/online.md).

Seeds ``seed0 .. seed0 + runs - 1`` change only the noise, so the scenario's tracks, the true
plots and the Cramér-Rao bound are computed once; the runs' rows are drawn together and every
run's filter advances in one compiled call (:mod:`registration.online.runs`). A state (or sum) is
evaluated when the observability report calls it identifiable in every run. Memory: about
1.2 kB per row and run.
"""

from __future__ import annotations

import numpy as np

from registration.core.consistency import nees_interval
from registration.core.observability import observability_report
from registration.online.config import RegistrationConfig
from registration.online.contract import (
    IS_ANGLE,
    N_STATE,
    STATE_LABELS,
    STATE_NAMES,
    STATE_UNITS,
    check_times,
)
from registration.online.crlb import crlb_from_information, crlb_information, nees_series, quadratic_forms
from registration.online.mcresult import MonteCarloResult, Quantity
from registration.online.result import identifiable_combinations
from registration.online.runs import check_run_rows, filter_runs, information_at_estimates
from registration.online.scenario import paper_scenarios

__all__ = [
    "Quantity",
    "MonteCarloResult",
    "run_montecarlo",
    "collect_runs",
    "summarise_runs",
    "crlb_information",
    "nees_interval",
    "nees_series",
    "parse_sum",
]


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
    lo, hi = sorted((i, j))
    return STATE_NAMES[lo], STATE_NAMES[hi]


def _observability_counts(
    J: np.ndarray, x: np.ndarray, P: np.ndarray, prior_sigma, progress: bool
) -> tuple[dict, dict]:
    """Per run, the observability report of its information at its final estimate J[r]: how many
    runs give each state each status, and how many list each identifiable sum (runs in order)."""
    status_counts: dict = {n: {} for n in STATE_NAMES}
    combo_counts: dict = {}
    prior = np.array(prior_sigma)
    iterator = range(len(J))
    if progress:
        from registration.core.progress import progress_bar

        iterator = progress_bar(progress, "Monte Carlo observability", unit="run", iterable=iterator)
    for r in iterator:
        report = observability_report(J[r], prior, STATE_NAMES, STATE_LABELS, STATE_UNITS)
        for name, status in report.status.items():
            counts = status_counts[name]
            counts[status] = counts.get(status, 0) + 1
        for comb in identifiable_combinations(x[r], P[r], report):
            pair = tuple(STATE_NAMES[i] for i in sorted(comb["indices"]))
            combo_counts[pair] = combo_counts.get(pair, 0) + 1
    return status_counts, combo_counts


def collect_runs(
    runs: int, seed0: int, config: RegistrationConfig | None, progress: bool, scenario_kwargs: dict
) -> dict:
    """Simulate and register every seed's run: what :func:`summarise_runs` needs.

    Keys: ``time`` (K,) s; ``description`` of the scenario (without the seed); ``err`` (R, K, 12)
    estimate - truth and ``P`` (R, K, 12, 12) the filter's covariances (rad, m); ``nis`` (R, K);
    ``crlb`` (K, 12, 12) the Cramér-Rao bound; ``config`` the filter settings used;
    ``status_counts`` (state -> {status: runs}) and ``combo_counts`` ((a, b) -> runs listing the
    identifiable sum a + b), counted over the runs in seed order.
    """
    sims = paper_scenarios(range(seed0, seed0 + runs), **scenario_kwargs)
    cfg = config if config is not None else RegistrationConfig(sigma0=tuple(sims.sigma0))
    check_times(sims.time)
    check_run_rows(sims.rows)
    # the bound uses only the true plots and attitudes, the same in every run
    crlb = crlb_from_information(crlb_information(sims.scenario(0)), cfg.prior_sigma)
    out = filter_runs(cfg, sims.rows)
    x_final = out["x"][:, -1].copy()
    J = information_at_estimates(sims.rows, x_final, cfg.sigma0, cfg.t_variant)
    time, description, truth_state = np.array(sims.time), dict(sims.description), sims.truth_state
    del sims  # the rows are no longer needed
    status_counts, combo_counts = _observability_counts(
        J, x_final, out["P"][:, -1], cfg.prior_sigma, progress
    )
    err = out["x"]
    err -= truth_state  # estimate - truth, in place (the estimates are not needed any more)
    return {
        "time": time,
        "description": description,
        "err": err,
        "P": out["P"],
        "nis": out["nis"],
        "crlb": crlb,
        "config": cfg,
        "status_counts": status_counts,
        "combo_counts": combo_counts,
    }


def _direction(names) -> np.ndarray:
    d = np.zeros(N_STATE)
    d[[STATE_NAMES.index(n) for n in names]] = 1.0
    return d


def _select_quantities(runs, status_counts, combo_counts, include_weak, sums_requested) -> tuple[list, dict]:
    """Identifiable (in every run) states, then identifiable
    sums, then flagged weak states and requested sums."""
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
    for (a, b), count in sorted(
        combo_counts.items(), key=lambda t: (STATE_NAMES.index(t[0][0]), STATE_NAMES.index(t[0][1]))
    ):
        if count == runs:
            quantities.append(
                Quantity(
                    f"{a} + {b}",
                    _direction([a, b]),
                    "identifiable combination",
                    bool(IS_ANGLE[STATE_NAMES.index(a)]),
                )
            )
    have = {q.name for q in quantities}
    for a, b in sums_requested:
        name = f"{a} + {b}"
        if name not in have:
            quantities.append(
                Quantity(name, _direction([a, b]), "requested sum", bool(IS_ANGLE[STATE_NAMES.index(a)]))
            )
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
    runs_data = collect_runs(runs, seed0, config, progress, scenario_kwargs)
    return summarise_runs(
        runs_data,
        seed0,
        include_weak=include_weak,
        sums_requested=sums_requested,
        scenario_kwargs=scenario_kwargs,
    )


def summarise_runs(
    runs_data: dict,
    seed0: int,
    *,
    include_weak: bool = False,
    sums_requested=(),
    scenario_kwargs: dict | None = None,
) -> MonteCarloResult:
    """The statistics of :func:`collect_runs`'s output (``sums_requested``: (name, name) pairs)."""
    runs = len(runs_data["err"])
    scenario_kwargs = scenario_kwargs or {}
    quantities, excluded = _select_quantities(
        runs, runs_data["status_counts"], runs_data["combo_counts"], include_weak, sums_requested
    )
    err, P, crlb = runs_data["err"], runs_data["P"], runs_data["crlb"]
    m = len(quantities)
    T = np.array([q.direction for q in quantities]).reshape(m, N_STATE)
    e_q = err @ T.T  # (runs, K, m)
    var_q = quadratic_forms(P, T, diagonal=True)  # T P T^T per run and step, as numpy.einsum gives it
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
        runs=runs,
        seed0=seed0,
        config=runs_data["config"],
        scenario=description,
        scenario_kwargs={
            k: (v.__dict__ if hasattr(v, "__dict__") else v) for k, v in scenario_kwargs.items()
        },
        time=runs_data["time"],
        quantities=quantities,
        rmse=np.sqrt(np.mean(e_q**2, axis=0)),
        mean_error=np.mean(e_q, axis=0),
        filter_sigma=np.sqrt(np.mean(var_q, axis=0)),
        filter_two_sigma_mean=np.mean(2.0 * np.sqrt(np.clip(var_q, 0.0, None)), axis=0),
        crlb_sigma=np.sqrt(np.clip(np.einsum("qi,kij,qj->kq", T, crlb, T), 0.0, None)),
        nees=nees,
        nees_dof=m_nees,
        nees_interval=interval,
        nis=runs_data["nis"].mean(axis=0),
        nis_interval=nees_interval(runs, 3),
        status_counts=runs_data["status_counts"],
        combination_counts={f"{a} + {b}": c for (a, b), c in combo_counts.items()},
        excluded=excluded,
    )
