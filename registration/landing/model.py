"""Radar/camera fusion for carrier landing (seed 002): space alignment, error transfer, fusion.

Frames (full definitions with sign conventions in ``derive/landing.py`` and ``docs/landing.md``):

- ``deck``: ship-fixed; origin at the ship's motion centre; x starboard, y bow, z deck normal.
- ``level``: origin at the motion centre, x starboard / y bow along the *mean* heading, z up;
  ``R_level_deck = Rz(yaw) Rx(pitch) Ry(roll)``; attitude = [yaw deviation, pitch, roll] (rad),
  positive yaw turns the bow to starboard, positive pitch lifts the bow, positive roll puts the
  starboard side down.
- ``td``: origin at the ideal touchdown point (deck-fixed, so it moves with the ship's motion);
  level axes: x horizontal aft along the angled-deck centreline (towards the approaching
  aircraft), z up, y = z x x. ``M = R_td_deck = T_A(phi_c) T_L R_level_deck`` (eqs. 7-8).
- ``rdr``: radar polar ``[r, a, b]`` (m, rad, rad) about the radar in deck axes; a counter-clockwise
  from starboard towards the bow, b above the deck plane (dead astern: a = -pi/2).
- ``cam``: camera angles ``[a, b]`` (rad) about the camera, deck-fixed axes equal to the td axes
  at zero attitude (x aft along the angled-deck centreline, z deck normal).
- ``ctd``: camera-centred td axes. Fusion works in its polar coordinates ``[r, a, b]``.

Every transform and Jacobian comes from the generated functions ``landing_*`` (derived in sympy);
this module only does linear algebra on them: covariance products and inverse-variance weights.
Arrays are vectorised over a leading axis of N instants. SI units and radians throughout.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration import _codegen as _loader
from registration.core.alignment import AlignedSamples, align
from registration.core.validation import as_float_array, check_finite, check_positive, check_range

__all__ = [
    "LandingGeometry",
    "RadarTransfer",
    "CameraTransfer",
    "PositionEstimate",
    "LandingConfig",
    "LandingResult",
    "FUSION_METHODS",
    "deck_to_touchdown_rotation",
    "radar_to_touchdown",
    "transfer_radar",
    "transfer_camera",
    "variance_ratios",
    "radar_only",
    "combine",
    "process",
]

#: ways to combine the camera-centred radar polar point with the camera angles
#: ``radar``: radar only; ``camera``: camera angles with the radar range; ``paper``: eq. (12),
#: range from the radar, each angle inverse-variance weighted with its own variance;
#: ``information``: the joint linear minimum-variance update of [r, a, b] with both camera angles
#: (uses the radar's range-angle correlations, so it can also improve the range).
FUSION_METHODS = ("radar", "camera", "paper", "information")


def _vec3(name: str, value) -> np.ndarray:
    arr = as_float_array(name, value)
    if arr.shape != (3,):
        raise ValueError(f"{name}: expected 3 numbers (m, deck axes), got shape {arr.shape}")
    check_finite(name, arr, "m")
    return arr


@dataclass(frozen=True)
class LandingGeometry:
    """Known deck geometry (the paper's assumptions 2 and 3).

    Attributes:
        angled_deck_rad: angle between the angled-deck centreline and the ship's centreline,
            rad, positive when the landing area's forward end points to port (US carriers ~0.16).
        l_touchdown_deck_m: ideal touchdown point, deck frame, m from the motion centre.
        l_radar_deck_m: radar phase centre, deck frame, m from the motion centre.
        l_camera_deck_m: camera optical centre, deck frame, m from the motion centre.
    """

    angled_deck_rad: float
    l_touchdown_deck_m: np.ndarray
    l_radar_deck_m: np.ndarray
    l_camera_deck_m: np.ndarray

    def __post_init__(self) -> None:
        a = as_float_array("angled_deck_rad", self.angled_deck_rad)
        check_range("angled_deck_rad", a, -np.pi / 4, np.pi / 4, "rad (angled-deck angle)", angle=True)
        object.__setattr__(self, "angled_deck_rad", float(a))
        for name in ("l_touchdown_deck_m", "l_radar_deck_m", "l_camera_deck_m"):
            object.__setattr__(self, name, _vec3(name, getattr(self, name)))

    @property
    def d_radar_deck_m(self) -> np.ndarray:
        """Radar minus touchdown point, deck axes (m)."""
        return self.l_radar_deck_m - self.l_touchdown_deck_m

    @property
    def d_camera_deck_m(self) -> np.ndarray:
        """Camera minus touchdown point, deck axes (m)."""
        return self.l_camera_deck_m - self.l_touchdown_deck_m


def _attitude(attitude) -> np.ndarray:
    att = as_float_array("attitude", attitude)
    if att.ndim == 1:
        att = att.reshape(1, 3) if att.shape == (3,) else att
    if att.ndim != 2 or att.shape[1] != 3:
        raise ValueError(f"attitude: expected shape (3,) or (N, 3) [yaw, pitch, roll] in rad, got {att.shape}")
    check_range("attitude", att, -np.pi / 2, np.pi / 2, "rad ([yaw deviation, pitch, roll])", angle=True)
    return att


def _polar(name: str, value, width: int) -> np.ndarray:
    arr = as_float_array(name, value)
    if arr.ndim == 1:
        arr = arr.reshape(1, -1)
    if arr.ndim != 2 or arr.shape[1] != width:
        what = "[r m, a rad, b rad]" if width == 3 else "[a rad, b rad]"
        raise ValueError(f"{name}: expected shape ({width},) or (N, {width}) {what}, got {arr.shape}")
    check_finite(name, arr, "m / rad")
    if width == 3:
        check_positive(f"{name}[:, 0]", arr[:, 0], "m (range)")
        angles = arr[:, 1:]
    else:
        angles = arr
    check_range(f"{name} azimuth", angles[:, 0], -2 * np.pi, 2 * np.pi, "rad", angle=True)
    check_range(f"{name} elevation", angles[:, 1], -np.pi / 2, np.pi / 2, "rad", angle=True)
    return arr


def _covariance(name: str, value, n: int, width: int) -> np.ndarray:
    P = as_float_array(name, value)
    if P.shape == (width, width):
        P = np.broadcast_to(P, (n, width, width))
    if P.shape != (n, width, width):
        raise ValueError(f"{name}: expected shape ({width}, {width}) or ({n}, {width}, {width}), got {P.shape}")
    check_finite(name, P, "m^2 / rad^2")
    diag = np.diagonal(P, axis1=1, axis2=2)
    if (diag <= 0).any():
        i = tuple(int(v) for v in np.argwhere(diag <= 0)[0])
        raise ValueError(f"{name}: variance at (point, component) {i} must be > 0 (units m^2 for range, rad^2 for angles)")
    return np.asarray(P, dtype=np.float64)


def _same_n(**arrays: np.ndarray) -> int:
    ns = {k: a.shape[0] for k, a in arrays.items()}
    big = {v for v in ns.values() if v != 1}
    if len(big) > 1:
        raise ValueError(f"point counts differ: {ns}; give one row or N rows each")
    return big.pop() if big else 1


def _wrap(a: np.ndarray) -> np.ndarray:
    """Wrap angles to (-pi, pi]."""
    w = np.mod(a + np.pi, 2 * np.pi) - np.pi
    return np.where(w == -np.pi, np.pi, w)


def _sandwich(J: np.ndarray, P: np.ndarray) -> np.ndarray:
    return J @ P @ np.swapaxes(J, -1, -2)


# --------------------------------------------------------------------------- space alignment
def deck_to_touchdown_rotation(attitude, geometry: LandingGeometry) -> np.ndarray:
    """M = R_td_deck (N, 3, 3) = T_A(phi_c) T_L R_level_deck(yaw, pitch, roll) (eq. 8); attitude in rad."""
    att = _attitude(attitude)
    return _loader.get("landing_deck2td_rotation")(att, geometry.angled_deck_rad)[0]


def radar_to_touchdown(polar_rdr, attitude, geometry: LandingGeometry) -> tuple[np.ndarray, np.ndarray]:
    """Eq. (7): radar polar ``[r m, a rad, b rad]`` (deck axes) -> target ``p_td`` (N, 3) m in the
    touchdown frame, and ``J = dp_td/dpolar_rdr = M A`` (N, 3, 3)."""
    pol = _polar("polar_rdr", polar_rdr, 3)
    att = _attitude(attitude)
    _same_n(polar_rdr=pol, attitude=att)
    p_td, _, _, _, J = _loader.get("landing_radar2td")(pol, att, geometry.angled_deck_rad, geometry.d_radar_deck_m)
    return p_td, J


# --------------------------------------------------------------------------- error transfer
@dataclass(frozen=True)
class RadarTransfer:
    """Radar measurement moved to the camera-centred polar frame (eqs. 7-11), N points.

    Attributes:
        polar_rdr: (N, 3) the radar measurement [r m, a rad, b rad], deck axes.
        polar_ctd: (N, 3) [r m, a rad, b rad] about the camera, td axes (the paper's r_RL, a_RL, b_RL).
        P_ctd: (N, 3, 3) its covariance ``BMA P_R (BMA)^T`` (m^2, m rad, rad^2).
        P_rdr: (N, 3, 3) the radar covariance that was transferred.
        A: (N, 3, 3) du_deck/dpolar_rdr at the radar (eq. 8).
        M: (N, 3, 3) R_td_deck.
        B: (N, 3, 3) dpolar_ctd/dv_ctd at the camera (eq. 9).
        BMA: (N, 3, 3) dpolar_ctd/dpolar_rdr (eq. 10).
        p_td: (N, 3) the radar point in the touchdown frame, m.
    """

    polar_rdr: np.ndarray
    polar_ctd: np.ndarray
    P_ctd: np.ndarray
    P_rdr: np.ndarray
    A: np.ndarray
    M: np.ndarray
    B: np.ndarray
    BMA: np.ndarray
    p_td: np.ndarray


def transfer_radar(polar_rdr, P_rdr, attitude, geometry: LandingGeometry) -> RadarTransfer:
    """Move radar polar measurements and their covariance into the camera's polar frame (eqs. 7-11).

    Args:
        polar_rdr: (N, 3) or (3,) [r m, a rad, b rad] in deck axes about the radar.
        P_rdr: (3, 3) or (N, 3, 3) covariance of ``polar_rdr`` (m^2, m rad, rad^2).
        attitude: (N, 3) or (3,) [yaw deviation, pitch, roll], rad, assumed exact (paper assumption 1).
        geometry: :class:`LandingGeometry`.
    """
    pol = _polar("polar_rdr", polar_rdr, 3)
    att = _attitude(attitude)
    n = _same_n(polar_rdr=pol, attitude=att)
    P = _covariance("P_rdr", P_rdr, n, 3)
    phic, d_r, d_c = geometry.angled_deck_rad, geometry.d_radar_deck_m, geometry.d_camera_deck_m
    p_td, _, A, M, _ = _loader.get("landing_radar2td")(pol, att, phic, d_r)
    _, B = _loader.get("landing_td2ctd")(p_td, att, phic, d_c)
    polar_ctd, BMA = _loader.get("landing_radar2ctd")(pol, att, phic, d_r, d_c)
    return RadarTransfer(
        polar_rdr=pol, polar_ctd=polar_ctd, P_ctd=_sandwich(BMA, P), P_rdr=P, A=A, M=M, B=B, BMA=BMA, p_td=p_td
    )


@dataclass(frozen=True)
class CameraTransfer:
    """Camera angles moved from the deck-fixed camera axes to the camera-centred td axes.

    Attributes:
        angles_ctd: (N, 2) [a, b] rad (the paper's a_TL, b_TL).
        P_ctd: (N, 2, 2) their covariance ``J P_cam J^T`` (rad^2).
        P_cam: (N, 2, 2) the camera covariance that was transferred.
        J: (N, 2, 2) dangles_ctd/dangles_cam.
    """

    angles_ctd: np.ndarray
    P_ctd: np.ndarray
    P_cam: np.ndarray
    J: np.ndarray


def transfer_camera(angles_cam, P_cam, attitude, geometry: LandingGeometry) -> CameraTransfer:
    """Rotate camera angles (rad; deck-fixed landing-area axes) into the ctd frame with their covariance.

    Args:
        angles_cam: (N, 2) or (2,) [a, b], rad.
        P_cam: (2, 2) or (N, 2, 2) covariance, rad^2.
        attitude: (N, 3) or (3,) [yaw deviation, pitch, roll], rad.
        geometry: :class:`LandingGeometry`.
    """
    ang = _polar("angles_cam", angles_cam, 2)
    att = _attitude(attitude)
    n = _same_n(angles_cam=ang, attitude=att)
    P = _covariance("P_cam", P_cam, n, 2)
    angles_ctd, J = _loader.get("landing_camera2ctd")(ang, att, geometry.angled_deck_rad)
    return CameraTransfer(angles_ctd=angles_ctd, P_ctd=_sandwich(J, P), P_cam=P, J=J)


def variance_ratios(P_in: np.ndarray, P_out: np.ndarray) -> np.ndarray:
    """Variance amplification ratios (the paper's Figs. 2-3): diag(P_out) / diag(P_in), (N, k).

    For the radar, ``P_in`` is its own polar covariance and ``P_out`` the transferred one, so the
    ratios say how much each component's variance grows when seen from the camera in td axes
    (cross terms included: the radar's range error shows up in the camera-frame angles).
    """
    return np.diagonal(P_out, axis1=-2, axis2=-1) / np.diagonal(P_in, axis1=-2, axis2=-1)


# --------------------------------------------------------------------------- fusion
@dataclass(frozen=True)
class PositionEstimate:
    """One method's estimate at N instants.

    Attributes:
        method: one of :data:`FUSION_METHODS`.
        polar_ctd: (N, 3) [r m, a rad, b rad] about the camera in td axes.
        P_polar: (N, 3, 3) covariance of ``polar_ctd``.
        p_td: (N, 3) position in the touchdown frame, m.
        P_td: (N, 3, 3) its covariance, m^2 (first order).
        weights: (N, 2) weight of the camera in the fused azimuth and elevation (0 radar only,
            1 camera only); NaN for ``information``, whose gain is a matrix.
    """

    method: str
    polar_ctd: np.ndarray
    P_polar: np.ndarray
    p_td: np.ndarray
    P_td: np.ndarray
    weights: np.ndarray


def radar_only(radar: RadarTransfer, attitude, geometry: LandingGeometry) -> PositionEstimate:
    """The radar's own estimate: ``p_td`` by eq. (7), covariance ``J P_R J^T`` with ``J = M A``."""
    p_td, J = radar_to_touchdown(radar.polar_rdr, attitude, geometry)
    n = p_td.shape[0]
    return PositionEstimate(
        method="radar",
        polar_ctd=radar.polar_ctd,
        P_polar=radar.P_ctd,
        p_td=p_td,
        P_td=_sandwich(J, radar.P_rdr),
        weights=np.zeros((n, 2)),
    )


def combine(
    radar: RadarTransfer,
    camera: CameraTransfer,
    attitude,
    geometry: LandingGeometry,
    method: str = "paper",
) -> PositionEstimate:
    """Combine the transferred radar point with the transferred camera angles (eq. 12).

    Both inputs must describe the same N instants (already time-aligned). The sensors' errors are
    taken as independent. ``method`` (see :data:`FUSION_METHODS`):

    - ``radar``: ``[r, a, b]`` of the radar as seen from the camera.
    - ``camera``: radar range with the camera's angles.
    - ``paper``: eq. (12): ``r = r_RL``; ``a = s2 (a_TL / s2_TL + a_RL / s2_RL)`` with
      ``s2 = s2_TL s2_RL / (s2_TL + s2_RL)``, and likewise b, using each angle's own variance
      (diagonal entries of the transferred covariances).
    - ``information``: linear minimum-variance update of the radar's full ``[r, a, b]`` with the
      camera's angle pair (Kalman form), using all covariance entries.

    The fused covariance is exact for the linear combination: ``G_R P_RL G_R^T + G_T P_TL G_T^T``.
    The position ``p_td`` is rebuilt from the fused polar point about the camera, with
    ``P_td = J P J^T``, ``J = dp_td/dpolar``.
    """
    if method not in FUSION_METHODS:
        raise ValueError(f"method: expected one of {FUSION_METHODS}, got {method!r}")
    x_r, P_r = radar.polar_ctd, radar.P_ctd
    z_c, P_c = camera.angles_ctd, camera.P_ctd
    n = x_r.shape[0]
    if z_c.shape[0] != n:
        raise ValueError(f"camera: has {z_c.shape[0]} instants but radar has {n}; align them to the same instants first")
    att = _attitude(attitude)
    innov = _wrap(z_c - x_r[:, 1:])  # camera minus radar angles, (N, 2)
    if method == "information":
        H = np.zeros((2, 3))
        H[0, 1] = H[1, 2] = 1.0
        S = H @ P_r @ H.T + P_c
        K = P_r @ H.T @ np.linalg.inv(S)  # (N, 3, 2)
        x = x_r + np.einsum("nij,nj->ni", K, innov)
        I_KH = np.eye(3) - K @ H
        P = _sandwich(I_KH, P_r) + _sandwich(K, P_c)  # Joseph form: symmetric, PSD
        w = np.full((n, 2), np.nan)
    else:
        if method == "radar":
            w = np.zeros((n, 2))
        elif method == "camera":
            w = np.ones((n, 2))
        else:  # paper, eq. (12): camera weight = s2_RL / (s2_TL + s2_RL)
            s2_r = np.diagonal(P_r, axis1=1, axis2=2)[:, 1:]
            s2_c = np.diagonal(P_c, axis1=1, axis2=2)
            w = s2_r / (s2_r + s2_c)
        x = x_r.copy()
        x[:, 1:] = x_r[:, 1:] + w * innov
        G_r = np.zeros((n, 3, 3))
        G_r[:, 0, 0] = 1.0
        G_r[:, 1, 1] = 1.0 - w[:, 0]
        G_r[:, 2, 2] = 1.0 - w[:, 1]
        G_c = np.zeros((n, 3, 2))
        G_c[:, 1, 0] = w[:, 0]
        G_c[:, 2, 1] = w[:, 1]
        P = _sandwich(G_r, P_r) + _sandwich(G_c, P_c)
    x[:, 1] = _wrap(x[:, 1])
    p_td, J = _loader.get("landing_ctd2td")(x, att, geometry.angled_deck_rad, geometry.d_camera_deck_m)
    return PositionEstimate(method=method, polar_ctd=x, P_polar=P, p_td=p_td, P_td=_sandwich(J, P), weights=w)


# --------------------------------------------------------------------------- the whole pipeline
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


def _runs_first(name: str, value, width: int, n_t: int) -> np.ndarray:
    arr = as_float_array(name, value)
    if arr.ndim == 2:
        arr = arr[None]
    if arr.ndim != 3 or arr.shape[1:] != (n_t, width):
        raise ValueError(f"{name}: expected shape ({n_t}, {width}) or (R, {n_t}, {width}) to match its timestamps, got {arr.shape}")
    return arr


def fusion_instants(t_radar: np.ndarray, t_camera: np.ndarray, config: LandingConfig) -> np.ndarray:
    """A uniform grid (s, reference clock) at ``fusion_rate_hz`` inside both sensors' coverage."""
    lo = max(t_radar[0] - config.radar_clock_offset_s, t_camera[0] - config.camera_clock_offset_s) + config.half_window_s
    hi = min(t_radar[-1] - config.radar_clock_offset_s, t_camera[-1] - config.camera_clock_offset_s) - config.half_window_s
    if hi <= lo:
        raise ValueError(
            f"sensor data overlap too short: [{lo:.3f}, {hi:.3f}] s after removing half_window_s = {config.half_window_s} s at each end"
        )
    step = 1.0 / config.fusion_rate_hz
    return lo + step * np.arange(int(np.floor((hi - lo) / step)) + 1)


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
    t_r = as_float_array("t_radar", t_radar)
    t_c = as_float_array("t_camera", t_camera)
    if t_r.ndim != 1 or t_r.size < 2 or t_c.ndim != 1 or t_c.size < 2:
        raise ValueError("t_radar, t_camera: expected 1-D arrays of at least 2 timestamps (s)")
    pol = _runs_first("polar_rdr", polar_rdr, 3, t_r.size)
    ang = _runs_first("angles_cam", angles_cam, 2, t_c.size)
    if pol.shape[0] != ang.shape[0]:
        raise ValueError(f"polar_rdr has {pol.shape[0]} runs but angles_cam has {ang.shape[0]}")
    runs = pol.shape[0]
    s_r = as_float_array("sigma_rdr", sigma_rdr)
    s_c = as_float_array("sigma_cam", sigma_cam)
    if s_r.shape != (3,) or s_c.shape != (2,):
        raise ValueError(f"sigma_rdr: expected 3 values [m, rad, rad], sigma_cam 2 values [rad, rad]; got {s_r.shape}, {s_c.shape}")
    check_positive("sigma_rdr", s_r, "[m, rad, rad]")
    check_positive("sigma_cam", s_c, "[rad, rad]")
    tau = fusion_instants(t_r, t_c, config) if t_fusion is None else as_float_array("t_fusion", t_fusion)

    common = dict(
        degree=config.degree, half_window_s=config.half_window_s, max_extrapolation_s=config.max_extrapolation_s, strict=False
    )
    # all runs as extra columns: one fit per window serves every run
    try:
        ra = align(
            t_r, pol.transpose(1, 0, 2).reshape(t_r.size, runs * 3), tau,
            clock_offset_s=config.radar_clock_offset_s, angle_columns=list(range(1, runs * 3, 3)), **common,
        )
    except ValueError as exc:
        raise ValueError(f"radar track (t = t_radar, y = polar_rdr as columns [r, a, b] per run): {exc}") from exc
    try:
        ca = align(
            t_c, ang.transpose(1, 0, 2).reshape(t_c.size, runs * 2), tau,
            clock_offset_s=config.camera_clock_offset_s, angle_columns=list(range(0, runs * 2, 2)), **common,
        )
    except ValueError as exc:
        raise ValueError(f"camera track (t = t_camera, y = angles_cam as columns [a, b] per run): {exc}") from exc
    ok = ra.valid & ca.valid
    if not ok.any():
        raise ValueError("no fusion instant can be evaluated by both sensors; check the timestamps and window")
    tau = tau[ok]
    m = tau.size
    att_m = _attitude(attitude_fn(tau))
    if att_m.shape != (m, 3):
        raise ValueError(f"attitude_fn: returned shape {att_m.shape}, expected ({m}, 3)")

    pol_al = ra.y[ok].reshape(m, runs, 3).transpose(1, 0, 2).reshape(runs * m, 3)
    ang_al = ca.y[ok].reshape(m, runs, 2).transpose(1, 0, 2).reshape(runs * m, 2)
    att = np.tile(att_m, (runs, 1))
    vf_r = np.tile(ra.variance_factor[ok], runs)
    vf_c = np.tile(ca.variance_factor[ok], runs)
    P_r = vf_r[:, None, None] * np.diag(s_r**2)[None]
    P_c = vf_c[:, None, None] * np.diag(s_c**2)[None]

    radar = transfer_radar(pol_al, P_r, att, geometry)
    camera = transfer_camera(ang_al, P_c, att, geometry)
    estimates = {}
    for method in config.methods:
        if method == "radar":
            estimates[method] = radar_only(radar, att, geometry)
        else:
            estimates[method] = combine(radar, camera, att, geometry, method)
    return LandingResult(
        t=tau, attitude=att_m, runs=runs, radar_aligned=ra, camera_aligned=ca, radar=radar, camera=camera, estimates=estimates
    )
