"""AIS sentences (``!AIVDM`` received from other vessels, ``!AIVDO`` the own ship's) assembled into
messages and decoded by pyais.

A message of several sentences (``!AIVDM,2,1,3,A,...`` then ``!AIVDM,2,2,3,A,...``) is assembled
from consecutive fragments of one address and sequential message id, in order. A fragment whose
other parts do not follow (a first part followed by another first part, a later part without
the one before it, a message still open at the end of the log) is set aside as ``ais_fragment``
with its line number. The reception time of a message is that of its first part that has one
(tag block ``c:`` or logger prefix).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.fields import columns, numbers
from registration.io.nmea.lines import SentenceLog

__all__ = ["AisMessage", "read_ais"]


@dataclass
class AisMessage:
    """One decoded AIS message: ``parts`` (the log indices of its sentences), ``own`` (from
    ``!AIVDO``), ``received`` (unix s, NaN without), ``data`` (pyais' decoded message)."""

    parts: list[int]
    own: bool
    received: float
    data: Any  # pyais' decoded message (a class per message type)


class _Assembler:
    """Collects fragments per (address, sequential id, count); emits complete messages in order."""

    def __init__(self, log: SentenceLog, rejections: RejectedLedger) -> None:
        self.log, self.rejections = log, rejections
        self.open: dict[tuple, list[int]] = {}
        self.complete: list[list[int]] = []
        self.orphans: list[int] = []

    def add(self, index: int, key: tuple, count: int, number: int) -> None:
        if count == 1:
            self.complete.append([index])
            return
        parts = self.open.pop(key, None)
        if number == 1:
            if parts:
                self.orphans.extend(parts)
            self.open[key] = [index]
        elif parts is None or len(parts) != number - 1:
            self.orphans.extend(parts or [])
            self.orphans.append(index)
        elif number == count:
            self.complete.append(parts + [index])
        else:
            self.open[key] = parts + [index]

    def finish(self) -> list[list[int]]:
        for parts in self.open.values():
            self.orphans.extend(parts)
        self.open.clear()
        if self.orphans:
            i = np.array(sorted(self.orphans))
            lines = self.log.line[i]
            self.rejections.add(
                self.log.file[i],
                "ais_fragment",
                "AIS fragment without its other parts (the message is incomplete)",
                line=lines,
            )
        return self.complete


def _decode(log: SentenceLog, parts: list[int]) -> tuple[Any, str | None]:
    """pyais' decoded message of the sentences ``parts``, or the error text."""
    import pyais

    try:
        return pyais.decode(*[log.sentence[i] for i in parts]), None
    except Exception as exc:  # pyais raises many types on bad payloads
        return None, f"{type(exc).__name__}: {exc}"[:200]


def read_ais(log: SentenceLog, rejections: RejectedLedger) -> list[AisMessage]:
    """The AIS messages of the log, assembled and decoded, in log order of their first part;
    fragments and payloads pyais cannot decode are set aside."""
    c = columns(log, log.where("VDM", "VDO"), 6, 7, rejections, "AIS")
    count, number = numbers(c.cols[1]), numbers(c.cols[2])
    bad = ~(
        (count >= 1)
        & (count <= 9)
        & (number >= 1)
        & (number <= count)
        & (count == np.round(count))
        & (number == np.round(number))
    )
    c = c.reject(bad, rejections, "bad_field", "AIS fragment count or number is not 1-9")
    count, number = count[~bad].astype(int), number[~bad].astype(int)
    asm = _Assembler(log, rejections)
    for index, address, seq, cnt, num in zip(c.index, c.cols[0], c.cols[3], count, number):
        asm.add(int(index), (address, seq.strip(), int(cnt)), int(cnt), int(num))
    out, failed, reasons = [], [], []
    for parts in asm.finish():
        data, error = _decode(log, parts)
        if error is None and not (
            isinstance(getattr(data, "mmsi", None), int)
            and isinstance(getattr(data, "msg_type", None), int)
            and 1 <= data.msg_type <= 27
        ):
            error = "the payload is too short to hold a message type and an MMSI"
        if error is not None:
            failed.extend(parts)
            reasons.extend([f"AIS payload not decoded by pyais ({error})"] * len(parts))
            continue
        received = log.received[parts]
        first = np.flatnonzero(np.isfinite(received))
        out.append(
            AisMessage(
                parts, log.kind[parts[0]] == "VDO", float(received[first[0]]) if first.size else np.nan, data
            )
        )
    if failed:
        i = np.array(failed)
        rejections.add(log.file[i], "ais_decode", reasons, line=log.line[i])
    return out
