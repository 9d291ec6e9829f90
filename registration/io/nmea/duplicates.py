"""Identical lines from a duplicated feed: a sentence whose text equals one of the last
:data:`WINDOW_LINES` sentences and that carries the same time, its own (the sentence types with a
UTC time field: the same text is the same time) or the same reception time (tag block or logger
stamp), is set aside as ``duplicate`` before the sentences are typed. A sentence without a time of
its own nor a reception time (``$HEHDT,40.00,T`` repeated at 10 Hz while the heading holds) is never
a duplicate: nothing tells a second copy from a new reading."""

from __future__ import annotations

import dataclasses

import numpy as np

from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.lines import SentenceLog

__all__ = ["TIMED_TYPES", "WINDOW_LINES", "drop_duplicates"]

#: Sentence types whose fields hold their own UTC time (the same text: the same time).
TIMED_TYPES = frozenset(("GGA", "GNS", "RMC", "ZDA", "TTM", "PASHR", "GLL", "GBS", "GST"))
#: How many sentences back an identical one counts as a duplicate.
WINDOW_LINES = 200


def drop_duplicates(log: SentenceLog, rejections: RejectedLedger) -> tuple[SentenceLog, int]:
    """The log without its duplicate sentences (set aside in ``rejections``) and their number."""
    last: dict[str, int] = {}
    dup = np.zeros(len(log.sentence), dtype=bool)
    received = log.received
    for k, (text, kind) in enumerate(zip(log.sentence, log.kind.tolist())):
        j = last.get(text)
        last[text] = k
        if j is None or k - j > WINDOW_LINES:
            continue
        same_time = kind in TIMED_TYPES or (received[k] == received[j])  # NaN == NaN is False
        dup[k] = same_time
    if not dup.any():
        return log, 0
    rejections.add(
        log.file[dup],
        "duplicate",
        "the same sentence with the same time came earlier (a duplicated feed)",
        line=log.line[dup],
    )
    keep = ~dup
    kept = dataclasses.replace(
        log,
        file=log.file[keep],
        line=log.line[keep],
        sentence=[s for s, k in zip(log.sentence, keep.tolist()) if k],
        talker=log.talker[keep],
        kind=log.kind[keep],
        received=log.received[keep],
    )
    return kept, int(dup.sum())
