"""``import_nmea``: an NMEA 0183 bridge log with AIS -> the fleet tables of one platform
(docs/howto/import-nmea.md).

The tables are DataFrames in the fleet *file* columns (degrees, metres, seconds;
docs/reference/fleet-files.md,
"The files"), ready to be written and read back by :func:`registration.fleet.read_fleet_tables`;
``time_s`` counts from midnight UTC of the log's first day (or of ``date``) in all of them.
"""

from __future__ import annotations

import datetime as dt
import math
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Iterator, Mapping, Sequence

import numpy as np

from registration.io.files.ledger import RejectedLedger
from registration.io.files.limits import DEFAULT_MAX_BYTES, DEFAULT_MAX_REJECTED_ROWS, BoundedLedger, Limits
from registration.io.imports import ImportResult
from registration.io.nmea.ais import read_ais
from registration.io.nmea.attitude import PASHR_ANGLES, pashr_subtypes, read_headings, read_pashr
from registration.io.nmea.clock import fit_clock
from registration.io.nmea.duplicates import drop_duplicates
from registration.io.nmea.errors import LEDGER_COLUMNS, NmeaImportError
from registration.io.nmea.fixes import read_fixes
from registration.io.nmea.lines import SentenceLog, read_log
from registration.io.nmea.navigation import build_navigation
from registration.io.nmea.reference import AisSigmas, read_references
from registration.io.nmea.sensors import (
    TALKER_COLUMN,
    check_sensors,
    platform_sensors,
    read_sensors,
    talker_map,
)
from registration.io.nmea.summary import ImportParts, build_summary
from registration.io.nmea.ttm import read_ttm

if TYPE_CHECKING:
    import pandas as pd

__all__ = [
    "NmeaImport",
    "import_nmea",
    "read_sentences",
    "platforms_table",
    "USED_TYPES",
    "PLATFORM_PRIOR_COLUMNS",
]

#: The sentence types the reader uses.
USED_TYPES = ("GGA", "GNS", "RMC", "ZDA", "HDT", "THS", "PASHR", "TTM", "VDM", "VDO")
#: The platforms file's prior columns (deg; empty: no prior, 0: held fixed).
PLATFORM_PRIOR_COLUMNS = ("prior_heading_deg", "prior_pitch_deg", "prior_roll_deg")


class NmeaImport(ImportResult):
    """What :func:`import_nmea` gives (:class:`~registration.io.imports.ImportResult`): the fleet
    tables of one platform from an NMEA log, as DataFrames in the fleet file columns:

    * ``navigation``: ``time_s``, ``platform``, ``lat_deg``, ``lon_deg``, ``alt_m`` (above the
      ellipsoid), ``heading_deg``, ``pitch_deg``, ``roll_deg`` (one row per attitude sample);
    * ``plots``: ``time_s``, ``sensor``, ``track`` (the TTM target number, sensor-local),
      ``range_m``, ``bearing_deg`` (deck bearing);
    * ``sensors``: the input rows of the platform (``talker`` dropped);
    * ``platforms``: one row, ``platform`` and the attitude priors (empty: free);
    * ``reference``: ``time_s``, ``target`` (MMSI), ``lat_deg``, ``lon_deg``, ``alt_m`` (mean sea
      level), ``sigma_m`` (horizontal), ``sigma_up_m`` (inf: no height);
    * ``targets``: the AIS vessels as surface targets: ``target`` (MMSI), ``name``, ``surface_alt_m``
      (mean sea level above the ellipsoid), ``sigma_surface_m``;
    * ``rejected``: the lines set aside: ``file``, ``line`` (from 1), ``code``, ``reason``;
    * ``summary``: a JSON-able dict (docs/howto/import-nmea.md, "The summary").

    :meth:`write` writes them into a folder.
    """


def _known_types() -> set:
    import pynmea2

    return set(pynmea2.TalkerSentence.sentence_types) | set(USED_TYPES)


def _sort_types(log: SentenceLog, rejections: RejectedLedger) -> dict:
    """Sentences of types not used: unknown types set aside (``unknown_type``); types pynmea2 knows
    counted (returned: type -> count; Ashtech's other $PASHR messages as ``PASHR (not attitude)``)."""
    import pynmea2

    known, makers = _known_types(), set(pynmea2.ProprietarySentence.sentence_types)
    kinds, counts = np.unique(log.kind.astype(str), return_counts=True)
    not_used = {}
    for kind, n in zip(kinds, counts):
        if kind in USED_TYPES:
            continue
        if kind in known or (kind.startswith("P") and kind[1:4] in makers):
            not_used[kind] = int(n)
            continue
        i = log.where(kind)
        rejections.add(log.file[i], "unknown_type", f"unknown sentence type {kind!r}", line=log.line[i])
    other = pashr_subtypes(log)[1]
    if other.size:
        not_used["PASHR (not attitude)"] = int(other.size)
    return not_used


def _sensors_table(sensors: pd.DataFrame | str | Path, platform: str) -> pd.DataFrame:
    if isinstance(sensors, (str, Path)):
        table, source = read_sensors(sensors), str(sensors)
    else:
        source = getattr(sensors, "attrs", {}).get("source", "sensors")
        table = check_sensors(sensors, source)
    return platform_sensors(table, platform, source)


def platforms_table(platform: str, priors: Mapping[str, float] | None) -> pd.DataFrame:
    """The platforms table (file columns) of ``platform`` with its attitude prior sigmas (deg by
    column of :data:`PLATFORM_PRIOR_COLUMNS`; missing or None: free); ValueError naming the key."""
    import pandas as pd

    priors = dict(priors or {})
    unknown = sorted(set(priors) - set(PLATFORM_PRIOR_COLUMNS))
    if unknown:
        raise ValueError(
            f"platform_priors: unknown key(s) {unknown}; expected {list(PLATFORM_PRIOR_COLUMNS)} (deg)"
        )
    row: dict[str, list] = {"platform": [str(platform)]}
    for column in PLATFORM_PRIOR_COLUMNS:
        v = priors.get(column, math.nan)
        if v is None:
            v = math.nan
        if not isinstance(v, (int, float)) or (not math.isnan(v) and v < 0):
            raise ValueError(
                f"platform_priors[{column!r}]: expected a prior sigma >= 0 deg (or None, inf: free), "
                f"got {v!r}"
            )
        row[column] = [math.nan if math.isinf(v) else float(v)]
    return pd.DataFrame(row)


def _anchors(fixes: dict, dates, pashr) -> tuple[np.ndarray, np.ndarray]:
    """(indices, times of day) of the sentences that time the log: fixes, dates and $PASHR."""
    index = np.concatenate([fixes[k].index for k in ("GGA", "GNS", "RMC")] + [dates.index, pashr.index])
    tod = np.concatenate([fixes[k].tod for k in ("GGA", "GNS", "RMC")] + [dates.tod, pashr.tod])
    index, first = np.unique(index, return_index=True)
    return index, tod[first]


def _ledger(paths: list, max_bytes: int, max_rejected_rows: int) -> BoundedLedger:
    """The rejected ledger of the import, the bounds checked (positive integers)."""
    Limits(max_bytes=max_bytes, max_rejected_rows=max_rejected_rows)
    return BoundedLedger(LEDGER_COLUMNS, max_rejected_rows, [str(Path(p)) for p in paths])


@contextmanager
def _naming_the_log(paths: list) -> Iterator[None]:
    """A :class:`NmeaImportError` about the log as a whole (no position, no heading) names its files."""
    try:
        yield
    except NmeaImportError as exc:
        names = [str(p) for p in paths]
        if str(exc).startswith(tuple(names)):
            raise
        where = names[0] if len(names) == 1 else f"{names[0]} (and {len(names) - 1} more files)"
        raise NmeaImportError(f"{where}: {exc}") from None


def import_nmea(
    paths: str | Path | Sequence[str | Path],
    platform: str,
    sensors: pd.DataFrame | str | Path,
    date: dt.date | str | None = None,
    keep_acquiring: bool = False,
    progress: bool = False,
    *,
    platform_priors: Mapping[str, float] | None = None,
    ais_sigmas: AisSigmas | None = None,
    pashr_angles: str = "tait-bryan",
    keep_duplicates: bool = False,
    max_bytes: int = DEFAULT_MAX_BYTES,
    max_rejected_rows: int = DEFAULT_MAX_REJECTED_ROWS,
) -> NmeaImport:
    """Import NMEA 0183 log files (with AIS) as the fleet tables of ``platform`` (docs/howto/import-nmea.md).

    ``paths``: a log file or a list of them, read in the order given (one log cut into files);
    ``sensors``: the fleet sensors table as a DataFrame in file columns, or a path to its file,
    plus an optional ``talker`` column saying which sensor a TTM talker is (with one sensor on the
    platform and no talker, that sensor); ``date``: ``datetime.date`` or ``'YYYY-MM-DD'``, the UTC
    date the log starts on when it has no ZDA or RMC, and the origin of ``time_s``;
    ``keep_acquiring``: keep TTM targets in acquisition (status Q); ``progress``: a bar of lines read
    (:func:`registration.core.progress.progress_bar`);
    ``platform_priors``: the platform's attitude prior sigmas by platforms file column
    (``prior_heading_deg``, ``prior_pitch_deg``, ``prior_roll_deg``; deg; missing or None: free);
    ``ais_sigmas``: the AIS reference sigma model (:class:`AisSigmas`); ``pashr_angles``:
    ``"tait-bryan"`` or ``"tss"``, the roll convention of ``$PASHR``; ``keep_duplicates``: keep
    identical sentences with the same time (by default set aside as ``duplicate``,
    :mod:`registration.io.nmea.duplicates`); ``max_bytes``: the bytes read per file (default 8
    GiB; the lines beyond are set aside as ``over_limit``); ``max_rejected_rows``: the rows
    ``rejected`` lists (default 10^5; the rest counted in the summary, one last row ``not_listed``
    says how many; :mod:`registration.io.files.limits`).

    Bad lines never raise: they are set aside in ``rejected`` with a reason. ValueError for bad
    arguments and a bad sensors table (naming row, column, unit);
    :class:`~registration.io.nmea.errors.NmeaImportError` (a ValueError) for a log without any
    valid position or heading.
    """
    if pashr_angles not in PASHR_ANGLES:
        raise ValueError(f"pashr_angles: expected one of {PASHR_ANGLES}, got {pashr_angles!r}")
    platform = str(platform)
    sensor_rows = _sensors_table(sensors, platform)
    talkers, only = talker_map(sensor_rows)
    platforms = platforms_table(platform, platform_priors)
    paths = [paths] if isinstance(paths, (str, Path)) else list(paths)
    if not paths:
        raise ValueError("paths: no log file given")
    rejections = _ledger(paths, max_bytes, max_rejected_rows)
    with _naming_the_log(paths):
        log = read_log(paths, rejections, progress, max_bytes)
        parts, duplicates = read_sentences(
            log, rejections, talkers, only, date, keep_acquiring, ais_sigmas, pashr_angles, keep_duplicates
        )
        summary = build_summary(parts)
        if duplicates:
            summary["duplicates"] = {"sentences": duplicates}
        return NmeaImport(
            plots=parts.plots.frame(),
            navigation=parts.navigation.frame(platform),
            sensors=sensor_rows.drop(columns=[TALKER_COLUMN], errors="ignore"),
            platforms=platforms,
            reference=parts.references.frame(),
            rejected=rejections.frame(),
            summary=summary,
            targets=parts.references.targets_frame(),
        )


def read_sentences(
    log: SentenceLog,
    rejections: RejectedLedger,
    talkers: dict[str, str],
    only: str | None,
    date=None,
    keep_acquiring: bool = False,
    sigmas: AisSigmas | None = None,
    pashr_angles: str = "tait-bryan",
    keep_duplicates: bool = False,
) -> tuple[ImportParts, int]:
    """The import of the sentences of ``log`` (the steps of :func:`import_nmea` after reading the
    lines; the live service runs them on each piece of a stream): (the parts, the number of
    duplicate sentences set aside). ``talkers``, ``only``: :func:`~registration.io.nmea.sensors.talker_map`
    of the platform's sensors; the other arguments as :func:`import_nmea`'s.
    :class:`~registration.io.nmea.errors.NmeaImportError` without a valid position or heading."""
    sigmas = sigmas if sigmas is not None else AisSigmas()
    log, duplicates = (log, 0) if keep_duplicates else drop_duplicates(log, rejections)
    not_used = _sort_types(log, rejections)
    fixes, dates = read_fixes(log, rejections)
    attitudes = {
        "PASHR": read_pashr(log, rejections, pashr_angles),
        "HDT": read_headings(log, "HDT", rejections),
        "THS": read_headings(log, "THS", rejections),
    }
    clock = fit_clock(*_anchors(fixes, dates, attitudes["PASHR"]), dates, date, log.received)
    nav = build_navigation(log, clock, fixes, attitudes, rejections)
    plots = read_ttm(log, clock, nav, talkers, only, keep_acquiring, rejections)
    messages = read_ais(log, rejections)
    refs = read_references(log, messages, clock, nav.sea_level, sigmas, rejections)
    return ImportParts(log, clock, nav, plots, refs, rejections, not_used, len(messages)), duplicates
