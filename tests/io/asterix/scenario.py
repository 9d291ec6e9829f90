"""The standard test recording: two radars in SITES and one not, their CAT034 north markers and
sector crossings, CAT048 plots of every kind the reader tells apart (Mode S, Mode 3/A valid,
smoothed, shared, garbled, not validated, primary only, test, simulated, field monitor), and
CAT021 ADS-B reports of every quality the reader tells apart. Encoded with libasterix
(:mod:`tests.io.asterix.encode`). ``EXPECTED`` lists what the reader must make of each.

Run ``python -m tests.io.asterix.scenario FOLDER`` to write the recording as raw, pcap and
pcapng files (and their gzip forms).
"""

from __future__ import annotations

import datetime as dt
import sys
from pathlib import Path

import pandas as pd

from tests.io.asterix.encode import (
    cat021_record,
    cat034_record,
    cat048_record,
    encode_recording,
    service_messages,
)

__all__ = [
    "DATE",
    "T0",
    "SITES",
    "RADARS",
    "PLOT_TARGETS",
    "ADSB_TARGETS",
    "standard_messages",
    "standard_recording",
    "sites_frame",
    "STAMP_DELAY_S",
]

DATE = dt.date(2024, 5, 1)
T0 = 36000.0
DURATION = 40.0
#: sensor -> (sac, sic, lat, lon, alt, scan period s, sectors)
RADARS = {
    "R1": (10, 1, 45.0, 5.0, 120.0, 4.0, 8),
    "R2": (10, 2, 45.3, 5.4, 80.0, 5.0, 16),
    "RX": (10, 9, 44.0, 4.0, 10.0, 6.0, 8),
}
SITES = ("R1", "R2")  # RX is not in SITES
#: R2 time-stamps its plots this late (s) against its own service messages: the clock check sees it.
STAMP_DELAY_S = {"R1": 0.0, "R2": 0.25, "RX": 0.0}
#: name -> (bearing deg, range NM, CAT048 keyword arguments, expected target id or a reason code)
PLOT_TARGETS = {
    "MS1": (30.0, 20.0, dict(typ=5, address=0x4CA1F3, mode_a=0o4521, extras=True), "4CA1F3"),
    "MS2": (75.0, 35.0, dict(typ=7, address=0x3C6DD2), "3C6DD2"),
    "MA1": (100.0, 40.0, dict(typ=2, mode_a=0o1234), "A1234"),
    "MA2": (140.0, 12.5, dict(typ=3, mode_a=0o6543, m3a_l=1), "A6543"),
    "MA3": (170.0, 60.0, dict(typ=2, mode_a=0o7000), ""),
    "MA4": (200.0, 80.0, dict(typ=2, mode_a=0o2345, g=1), ""),
    "MA5": (230.0, 90.0, dict(typ=2, mode_a=0o3456, v=1), ""),
    "PR1": (260.0, 15.0, dict(typ=1), ""),
    "TS1": (290.0, 25.0, dict(typ=5, address=0x111111, tst=1), "test_target"),
    "SM1": (310.0, 45.0, dict(typ=5, address=0x222222, sim=1), "simulated"),
    "RB1": (330.0, 5.0, dict(typ=2, mode_a=0o7777, rab=1), "field_monitor"),
}
#: address -> (cat021 keyword arguments, expected sigma_m or a reason code)
ADSB_TARGETS = {
    0x4CA1F3: (dict(nacp=10, gva=2, hires=True), "kept"),
    0x3C6DD2: (dict(nacp=8, gva=None, hires=False, time_item="073"), "kept"),
    0xAAAAAA: (dict(nacp=6), "low_nacp"),
    0xBBBBBB: (dict(nacp=None), "no_quality"),
    0xCCCCCC: (dict(nacp=9, height=False), "no_geometric_height"),
    0xDDDDDD: (dict(nacp=11, time_item="077"), "unplotted"),
    0xEEEEEE: (dict(nacp=9, sim=1), "simulated"),
}


def sites_frame() -> pd.DataFrame:
    rows = [(s, *RADARS[s][:5]) for s in SITES]
    frame = pd.DataFrame(rows, columns=["sensor", "sac", "sic", "lat_deg", "lon_deg", "alt_m"])
    frame["sigma_range_m"] = [30.0, 40.0]
    frame["sigma_bearing_deg"] = [0.1, 0.12]
    return frame


def _radar_messages(name: str, t0: float, duration: float) -> list:
    sac, sic, _, _, _, period, sectors = RADARS[name]
    out = []
    for t, kind, sector in service_messages(sac, sic, t0, t0 + duration, period, sectors):
        rec = cat034_record(
            "1.29",
            sac,
            sic,
            1 if kind == "north" else 2,
            t,
            sector,
            period if kind == "north" else None,
            extras=kind == "north",
        )
        out.append((t, 34, sac, sic, rec))
    for scan in range(int(duration // period)):
        for k, (bearing, rho, kwargs, _) in enumerate(PLOT_TARGETS.values()):
            bearing = (bearing + 0.5 * scan) % 360.0
            t = t0 + (scan + bearing / 360.0) * period + STAMP_DELAY_S[name]
            rec = cat048_record(
                "1.32",
                sac,
                sic,
                t,
                int(round(rho * 256)),
                int(round(bearing / 360 * 65536)) % 65536,
                **kwargs,
            )
            out.append((t, 48, sac, sic, rec))
    return out


def _adsb_messages(t0: float, duration: float) -> list:
    out = []
    for j, (address, (kwargs, _)) in enumerate(ADSB_TARGETS.items()):
        kwargs = dict(kwargs)
        height = kwargs.pop("height", True)
        for k in range(int(duration)):
            t = t0 + k + 0.1 * j
            rec = cat021_record(
                "2.6",
                20,
                1,
                t,
                address=address,
                lat_deg=45.1 + 0.001 * k,
                lon_deg=5.2 + 0.01 * j,
                height_ft_raw=1600 + k if height else None,
                **kwargs,
            )
            out.append((t, 21, 20, 1, rec))
    return out


def standard_messages(t0: float = T0, duration: float = DURATION) -> list:
    """All messages (time, category, sac, sic, libasterix record) of the standard recording."""
    out = []
    for name in RADARS:
        out += _radar_messages(name, t0, duration)
    return out + _adsb_messages(t0, duration)


def standard_recording(t0: float = T0, duration: float = DURATION, date: dt.date = DATE):
    """The standard recording (:class:`~tests.io.asterix.encode.Recording`)."""
    return encode_recording(standard_messages(t0, duration), date)


if __name__ == "__main__":
    folder = Path(sys.argv[1] if len(sys.argv) > 1 else "asterix-fixtures")
    rec = standard_recording()
    written = {**rec.write(folder), **{f"{k}.gz": p for k, p in rec.write(folder, gz=True).items()}}
    print({k: str(v) for k, v in written.items()})
    sites_frame().to_csv(folder / "SITES.csv", index=False)
    print(f"{len(rec.blocks)} data blocks in {len(rec.datagrams)} datagrams; SITES.csv in {folder}")
