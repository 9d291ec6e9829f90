"""True geometry of a simulated bridge log: the own ship (moving, yawing, pitching, rolling), the
other vessels (straight courses at sea level), and the radar's measurements of them with a known
range bias, bearing bias, clock offset and noise.

The geometry uses the package's frame functions (``registration.core.frames``): the truth may be
the package's. The *encoding* of the log (bridgelog.py) is pynmea2's and pyais' only.

Conventions as in docs/reference/conventions.md: heading clockwise from north, pitch bow up, roll starboard
down; deck bearing from the bow, starboard positive; measured = true + bias + noise; reported
plot time = true time + clock offset (the fleet's time bias).
"""

from __future__ import annotations

import datetime as dt
from dataclasses import dataclass, field

import numpy as np

from registration.core.frames import deck2enu_rotation, enu2ecef_rotation, geodetic2ecef

A_WGS84 = 6378137.0
E2_WGS84 = 0.006694379990141317


@dataclass(frozen=True)
class BridgeLogConfig:
    """Parameters of a simulated bridge log (SI units, radians). ``start_utc``: the first second of
    the log; ``bearing_reference``: ``"R"``, ``"T"`` or ``"mixed"`` (TTM bearings relative or true);
    ``distance_unit``: ``"N"``, ``"K"``, ``"S"`` or ``"mixed"``; ``ais_noise_m``: the AIS
    position noise per axis with the accuracy flag 1 and 0; ``reception_stamp``: how AIS
    reception times are written: ``"tagblock"`` (NMEA 4.10 ``c:``), ``"prefix-iso"`` or
    ``"prefix-unix"`` (a logger's timestamp before every line)."""

    seed: int = 0
    start_utc: dt.datetime = dt.datetime(2024, 5, 1, 12, 0, 0, tzinfo=dt.timezone.utc)
    duration_s: float = 600.0
    n_vessels: int = 14
    n_ais: int = 11
    range_bias_m: float = 60.0
    bearing_bias_rad: float = float(np.radians(0.6))
    clock_offset_s: float = 0.8
    sigma_range_m: float = 15.0
    sigma_bearing_rad: float = float(np.radians(0.1))
    scan_period_s: float = 2.5
    attitude_rate_hz: float = 10.0
    bearing_reference: str = "R"
    distance_unit: str = "N"
    latency_max_s: float = 1.5
    reception_stamp: str = "tagblock"
    unavailable_second_fraction: float = 0.05
    ais_noise_m: tuple = (5.0, 10.0)
    class_b_period_s: int = 30
    heading_error_rad: float = 0.0
    lever_arm_m: tuple = (0.0, 15.0, 22.0)
    geoid_separation_m: float = 42.0
    antenna_msl_m: float = 30.0
    own_speed_mps: float = 8.0
    own_course_rad: float = float(np.radians(40.0))
    roll_amplitude_rad: float = float(np.radians(4.0))
    roll_period_s: float = 11.0
    pitch_amplitude_rad: float = float(np.radians(1.5))
    pitch_period_s: float = 7.0
    yaw_amplitude_rad: float = float(np.radians(1.0))
    yaw_period_s: float = 17.0
    vdo_period_s: float = 10.0
    static_period_s: float = 60.0
    extra_sentences: bool = False
    centre_lat_rad: float = float(np.radians(43.0))
    centre_lon_rad: float = float(np.radians(7.5))


@dataclass
class Vessel:
    """A vessel on a straight course at sea level: start east/north of the centre (m) at the log's
    start, velocity east/north (m/s); ``track`` its TTM target number; ``mmsi`` (None: no AIS);
    ``ais_class`` ``"A"`` or ``"B"``; ``period_s`` its AIS report interval; ``accuracy`` its flag."""

    track: int
    east: float
    north: float
    v_east: float
    v_north: float
    mmsi: str | None = None
    name: str = ""
    ais_class: str = ""
    period_s: int = 0
    accuracy: bool = False
    phase_s: float = 0.0


@dataclass
class Truth:
    """The true geometry; times ``t`` are s since midnight UTC of the start's date."""

    config: BridgeLogConfig
    t0: float
    vessels: list[Vessel] = field(default_factory=list)

    @property
    def day(self) -> dt.date:
        return self.config.start_utc.date()

    def _to_geodetic(self, east, north):
        return self.offset(self.config.centre_lat_rad, self.config.centre_lon_rad, east, north)

    @staticmethod
    def offset(lat, lon, east, north):
        """(lat, lon) rad of a point ``east``, ``north`` m from (lat, lon) (the radii of curvature there)."""
        w = np.sqrt(1 - E2_WGS84 * np.sin(lat) ** 2)
        r_meridian = A_WGS84 * (1 - E2_WGS84) / w**3
        r_normal = A_WGS84 / w
        return lat + np.asarray(north) / r_meridian, lon + np.asarray(east) / (r_normal * np.cos(lat))

    def own(self, t) -> dict:
        """True own-ship state at times ``t`` (s): lat, lon (rad), alt (m, ellipsoid), heading,
        pitch, roll (rad), speed (m/s), course (rad)."""
        c = self.config
        t = np.asarray(t, dtype=np.float64)
        s = t - self.t0
        east = c.own_speed_mps * np.sin(c.own_course_rad) * s
        north = c.own_speed_mps * np.cos(c.own_course_rad) * s
        lat, lon = self._to_geodetic(east, north)
        w = 2 * np.pi
        return {
            "lat": lat,
            "lon": lon,
            "alt": np.full(t.shape, c.antenna_msl_m + c.geoid_separation_m),
            "heading": c.own_course_rad + c.yaw_amplitude_rad * np.sin(w * s / c.yaw_period_s),
            "pitch": c.pitch_amplitude_rad * np.sin(w * s / c.pitch_period_s + 0.4),
            "roll": c.roll_amplitude_rad * np.sin(w * s / c.roll_period_s + 1.1),
            "speed": np.full(t.shape, c.own_speed_mps),
            "course": np.full(t.shape, c.own_course_rad),
        }

    def reported_heading(self, t) -> np.ndarray:
        """The heading the navigation reports (true + heading error), rad."""
        return self.own(t)["heading"] + self.config.heading_error_rad

    def vessel(self, k: int, t) -> dict:
        """True position of vessel ``k`` at ``t``: lat, lon (rad), alt (m: sea level), speed (m/s),
        course (rad)."""
        v = self.vessels[k]
        s = np.asarray(t, dtype=np.float64) - self.t0
        lat, lon = self._to_geodetic(v.east + v.v_east * s, v.north + v.v_north * s)
        shape = np.shape(s)
        return {
            "lat": lat,
            "lon": lon,
            "alt": np.full(shape, self.config.geoid_separation_m),
            "speed": np.full(shape, np.hypot(v.v_east, v.v_north)),
            "course": np.full(shape, np.mod(np.arctan2(v.v_east, v.v_north), 2 * np.pi)),
        }

    def radar(self, k: int, t) -> tuple[np.ndarray, np.ndarray]:
        """True slant range (m) and deck bearing (rad) of vessel ``k`` from the radar at times ``t``
        (the fleet model: u_deck = R_enu_deck^T R_ecef_enu^T (p - p_nav) - lever)."""
        t = np.atleast_1d(np.asarray(t, dtype=np.float64))
        o, v = self.own(t), self.vessel(k, t)
        d_ecef = geodetic2ecef(v["lat"], v["lon"], v["alt"]) - geodetic2ecef(o["lat"], o["lon"], o["alt"])
        u_enu = np.einsum("nji,nj->ni", enu2ecef_rotation(o["lat"], o["lon"]), d_ecef)
        u_deck = np.einsum("nji,nj->ni", deck2enu_rotation(o["heading"], o["pitch"], o["roll"]), u_enu)
        u_deck = u_deck - np.asarray(self.config.lever_arm_m)
        return np.linalg.norm(u_deck, axis=1), np.arctan2(u_deck[:, 0], u_deck[:, 1])


NAMES = [
    "NORDIC STAR",
    "AURORA",
    "BLUE WHALE",
    "CAPE ROSA",
    "DELFINO",
    "ELBE TRADER",
    "FJORD KING",
    "GALATEA",
    "HELIOS",
    "IONIAN SEA",
    "JUNO",
    "KASTOR",
    "LIGURIA",
    "MISTRAL",
    "NEREIDE",
    "ORION",
    "POSEIDON",
    "QUEEN MAB",
    "RIVIERA",
    "SIRIUS",
]


def make_truth(config: BridgeLogConfig) -> Truth:
    """The own ship and ``n_vessels`` vessels 3-18 km away on random straight courses; the first
    ``n_ais`` of them on AIS (two in three class A)."""
    rng = np.random.default_rng(config.seed)
    start = config.start_utc
    t0 = start.hour * 3600.0 + start.minute * 60.0 + start.second + start.microsecond * 1e-6
    truth = Truth(config, t0)
    tracks = rng.permutation(np.arange(1, config.n_vessels + 1))
    for k in range(config.n_vessels):
        r, az = rng.uniform(3e3, 18e3), rng.uniform(0, 2 * np.pi)
        speed, course = rng.uniform(3.0, 12.0), rng.uniform(0, 2 * np.pi)
        v = Vessel(
            int(tracks[k]),
            r * np.sin(az),
            r * np.cos(az),
            speed * np.sin(course),
            speed * np.cos(course),
            phase_s=float(rng.uniform(0, config.scan_period_s)),
        )
        if k < config.n_ais:
            v.mmsi = str(244000100 + k)
            v.name = NAMES[k % len(NAMES)]
            v.ais_class = "A" if k % 3 != 2 else "B"
            v.period_s = (
                int(rng.choice([2, 3, 6, 10])) if v.ais_class == "A" else int(config.class_b_period_s)
            )
            v.accuracy = bool(rng.random() < 0.5)
        truth.vessels.append(v)
    return truth
