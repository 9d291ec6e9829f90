"""The records of many data blocks of one category walked at once (numpy): FSPEC, then each item
present in FRN order, its length from the UAP (:mod:`registration.io.asterix.decode.uap`): the offsets
of the items the caller wants are kept, the others skipped.

The records of a data block follow each other, so a block's second record is found only once its
first is walked. The walk therefore advances all blocks together, one record of each per step
(a "wavefront"): a recording of N records in B blocks of at most M records takes M steps over
about N/M lanes each. A record found bad (:func:`registration.io.asterix.decode.scalar.explain_record`
says why) ends the walk of its block: the records after it cannot be found.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.io.asterix.decode.uap import (
    Compound,
    Explicit,
    Extended,
    Fixed,
    MultiUap,
    Repetitive,
    RepetitiveFx,
    Uap,
)

__all__ = ["Records", "walk_records", "MAX_REPETITIONS"]

#: The most FX-chained repetitions read before an item is declared bad.
MAX_REPETITIONS = 1 << 16


@dataclass
class Records:
    """The records found, in block order then record order, (R,) each: ``start`` (offset of the
        FSPEC), ``end`` (one past the last octet), ``block`` (index into the blocks walked), and per
        wanted item name its offset (-1: absent) in ``items``. ``bad_start``, ``bad_block``: the
        records found bad (one at most per block; the rest of that block is not walked). ``variant``:
    per record the index of its UAP in a :class:`~registration.io.asterix.decode.uap.MultiUap` (CAT001:
    0 plot, 1 track), all 0 for a category of one UAP."""

    start: np.ndarray
    end: np.ndarray
    block: np.ndarray
    items: dict
    bad_start: np.ndarray
    bad_block: np.ndarray
    variant: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))


def _fspec(buf: np.ndarray, at: np.ndarray, octets: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """FSPEC bits (octet j at bits 8 (octets - 1 - j) of a uint64), its length in octets, and
    whether the FX bit of its last allowed octet is still set (too long)."""
    bits = np.zeros(at.size, dtype=np.uint64)
    length = np.zeros(at.size, dtype=np.int64)
    cont = np.ones(at.size, dtype=bool)
    for j in range(octets):
        octet = buf[at + j]
        bits |= np.where(cont, octet, 0).astype(np.uint64) << np.uint64(8 * (octets - 1 - j))
        length += cont
        cont &= (octet & 1).astype(bool)
        if not cont.any():
            break
    return bits, length, cont


def _bit(frn: int, octets: int) -> int:
    """Bit of FRN ``frn`` (from 1) in the uint64 of :func:`_fspec`."""
    j, k = divmod(frn - 1, 7)
    return 8 * (octets - 1 - j) + 7 - k


def _fx_mask(octets: int) -> int:
    return sum(1 << (8 * j) for j in range(octets))


def _extended(buf: np.ndarray, at: np.ndarray, groups: tuple) -> tuple[np.ndarray, np.ndarray]:
    size = np.zeros(at.size, dtype=np.int64)
    cont = np.ones(at.size, dtype=bool)
    for octets, fx in groups:
        size += octets * cont
        if not fx:
            return size, np.zeros(at.size, dtype=bool)
        cont &= (buf[at + size - 1] & 1).astype(bool)
        if not cont.any():
            break
    return size, cont


def _repetitive_fx(buf: np.ndarray, at: np.ndarray, octets: int) -> tuple[np.ndarray, np.ndarray]:
    size = np.full(at.size, octets, dtype=np.int64)
    cont = (buf[at + size - 1] & 1).astype(bool)
    for _ in range(MAX_REPETITIONS):
        if not cont.any():
            break
        size += octets * cont
        cont &= (buf[at + size - 1] & 1).astype(bool)
    return size, cont


def _compound(buf: np.ndarray, at: np.ndarray, subitems: tuple) -> tuple[np.ndarray, np.ndarray]:
    octets = -(-len(subitems) // 7)
    bits, size, bad = _fspec(buf, at, octets)
    union = int(np.bitwise_or.reduce(bits)) if bits.size else 0
    for k in range(1, octets * 7 + 1):
        b = _bit(k, octets)
        if not (union >> b) & 1:
            continue
        present = ((bits >> np.uint64(b)) & np.uint64(1)).astype(bool)
        layout = subitems[k - 1] if k <= len(subitems) else None
        if layout is None:
            bad |= present
            continue
        idx = np.flatnonzero(present)
        sub, sub_bad = item_size(buf, at[idx] + size[idx], layout)
        size[idx] += sub
        bad[idx] |= sub_bad
    return size, bad


def item_size(buf: np.ndarray, at: np.ndarray, layout: object) -> tuple[np.ndarray, np.ndarray]:
    """(octets, bad) of items of ``layout`` starting at offsets ``at``: bad for an extended item
    with more extensions than its layout has, an explicit length of 0, a spare compound subfield
    set, or a compound FSPEC longer than its subitems allow."""
    if isinstance(layout, Fixed):
        return np.full(at.size, layout.octets, dtype=np.int64), np.zeros(at.size, dtype=bool)
    if isinstance(layout, Extended):
        return _extended(buf, at, layout.groups)
    if isinstance(layout, RepetitiveFx):
        return _repetitive_fx(buf, at, layout.octets)
    if isinstance(layout, Repetitive):
        count = np.zeros(at.size, dtype=np.int64)
        for j in range(layout.rep):
            count = (count << 8) | buf[at + j]
        return layout.rep + count * layout.octets, np.zeros(at.size, dtype=bool)
    if isinstance(layout, Explicit):
        size = buf[at].astype(np.int64)
        return size, size == 0
    if isinstance(layout, Compound):
        return _compound(buf, at, layout.subitems)
    raise TypeError(f"unknown item layout {layout!r}")


def _step(buf: np.ndarray, pos: np.ndarray, end: np.ndarray, uap: Uap, wanted: tuple) -> tuple:
    """One record per lane: (its end, bad, offsets of the wanted items)."""
    octets = uap.fspec_octets
    bits, length, bad = _fspec(buf, pos, octets)
    bad |= (bits & np.uint64(~_fx_mask(octets) & ((1 << 8 * octets) - 1))) == 0  # no item
    cursor = pos + length
    union = int(np.bitwise_or.reduce(bits)) if bits.size else 0
    offsets = {name: np.full(pos.size, -1, dtype=np.int64) for name in wanted}
    for k in range(1, octets * 7 + 1):
        b = _bit(k, octets)
        if not (union >> b) & 1:
            continue
        present = ((bits >> np.uint64(b)) & np.uint64(1)).astype(bool)
        item = uap.items[k - 1] if k <= len(uap.items) else None
        if item is None:
            bad |= present
            continue
        name, layout = item
        if name in offsets:
            offsets[name][present] = cursor[present]
        if isinstance(layout, Fixed):
            cursor += layout.octets * present
        else:
            idx = np.flatnonzero(present)
            size, item_bad = item_size(buf, cursor[idx], layout)
            cursor[idx] += size
            bad[idx] |= item_bad
    bad |= cursor > end
    return cursor, bad, offsets


def _selected(buf: np.ndarray, pos: np.ndarray, uap: MultiUap) -> tuple[np.ndarray, np.ndarray]:
    """(variant index, no selecting item) per record at ``pos``: the selecting item's offset from
    the FSPEC and the FRNs before it, which are Fixed and the same in every variant."""
    octets = uap.fspec_octets
    first = uap.variants[0]
    frn = first.frn(uap.selector)
    bits, length, _ = _fspec(buf, pos, octets)
    cursor = pos + length
    for k in range(1, frn):
        present = ((bits >> np.uint64(_bit(k, octets))) & np.uint64(1)).astype(np.int64)
        cursor += first.items[k - 1][1].octets * present
    has = ((bits >> np.uint64(_bit(frn, octets))) & np.uint64(1)).astype(bool)
    return np.where(has & (buf[cursor] & uap.selector_mask).astype(bool), 1, 0), ~has


def _step_any(buf: np.ndarray, pos: np.ndarray, end: np.ndarray, uap: Uap | MultiUap, wanted: tuple) -> tuple:
    """:func:`_step` with each record's UAP: (its end, bad, offsets, variant index)."""
    if isinstance(uap, Uap):
        return (*_step(buf, pos, end, uap, wanted), np.zeros(pos.size, dtype=np.int64))
    variant, unknown = _selected(buf, pos, uap)
    cursor, bad = np.zeros(pos.size, dtype=np.int64), unknown.copy()
    offsets = {name: np.full(pos.size, -1, dtype=np.int64) for name in wanted}
    for k, one in enumerate(uap.variants):
        idx = np.flatnonzero((variant == k) & ~unknown)
        if idx.size == 0:
            continue
        names = tuple(n for n in wanted if any(i is not None and i[0] == n for i in one.items))
        c, b, o = _step(buf, pos[idx], end[idx], one, names)
        cursor[idx], bad[idx] = c, b
        for name in names:
            offsets[name][idx] = o[name]
    return cursor, bad, offsets, variant


def walk_records(
    buf: np.ndarray, start: np.ndarray, end: np.ndarray, uap: Uap | MultiUap, wanted: tuple = ()
) -> Records:
    """The records of the data blocks [start, end) (offsets of their headers and ends in ``buf``),
    all of ``uap``'s category, and the offsets of the ``wanted`` items (names such as "040"). A
    :class:`~registration.io.asterix.decode.uap.MultiUap` walks each record with the UAP its
    selecting item names; a record without that item is bad."""
    lanes = np.flatnonzero(start + 3 < end)
    pos, stop = start[lanes] + 3, end[lanes]
    found: dict[str, list[np.ndarray]] = {k: [] for k in ("start", "end", "block", "variant", *wanted)}
    bad_start: list[np.ndarray] = []
    bad_block: list[np.ndarray] = []
    while lanes.size:
        cursor, bad, offsets, variant = _step_any(buf, pos, stop, uap, wanted)
        ok = ~bad
        found["start"].append(pos[ok])
        found["end"].append(cursor[ok])
        found["block"].append(lanes[ok])
        found["variant"].append(variant[ok])
        for name in wanted:
            found[name].append(offsets[name][ok])
        bad_start.append(pos[bad])
        bad_block.append(lanes[bad])
        more = ok & (cursor < stop)
        lanes, pos, stop = lanes[more], cursor[more], stop[more]
    cat = {k: np.concatenate(v) if v else np.zeros(0, dtype=np.int64) for k, v in found.items()}
    order = np.lexsort((cat["start"], cat["block"]))
    return Records(
        cat["start"][order],
        cat["end"][order],
        cat["block"][order],
        {name: cat[name][order] for name in wanted},
        np.concatenate(bad_start) if bad_start else np.zeros(0, dtype=np.int64),
        np.concatenate(bad_block) if bad_block else np.zeros(0, dtype=np.int64),
        cat["variant"][order].astype(np.int64),
    )
