"""CAT021 (ADS-B target reports) fields, read from the walked records all at once: raw integers
as transmitted, with their LSBs here. Editions 2.x and 0.2x differ in almost every item (field:
editions 2.x; editions 0.2x):

* source: I021/010 SAC, SIC; the same;
* address: I021/080, 24 bits; the same;
* RAB, SIM, TST: I021/040 first octet bit 2, first extension bits 6, 5; I021/040 bits 12, 14, 13
  (of 16);
* time (1/128 s): I021/071 (applicability for position), else I021/073 (reception of position),
  else I021/077 (report transmission); I021/030 (time of day);
* position: I021/131 (2 x 32 bits, 180/2^30 deg), else I021/130 (2 x 24 bits, 180/2^23 deg);
  I021/130: 2 x 24 bits, 180/2^23 deg (0.23), 2 x 32 bits, 180/2^25 deg (0.24-0.26);
* geometric height: I021/140, 16 bits signed, 6.25 ft, above the WGS-84 ellipsoid; the same;
* flight level: I021/145, 16 bits signed, 1/4 FL (25 ft), the barometric (pressure) altitude; the
  same;
* quality: I021/090: NACp (first extension bits 4-1), GVA (second extension bits 3-2); I021/090
  PA: NUCp (bits 4-1).
"""

from __future__ import annotations

import numpy as np

from registration.io.asterix.decode.walker import Records
from registration.io.asterix.octets import signed, u8, u16, u24, u32

__all__ = ["wanted", "decode021", "TOD_LSB_S", "HEIGHT_LSB_FT", "FLIGHT_LEVEL_LSB_FL", "FOOT_M"]

TOD_LSB_S = 1.0 / 128.0
HEIGHT_LSB_FT = 6.25
FLIGHT_LEVEL_LSB_FL = 0.25
#: The international foot (m).
FOOT_M = 0.3048


def wanted(edition: str) -> tuple:
    """The items read for ``edition``; the others are skipped."""
    if edition.startswith("0."):
        return ("010", "040", "030", "130", "080", "140", "145", "090")
    return ("010", "040", "071", "073", "077", "130", "131", "140", "145", "080", "090")


def _time(buf: np.ndarray, rec: Records, names: tuple) -> tuple[np.ndarray, np.ndarray]:
    """(time of day in 1/128 s, item it came from, '' for none) from the first of ``names`` present."""
    tod = np.zeros(rec.start.size, dtype=np.int64)
    source = np.full(rec.start.size, "", dtype=object)
    for name in reversed(names):
        h = rec.items[name] >= 0
        tod[h] = u24(buf, rec.items[name][h])
        source[h] = name
    return tod, source


def _position(buf: np.ndarray, rec: Records, edition: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(latitude, longitude in degrees, whether given) from I021/131, else I021/130."""
    n = rec.start.size
    lat, lon = np.zeros(n), np.zeros(n)
    o130 = rec.items["130"]
    h = o130 >= 0
    if edition == "0.23" or not edition.startswith("0."):
        lat[h] = signed(u24(buf, o130[h]), 24) * (180.0 / 2**23)
        lon[h] = signed(u24(buf, o130[h] + 3), 24) * (180.0 / 2**23)
    else:
        lat[h] = signed(u32(buf, o130[h]), 32) * (180.0 / 2**25)
        lon[h] = signed(u32(buf, o130[h] + 4), 32) * (180.0 / 2**25)
    if "131" in rec.items:
        o131 = rec.items["131"]
        hr = o131 >= 0
        lat[hr] = signed(u32(buf, o131[hr]), 32) * (180.0 / 2**30)
        lon[hr] = signed(u32(buf, o131[hr] + 4), 32) * (180.0 / 2**30)
        h = h | hr
    return lat, lon, h


def _flags_v2(buf: np.ndarray, o040: np.ndarray, h: np.ndarray, out: dict) -> None:
    first = u8(buf, o040)
    ext = first & 1
    second = u8(buf, o040 + 1) * ext
    out["rab"] = np.where(h, (first >> 1) & 1, 0)
    out["sim"] = np.where(h, (second >> 5) & 1, 0)
    out["tst"] = np.where(h, (second >> 4) & 1, 0)


def _quality_v2(buf: np.ndarray, o090: np.ndarray, h: np.ndarray, out: dict) -> None:
    first = u8(buf, o090)
    second = u8(buf, o090 + 1)
    third = u8(buf, o090 + 2)
    ext1 = h & (first & 1).astype(bool)
    ext2 = ext1 & (second & 1).astype(bool)
    out["has_nacp"], out["nacp"] = ext1, np.where(ext1, (second >> 1) & 0x0F, 0)
    out["has_gva"], out["gva"] = ext2, np.where(ext2, (third >> 1) & 0x03, 0)
    out["has_nucp"], out["nucp"] = np.zeros_like(h), np.zeros(h.size, dtype=np.int64)


def decode021(buf: np.ndarray, rec: Records, edition: str) -> dict:
    """Per record (R,): ``address`` (``has_080``), ``sac``, ``sic``, ``rab``, ``sim``, ``tst``,
    ``tod`` (1/128 s) and ``time_item`` (the item it came from, '' for none), ``lat_deg``,
    ``lon_deg`` (``has_position``), ``height`` (6.25 ft, ``has_140``), ``flight_level`` (1/4 FL,
    ``has_145``), ``nacp`` (``has_nacp``), ``gva`` (``has_gva``), ``nucp`` (``has_nucp``, editions
    0.2x); 0 where absent."""
    items = rec.items
    has = {name: items[name] >= 0 for name in wanted(edition)}
    at = {name: np.where(has[name], items[name], 0) for name in has}
    out = {f"has_{name}": h for name, h in has.items()}
    out["sac"] = np.where(has["010"], u8(buf, at["010"]), 0)
    out["sic"] = np.where(has["010"], u8(buf, at["010"] + 1), 0)
    out["address"] = np.where(has["080"], u24(buf, at["080"]), 0)
    out["height"] = np.where(has["140"], signed(u16(buf, at["140"]), 16), 0)
    out["flight_level"] = np.where(has["145"], signed(u16(buf, at["145"]), 16), 0)
    out["lat_deg"], out["lon_deg"], out["has_position"] = _position(buf, rec, edition)
    if edition.startswith("0."):
        flags = u16(buf, at["040"])
        out["sim"], out["tst"], out["rab"] = [np.where(has["040"], (flags >> b) & 1, 0) for b in (13, 12, 11)]
        out["tod"], out["time_item"] = _time(buf, rec, ("030",))
        h = has["090"]
        out["has_nucp"], out["nucp"] = h, np.where(h, u16(buf, at["090"]) & 0x0F, 0)
        out["has_nacp"], out["nacp"] = np.zeros_like(h), np.zeros(h.size, dtype=np.int64)
        out["has_gva"], out["gva"] = np.zeros_like(h), np.zeros(h.size, dtype=np.int64)
    else:
        _flags_v2(buf, at["040"], has["040"], out)
        out["tod"], out["time_item"] = _time(buf, rec, ("071", "073", "077"))
        _quality_v2(buf, at["090"], has["090"], out)
    return out
