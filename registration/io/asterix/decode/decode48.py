"""CAT048 (monoradar target reports) fields, read from the walked records all at once. Raw
integers as transmitted, with their LSBs here; the physical values and the plot rules are in
:mod:`registration.io.asterix.tables.plots48`.

| item | field | LSB |
|---|---|---|
| I048/010 | SAC, SIC | |
| I048/140 | time of day | 1/128 s |
| I048/020 | TYP (bits 8-6), SIM (5), RAB (2) of the first octet; TST (8) of the first extension | |
| I048/040 | RHO, slant range, unsigned 16 bits | 1/256 NM |
| I048/040 | THETA, azimuth from north, clockwise, unsigned 16 bits | 360/2^16 deg |
| I048/070 | V (16, 1: not validated), G (15, garbled), L (14, smoothed), Mode 3/A (12 bits) | |
| I048/090 | V (16, 1: not validated), G (15, garbled), flight level (two's complement, 14 bits) | 1/4 FL |
| I048/220 | aircraft address, 24 bits | |
"""

from __future__ import annotations

import numpy as np

from registration.io.asterix.decode.walker import Records
from registration.io.asterix.octets import signed, u8, u16, u24

__all__ = ["WANTED", "TOD_LSB_S", "RHO_LSB_NM", "THETA_LSB_DEG", "FLIGHT_LEVEL_LSB_FL", "decode048"]

#: The items read; the others are skipped.
WANTED = ("010", "140", "020", "040", "070", "090", "220")
TOD_LSB_S = 1.0 / 128.0
RHO_LSB_NM = 1.0 / 256.0
THETA_LSB_DEG = 360.0 / 65536.0
FLIGHT_LEVEL_LSB_FL = 0.25


def decode048(buf: np.ndarray, rec: Records) -> dict:
    """Per record (R,): ``has_<item>`` (bool) for each of :data:`WANTED` and the raw fields ``sac``,
    ``sic``, ``tod`` (1/128 s), ``typ``, ``sim``, ``rab``, ``tst`` (0 when I048/020 has no first
    extension), ``rho`` (1/256 NM), ``theta`` (360/2^16 deg), ``m3a_v``, ``m3a_g``, ``m3a_l``,
    ``m3a`` (12-bit code), ``mc_v``, ``mc_g``, ``mode_c`` (1/4 FL, signed), ``address``; 0 where the
    item is absent."""
    has = {name: rec.items[name] >= 0 for name in WANTED}
    at = {name: np.where(has[name], rec.items[name], 0) for name in WANTED}
    out = {f"has_{name}": h for name, h in has.items()}
    out["sac"], out["sic"] = u8(buf, at["010"]), u8(buf, at["010"] + 1)
    out["tod"] = u24(buf, at["140"])
    first = u8(buf, at["020"])
    ext = first & 1
    out["typ"], out["sim"], out["rab"] = first >> 5, (first >> 4) & 1, (first >> 1) & 1
    out["tst"] = ext * (u8(buf, at["020"] + 1) >> 7)
    out["rho"], out["theta"] = u16(buf, at["040"]), u16(buf, at["040"] + 2)
    m3a = u16(buf, at["070"])
    out["m3a_v"], out["m3a_g"], out["m3a_l"], out["m3a"] = (
        m3a >> 15,
        (m3a >> 14) & 1,
        (m3a >> 13) & 1,
        m3a & 0x0FFF,
    )
    mc = u16(buf, at["090"])
    out["mc_v"], out["mc_g"], out["mode_c"] = mc >> 15, (mc >> 14) & 1, signed(mc & 0x3FFF, 14)
    out["address"] = u24(buf, at["220"])
    for name, h in has.items():  # absent items read as 0
        for key in _FIELDS[name]:
            out[key] = np.where(h, out[key], 0)
    return out


_FIELDS = {
    "010": ("sac", "sic"),
    "140": ("tod",),
    "020": ("typ", "sim", "rab", "tst"),
    "040": ("rho", "theta"),
    "070": ("m3a_v", "m3a_g", "m3a_l", "m3a"),
    "090": ("mc_v", "mc_g", "mode_c"),
    "220": ("address",),
}
