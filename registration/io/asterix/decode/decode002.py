"""CAT002 (monoradar service messages) fields, read from the walked records all at once: raw
integers as transmitted, with their LSBs here, under the names of
:func:`~registration.io.asterix.decode.decode34.decode034` (the service table treats both alike).

| item | field | LSB |
|---|---|---|
| I002/010 | SAC, SIC | |
| I002/000 | message type: 1 north marker, 2 sector crossing, 3 south marker, 8/9 blind zone filter on/off | |
| I002/020 | sector number: azimuth of the sector's start from north, clockwise | 360/2^8 deg |
| I002/030 | time of day | 1/128 s |
| I002/041 | antenna rotation period | 1/128 s |
"""

from __future__ import annotations

import numpy as np

from registration.io.asterix.decode.walker import Records
from registration.io.asterix.octets import u8, u16, u24

__all__ = ["WANTED", "SOUTH_MARKER", "decode002"]

WANTED = ("010", "000", "020", "030", "041")
SOUTH_MARKER = 3


def decode002(buf: np.ndarray, rec: Records) -> dict:
    """Per record (R,): ``has_<item>`` for each of :data:`WANTED` and the raw fields ``sac``,
    ``sic``, ``msg_type``, ``tod`` (1/128 s), ``sector`` (360/2^8 deg), ``rotation`` (1/128 s);
    0 where the item is absent."""
    has = {name: rec.items[name] >= 0 for name in WANTED}
    at = {name: np.where(has[name], rec.items[name], 0) for name in WANTED}
    out = {f"has_{name}": h for name, h in has.items()}
    out["sac"] = np.where(has["010"], u8(buf, at["010"]), 0)
    out["sic"] = np.where(has["010"], u8(buf, at["010"] + 1), 0)
    out["msg_type"] = np.where(has["000"], u8(buf, at["000"]), 0)
    out["tod"] = np.where(has["030"], u24(buf, at["030"]), 0)
    out["sector"] = np.where(has["020"], u8(buf, at["020"]), 0)
    out["rotation"] = np.where(has["041"], u16(buf, at["041"]), 0)
    return out
