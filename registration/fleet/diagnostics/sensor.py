"""One sensor's residuals binned (by measured azimuth, range, time, plot kind and target) and the
tests that name what the model misses (:mod:`registration.fleet.diagnostics`): each test a
:class:`Candidate` with its z, judged against the run's threshold afterwards."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.fleet.diagnostics.stats import (
    MIN_VALUES,
    BinMeans,
    Fit,
    best_step,
    bin_means,
    group_difference,
    sinusoid_fit,
    slope_fit,
)

__all__ = ["AZIMUTH_BINS", "CHANNEL_NAMES", "RANGE_BINS", "TIME_BINS", "Candidate", "SensorPlots", "analyse"]

#: Bins of measured azimuth (equal, over 360 deg), of range (quantiles) and of time (equal, over the span).
AZIMUTH_BINS = 12
RANGE_BINS = 8
TIME_BINS = 10
#: Channel names, display units and the factor from SI to display units.
CHANNEL_NAMES = ("range", "bearing", "elevation")
DISPLAY_UNITS = ("m", "deg", "deg")
DISPLAY_FACTOR = (1.0, 180.0 / np.pi, 180.0 / np.pi)
#: Plot kinds that name primary-only (PSR) plots.
PRIMARY_KINDS = frozenset({"primary", "psr", "none"})


@dataclass
class SensorPlots:
    """One sensor's plots with a residual (M,): ``time`` s, ``range`` m and ``bearing`` rad as
    measured (deck frame; NaN: not measured), ``target`` ids, ``kind`` labels ('' : none given),
    ``e`` (M, 3) normalised residuals (NaN: not measured), ``sigma`` (3,) the channels' noise sigma
    (m, rad; NaN: not measured), ``gain_estimated``: the model has the sensor's range gain."""

    sensor: str
    time: np.ndarray
    range: np.ndarray
    bearing: np.ndarray
    target: np.ndarray
    kind: np.ndarray
    e: np.ndarray
    sigma: np.ndarray
    gain_estimated: bool
    scale: np.ndarray = field(default_factory=lambda: np.ones(3))  # per channel, set by analyse

    def channels(self) -> list[int]:
        """The channels measured (with at least MIN_VALUES residuals)."""
        return [
            c
            for c in range(3)
            if np.isfinite(self.sigma[c]) and np.isfinite(self.e[:, c]).sum() >= MIN_VALUES
        ]

    def display(self, c: int) -> float:
        """Normalised residual -> display units (m, deg) of channel ``c``."""
        return float(self.sigma[c] * DISPLAY_FACTOR[c])


@dataclass(frozen=True)
class Candidate:
    """One test of a sensor: ``what`` it found, ``size`` in display ``unit``, ``z``, ``tests`` (the
    number of tests it counts for: a maximum over candidates counts each), ``hint``, ``channel``."""

    sensor: str
    test: str
    channel: str
    what: str
    size: float
    unit: str
    z: float
    tests: int
    hint: str


def _bins_json(p: SensorPlots, groups: np.ndarray, n_bins: int, **labels) -> dict:
    """Per measured channel, the bin means (display units) and their z, chi-square, dof, p."""
    out: dict = dict(labels)
    for c in p.channels():
        ok = np.isfinite(p.e[:, c])
        b: BinMeans = bin_means(p.e[ok, c], groups[ok], n_bins, p.scale[c])
        k = p.display(c)
        out.setdefault("n", b.n.tolist())
        out[CHANNEL_NAMES[c]] = {
            "unit": DISPLAY_UNITS[c],
            "n": b.n.tolist(),
            "mean": [None if not np.isfinite(v) else float(v * k) for v in b.mean],
            "z": [None if not np.isfinite(v) else float(v) for v in b.z],
            "chi2": b.chi2,
            "dof": b.dof,
            "p": None if not np.isfinite(b.p) else b.p,
        }
    return out


def _edges_quantile(x: np.ndarray, n: int) -> np.ndarray:
    edges = np.quantile(x, np.linspace(0.0, 1.0, n + 1))
    edges[-1] = np.nextafter(edges[-1], np.inf)
    return edges


def _groups(values: np.ndarray) -> tuple[list[str], np.ndarray]:
    labels, inverse = np.unique(values.astype(str), return_inverse=True)
    return [str(v) for v in labels], inverse.ravel()


def analyse(p: SensorPlots) -> tuple[dict, list[Candidate]]:
    """(the bins and fits of one sensor, for summary.json; its tests as :class:`Candidate`)."""
    for c in range(3):
        col = p.e[:, c]
        col = col[np.isfinite(col)]
        p.scale[c] = max(1.0, float(np.std(col))) if col.size >= MIN_VALUES else 1.0
    channels = p.channels()
    out: dict = {"plots": int(p.time.size), "scale": {CHANNEL_NAMES[c]: float(p.scale[c]) for c in channels}}
    net = p.e.copy()  # the residuals net of the fitted sinusoid, slope and step, for the group tests
    found = _azimuth(p, channels, net, out) + _range(p, channels, net, out) + _time(p, channels, net, out)
    found += _kinds(p, net, out) + _targets(p, net, out)
    return out, found


def _azimuth(p: SensorPlots, channels: list, net: np.ndarray, out: dict) -> list[Candidate]:
    """The bins by measured azimuth and the sinusoid of the bearing residuals (eccentricity)."""
    az = np.mod(p.bearing, 2 * np.pi)
    has_az = np.isfinite(az)
    az_bin = np.where(has_az, np.minimum((np.nan_to_num(az) / (2 * np.pi) * AZIMUTH_BINS).astype(int), 11), 0)
    if has_az.all():
        out["by_azimuth"] = _bins_json(p, az_bin, AZIMUTH_BINS, edges_deg=np.linspace(0, 360, 13).tolist())
    if 1 not in channels:
        return []
    ok = np.isfinite(p.e[:, 1]) & has_az
    fit = sinusoid_fit(p.e[ok, 1], az[ok], p.scale[1])
    if np.isfinite(fit.value):
        net[ok, 1] -= fit.value * np.sin(az[ok] + fit.phase)
    k = p.display(1)
    out["azimuth_sinusoid"] = {
        "amplitude_deg": fit.value * k,
        "sigma_deg": fit.sigma * k,
        "phase_deg": float(np.degrees(fit.phase)),
        "z": fit.z,
    }
    what = "bearing residual a sinusoid of azimuth, amplitude"
    return [
        Candidate(p.sensor, "eccentricity", "bearing", what, fit.value * k, "deg", fit.z, 1, "eccentricity?")
    ]


def _range(p: SensorPlots, channels: list, net: np.ndarray, out: dict) -> list[Candidate]:
    """The bins by range and, when no range gain is estimated, the slope of the range residuals."""
    if 0 not in channels:
        return []
    ok = np.isfinite(p.e[:, 0]) & np.isfinite(p.range)
    edges = _edges_quantile(p.range[ok], RANGE_BINS)
    r_bin = np.clip(np.searchsorted(edges, np.nan_to_num(p.range), side="right") - 1, 0, RANGE_BINS - 1)
    out["by_range"] = _bins_json(p, r_bin, RANGE_BINS, edges_m=edges.tolist())
    if p.gain_estimated:
        return []
    fit = slope_fit(p.e[ok, 0], p.range[ok], p.scale[0])
    if np.isfinite(fit.value):
        net[ok, 0] -= fit.value * (p.range[ok] - np.mean(p.range[ok]))
    ppm = p.sigma[0] * 1e6
    out["range_slope"] = {"ppm": fit.value * ppm, "sigma_ppm": fit.sigma * ppm, "z": fit.z}
    what = "range residual grows with range,"
    return [Candidate(p.sensor, "range_gain", "range", what, fit.value * ppm, "ppm", fit.z, 1, "range gain?")]


def _time(p: SensorPlots, channels: list, net: np.ndarray, out: dict) -> list[Candidate]:
    """The bins by time and the best single step of each channel (a bias change)."""
    t_edges = np.linspace(p.time.min(), p.time.max(), TIME_BINS + 1)
    t_bin = np.clip(np.searchsorted(t_edges, p.time, side="right") - 1, 0, TIME_BINS - 1)
    out["by_time"] = _bins_json(p, t_bin, TIME_BINS, edges_s=t_edges.tolist())
    steps, found = {}, []
    for c in channels:
        ok = np.isfinite(p.e[:, c])
        step = best_step(p.e[ok, c], p.time[ok], t_edges, p.scale[c])
        if np.isfinite(step.size):
            net[ok, c] -= step.size * (p.time[ok] >= step.time)
        net[ok, c] -= np.mean(net[ok, c])
        k, name, unit = p.display(c), CHANNEL_NAMES[c], DISPLAY_UNITS[c]
        steps[name] = {
            "time_s": step.time,
            "size": step.size * k,
            "unit": unit,
            "z": step.z,
            "candidates": step.candidates,
        }
        what = f"{name} bias step at {step.time:.0f} s,"
        hint = "bias change: try --bias-period-s"
        found.append(
            Candidate(p.sensor, "step", name, what, step.size * k, unit, step.z, step.candidates, hint)
        )
    out["time_step"] = steps
    return found


def _kinds(p: SensorPlots, net: np.ndarray, out: dict) -> list[Candidate]:
    """Per channel, the plot kind whose mean differs most from the other plots' (a maximum over the
    kinds given, '' not counted: one test per kind, one when there are two), on the residuals
    ``net`` of the fitted sinusoid, slope and step (the bins: on the residuals as they are)."""
    labels, group = _groups(p.kind)
    named = [i for i, label in enumerate(labels) if label != ""]
    if len(named) < 2:
        return []
    out["by_kind"] = _bins_json(p, group, len(labels), labels=labels)
    tested = named if len(labels) > 2 else named[:1]
    found = []
    for c in p.channels():
        ok = np.isfinite(net[:, c])
        fits = [group_difference(net[ok, c], group[ok] == i, p.scale[c]) for i in tested]
        z = np.array([f.z for f in fits])
        if not np.isfinite(z).any():
            continue
        j = int(np.nanargmax(np.abs(z)))
        label, fit = labels[tested[j]], fits[j]
        if len(labels) == 2 and labels[named[1]].lower() in PRIMARY_KINDS:  # name the primary kind
            label, fit = labels[named[1]], Fit(-fit.value, fit.sigma, -fit.z, fit.n)
        hint = (
            "PSR/SSR difference: psr_channel own?"
            if label.lower() in PRIMARY_KINDS
            else "plot kinds differ: their own biases?"
        )
        found.append(
            Candidate(
                p.sensor,
                "kind",
                CHANNEL_NAMES[c],
                f"{CHANNEL_NAMES[c]} of {label!r} plots minus the others",
                fit.value * p.display(c),
                DISPLAY_UNITS[c],
                fit.z,
                len(tested),
                hint,
            )
        )
    return found


def _targets(p: SensorPlots, net: np.ndarray, out: dict) -> list[Candidate]:
    """Each target's mean residual against zero (the test: on the residuals ``net`` of the fitted
    sinusoid, slope and step; the bins: on the residuals as they are)."""
    labels, group = _groups(p.target)
    out["by_target"] = _bins_json(p, group, len(labels), labels=labels)
    found = []
    for c in p.channels():
        ok = np.isfinite(net[:, c])
        b = bin_means(net[ok, c], group[ok], len(labels), p.scale[c])
        z = b.z
        tested = int(np.isfinite(z).sum())
        if not tested:
            continue
        i = int(np.nanargmax(np.abs(z)))
        found.append(
            Candidate(
                p.sensor,
                "target",
                CHANNEL_NAMES[c],
                f"{CHANNEL_NAMES[c]} of target {labels[i]},",
                float(b.mean[i] * p.display(c)),
                DISPLAY_UNITS[c],
                float(z[i]),
                tested,
                f"target {labels[i]} off: wrong id or reference?",
            )
        )
    return found
