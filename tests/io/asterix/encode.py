"""ASTERIX recordings encoded with libasterix, the independent encoder (never with the reader's own
code), from arrays of plots, service messages and ADS-B reports; written as a raw recording and as
pcap and pcapng captures holding the same data blocks.

:func:`encode_recording` is the general entry (the acceptance scenario uses it too); the
record builders encode one record each, raw integers as transmitted (quantised here, so the
expected values are known exactly).
"""

from __future__ import annotations

import datetime as dt
import gzip
from dataclasses import dataclass, field
from pathlib import Path

from tests.io.asterix.containers import arp_frame, pcap_bytes, pcapng_bytes, tcp_frame, udp_frame

__all__ = [
    "SPECS",
    "cat048_record",
    "cat034_record",
    "cat021_record",
    "Recording",
    "encode_recording",
    "service_messages",
    "DAY_S",
]

DAY_S = 86400.0


def _gen():
    import asterix.generated as gen

    return gen


def spec(cat: int, edition: str):
    """The libasterix class of ``cat`` and ``edition`` (e.g. 48, "1.32")."""
    major, minor = edition.split(".")
    return getattr(_gen(), f"Cat_{cat:03d}_{int(major)}_{int(minor)}")


#: The editions the fixtures are encoded in unless told otherwise.
SPECS = {48: "1.32", 34: "1.29", 21: "2.6"}


def tod_raw(t_s: float) -> int:
    """Time of day in 1/128 s of ``t_s`` seconds since midnight (any day)."""
    return int(round(t_s * 128)) % (86400 * 128)


def cat048_record(
    edition: str,
    sac: int,
    sic: int,
    t_s: float,
    rho_raw: int,
    theta_raw: int,
    *,
    typ: int = 5,
    address: int | None = None,
    mode_a: int | None = None,
    v: int = 0,
    g: int = 0,
    m3a_l: int = 0,
    sim: int = 0,
    rab: int = 0,
    tst: int | None = None,
    fl_raw: int | None = None,
    extras: bool = False,
):
    """A CAT048 target report; ``fl_raw``: I048/090's flight level in 1/4 FL (V, G 0; None: no
    I048/090); ``extras`` adds items the reader skips (compound, repetitive, extended, explicit)
    around the ones it reads."""
    items = {
        "010": (("SAC", sac), ("SIC", sic)),
        "140": tod_raw(t_s),
        "040": (("RHO", rho_raw), ("THETA", theta_raw)),
    }
    first = (typ << 4) | (sim << 3) | (rab << 0)  # 7 bits: TYP(3) SIM RDP SPI RAB
    items["020"] = (first,) if tst is None else (first, tst << 6)
    if mode_a is not None:
        items["070"] = (("V", v), ("G", g), ("L", m3a_l), 0, ("MODE3A", mode_a))
    if address is not None:
        items["220"] = address
    if fl_raw is not None:
        items["090"] = (("V", 0), ("G", 0), ("FL", fl_raw % (1 << 14)))
    if extras:
        items.update(
            {
                "090": 0x0123,
                "130": {"SRL": 3, "SAM": 200, "APD": 7},
                "240": 0x123456789ABC,
                "250": [0x1122334455667788, 0x0102030405060708],
                "161": 1234,
                "042": 0x01020304,
                "200": 0x0A0B0C0D,
                "170": (0x40, 0x20),
                "030": [3, 5, 9],
                "120": {"CAL": 77, "RDS": [1, 2, 3]},
                "230": 0x2020,
                "SP": b"special",
                "RE": b"\x80\x01",
            }
        )
    return spec(48, edition).cv_record.create(items)


def cat034_record(
    edition: str,
    sac: int,
    sic: int,
    msg_type: int,
    t_s: float,
    sector_raw: int | None = None,
    rotation_s: float | None = None,
    extras: bool = False,
):
    """A CAT034 north marker (type 1) or sector crossing (type 2) message."""
    items = {"010": (("SAC", sac), ("SIC", sic)), "000": msg_type, "030": tod_raw(t_s)}
    if sector_raw is not None:
        items["020"] = sector_raw
    if rotation_s is not None:
        items["041"] = int(round(rotation_s * 128))
    if extras:
        items.update(
            {
                "050": {"COM": 0x10, "PSR": 0x20, "MDS": 0x1234},
                "060": {"COM": 1, "SSR": 2},
                "070": [0x1001, 0x2002],
                "090": 0x0102,
            }
        )
    return spec(34, edition).cv_record.create(items)


def cat021_record(
    edition: str,
    sac: int,
    sic: int,
    t_s: float,
    *,
    address: int | None,
    lat_deg: float,
    lon_deg: float,
    height_ft_raw: int | None,
    nacp: int | None,
    gva: int | None = 2,
    time_item: str = "071",
    hires: bool = True,
    sim: int = 0,
    tst: int = 0,
    rab: int = 0,
    fl_raw: int | None = None,
    extras: bool = False,
):
    """A CAT021 edition 2.x ADS-B report (``nacp`` None: no I021/090; ``height_ft_raw`` None: no
    I021/140; ``fl_raw``: I021/145's flight level in 1/4 FL, None: none), or edition 0.2x with
    ``nacp`` read as the NUCp of I021/090."""
    items = {"010": (("SAC", sac), ("SIC", sic))}
    old = edition.startswith("0.")
    if old:
        items["040"] = (sim << 13) | (tst << 12) | (rab << 11) | (1 << 5)
        items["030"] = tod_raw(t_s)
        octets = 3 if edition == "0.23" else 4
        lsb = 180.0 / 2 ** (23 if octets == 3 else 25)
        items["130"] = (
            ("LAT", int(round(lat_deg / lsb)) % 2 ** (8 * octets)),
            ("LON", int(round(lon_deg / lsb)) % 2 ** (8 * octets)),
        )
        if nacp is not None:
            items["090"] = nacp
    else:
        items["040"] = (rab,) if not (sim or tst) else (rab, (sim << 4) | (tst << 3))
        items[time_item] = tod_raw(t_s)
        key, bits = ("131", 30) if hires else ("130", 23)
        lsb = 180.0 / 2**bits
        size = 32 if hires else 24
        items[key] = (
            ("LAT", int(round(lat_deg / lsb)) % 2**size),
            ("LON", int(round(lon_deg / lsb)) % 2**size),
        )
        if nacp is not None:
            items["090"] = (0x0F, nacp) if gva is None else (0x0F, nacp, gva)
    if address is not None:
        items["080"] = address
    if height_ft_raw is not None:
        items["140"] = height_ft_raw % 65536
    if fl_raw is not None:
        items["145"] = fl_raw % 65536
    if extras and not old:
        items.update(
            {
                "161": 77,
                "015": 3,
                "150": 0x1234,
                "151": 0x0222,
                "210": 0x28,
                "070": 0x0FFF,
                "230": 0,
                "145": 300,
                "200": 1,
                "165": 2,
                "170": 0x010203040506,
                "020": 3,
                "220": {"WS": 12, "TRB": 1},
                "110": {"TIS": (0x40,), "TID": [0x01020304050607080910111213141]},
                "016": 9,
                "271": (0x2, 0x1),
                "250": [0x0102030405060708],
                "295": {"AOS": 1, "GH": 2, "SCC": 3},
                "SP": b"sp",
            }
        )
    return spec(21, edition).cv_record.create(items)


def service_messages(
    sac: int, sic: int, t0: float, t1: float, period: float, sectors: int = 8, rotation: bool = True
) -> list[tuple]:
    """(time, kind, sector_raw) of the north markers ("north", sector None) and sector crossings
    ("sector", raw 360/256 deg) of an antenna turning clockwise from north at ``t0`` with ``period``."""
    out = []
    k = 0
    while True:
        t = t0 + k * period / sectors
        if t >= t1:
            return out
        j = k % sectors
        if j == 0:
            out.append((t, "north", None))
        out.append((t, "sector", j * 256 // sectors))
        k += 1


@dataclass
class Recording:
    """Encoded data blocks in emission order, their emission times (s since midnight of ``date``,
    may pass 86400), and the datagrams (lists of block indices) of the captures."""

    blocks: list
    times: list
    datagrams: list
    date: dt.date
    extra_frames: dict = field(default_factory=dict)  # datagram index -> frame inserted before it

    def raw(self) -> bytes:
        return b"".join(self.blocks)

    def _frames(self) -> tuple[list, list]:
        midnight = dt.datetime.combine(self.date, dt.time(), dt.timezone.utc).timestamp()
        frames, times = [], []
        for k, group in enumerate(self.datagrams):
            t = midnight + max(self.times[i] for i in group) + 0.01
            if k in self.extra_frames:
                frames.append(self.extra_frames[k])
                times.append(t - 0.001)
            frames.append(
                udp_frame(b"".join(self.blocks[i] for i in group), ident=k, vlan=7 if k % 5 == 3 else None)
            )
            times.append(t)
        return frames, times

    def pcap(self, nanosecond: bool = False) -> bytes:
        return pcap_bytes(*self._frames(), nanosecond=nanosecond)

    def pcapng(self) -> bytes:
        return pcapng_bytes(*self._frames())

    def write(self, folder: Path, stem: str = "rec", gz: bool = False) -> dict:
        """Write ``stem.ast``, ``stem.pcap``, ``stem.pcapng`` (gzip-compressed with ``gz``, same names
        plus ``.gz``); returns form -> path."""
        folder.mkdir(parents=True, exist_ok=True)
        out = {}
        for form, data in (("raw", self.raw()), ("pcap", self.pcap()), ("pcapng", self.pcapng())):
            path = folder / f"{stem}.{'ast' if form == 'raw' else form}{'.gz' if gz else ''}"
            path.write_bytes(gzip.compress(data) if gz else data)
            out[form] = path
        return out


def encode_recording(
    messages: list[tuple],
    date: dt.date,
    *,
    max_records: int = 12,
    editions: dict | None = None,
    non_udp: bool = True,
) -> Recording:
    """Data blocks of ``messages``, each (time s since midnight of ``date``, category, sac, sic,
    libasterix record), grouped in emission order: consecutive messages of one category and
    source share a block (at most ``max_records``); every third datagram holds two blocks.
    ``non_udp``: an ARP and a TCP frame go into the captures too."""
    editions = {**SPECS, **(editions or {})}
    order = sorted(range(len(messages)), key=lambda k: messages[k][0])
    blocks, times, current, key = [], [], [], None
    for k in order + [None]:
        m = messages[k] if k is not None else None
        new_key = None if m is None else (m[1], m[2], m[3])
        if current and (new_key != key or len(current) >= max_records):
            cat = key[0]
            blocks.append(
                spec(cat, editions[cat]).create([messages[j][4] for j in current]).unparse().to_bytes()
            )
            times.append(messages[current[-1]][0])
            current = []
        if m is not None:
            current.append(k)
            key = new_key
    datagrams, k, n = [], 0, 0
    while k < len(blocks):
        size = 2 if n % 3 == 2 and k + 1 < len(blocks) else 1
        datagrams.append(list(range(k, k + size)))
        k, n = k + size, n + 1
    extra = {1: arp_frame(), 2: tcp_frame()} if non_udp and len(datagrams) > 2 else {}
    return Recording(blocks, times, datagrams, date, extra)
