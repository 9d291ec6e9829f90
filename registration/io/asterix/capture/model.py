"""What a file read is (:class:`Capture`) and the ASTERIX categories that tell a data block,
shared by the capture readers (:mod:`registration.io.asterix.capture.capture`,
:mod:`registration.io.asterix.capture.blocks`, :mod:`registration.io.asterix.capture.unwrap`)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from registration.io.asterix.capture.netstack import Segments

__all__ = ["ASTERIX_CATEGORIES", "Capture"]

#: Categories assigned by EUROCONTROL (the ASTERIX category list), used to recognise a raw file.
ASTERIX_CATEGORIES = frozenset(
    (
        1,
        2,
        3,
        4,
        7,
        8,
        9,
        10,
        11,
        15,
        16,
        17,
        18,
        19,
        20,
        21,
        22,
        23,
        24,
        25,
        30,
        31,
        32,
        34,
        48,
        62,
        63,
        65,
        150,
        151,
        152,
        205,
        238,
        240,
        247,
        252,
    )
)


@dataclass
class Capture:
    """A file read: ``buf`` its (decompressed) octets followed by zero padding, ``size`` the number of
    octets without padding, ``kind`` 'raw', 'pcap', 'pcapng' or the name of a recorder framing
    (:mod:`registration.io.asterix.capture.framings`), ``segments`` the stretches of ``buf`` holding
    ASTERIX data blocks (the whole file, each UDP payload, or each framing record), ``counts`` of
    packets (captures) and ``notes`` about the file. ``framing``: 'netto' (raw data blocks end to
    end), 'pcap', 'pcapng' or the framing's name. ``clock``: what ``segments.time`` holds: 'utc'
    (UTC s since 1970, NaN: none) or 'time_of_day' (a recorder's time of day, s since midnight UTC,
    of a framing that gives no date)."""

    path: str
    buf: np.ndarray
    size: int
    kind: str
    gzip: bool
    segments: Segments
    counts: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)
    framing: str = "netto"
    clock: str = "utc"
