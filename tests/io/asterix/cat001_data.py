"""CAT001 plots and tracks with CAT002 service messages, encoded with libasterix (the independent
encoder), and libasterix's own decoding of such recordings record by record (its UAP chosen per
record by the TYP bit of I001/020, libasterix's ``cv_selector``).

The recording: radars A and B send CAT002 north markers and sector crossings and CAT001 plots
(and A tracks); radar C sends CAT001 plots only (its full time comes from the others' messages).
It runs from 23:53:20 across the 512 s wrap of I001/141 at 86016 s and across midnight; plots
are emitted 0.4 s after their time stamp, so a plot stamped just before north comes after the
north marker in the stream. Beside it the helpers of ``test_cat001.py`` (buffers, block bounds,
libasterix item values, random plots and tracks, mutations).
"""

from __future__ import annotations

import datetime as dt

import numpy as np
import pandas as pd

from registration.io.asterix.octets import PAD
from tests.io.asterix.encode import encode_recording, service_messages, spec, tod_raw
from tests.io.asterix.libasterix_help import random_items

__all__ = [
    "DATE",
    "RADARS",
    "EDITIONS",
    "cat001_messages",
    "cat001_recording",
    "parse_cat001",
    "sites",
    "buffer_of",
    "block_bounds",
    "item_value",
    "item_quantity",
    "random_cat001",
    "mutate",
]

DATE = dt.date(2024, 5, 1)
#: name -> (sac, sic, sends CAT002, scan period s)
RADARS = {"A": (30, 1, True, 12.0), "B": (30, 2, True, 10.0), "C": (30, 3, False, 15.0)}
EDITIONS = {1: "1.4", 2: "1.2"}
T0, T1 = 86000.0, 86430.0
EMIT_DELAY_S = 0.4


def sites() -> pd.DataFrame:
    rows = [
        (n, s, i, 48.0 + k * 0.1, 11.0, 500.0, 30.0, 0.1)
        for k, (n, (s, i, _, _)) in enumerate(RADARS.items())
    ]
    columns = ["sensor", "sac", "sic", "lat_deg", "lon_deg", "alt_m", "sigma_range_m", "sigma_bearing_deg"]
    return pd.DataFrame(rows, columns=columns)


def cat001_plot(edition: str, sac: int, sic: int, t_s: float, rho_raw: int, theta_raw: int, **kw):
    """A CAT001 plot record (TYP 0); ``mode_a`` (code, v, g), ``fl_raw`` (1/4 FL), ``ssrpsr``, ``sim``,
    ``tst`` optional."""
    first = (0 << 6) | (kw.get("sim", 0) << 5) | (kw.get("ssrpsr", 3) << 3) | (kw.get("rab", 0) << 0)
    items = {
        "010": (("SAC", sac), ("SIC", sic)),
        "020": (first,) if kw.get("tst") is None else (first, kw["tst"] << 6),
        "040": (("RHO", rho_raw), ("THETA", theta_raw)),
        "141": tod_raw(t_s) % 65536,
    }
    if kw.get("mode_a") is not None:
        code, v, g = kw["mode_a"]
        items["070"] = (("V", v), ("G", g), ("L", 0), 0, ("MODE3A", code))
    if kw.get("fl_raw") is not None:
        items["090"] = (("V", 0), ("G", 0), ("HGT", kw["fl_raw"] % (1 << 14)))
    if kw.get("extras"):
        items.update({"130": [0x11, 0x22, 0x33], "131": 200, "120": 7, "030": [5], "SP": b"abc"})
    return spec(1, edition).cv_uap.cv_uaps["plot"].create(items)


def cat001_track(edition: str, sac: int, sic: int, t_s: float, rho_raw: int, theta_raw: int):
    """A CAT001 track record (TYP 1) with items of the track UAP."""
    items = {
        "010": (("SAC", sac), ("SIC", sic)),
        "020": ((1 << 6) | (2 << 3),),
        "161": 77,
        "040": (("RHO", rho_raw), ("THETA", theta_raw)),
        "200": 0x01020304,
        "070": (("V", 0), ("G", 0), ("L", 0), 0, ("MODE3A", 0o4321)),
        "141": tod_raw(t_s) % 65536,
        "170": (0x10, 0x20),
        "210": [3, 5],
    }
    return spec(1, edition).cv_uap.cv_uaps["track"].create(items)


def cat002_record(edition: str, sac: int, sic: int, msg_type: int, t_s: float, sector=None, period=None):
    """A CAT002 message (``msg_type`` 1 north marker, 2 sector crossing) at ``t_s``."""
    items = {"010": (("SAC", sac), ("SIC", sic)), "000": msg_type, "030": tod_raw(t_s)}
    if sector is not None:
        items["020"] = sector
    if period is not None:
        items["041"] = int(round(period * 128))
    return spec(2, edition).cv_record.create(items)


def cat001_messages(editions: dict | None = None, seed: int = 1) -> tuple[list, list]:
    """(messages for :func:`~tests.io.asterix.encode.encode_recording`, truth): truth per CAT001
    plot: (stamp time s since midnight of DATE, radar, is plot)."""
    editions = {**EDITIONS, **(editions or {})}
    rng = np.random.default_rng(seed)
    messages, truth = [], []
    for name, (sac, sic, cat002, period) in RADARS.items():
        t0 = T0 + {"A": 0.0, "B": 0.7, "C": 1.3}[name]
        if cat002:
            for t, kind, sector in service_messages(sac, sic, t0, T1, period, sectors=2):
                rec = cat002_record(editions[2], sac, sic, 1 if kind == "north" else 2, t, sector, period)
                messages.append((t, 2, sac, sic, rec))
        for scan in range(int((T1 - t0) // period)):
            for k in range(3):
                bearing = (40.0 + 120.0 * k + 7.3 * scan) % 360.0
                if k == 2:
                    bearing = 359.5  # stamped just before the next north: emitted after its marker
                t = t0 + (scan + bearing / 360.0) * period
                theta = int(bearing / 360.0 * 65536) % 65536
                rho = int(rng.integers(1, 1 << 15))
                kw = {
                    "mode_a": (int(rng.integers(0, 4096)), int(rng.random() < 0.2), int(rng.random() < 0.1))
                    if k != 1
                    else None,
                    "fl_raw": int(rng.integers(-48, 5000)) if k == 0 else None,
                    "ssrpsr": 1 if k == 1 else 3,
                    "extras": scan % 3 == 0,
                }
                messages.append(
                    (t + EMIT_DELAY_S, 1, sac, sic, cat001_plot(editions[1], sac, sic, t, rho, theta, **kw))
                )
                truth.append((t, name))
            if name == "A":
                t = t0 + (scan + 0.5) * period
                messages.append(
                    (t + EMIT_DELAY_S, 1, sac, sic, cat001_track(editions[1], sac, sic, t, 1000, 32768))
                )
    return messages, truth


def cat001_recording(editions: dict | None = None):
    """The recording (:class:`~tests.io.asterix.encode.Recording`) and the truth of
    :func:`cat001_messages`."""
    messages, truth = cat001_messages(editions)
    return encode_recording(messages, DATE, editions={**EDITIONS, **(editions or {})}), truth


def parse_cat001(data: bytes, edition: str) -> list:
    """Per CAT001 record of the raw recording ``data`` (blocks of other categories skipped), as
    libasterix parses it: (offset of the record, UAP name, record). Each record is parsed with
    every UAP; the one kept is the one whose I001/020 TYP selects it (libasterix's selector)."""
    from asterix.base import Bits, ParsingMode

    uap = spec(1, edition).cv_uap
    (path, table) = uap.cv_selector
    out, offset = [], 0
    while offset < len(data):
        cat, size = data[offset], int.from_bytes(data[offset + 1 : offset + 3], "big")
        pos = offset + 3
        while cat == 1 and pos < offset + size:
            chosen = None
            for name, record in uap.cv_uaps.items():
                result = record._parse(ParsingMode.StrictParsing, Bits.from_bytes(data[pos : offset + size]))
                if isinstance(result, ValueError):
                    continue
                rec, _ = result
                typ = rec.get_item(path[0]).variation.get_item(path[1]).variation.unparse().to_uinteger()
                if table[typ] == name:
                    chosen = (pos, name, rec)
            assert chosen is not None, pos
            out.append(chosen)
            pos += len(chosen[2].unparse()) // 8
        offset += size
    return out


def buffer_of(data: bytes) -> np.ndarray:
    """``data`` as the reader's padded uint8 buffer."""
    buf = np.zeros(len(data) + PAD, dtype=np.uint8)
    buf[: len(data)] = np.frombuffer(data, dtype=np.uint8)
    return buf


def block_bounds(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    """(starts, ends) of the data blocks of a raw recording."""
    starts, p = [], 0
    while p < len(data):
        starts.append(p)
        p += int.from_bytes(data[p + 1 : p + 3], "big")
    s = np.array(starts, dtype=np.int64)
    return s, np.append(s[1:], len(data))


def item_value(rec, *path):
    """The raw value of an item (or a subitem along ``path``) of a libasterix record, None if absent."""
    item = rec.get_item(path[0])
    if item is None:
        return None
    var = item.variation
    for name in path[1:]:
        var = var.get_item(name).variation
    return var.unparse().to_uinteger()


def item_quantity(rec, unit, *path):
    """The value in ``unit`` of an item or subitem of a libasterix record (libasterix's scaling)."""
    var = rec.get_item(path[0]).variation
    for name in path[1:]:
        var = var.get_item(name).variation
    return var.content.as_quantity(unit)


def random_cat001(edition: str, rng: np.random.Generator, blocks: int) -> bytes:
    """Data blocks of random plots and tracks (random items and contents, TYP set to the UAP)."""
    uap = spec(1, edition).cv_uap
    out = []
    for _ in range(blocks):
        records = []
        for _ in range(int(rng.integers(1, 9))):
            typ = int(rng.integers(0, 2))
            record = uap.cv_uaps[("plot", "track")[typ]]
            items = random_items(record, rng)
            first = items["020"][0] if "020" in items else int(rng.integers(0, 128))
            items["020"] = ((first & 0x3F) | (typ << 6), *items.get("020", (0,))[1:])
            records.append(record.create(items))
        out.append(spec(1, edition).create(records).unparse().to_bytes())
    return b"".join(out)


def mutate(data: bytes, rng: np.random.Generator) -> bytes:
    """One to three mutations: octets overwritten, a stretch cut or inserted, an FSPEC-like octet."""
    out = bytearray(data)
    for _ in range(int(rng.integers(1, 4))):
        n, kind = len(out), int(rng.integers(0, 4))
        at, span = int(rng.integers(0, n)), int(rng.integers(1, 32))
        if kind == 0:
            for k in rng.integers(0, n, size=int(rng.integers(1, 12))):
                out[int(k)] = int(rng.integers(0, 256))
        elif kind == 1:
            del out[at : at + span]
        elif kind == 2:
            out[at:at] = rng.bytes(span)
        else:
            out[at : at + 1] = bytes([int(rng.choice([0x80, 0xC0, 0xFF, 0x01]))])
    return bytes(out)
