"""Which framing a file is in, told by content: each framing of :data:`FRAMINGS` is walked over the
first records of the file, and it "walks" when its records chain (to the end of the sample or of
the file) and the data blocks inside are plausible ASTERIX. Raw ASTERIX ('netto': data blocks end to
end) is judged by plausibility too, last.

Plausible ASTERIX (:func:`plausible`): most octets lie in data blocks of known categories
(:data:`~registration.io.asterix.capture.model.ASTERIX_CATEGORIES`) whose lengths chain, and the
times of day of the first record of sampled CAT048, CAT034 and CAT021 blocks, in file order, mostly
advance (a step back of up to a minute or forward of up to an hour; the midnight wrap counts as a
step forward; a replayed tail is one step back among many).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from registration.io.asterix.capture.framings import (
    Framed,
    walk_gps,
    walk_ioss,
    walk_ioss_seq,
    walk_oradis,
    walk_rff,
)
from registration.io.asterix.capture.hdlc import walk_hdlc
from registration.io.asterix.capture.model import ASTERIX_CATEGORIES
from registration.io.asterix.decode.decode21 import decode021
from registration.io.asterix.decode.decode21 import wanted as wanted021
from registration.io.asterix.decode.decode34 import WANTED as WANTED034
from registration.io.asterix.decode.decode34 import decode034
from registration.io.asterix.decode.decode48 import WANTED as WANTED048
from registration.io.asterix.decode.decode48 import decode048
from registration.io.asterix.decode.uap import DEFAULT_EDITIONS, uap_for
from registration.io.asterix.decode.walker import walk_records

__all__ = [
    "FRAMINGS",
    "FRAMING_NAMES",
    "Verdict",
    "plausible",
    "framed_verdict",
    "chain_blocks",
    "SAMPLE_RECORDS",
]

#: Framing name -> reader, in the order detection tries them ('netto', raw ASTERIX, comes last).
FRAMINGS: dict[str, Callable[..., Framed]] = {
    "gps": walk_gps,
    "rff": walk_rff,
    "ioss_seq": walk_ioss_seq,
    "ioss": walk_ioss,
    "oradis": walk_oradis,
    "hdlc": walk_hdlc,
}
#: The values of ``framing`` (``--framing``): 'auto' (detect), 'netto' (raw data blocks) or a framing.
FRAMING_NAMES = ("auto", "netto", *FRAMINGS)
#: Records walked to tell a framing.
SAMPLE_RECORDS = 256
#: Share of the sampled octets that must lie in chained blocks of known categories (in a framing's
#: records; a raw file, whose corrupt stretches are skipped, needs RAW_MIN_KNOWN).
MIN_KNOWN, RAW_MIN_KNOWN = 0.9, 0.5
#: Steps of the time of day (s) taken as advancing: back by up to this, forward by up to _AHEAD_S.
_BACK_S, _AHEAD_S = 60.0, 3600.0
#: Blocks per category whose first record's time of day is read.
_TIME_SAMPLE = 64


@dataclass
class Verdict:
    """``ok`` whether the blocks look like ASTERIX; ``why`` in words when not."""

    ok: bool
    why: str = ""


def chain_blocks(buf: np.ndarray, start: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The data blocks of each stretch [start, end) that chain exactly to its end: (block starts,
    block ends) of the stretches that do (a stretch that does not chain gives none)."""
    mv = memoryview(buf)  # type: ignore[arg-type]  # a uint8 array is a buffer
    starts: list = []
    ends: list = []
    for s, e in zip(start.tolist(), end.tolist()):
        p, mine = s, []
        while p + 3 <= e:
            length = (mv[p + 1] << 8) | mv[p + 2]
            if length < 3 or p + length > e:
                break
            mine.append(p)
            p += length
        if p == e and mine:
            starts += mine
            ends += mine[1:] + [e]
    return np.array(starts, dtype=np.int64), np.array(ends, dtype=np.int64)


#: The octets of a data block read for its first record's time of day (records are far shorter).
_FIRST_RECORD_OCTETS = 1024


def _first_times(buf: np.ndarray, start: np.ndarray, end: np.ndarray, cats: np.ndarray) -> np.ndarray:
    """(offset, time of day s) of the first record of up to _TIME_SAMPLE blocks each of CAT048,
    CAT034, CAT021 that has a time of day item (it may be 24 h or more), ordered by offset."""
    out = []
    for cat, decode, wanted in (
        (48, decode048, WANTED048),
        (34, decode034, WANTED034),
        (21, None, wanted021(DEFAULT_EDITIONS[21])),
    ):
        sel = np.flatnonzero(cats == cat)[:_TIME_SAMPLE]
        if not sel.size:
            continue
        edition = DEFAULT_EDITIONS[cat]
        # the first record of each block is all that is read: the walk stops _FIRST_RECORD_OCTETS in
        # (a block of 65 000 one-octet records would otherwise be walked whole, file after file)
        cut = np.minimum(end[sel], start[sel] + _FIRST_RECORD_OCTETS)
        rec = walk_records(buf, start[sel], cut, uap_for(cat, edition), wanted)
        if not rec.start.size:
            continue
        f = decode(buf, rec) if decode is not None else decode021(buf, rec, edition)
        has = (f["time_item"] != "") if cat == 21 else f["has_140" if cat == 48 else "has_030"]
        _, first = np.unique(rec.block, return_index=True)
        first = first[has[first]]
        out.append(np.column_stack([rec.start[first].astype(float), f["tod"][first] / 128.0]))
    if not out:
        return np.zeros((0, 2))
    a = np.concatenate(out)
    return a[np.argsort(a[:, 0], kind="stable")]


def plausible(
    buf: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    cats: np.ndarray,
    size: int,
    what: str = "",
    min_known: float = MIN_KNOWN,
) -> Verdict:
    """Whether the data blocks (start, end, category) found in ``size`` sampled octets look like
    ASTERIX: at least ``min_known`` of the octets in blocks of known categories, and times of day
    that advance. ``what``: the octets in words."""
    if not start.size:
        return Verdict(False, "no data blocks")
    known = np.isin(cats, list(ASTERIX_CATEGORIES))
    share = float((end[known] - start[known]).sum()) / max(size, 1)
    if share < min_known:
        return Verdict(
            False,
            f"only {100 * share:.0f} % of {what or f'the first {size} bytes'} lie in data blocks of known "
            "categories "
            f"({start.size} blocks of {np.unique(cats).size} categories)",
        )
    tod = _first_times(buf, start, end, cats)[:, 1]
    if tod.size >= 4:
        valid = tod[tod < 86400.0]
        step = (np.diff(valid) + 43200.0) % 86400.0 - 43200.0
        ahead = float(((step >= -_BACK_S) & (step <= _AHEAD_S)).mean()) if step.size else 0.0
        if valid.size < 0.75 * tod.size or ahead < 0.6:
            return Verdict(
                False,
                f"the times of day of {tod.size} sampled CAT048/034/021 blocks do not advance "
                f"({valid.size} valid, {100 * ahead:.0f} % of the steps forward by up to an hour)",
            )
    return Verdict(True)


def framed_verdict(buf: np.ndarray, n: int, framed: Framed) -> Verdict:
    """Whether a framing walked over a sample looks right: records found, no break inside the
    sample (a record cut off at the end of the file aside), the blocks of most records chaining,
    and those blocks plausible ASTERIX."""
    if not framed.start.size:
        return Verdict(False, framed.problems[0][2] if framed.problems else "no record")
    problems = framed.problems[:-1] if framed.cut else framed.problems
    if problems:
        return Verdict(False, f"{problems[0][2]} at offset {problems[0][0]}")
    bs, be = chain_blocks(buf, framed.start, framed.end)
    span = int((framed.end - framed.start).sum())
    if not bs.size:
        return Verdict(False, "the records hold no data blocks that chain")
    return plausible(buf, bs, be, buf[bs].astype(np.int64), span)
