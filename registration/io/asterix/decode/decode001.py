"""CAT001 (monoradar target reports, plots and tracks) fields, read from the walked records all at
once. Raw integers as transmitted, with their LSBs here; the plot rules are in
:mod:`registration.io.asterix.tables.plots01`, the full time of day (I001/141 is truncated) in
:mod:`registration.io.asterix.tables.truncated`.

| item | field | LSB |
|---|---|---|
| I001/010 | SAC, SIC | |
| I001/020 | TYP (8: 0 plot, 1 track), SIM (7), SSR/PSR (6-5), SPI (3), RAB (2); extension: TST (8) | |
| I001/040 | RHO, slant range, unsigned 16 bits | 1/128 NM |
| I001/040 | THETA, azimuth from north, clockwise, unsigned 16 bits | 360/2^16 deg |
| I001/070 | V (16, 1: not validated), G (15, garbled), L (14, smoothed), Mode 3/A (12 bits) | |
| I001/090 | V (16), G (15), Mode C height, two's complement 14 bits | 1/4 FL (25 ft) |
| I001/141 | truncated time of day: the time of day modulo 512 s, 16 bits | 1/128 s |

The record's UAP (plot or track) is the walker's (``Records.variant``), which is TYP.
"""

from __future__ import annotations

import numpy as np

from registration.io.asterix.decode.walker import Records
from registration.io.asterix.octets import signed, u8, u16

__all__ = ["WANTED", "RHO_LSB_NM", "THETA_LSB_DEG", "MODE_C_LSB_FL", "TRUNCATED_TOD_WRAP", "decode001"]

#: The items read (in both UAPs); the others are skipped.
WANTED = ("010", "020", "040", "070", "090", "141")
RHO_LSB_NM = 1.0 / 128.0
THETA_LSB_DEG = 360.0 / 65536.0
MODE_C_LSB_FL = 0.25
#: I001/141 counts 1/128 s modulo this (512 s).
TRUNCATED_TOD_WRAP = 1 << 16


def decode001(buf: np.ndarray, rec: Records) -> dict:
    """Per record (R,): ``has_<item>`` (bool) for each of :data:`WANTED` and the raw fields ``sac``,
    ``sic``, ``typ`` (the UAP walked: 0 plot, 1 track), ``sim``, ``ssrpsr`` (0 no detection
    indicated, 1 PSR, 2 SSR, 3 SSR + PSR), ``spi``, ``rab``, ``tst`` (0 without the extension),
    ``rho`` (1/128 NM), ``theta`` (360/2^16 deg), ``m3a_v``, ``m3a_g``, ``m3a_l``, ``m3a`` (12-bit
    code), ``mc_v``, ``mc_g``, ``mode_c`` (1/4 FL, signed), ``ttod`` (1/128 s modulo 512 s);
    0 where the item is absent. ``has_220``/``address`` (no Mode S address in CAT001) are all
    False/0, so that the CAT048 target id rules apply."""
    has = {name: rec.items[name] >= 0 for name in WANTED}
    at = {name: np.where(has[name], rec.items[name], 0) for name in WANTED}
    out = {f"has_{name}": h for name, h in has.items()}
    out["sac"], out["sic"] = u8(buf, at["010"]), u8(buf, at["010"] + 1)
    first = u8(buf, at["020"])
    out["typ"] = rec.variant.astype(np.int64) if rec.variant.size == first.size else first >> 7
    out["sim"], out["ssrpsr"] = (first >> 6) & 1, (first >> 4) & 3
    out["spi"], out["rab"] = (first >> 2) & 1, (first >> 1) & 1
    out["tst"] = (first & 1) * (u8(buf, at["020"] + 1) >> 7)
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
    out["ttod"] = u16(buf, at["141"])
    for name, h in has.items():  # absent items read as 0
        for key in _FIELDS[name]:
            out[key] = np.where(h, out[key], 0)
    out["has_220"] = np.zeros(first.size, dtype=bool)
    out["address"] = np.zeros(first.size, dtype=np.int64)
    return out


_FIELDS = {
    "010": ("sac", "sic"),
    "020": ("sim", "ssrpsr", "spi", "rab", "tst"),
    "040": ("rho", "theta"),
    "070": ("m3a_v", "m3a_g", "m3a_l", "m3a"),
    "090": ("mc_v", "mc_g", "mode_c"),
    "141": ("ttod",),
}
