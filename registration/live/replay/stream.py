"""A recording file read a piece at a time: gzip or not (told by its first two octets, 1f 8b), each
gzip member after the other, the decompressed octets handed out in pieces of a chosen size, so that
a file of any size is replayed with bounded memory; and :class:`Datagrams`, a piece of a recording
as the datagrams to send.

A gzip stream that is truncated or corrupt ends where its good part ends (a note says so), as the
importers read it (:mod:`registration.io.asterix.capture.capture`).
"""

from __future__ import annotations

import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

__all__ = ["ByteStream", "Datagrams", "READ_BYTES"]

#: Compressed octets read from the file at a time (gzip).
READ_BYTES = 1 << 20
_GZIP = b"\x1f\x8b"


@dataclass
class Datagrams:
    """A piece of a recording: datagram ``k`` is ``buf[start[k]:end[k]]`` (``buf`` bytes or a uint8
    array), recorded at ``time[k]`` (s; NaN: at the previous datagram's time), a time of day (s
    since midnight UTC, to be placed on a day) when ``time_of_day``, else UTC s since 1970.
    ``position``: the octets of the file read so far."""

    buf: bytes | np.ndarray
    start: np.ndarray
    end: np.ndarray
    time: np.ndarray
    time_of_day: bool
    position: int = 0

    @property
    def size(self) -> int:
        return int(self.start.size)


class ByteStream:
    """The decompressed octets of ``path``: :meth:`read` ``n`` of them (fewer only at the end);
    ``position``: the octets of the file itself read so far (for a progress bar over file sizes);
    ``gzip``: whether the file is gzip-compressed; ``out``: the octets handed out; ``notes``: what
    went wrong in a gzip stream. Use it as a context manager (it closes the file)."""

    def __init__(self, path: str | Path) -> None:
        self.path = str(path)
        self._file = open(path, "rb")
        self.gzip = self._file.read(2) == _GZIP
        self._file.seek(0)
        self._inflate = zlib.decompressobj(wbits=31) if self.gzip else None
        self._pending = b""
        self.notes: list[str] = []
        self.done = False
        self.out = 0

    def __enter__(self) -> "ByteStream":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        self._file.close()

    @property
    def position(self) -> int:
        return self._file.tell() if not self._file.closed else 0

    def read(self, n: int) -> bytes:
        """The next ``n`` decompressed octets (fewer at the end of the file, b"" after it)."""
        parts: list[bytes] = []
        got = 0
        while got < n and not self.done:
            piece = self._file.read(n - got) if self._inflate is None else self._inflated(n - got)
            if not piece and (self._inflate is None or self.done):
                self.done = True
                break
            parts.append(piece)
            got += len(piece)
            self.out += len(piece) if self._inflate is None else 0
        return b"".join(parts)

    def _inflated(self, n: int) -> bytes:
        """Up to ``n`` octets out of the gzip stream; sets ``done`` at its end or at a fault."""
        d = self._inflate
        assert d is not None
        data = d.unconsumed_tail or self._pending or self._file.read(READ_BYTES)
        self._pending = b""
        if not data:
            if not d.eof:
                self.notes.append(
                    f"{self.path}: the gzip stream is truncated after {self.out} decompressed bytes; "
                    "what came before is replayed"
                )
            self.done = True
            return b""
        try:
            piece = d.decompress(data, n)
        except zlib.error as exc:
            self.notes.append(
                f"{self.path}: the gzip stream is corrupt after {self.out} decompressed bytes ({exc}); "
                "the rest of the file is lost"
            )
            self.done = True
            return b""
        self.out += len(piece)
        if d.eof:
            rest = d.unused_data or self._file.read(READ_BYTES)
            if rest[:2] == _GZIP:  # the next member
                self._inflate, self._pending = zlib.decompressobj(wbits=31), rest
            else:  # the end, or octets that are no gzip member (ignored, as gzip does)
                if rest:
                    self.notes.append(f"{self.path}: {len(rest)}+ bytes after the gzip stream are ignored")
                self.done = True
        return piece
