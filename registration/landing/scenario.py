"""The carrier-landing scenario (SPEC section 4) and its Monte Carlo evaluation.

Default scenario (the project's reading of seed 002; every number is an assumption, documented
in docs/landing.md, and every one can be changed through the dataclasses or the CLI):

- Aircraft on a 3.5 deg glide slope along the angled-deck centreline, from 4 km (distance to the
  touchdown point along the path) to touchdown, at 70 m/s *ground* speed. The glide path is a
  straight line in the ``mtd`` frame (the touchdown frame at zero attitude, moving with the ship's
  mean velocity), so the closure speed on the deck is what remains after the ship's own 15 m/s
  (about 55 m/s here).
- Carrier at 15 m/s; attitude about the mean heading: yaw 0.5 deg (15 s), pitch 1 deg (8 s),
  roll 2 deg (12 s), sinusoids with zero phase at t = 0; known without error (paper assumption 1).
- Angled deck 9 deg. Deck positions (deck frame, m from the ship's motion centre, taken at the
  waterline amidships): touchdown point (-8, -105, 20); centreline camera 25 m forward of it on the
  angled-deck centreline; radar on the starboard side (38, -40, 35).
- Radar 20 Hz, sigma_r = 3 m, sigma_a = sigma_b = 1 mrad; its clock is the reference.
- Camera 25 Hz, sigma_a = sigma_b = 0.3 mrad; its clock reads 4 ms ahead of the reference.
- Noise white Gaussian, independent between sensors, components and samples; no biases.

Units: SI and radians inside; the CLI converts its ``_deg``/``_mrad``/``_ms`` options.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from registration import _codegen as _loader
from registration.landing.model import (
    FUSION_METHODS,
    LandingConfig,
    LandingGeometry,
    LandingResult,
    deck_to_touchdown_rotation,
    process,
    transfer_camera,
    transfer_radar,
    variance_ratios,
)

__all__ = [
    "ShipMotion",
    "RadarModel",
    "CameraModel",
    "Approach",
    "LandingScenario",
    "LandingSimulation",
    "MonteCarloResult",
    "default_geometry",
    "default_scenario",
    "simulate",
    "monte_carlo",
]


@dataclass(frozen=True)
class ShipMotion:
    """Ship speed (m/s) and sinusoidal attitude about the mean heading (rad, s)."""

    speed_mps: float = 15.0
    yaw_amplitude_rad: float = float(np.radians(0.5))
    yaw_period_s: float = 15.0
    yaw_phase_rad: float = 0.0
    pitch_amplitude_rad: float = float(np.radians(1.0))
    pitch_period_s: float = 8.0
    pitch_phase_rad: float = 0.0
    roll_amplitude_rad: float = float(np.radians(2.0))
    roll_period_s: float = 12.0
    roll_phase_rad: float = 0.0

    def __post_init__(self) -> None:
        for name in ("yaw_period_s", "pitch_period_s", "roll_period_s"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name}: expected a period > 0 s, got {getattr(self, name)!r}")
        for name in ("yaw_amplitude_rad", "pitch_amplitude_rad", "roll_amplitude_rad"):
            v = getattr(self, name)
            if not 0 <= v < np.pi / 4:
                raise ValueError(f"{name}: expected 0 <= amplitude < pi/4 rad, got {v!r} (degrees passed as radians?)")
        if not self.speed_mps >= 0:
            raise ValueError(f"speed_mps: expected >= 0 m/s, got {self.speed_mps!r}")

    def attitude(self, t) -> np.ndarray:
        """[yaw deviation, pitch, roll] (N, 3) in rad at times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        cols = []
        for a, T, ph in (
            (self.yaw_amplitude_rad, self.yaw_period_s, self.yaw_phase_rad),
            (self.pitch_amplitude_rad, self.pitch_period_s, self.pitch_phase_rad),
            (self.roll_amplitude_rad, self.roll_period_s, self.roll_phase_rad),
        ):
            cols.append(a * np.sin(2 * np.pi * t / T + ph))
        return np.stack(cols, axis=1)


@dataclass(frozen=True)
class RadarModel:
    """Landing-guidance radar: rate (Hz), clock offset (s; its clock reads true + offset), noise."""

    rate_hz: float = 20.0
    clock_offset_s: float = 0.0
    first_sample_s: float = 0.0
    sigma_range_m: float = 3.0
    sigma_azimuth_rad: float = 1.0e-3
    sigma_elevation_rad: float = 1.0e-3

    @property
    def sigma(self) -> np.ndarray:
        return np.array([self.sigma_range_m, self.sigma_azimuth_rad, self.sigma_elevation_rad])


@dataclass(frozen=True)
class CameraModel:
    """Centreline camera: rate (Hz), clock offset (s; its clock reads true + offset), angle noise (rad)."""

    rate_hz: float = 25.0
    clock_offset_s: float = 0.004
    first_sample_s: float = 0.0
    sigma_azimuth_rad: float = 0.3e-3
    sigma_elevation_rad: float = 0.3e-3

    @property
    def sigma(self) -> np.ndarray:
        return np.array([self.sigma_azimuth_rad, self.sigma_elevation_rad])


@dataclass(frozen=True)
class Approach:
    """Straight glide path in the mtd frame along the angled-deck centreline.

    ``start_range_m`` and ``end_range_m`` are distances to the touchdown point along the path (m);
    ``ground_speed_mps`` is the aircraft's speed over the sea (m/s); ``lateral_offset_m`` and
    ``height_offset_m`` shift the whole path sideways (mtd y) and up (mtd z), 0 by default.
    """

    glide_slope_rad: float = float(np.radians(3.5))
    ground_speed_mps: float = 70.0
    start_range_m: float = 4000.0
    end_range_m: float = 0.0
    lateral_offset_m: float = 0.0
    height_offset_m: float = 0.0

    def __post_init__(self) -> None:
        if not 0 <= self.glide_slope_rad < np.radians(30):
            raise ValueError(f"glide_slope_rad: expected [0, 0.52) rad, got {self.glide_slope_rad!r}")
        if not self.start_range_m > self.end_range_m >= 0:
            raise ValueError(f"start_range_m > end_range_m >= 0 (m) required, got {self.start_range_m!r}, {self.end_range_m!r}")
        if not self.ground_speed_mps > 0:
            raise ValueError(f"ground_speed_mps: expected > 0 m/s, got {self.ground_speed_mps!r}")


def default_geometry(angled_deck_rad: float = float(np.radians(9.0)), camera_ahead_m: float = 25.0) -> LandingGeometry:
    """The default deck layout (see the module docstring); the camera sits ``camera_ahead_m``
    forward of the touchdown point on the angled-deck centreline."""
    l_td = np.array([-8.0, -105.0, 20.0])
    R_td_deck0 = deck_to_touchdown_rotation(np.zeros(3), LandingGeometry(angled_deck_rad, l_td, l_td, l_td))[0]
    forward_deck = R_td_deck0.T @ np.array([-1.0, 0.0, 0.0])  # -x_td: forward along the angled deck
    return LandingGeometry(
        angled_deck_rad=angled_deck_rad,
        l_touchdown_deck_m=l_td,
        l_radar_deck_m=np.array([38.0, -40.0, 35.0]),
        l_camera_deck_m=l_td + camera_ahead_m * forward_deck,
    )


@dataclass(frozen=True)
class LandingScenario:
    """Everything the simulation needs; change any field with ``dataclasses.replace``."""

    ship: ShipMotion = field(default_factory=ShipMotion)
    geometry: LandingGeometry = field(default_factory=default_geometry)
    radar: RadarModel = field(default_factory=RadarModel)
    camera: CameraModel = field(default_factory=CameraModel)
    approach: Approach = field(default_factory=Approach)

    @property
    def glide_direction_mtd(self) -> np.ndarray:
        """Unit vector from the touchdown point up the glide path (aft and up), mtd axes."""
        g = self.approach.glide_slope_rad
        return np.array([np.cos(g), 0.0, np.sin(g)])

    @property
    def closure_speed_mps(self) -> float:
        """Aircraft speed relative to the ship's mean motion along the path, m/s.

        Solves ``|v_ship + c d| = ground speed`` for c > 0 with d the unit vector towards touchdown.
        """
        R_td_deck0 = deck_to_touchdown_rotation(np.zeros(3), self.geometry)[0]
        v_ship_mtd = R_td_deck0 @ np.array([0.0, self.ship.speed_mps, 0.0])  # level = deck at zero attitude
        d = -self.glide_direction_mtd
        dv = float(d @ v_ship_mtd)
        disc = dv**2 - self.ship.speed_mps**2 + self.approach.ground_speed_mps**2
        c = -dv + np.sqrt(disc) if disc >= 0 else -1.0
        if not c > 0:
            raise ValueError(
                f"ground_speed_mps = {self.approach.ground_speed_mps} m/s cannot close on a ship at "
                f"{self.ship.speed_mps} m/s along this path"
            )
        return float(c)

    @property
    def duration_s(self) -> float:
        return (self.approach.start_range_m - self.approach.end_range_m) / self.closure_speed_mps

    def attitude(self, t) -> np.ndarray:
        """Ship attitude [yaw, pitch, roll] (N, 3), rad, at true times t (s)."""
        return self.ship.attitude(t)

    def truth_mtd(self, t) -> np.ndarray:
        """Aircraft position (N, 3), m, in the mean touchdown frame at true times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        s = self.approach.start_range_m - self.closure_speed_mps * t
        p = s[:, None] * self.glide_direction_mtd[None, :]
        p[:, 1] += self.approach.lateral_offset_m
        p[:, 2] += self.approach.height_offset_m
        return p

    def truth_td(self, t) -> np.ndarray:
        """Aircraft position (N, 3), m, in the touchdown frame (which moves with the deck)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        g = self.geometry
        return _loader.get("landing_mtd2td")(self.truth_mtd(t), self.attitude(t), g.angled_deck_rad, g.l_touchdown_deck_m)[0]

    def truth_radar(self, t) -> np.ndarray:
        """Noise-free radar polar [r, a, b] (N, 3) at true times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        g = self.geometry
        return _loader.get("landing_td2radar")(self.truth_td(t), self.attitude(t), g.angled_deck_rad, g.d_radar_deck_m)[0]

    def truth_camera(self, t) -> np.ndarray:
        """Noise-free camera angles [a, b] (N, 2) at true times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        g = self.geometry
        return _loader.get("landing_td2camera")(self.truth_td(t), self.attitude(t), g.angled_deck_rad, g.d_camera_deck_m)[0]

    def truth_ctd(self, t) -> np.ndarray:
        """True polar [r, a, b] (N, 3) about the camera in td axes at true times t (s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        g = self.geometry
        return _loader.get("landing_td2ctd")(self.truth_td(t), self.attitude(t), g.angled_deck_rad, g.d_camera_deck_m)[0]

    def config(self, **overrides) -> LandingConfig:
        """A processing configuration that knows this scenario's clock offsets (calibrated clocks)."""
        base = dict(radar_clock_offset_s=self.radar.clock_offset_s, camera_clock_offset_s=self.camera.clock_offset_s)
        base.update(overrides)
        return LandingConfig(**base)


def default_scenario() -> LandingScenario:
    """SPEC section 4's default approach (see the module docstring)."""
    return LandingScenario()


@dataclass(frozen=True)
class LandingSimulation:
    """Noisy sensor tracks of R runs sharing one pair of clocks.

    ``t_radar``/``t_camera`` are the timestamps as each sensor's clock reads them (s);
    ``true_t_radar``/``true_t_camera`` the true sampling instants.
    """

    scenario: LandingScenario
    t_radar: np.ndarray
    true_t_radar: np.ndarray
    polar_rdr: np.ndarray
    t_camera: np.ndarray
    true_t_camera: np.ndarray
    angles_cam: np.ndarray


def _sample_times(rate_hz: float, first_s: float, duration_s: float) -> np.ndarray:
    if not rate_hz > 0:
        raise ValueError(f"rate_hz: expected > 0 Hz, got {rate_hz!r}")
    n = int(np.floor((duration_s - first_s) * rate_hz + 1e-9)) + 1
    if n < 2:
        raise ValueError(f"the approach ({duration_s:.3g} s) holds fewer than 2 samples at {rate_hz} Hz")
    return first_s + np.arange(n) / rate_hz


def simulate(scenario: LandingScenario, runs: int = 1, rng: np.random.Generator | int | None = 0) -> LandingSimulation:
    """Simulate ``runs`` independent noise realisations of the scenario's approach."""
    if not (isinstance(runs, (int, np.integer)) and runs >= 1):
        raise ValueError(f"runs: expected an integer >= 1, got {runs!r}")
    rng = np.random.default_rng(rng)
    T = scenario.duration_s
    tr = _sample_times(scenario.radar.rate_hz, scenario.radar.first_sample_s, T)
    tc = _sample_times(scenario.camera.rate_hz, scenario.camera.first_sample_s, T)
    pr = scenario.truth_radar(tr)
    pc = scenario.truth_camera(tc)
    polar = pr[None] + rng.standard_normal((runs, *pr.shape)) * scenario.radar.sigma
    angles = pc[None] + rng.standard_normal((runs, *pc.shape)) * scenario.camera.sigma
    return LandingSimulation(
        scenario=scenario,
        t_radar=tr + scenario.radar.clock_offset_s,
        true_t_radar=tr,
        polar_rdr=polar,
        t_camera=tc + scenario.camera.clock_offset_s,
        true_t_camera=tc,
        angles_cam=angles,
    )


def run_once(sim: LandingSimulation, config: LandingConfig) -> LandingResult:
    """Process one simulation (all its runs) with ``config``."""
    sc = sim.scenario
    return process(
        sim.t_radar, sim.polar_rdr, sc.radar.sigma, sim.t_camera, sim.angles_cam, sc.camera.sigma,
        sc.attitude, sc.geometry, config,
    )


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
    if not width_m > 0:
        raise ValueError(f"bin width: expected > 0 m, got {width_m!r}")
    top = np.ceil(scenario.approach.start_range_m / width_m) * width_m
    return np.arange(0.0, top + width_m / 2, width_m)


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
    t = None
    example: dict = {}
    batches = [min(runs_per_batch, runs - s) for s in range(0, runs, runs_per_batch)]
    it = batches
    if progress:
        from tqdm import tqdm

        it = tqdm(batches, desc="landing Monte Carlo", unit="batch", leave=False)
    for nrun in it:
        sim = simulate(scenario, nrun, rng)
        res = run_once(sim, config)
        if t is None:
            t = res.t
            p_true = scenario.truth_td(t)
            polar_true = scenario.truth_ctd(t)
            range_m = np.linalg.norm(p_true, axis=1)
            which = np.digitize(range_m, edges) - 1
            inside = (which >= 0) & (which < nb)
            onehot = np.zeros((t.size, nb))
            onehot[np.flatnonzero(inside), which[inside]] = 1.0
            count = onehot.sum(axis=0)
        elif res.t.size != t.size or np.any(res.t != t):
            raise RuntimeError("fusion instants changed between batches")  # clocks are deterministic
        for m in methods:
            est = res.estimates[m]
            e = res.per_run(est.p_td) - p_true[None]
            sse[m] = np.vstack([sse[m], (e**2).sum(axis=2) @ onehot])
            Pinv_e = np.linalg.solve(res.per_run(est.P_td), e[..., None])[..., 0]
            nees_sum[m] = np.vstack([nees_sum[m], (e * Pinv_e).sum(axis=2) @ onehot])
            ep = res.per_run(est.polar_ctd) - polar_true[None]
            ep[..., 1] = np.mod(ep[..., 1] + np.pi, 2 * np.pi) - np.pi
            polar_sse[m] += np.einsum("rmk,mb->bk", ep**2, onehot)
        if not example:
            example = {
                m: {
                    "polar_error": res.per_run(res.estimates[m].polar_ctd)[0] - polar_true,
                    "polar_sigma": np.sqrt(np.diagonal(res.per_run(res.estimates[m].P_polar)[0], axis1=1, axis2=2)),
                    "position_error": res.per_run(res.estimates[m].p_td)[0] - p_true,
                }
                for m in methods
            }
    # variance amplification ratios on the noise-free track (raw sensor covariances)
    att = scenario.attitude(t)
    g = scenario.geometry
    rt = transfer_radar(scenario.truth_radar(t), np.diag(scenario.radar.sigma**2), att, g)
    ct = transfer_camera(scenario.truth_camera(t), np.diag(scenario.camera.sigma**2), att, g)
    ratios = {"radar": variance_ratios(rt.P_rdr, rt.P_ctd), "camera": variance_ratios(ct.P_cam, ct.P_ctd)}
    return MonteCarloResult(
        bin_edges_m=edges, methods=methods, sse=sse, count=count, nees_sum=nees_sum, polar_sse=polar_sse,
        t=t, range_m=range_m, example=example, ratios=ratios, attitude=att, runs=runs,
    )


def with_overrides(scenario: LandingScenario, **sections) -> LandingScenario:
    """``with_overrides(sc, ship={"roll_amplitude_rad": 0.05})``: replace fields section by section."""
    out = scenario
    for name, fields in sections.items():
        if fields:
            out = replace(out, **{name: replace(getattr(out, name), **fields)})
    return out


__all__ += ["run_once", "default_bin_edges", "with_overrides", "FUSION_METHODS"]
