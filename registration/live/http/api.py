"""The live service's answers, built once per processing round into an immutable
:class:`Snapshot` that the HTTP threads only read (docs/reference/live-api.md): the estimates (JSON
and CSV, the rows of ``estimates.csv``), the status (ingest counters, plots per sensor, the
consistency figure, alarms, uptime and memory), each sensor's estimates over the last hour, the
residuals per sensor, and the Prometheus metrics."""

from __future__ import annotations

import csv
import io
import json
import math
from dataclasses import dataclass, field

from registration.live.estimator import LiveEstimator
from registration.live.inputs.asterix import IngestCounters

__all__ = ["Snapshot", "SensorActivity", "build_snapshot", "rss_bytes"]


def rss_bytes() -> int:
    """The resident memory of this process (bytes; 0 where /proc is not there)."""
    try:
        with open("/proc/self/status", encoding="ascii") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return 0


@dataclass(frozen=True)
class SensorActivity:
    """Per sensor: plots received, plots per second of data time lately, the time of its latest
    plot (s, None: none yet) and whether it has gone silent."""

    plots: int
    rate_per_s: float
    last_time_s: float | None
    silent: bool


@dataclass(frozen=True)
class Snapshot:
    """The encoded answers of one round (bytes), ``history`` per sensor."""

    estimates: bytes = b'{"time_s": null, "estimates": []}'
    estimates_csv: bytes = b"object,state,unit,estimate,sigma,status\n"
    status: bytes = b"{}"
    residuals: bytes = b'{"sensors": []}'
    metrics: bytes = b""
    history: dict = field(default_factory=dict)


def _finite(v):
    return v if isinstance(v, (int, str)) or (isinstance(v, float) and math.isfinite(v)) else None


def _json(value) -> bytes:
    return json.dumps(value, allow_nan=False, separators=(",", ":")).encode()


def _rows_json(rows: list[dict]) -> list[dict]:
    keys = ("object", "state", "unit", "estimate", "sigma", "status")
    return [{k: _finite(r.get(k)) for k in keys} for r in rows]


def _csv(rows: list[dict]) -> bytes:
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(["object", "state", "unit", "estimate", "sigma", "status"])
    for r in rows:
        w.writerow(
            [
                r["object"],
                r["state"],
                r["unit"],
                repr(r["estimate"]),
                "" if r["sigma"] is None else repr(r["sigma"]),
                r["status"],
            ]
        )
    return out.getvalue().encode()


def _metrics(
    rows: list[dict], counters: IngestCounters, activity: dict, status: dict, nmea: dict | None
) -> bytes:
    """Prometheus text exposition format 0.0.4."""
    lines = []

    def metric(name: str, kind: str, text: str, samples: list[tuple[str, float]]) -> None:
        lines.append(f"# HELP registration_{name} {text}")
        lines.append(f"# TYPE registration_{name} {kind}")
        for labels, value in samples:
            lines.append(f"registration_{name}{labels} {float(value)!r}")

    esc = lambda s: str(s).replace("\\", "\\\\").replace('"', '\\"')  # noqa: E731
    metric("datagrams_total", "counter", "UDP datagrams received.", [("", counters.datagrams)])
    metric("bytes_total", "counter", "Octets received.", [("", counters.bytes)])
    metric(
        "records_total",
        "counter",
        "ASTERIX records decoded, by category.",
        [(f'{{category="{c}"}}', n) for c, n in sorted(counters.records.items())],
    )
    metric("references_total", "counter", "ADS-B reference reports kept.", [("", counters.references)])
    metric(
        "rejected_total",
        "counter",
        "Records set aside, by reason.",
        [(f'{{reason="{esc(r)}"}}', n) for r, n in sorted(counters.rejected.items())],
    )
    metric(
        "plots_total",
        "counter",
        "Plots kept, by sensor.",
        [(f'{{sensor="{esc(s)}"}}', a.plots) for s, a in activity.items()],
    )
    metric(
        "sensor_silent",
        "gauge",
        "1 when the sensor has gone silent.",
        [(f'{{sensor="{esc(s)}"}}', int(a.silent)) for s, a in activity.items()],
    )
    est = [r for r in rows if "+" not in r["object"] and r["sigma"] is not None]
    metric(
        "estimate",
        "gauge",
        "Current estimate (unit label).",
        [
            (
                f'{{object="{esc(r["object"])}",state="{esc(r["state"])}",unit="{esc(r["unit"])}"}}',
                r["estimate"],
            )
            for r in est
        ],
    )
    metric(
        "sigma",
        "gauge",
        "One standard deviation of the estimate.",
        [
            (f'{{object="{esc(r["object"])}",state="{esc(r["state"])}",unit="{esc(r["unit"])}"}}', r["sigma"])
            for r in est
        ],
    )
    if nmea is not None:
        metric("nmea_lines_total", "counter", "NMEA lines imported.", [("", nmea["lines"])])
        metric(
            "nmea_rejected_total",
            "counter",
            "NMEA lines set aside, by reason.",
            [(f'{{reason="{esc(r)}"}}', n) for r, n in sorted(nmea["rejected"].items())],
        )
        metric(
            "nmea_references_total", "counter", "AIS reference positions kept.", [("", nmea["references"])]
        )
    metric("alarms_total", "counter", "Change alarms raised.", [("", len(status["alarms"]))])
    metric("uptime_seconds", "gauge", "Seconds since the service started.", [("", status["uptime_s"])])
    metric("resident_memory_bytes", "gauge", "Resident memory.", [("", status["memory_rss_bytes"])])
    return ("\n".join(lines) + "\n").encode()


def build_snapshot(
    estimator: LiveEstimator,
    counters: IngestCounters,
    activity: dict[str, SensorActivity],
    uptime_s: float,
    backlog_plots: int = 0,
    nmea: dict | None = None,
) -> Snapshot:
    """The answers of the current state (module docstring); ``backlog_plots``: plots imported and
    not yet given to the estimator; ``nmea``: a ship's NMEA stream's counters (status ``nmea``)."""
    rows = estimator.rows()
    ingest = counters.to_json()
    ingest["late_plots"] = estimator.late_plots
    ingest["unconverged_plots"] = estimator.filter.n_unconverged_plots
    ingest["backlog_plots"] = backlog_plots
    status = {
        "uptime_s": uptime_s,
        "memory_rss_bytes": rss_bytes(),
        "data_time_s": estimator.data_time_s,
        "epochs": estimator.epochs,
        "ingest": ingest,
        **({"nmea": nmea} if nmea is not None else {}),
        "sensors": [{"sensor": s, **a.__dict__} for s, a in activity.items()],
        "consistency": {
            k: _finite(v) if not isinstance(v, list) else v for k, v in estimator.consistency().items()
        },
        "alarms": [{k: _finite(v) for k, v in a.to_json().items()} for a in estimator.alarms],
    }
    history = {s: _json({"sensor": s, "states": estimator.history_of(s)}) for s in activity}
    return Snapshot(
        estimates=_json({"time_s": estimator.data_time_s, "estimates": _rows_json(rows)}),
        estimates_csv=_csv(rows),
        status=_json(status),
        residuals=_json({"sensors": estimator.residual_summary()}),
        metrics=_metrics(rows, counters, activity, status, nmea),
        history=history,
    )
