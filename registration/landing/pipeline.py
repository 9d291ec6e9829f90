"""The whole landing pipeline for recorded or simulated tracks: time alignment of both sensors to
common fusion instants, space alignment, error transfer and fusion (Wang, Liu & Gao 2017, eqs. 5-12).

Times in s, radar ``[r m, a rad, b rad]`` in deck axes, camera ``[a, b]`` rad; R runs sharing one
pair of sensor clocks are processed together (one alignment fit per window serves every run).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.core.alignment import AlignedSamples, align
from registration.core.validation import as_float_array, check_positive
from registration.landing.checks import as_attitude
from registration.landing.fusion import FUSION_METHODS, combine, radar_only
from registration.landing.geometry import LandingGeometry
from registration.landing.transfer import CameraTransfer, RadarTransfer, transfer_camera, transfer_radar

__all__ = ["LandingConfig", "LandingResult", "fusion_instants", "process"]


@dataclass(frozen=True)
class LandingConfig:
    """Processing choices (not the scenario).

    Attributes:
        fusion_rate_hz: rate of the common fusion instants, Hz (> 0).
        degree: polynomial degree of the time-alignment fit.
        half_window_s: half-width of the time-alignment window, s.
        max_extrapolation_s: how far (s) a fusion instant may lie outside a window's samples.
        radar_clock_offset_s, camera_clock_offset_s: the sensors' clock offsets as known to the
            processing (the clock reads reference time + offset), s.
        methods: estimates to compute, a subset of :data:`FUSION_METHODS`.
    """

    fusion_rate_hz: float = 10.0
    degree: int = 2
    half_window_s: float = 0.25
    max_extrapolation_s: float = 0.0
    radar_clock_offset_s: float = 0.0
    camera_clock_offset_s: float = 0.0
    methods: tuple[str, ...] = FUSION_METHODS

    def __post_init__(self) -> None:
        for name in ("fusion_rate_hz", "half_window_s"):
            v = getattr(self, name)
            if not (np.isfinite(v) and v > 0):
                raise ValueError(f"{name}: expected a finite number > 0, got {v!r}")
        bad = [m for m in self.methods if m not in FUSION_METHODS]
        if bad:
            raise ValueError(f"methods: unknown {bad}; expected a subset of {FUSION_METHODS}")


@dataclass(frozen=True)
class LandingResult:
    """Output of :func:`process` for R runs sharing one set of sensor clocks and M fusion instants.

    Estimates are flattened run-major: index ``run * M + k`` is run ``run`` at instant ``t[k]``;
    use :meth:`per_run` to reshape any (R*M, ...) array to (R, M, ...).
    """

    t: np.ndarray
    attitude: np.ndarray
    runs: int
    radar_aligned: AlignedSamples
    camera_aligned: AlignedSamples
    radar: RadarTransfer
    camera: CameraTransfer
    estimates: dict = field(default_factory=dict)

    def per_run(self, arr: np.ndarray) -> np.ndarray:
        return arr.reshape(self.runs, self.t.size, *arr.shape[1:])


def fusion_instants(t_radar: np.ndarray, t_camera: np.ndarray, config: LandingConfig) -> np.ndarray:
    """A uniform grid (s, reference clock) at ``fusion_rate_hz`` inside both sensors' coverage."""
    lo = (
        max(t_radar[0] - config.radar_clock_offset_s, t_camera[0] - config.camera_clock_offset_s)
        + config.half_window_s
    )
    hi = (
        min(t_radar[-1] - config.radar_clock_offset_s, t_camera[-1] - config.camera_clock_offset_s)
        - config.half_window_s
    )
    if hi <= lo:
        raise ValueError(
            f"sensor data overlap too short: [{lo:.3f}, {hi:.3f}] s after removing half_window_s = "
            f"{config.half_window_s} s at each end"
        )
    step = 1.0 / config.fusion_rate_hz
    return lo + step * np.arange(int(np.floor((hi - lo) / step)) + 1)


def _runs_first(name: str, value, width: int, n_t: int) -> np.ndarray:
    """(R, n_t, width) from (n_t, width) or (R, n_t, width)."""
    arr = as_float_array(name, value)
    if arr.ndim == 2:
        arr = arr[None]
    if arr.ndim != 3 or arr.shape[1:] != (n_t, width):
        raise ValueError(
            f"{name}: expected shape ({n_t}, {width}) or (R, {n_t}, {width}) to match its timestamps, got "
            f"{arr.shape}"
        )
    return arr


def _check_tracks(t_radar, polar_rdr, sigma_rdr, t_camera, angles_cam, sigma_cam) -> tuple[np.ndarray, ...]:
    """Validated (t_r, polar (R, n, 3), sigma_r (3,), t_c, angles (R, m, 2), sigma_c (2,))."""
    t_r = as_float_array("t_radar", t_radar)
    t_c = as_float_array("t_camera", t_camera)
    if t_r.ndim != 1 or t_r.size < 2 or t_c.ndim != 1 or t_c.size < 2:
        raise ValueError("t_radar, t_camera: expected 1-D arrays of at least 2 timestamps (s)")
    pol = _runs_first("polar_rdr", polar_rdr, 3, t_r.size)
    ang = _runs_first("angles_cam", angles_cam, 2, t_c.size)
    if pol.shape[0] != ang.shape[0]:
        raise ValueError(f"polar_rdr has {pol.shape[0]} runs but angles_cam has {ang.shape[0]}")
    s_r = as_float_array("sigma_rdr", sigma_rdr)
    s_c = as_float_array("sigma_cam", sigma_cam)
    if s_r.shape != (3,) or s_c.shape != (2,):
        raise ValueError(
            f"sigma_rdr: expected 3 values [m, rad, rad], sigma_cam 2 values [rad, rad]; got {s_r.shape}, "
            f"{s_c.shape}"
        )
    check_positive("sigma_rdr", s_r, "[m, rad, rad]")
    check_positive("sigma_cam", s_c, "[rad, rad]")
    return t_r, pol, s_r, t_c, ang, s_c


def _align_runs(
    what: str,
    t: np.ndarray,
    runs_y: np.ndarray,
    tau: np.ndarray,
    clock_offset_s: float,
    angle_column: int,
    config: LandingConfig,
) -> AlignedSamples:
    """Align R runs (R, n, k) sharing one clock at ``tau``, the runs as extra columns (one fit per
    window serves every run); column ``angle_column`` of each run is an angle. ``what`` names
    the track in errors."""
    runs, n, k = runs_y.shape
    try:
        return align(
            t,
            runs_y.transpose(1, 0, 2).reshape(n, runs * k),
            tau,
            degree=config.degree,
            half_window_s=config.half_window_s,
            max_extrapolation_s=config.max_extrapolation_s,
            clock_offset_s=clock_offset_s,
            angle_columns=list(range(angle_column, runs * k, k)),
            strict=False,
        )
    except ValueError as exc:
        raise ValueError(f"{what}: {exc}") from exc


def _run_major(y: np.ndarray, runs: int, k: int) -> np.ndarray:
    """Aligned values (M, R*k) -> (R*M, k), run-major."""
    m = y.shape[0]
    return y.reshape(m, runs, k).transpose(1, 0, 2).reshape(runs * m, k)


def _align_tracks(
    t_r: np.ndarray, pol: np.ndarray, t_c: np.ndarray, ang: np.ndarray, tau: np.ndarray, config: LandingConfig
):
    """Both tracks aligned at the fusion instants ``tau``: (the radar's alignment, the camera's, the
    mask (len(tau),) of the instants both sensors can evaluate); ValueError when there is none."""
    ra = _align_runs(
        "radar track (t = t_radar, y = polar_rdr as columns [r, a, b] per run)",
        t_r,
        pol,
        tau,
        config.radar_clock_offset_s,
        1,
        config,
    )
    ca = _align_runs(
        "camera track (t = t_camera, y = angles_cam as columns [a, b] per run)",
        t_c,
        ang,
        tau,
        config.camera_clock_offset_s,
        0,
        config,
    )
    ok = ra.valid & ca.valid
    if not ok.any():
        raise ValueError(
            "no fusion instant can be evaluated by both sensors; check the timestamps and window"
        )
    return ra, ca, ok


def process(
    t_radar,
    polar_rdr,
    sigma_rdr,
    t_camera,
    angles_cam,
    sigma_cam,
    attitude_fn,
    geometry: LandingGeometry,
    config: LandingConfig = LandingConfig(),
    t_fusion=None,
) -> LandingResult:
    """Time-align, space-align, transfer errors and fuse a radar and a camera track.

    Args:
        t_radar: (n,) radar timestamps, s, radar clock.
        polar_rdr: (n, 3) or (R, n, 3) radar [r m, a rad, b rad] (deck axes); R runs share the clock.
        sigma_rdr: (3,) radar noise standard deviations [m, rad, rad] (white, independent).
        t_camera: (m,) camera timestamps, s, camera clock.
        angles_cam: (m, 2) or (R, m, 2) camera [a, b], rad.
        sigma_cam: (2,) camera noise standard deviations, rad.
        attitude_fn: callable t (s, reference clock) -> (len(t), 3) [yaw, pitch, roll] rad: the
            ship's attitude, taken as known without error (paper assumption 1).
        geometry: :class:`LandingGeometry`.
        config: :class:`LandingConfig`.
        t_fusion: fusion instants (s); default :func:`fusion_instants`.

    The aligned value's variance is the sample variance times the alignment's
    ``variance_factor`` (white noise), so the weights account for how many samples each sensor
    contributed. Instants that either sensor cannot evaluate are dropped (see ``t``).
    """
    t_r, pol, s_r, t_c, ang, s_c = _check_tracks(
        t_radar, polar_rdr, sigma_rdr, t_camera, angles_cam, sigma_cam
    )
    runs = pol.shape[0]
    tau = fusion_instants(t_r, t_c, config) if t_fusion is None else as_float_array("t_fusion", t_fusion)
    ra, ca, ok = _align_tracks(t_r, pol, t_c, ang, tau, config)
    tau = tau[ok]
    att_m = as_attitude(attitude_fn(tau))
    if att_m.shape != (tau.size, 3):
        raise ValueError(f"attitude_fn: returned shape {att_m.shape}, expected ({tau.size}, 3)")
    att = np.tile(att_m, (runs, 1))
    P_r = np.tile(ra.variance_factor[ok], runs)[:, None, None] * np.diag(s_r**2)[None]
    P_c = np.tile(ca.variance_factor[ok], runs)[:, None, None] * np.diag(s_c**2)[None]
    radar = transfer_radar(_run_major(ra.y[ok], runs, 3), P_r, att, geometry)
    camera = transfer_camera(_run_major(ca.y[ok], runs, 2), P_c, att, geometry)
    estimates = {
        method: radar_only(radar, att, geometry)
        if method == "radar"
        else combine(radar, camera, att, geometry, method)
        for method in config.methods
    }
    return LandingResult(
        t=tau,
        attitude=att_m,
        runs=runs,
        radar_aligned=ra,
        camera_aligned=ca,
        radar=radar,
        camera=camera,
        estimates=estimates,
    )
