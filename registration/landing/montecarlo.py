"""Monte Carlo evaluation of the landing fusion: independent noise realisations of one approach,
per-run statistics in bins of true range to the touchdown point (position errors in m, NEES,
polar errors about the camera) and the variance amplification ratios on the noise-free track."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from registration.core.angles import wrap_angle
from registration.landing.pipeline import LandingConfig, LandingResult
from registration.landing.scenario import LandingScenario
from registration.landing.simulation import run_once, simulate
from registration.landing.transfer import transfer_camera, transfer_radar, variance_ratios

__all__ = ["MonteCarloResult", "default_bin_edges", "monte_carlo", "regroup"]


@dataclass
class MonteCarloResult:
    """Per-bin statistics over R runs (bins of true range to the touchdown point).

    Attributes:
        bin_edges_m: (B + 1,) range-bin edges, m.
        methods: estimates evaluated.
        sse: method -> (R, B) sum of squared 3-D position errors per run and bin, m^2.
        count: (B,) fusion instants per run in each bin (identical for every run).
        nees_sum: method -> (R, B) per run, sum over the bin's instants of e^T P_td^-1 e (expected 3
            per instant when the predicted covariance P_td is right).
        polar_sse: method -> (B, 3) sums of squared polar errors about the camera (m^2, rad^2).
        t: (M,) fusion instants, s.  range_m: (M,) true range to the touchdown point.
        example: one run's detailed arrays for plots (errors and predicted sigmas).
        ratios: variance amplification ratios on the noise-free track: "radar" (M, 3), "camera" (M, 2).
        attitude: (M, 3) rad.
    """

    bin_edges_m: np.ndarray
    methods: tuple[str, ...]
    sse: dict
    count: np.ndarray
    nees_sum: dict
    polar_sse: dict
    t: np.ndarray
    range_m: np.ndarray
    example: dict
    ratios: dict
    attitude: np.ndarray
    runs: int = 0

    def rmse(self, method: str) -> np.ndarray:
        """(B,) pooled RMSE of the 3-D position per bin, m (NaN for empty bins)."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.sqrt(self.sse[method].sum(axis=0) / (self.count * self.runs))

    def polar_rmse(self, method: str) -> np.ndarray:
        """(B, 3) pooled RMSE of [r m, a rad, b rad] about the camera per bin."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.sqrt(self.polar_sse[method] / (self.count[:, None] * self.runs))

    def nees(self, method: str) -> np.ndarray:
        """(B,) mean normalised estimation error squared (3 when the covariance is right)."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return self.nees_sum[method].sum(axis=0) / (self.count * self.runs)

    def paired_z(self, better: str, worse: str) -> np.ndarray:
        """(B,) z-score of mean over runs of (MSE_worse - MSE_better) per bin; runs are independent."""
        d = (self.sse[worse] - self.sse[better]) / np.maximum(self.count, 1)
        with np.errstate(invalid="ignore", divide="ignore"):
            return d.mean(axis=0) / (d.std(axis=0, ddof=1) / np.sqrt(d.shape[0]))


def default_bin_edges(scenario: LandingScenario, width_m: float = 500.0) -> np.ndarray:
    """Range-bin edges (m) every ``width_m`` from 0 to the approach's start range rounded up."""
    if not width_m > 0:
        raise ValueError(f"bin width: expected > 0 m, got {width_m!r}")
    top = np.ceil(scenario.approach.start_range_m / width_m) * width_m
    return np.arange(0.0, top + width_m / 2, width_m)


@dataclass(frozen=True)
class _Truth:
    """The truth at the fusion instants and each instant's range bin (one-hot (M, B))."""

    t: np.ndarray
    p_td: np.ndarray
    polar_ctd: np.ndarray
    range_m: np.ndarray
    onehot: np.ndarray

    @classmethod
    def at(cls, scenario: LandingScenario, t: np.ndarray, edges: np.ndarray) -> _Truth:
        nb = edges.size - 1
        p_true = scenario.truth_td(t)
        range_m = np.linalg.norm(p_true, axis=1)
        which = np.digitize(range_m, edges) - 1
        inside = (which >= 0) & (which < nb)
        onehot = np.zeros((t.size, nb))
        onehot[np.flatnonzero(inside), which[inside]] = 1.0
        return cls(t=t, p_td=p_true, polar_ctd=scenario.truth_ctd(t), range_m=range_m, onehot=onehot)


def _accumulate(res: LandingResult, truth: _Truth, sse: dict, nees_sum: dict, polar_sse: dict) -> None:
    """Add one batch's per-run position SSE and NEES sums (rows) and polar SSE (sums) per bin."""
    for m in sse:
        est = res.estimates[m]
        e = res.per_run(est.p_td) - truth.p_td[None]
        sse[m] = np.vstack([sse[m], (e**2).sum(axis=2) @ truth.onehot])
        Pinv_e = np.linalg.solve(res.per_run(est.P_td), e[..., None])[..., 0]
        nees_sum[m] = np.vstack([nees_sum[m], (e * Pinv_e).sum(axis=2) @ truth.onehot])
        ep = res.per_run(est.polar_ctd) - truth.polar_ctd[None]
        ep[..., 1] = wrap_angle(ep[..., 1])
        polar_sse[m] += np.einsum("rmk,mb->bk", ep**2, truth.onehot)


def _example(res: LandingResult, truth: _Truth, methods: tuple[str, ...]) -> dict:
    """The first run's polar errors, predicted polar sigmas and position errors per method."""
    return {
        m: {
            "polar_error": res.per_run(res.estimates[m].polar_ctd)[0] - truth.polar_ctd,
            "polar_sigma": np.sqrt(np.diagonal(res.per_run(res.estimates[m].P_polar)[0], axis1=1, axis2=2)),
            "position_error": res.per_run(res.estimates[m].p_td)[0] - truth.p_td,
        }
        for m in methods
    }


def _noise_free_ratios(scenario: LandingScenario, t: np.ndarray, att: np.ndarray) -> dict:
    """Variance amplification ratios of both sensors' raw covariances on the noise-free track."""
    g = scenario.geometry
    rt = transfer_radar(scenario.truth_radar(t), np.diag(scenario.radar.sigma**2), att, g)
    ct = transfer_camera(scenario.truth_camera(t), np.diag(scenario.camera.sigma**2), att, g)
    return {"radar": variance_ratios(rt.P_rdr, rt.P_ctd), "camera": variance_ratios(ct.P_cam, ct.P_ctd)}


def _batches(runs: int, runs_per_batch: int, progress: bool):
    batches = [min(runs_per_batch, runs - s) for s in range(0, runs, runs_per_batch)]
    if not progress:
        return batches
    from registration.core.progress import progress_bar

    return progress_bar(progress, "landing Monte Carlo", unit="batch", iterable=batches)


def monte_carlo(
    scenario: LandingScenario,
    config: LandingConfig | None = None,
    runs: int = 100,
    seed: int = 1,
    bin_edges_m=None,
    runs_per_batch: int = 25,
    progress: bool = False,
) -> MonteCarloResult:
    """Simulate and process ``runs`` noise realisations; accumulate per-bin statistics.

    Every run is an independent realisation of all sensor noise (same clocks and trajectory), so
    per-run quantities are i.i.d. across runs: that is what :meth:`MonteCarloResult.paired_z` uses.
    """
    config = scenario.config() if config is None else config
    edges = default_bin_edges(scenario) if bin_edges_m is None else np.asarray(bin_edges_m, dtype=float)
    if edges.ndim != 1 or edges.size < 2 or np.any(np.diff(edges) <= 0):
        raise ValueError("bin_edges_m: expected an increasing 1-D array of at least 2 edges (m)")
    rng = np.random.default_rng(seed)
    methods = tuple(config.methods)
    nb = edges.size - 1
    sse = {m: np.zeros((0, nb)) for m in methods}
    nees_sum = {m: np.zeros((0, nb)) for m in methods}
    polar_sse = {m: np.zeros((nb, 3)) for m in methods}
    truth: _Truth | None = None
    example: dict = {}
    for nrun in _batches(runs, runs_per_batch, progress):
        res = run_once(simulate(scenario, nrun, rng), config)
        if truth is None:
            truth = _Truth.at(scenario, res.t, edges)
        elif res.t.size != truth.t.size or np.any(res.t != truth.t):
            raise RuntimeError("fusion instants changed between batches")  # clocks are deterministic
        _accumulate(res, truth, sse, nees_sum, polar_sse)
        if not example:
            example = _example(res, truth, methods)
    assert truth is not None  # at least one run: the first batch sets it
    att = scenario.attitude(truth.t)
    return MonteCarloResult(
        bin_edges_m=edges,
        methods=methods,
        sse=sse,
        count=truth.onehot.sum(axis=0),
        nees_sum=nees_sum,
        polar_sse=polar_sse,
        t=truth.t,
        range_m=truth.range_m,
        example=example,
        ratios=_noise_free_ratios(scenario, truth.t, att),
        attitude=att,
        runs=runs,
    )


def regroup(mc: MonteCarloResult, edges: np.ndarray) -> MonteCarloResult:
    """Merge fine bins into coarser ones whose edges are a subset of the fine edges."""
    fine = mc.bin_edges_m
    idx = [int(np.argmin(np.abs(fine - e))) for e in edges]
    if any(abs(fine[i] - e) > 1e-6 for i, e in zip(idx, edges)):
        raise ValueError("coarse bin edges must be fine bin edges")
    sl = list(zip(idx[:-1], idx[1:]))

    def merge(a, axis):
        return np.stack([a.take(range(i, j), axis=axis).sum(axis=axis) for i, j in sl], axis=axis)

    return replace(
        mc,
        bin_edges_m=np.asarray(edges, dtype=float),
        sse={m: merge(v, 1) for m, v in mc.sse.items()},
        count=merge(mc.count, 0),
        nees_sum={m: merge(v, 1) for m, v in mc.nees_sum.items()},
        polar_sse={m: merge(v, 0) for m, v in mc.polar_sse.items()},
    )
