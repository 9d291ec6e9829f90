"""The residual diagnostics of a fleet run (:func:`diagnose`): every sensor's tests
(:mod:`registration.fleet.diagnostics.sensor`) judged against one threshold, the Bonferroni
``change_threshold(n_tests)`` over all the sensors x tests of the run (false alarms of the whole run
about 1 %, :data:`registration.fleet.changes.FALSE_ALARM`), and, for a run whose consistency is
outside its band, which sensors and bins carry the chi-square's excess. The diagnostics only read
the result: they change no estimate. See docs/background/diagnostics.md."""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from registration.fleet.changes import FALSE_ALARM, change_threshold
from registration.fleet.diagnostics.sensor import CHANNEL_NAMES, Candidate, SensorPlots, analyse

__all__ = ["Diagnostics", "diagnose", "sensor_plots"]

#: Worst bins named when the consistency is outside its band.
WORST_BINS = 5
_BINNINGS = {
    "by_azimuth": "azimuth",
    "by_range": "range",
    "by_time": "time",
    "by_kind": "kind",
    "by_target": "target",
}


@dataclass
class Diagnostics:
    """``threshold`` (|z|) and ``n_tests`` it holds the false alarms over; ``findings`` (the
    :class:`Candidate` tests above it, largest |z| first); ``tests`` all of them; ``sensors``: per
    sensor its bins and fits (JSON-ready, display units); ``excess``: per sensor its squared normalised
    residuals, values and share of the chi-square's excess; ``plots``: the per-sensor data (figures)."""

    threshold: float
    n_tests: int
    findings: list[Candidate]
    tests: list[Candidate]
    sensors: dict
    excess: dict
    plots: dict = field(default_factory=dict, repr=False)

    def finding_lines(self) -> list[str]:
        """One line per finding: sensor, what, size with unit, z, hint."""
        return [
            f"{f.sensor}: {f.what} {f.size:+.4g} {f.unit} (z {f.z:+.1f}, threshold {self.threshold:.2f}): "
            f"{f.hint}"
            for f in self.findings
        ]

    def worst_bins(self, n: int = WORST_BINS) -> list[dict]:
        """The ``n`` bins of largest |z| over all sensors, binnings and channels."""
        rows = []
        for sensor, d in self.sensors.items():
            for key, name in _BINNINGS.items():
                b = d.get(key)
                if b is None:
                    continue
                for ch in CHANNEL_NAMES:
                    if ch not in b:
                        continue
                    for i, z in enumerate(b[ch]["z"]):
                        if z is not None:
                            rows.append(
                                {
                                    "sensor": sensor,
                                    "binning": name,
                                    "channel": ch,
                                    "bin": _bin_text(b, name, i),
                                    "mean": b[ch]["mean"][i],
                                    "unit": b[ch]["unit"],
                                    "n": b[ch]["n"][i],
                                    "z": z,
                                }
                            )
        return sorted(rows, key=lambda r: -abs(r["z"]))[:n]

    def excess_lines(self) -> list[str]:
        """Which sensors, and which bins, carry the chi-square's excess (for a run outside its band)."""
        parts = [
            f"{s} {v['share']:.0%} (mean square {v['mean_square']:.3g} over {v['values']} values)"
            for s, v in sorted(self.excess.items(), key=lambda kv: -kv[1]["share"])
        ]
        out = ["consistency outside its band; the chi-square's excess by sensor: " + ", ".join(parts)]
        for b in self.worst_bins():
            out.append(
                f"  worst bin: {b['sensor']} {b['channel']} by {b['binning']} {b['bin']}: "
                f"mean {b['mean']:+.4g} {b['unit']} over {b['n']} plots (z {b['z']:+.1f})"
            )
        return out

    def to_json(self) -> dict:
        def finite(v):
            return v if isinstance(v, (str, int)) or np.isfinite(v) else None

        return {
            "threshold_z": self.threshold,
            "tests": self.n_tests,
            "false_alarm": FALSE_ALARM,
            "findings": [{k: finite(v) for k, v in f.__dict__.items()} for f in self.findings],
            "excess": self.excess,
            "worst_bins": self.worst_bins(),
            "sensors": _clean(self.sensors),
        }


def _clean(obj):
    """NaN and inf -> None, recursively (for JSON)."""
    if isinstance(obj, dict):
        return {k: _clean(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_clean(v) for v in obj]
    if isinstance(obj, float) and not np.isfinite(obj):
        return None
    return obj


def _bin_text(b: dict, name: str, i: int) -> str:
    if name == "azimuth":
        return f"{b['edges_deg'][i]:g}-{b['edges_deg'][i + 1]:g} deg"
    if name == "range":
        return f"{b['edges_m'][i] / 1e3:.1f}-{b['edges_m'][i + 1] / 1e3:.1f} km"
    if name == "time":
        return f"{b['edges_s'][i]:.0f}-{b['edges_s'][i + 1]:.0f} s"
    return repr(b["labels"][i])


def sensor_plots(problem, result, kind_by_row: np.ndarray | None = None) -> dict[str, SensorPlots]:
    """Per sensor id, its plots with a residual (:class:`SensorPlots`), from a fleet ``problem`` and
    a result with ``residuals`` (input rows, 3); ``kind_by_row``: the plot kind per input row (None:
    not known)."""
    rows = problem.row
    e = np.asarray(result.residuals, dtype=float)[rows]
    has = np.isfinite(e).any(axis=1)
    kind = (
        np.asarray(kind_by_row).astype(str)[rows]
        if kind_by_row is not None and len(kind_by_row) == result.residuals.shape[0]
        else np.full(rows.size, "")
    )
    meas = np.where(problem.mask, problem.meas, np.nan)
    names = problem.layout.names
    out = {}
    for s, sensor in enumerate(problem.sensor_ids):
        sel = has & (problem.sensor == s)
        if sel.sum() < 2:
            continue
        gain = f"{sensor}:range_gain"
        out[str(sensor)] = SensorPlots(
            str(sensor),
            problem.time[sel],
            meas[sel, 0],
            meas[sel, 1],
            np.asarray(problem.target_ids)[problem.target[sel]],
            kind[sel],
            e[sel],
            np.asarray(problem.sensor_sigma[s], dtype=float),
            gain in names and result.status.get(gain) != "fixed",
        )
    return out


def diagnose(problem, result, kind_by_row: np.ndarray | None = None) -> Diagnostics:
    """The diagnostics of a registration ``result`` (with ``residuals``, ``status``) of ``problem``
    (module docstring); ``kind_by_row``: the plot kind per input row of the plots table (None or ''
    cells: not known)."""
    plots = sensor_plots(problem, result, kind_by_row)
    sensors, tests = {}, []
    for name, p in plots.items():
        sensors[name], found = analyse(p)
        tests += [t for t in found if np.isfinite(t.z)]
    n_tests = sum(t.tests for t in tests)
    c = change_threshold(n_tests)
    findings = _annotated(sorted((t for t in tests if abs(t.z) > c), key=lambda t: -abs(t.z)))
    return Diagnostics(c, n_tests, findings, tests, sensors, _excess(plots), plots)


#: The tests of a term of the sensor's own (the group tests may follow from them).
_TERMS = {"eccentricity": "the eccentricity", "range_gain": "the range gain", "step": "the bias step"}


#: The terms of azimuth or range that a step test over time can see, and that can see a step
#: (``_annotated``).
_AZIMUTH_RANGE_TERMS = ("eccentricity", "range_gain")


def _annotated(findings: list[Candidate]) -> list[Candidate]:
    """Findings of a plot kind or a target in a channel where the same sensor has an eccentricity,
    range gain or step finding, their hints completed: the unmodelled term also bends the targets'
    fitted tracks, which the group tests then see (the tests use the residuals net of the fitted term,
    not of its effect on the tracks). Likewise a step beside a larger eccentricity or range gain
    finding of the same sensor and channel, and an eccentricity or range gain beside a larger step:
    as the traffic moves in azimuth and range, an unmodelled term of azimuth or range changes the
    residuals' mean over time, and a step changes their mean over the azimuths and ranges the
    traffic held before and after it. The term named is the sensor's largest (findings come largest
    |z| first)."""
    terms: dict = {}
    for f in findings:
        if f.test in _TERMS:
            terms.setdefault((f.sensor, f.channel), f.test)
    out = []
    for f in findings:
        term = terms.get((f.sensor, f.channel))
        follows = (
            f.test in ("kind", "target")
            or (f.test == "step" and term in _AZIMUTH_RANGE_TERMS)
            or (f.test in _AZIMUTH_RANGE_TERMS and term == "step")
        )
        if follows and term is not None and term != f.test:
            f = replace(f, hint=f"{f.hint} (or a consequence of {_TERMS[term]} above)")
        out.append(f)
    return out


def _excess(plots: dict[str, SensorPlots]) -> dict:
    """Per sensor: sum of squared normalised residuals, values, mean square, excess (sum - values)
    and its share of the positive excesses."""
    out = {}
    for name, p in plots.items():
        e = p.e[np.isfinite(p.e)]
        ss = float(np.sum(e * e))
        out[name] = {
            "sum_of_squares": ss,
            "values": int(e.size),
            "mean_square": ss / max(e.size, 1),
            "excess": ss - e.size,
        }
    total = sum(max(v["excess"], 0.0) for v in out.values())
    for v in out.values():
        v["share"] = max(v["excess"], 0.0) / total if total > 0 else 0.0
    return out
