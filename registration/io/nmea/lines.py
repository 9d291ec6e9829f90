"""Log files -> sentences: each line's optional logger timestamp prefix and NMEA 4.10 tag block, the
sentence's checksum (checked for all lines at once with numpy), its talker and type.

A line is ``[prefix] [\\tag block\\] sentence``:

* **prefix** (a logger's timestamp): an ISO 8601 UTC time (``2024-05-01T12:00:00.25Z``, a space
  for the ``T``, an offset such as ``+00:00``; without an offset UTC is assumed) or unix seconds
  (``1714564800.25``; 12 to 14 digits without a point: milliseconds), then spaces, a comma, a
  semicolon or a tab, then the rest;
* **tag block** (NMEA 4.10, as AIS receivers write): ``\\c:1714564800,s:rx1*hh\\``; its ``c:``
  field is the reception time in unix seconds (values above 10^11 are read as milliseconds); its
  checksum is checked;
* **sentence**: ``$`` or ``!``, the address (talker + type, or ``P`` + maker for a proprietary
  sentence), the fields, ``*`` and two hex digits of checksum. A sentence without a checksum is
  set aside: a truncated line loses it.

The reception time of a line is its tag block's ``c:`` if it has one, else its prefix's time.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from datetime import datetime, timezone
from pathlib import Path

import numpy as np

from registration.core.progress import progress_bar
from registration.io.files.ledger import RejectedLedger
from registration.io.nmea.errors import NmeaImportError

__all__ = ["SentenceLog", "read_log", "read_lines", "line_parts", "LineProblem"]

_START = re.compile(r"[$!\\]")
_UNIX = re.compile(r"^\d{9,11}(\.\d*)?$")
_UNIX_MS = re.compile(r"^\d{12,14}$")
_SEPARATORS = " \t,;|"
#: Hex digit value of every byte; 255 for a byte that is not a hex digit.
_HEX = np.full(256, 255, dtype=np.int32)
for _k, _c in enumerate("0123456789ABCDEF"):
    _HEX[ord(_c)] = _k
    _HEX[ord(_c.lower())] = _k


class LineProblem(Exception):
    """A line that holds no readable sentence: ``code`` (of errors.REASONS) and ``reason``."""

    def __init__(self, code: str, reason: str) -> None:
        super().__init__(reason)
        self.code = code
        self.reason = reason


@dataclass
class SentenceLog:
    """The sentences with a correct checksum, in file order then line order.

    ``file`` (N,) index into ``files``; ``line`` (N,) line number from 1; ``sentence`` the text from
    ``$``/``!`` to the checksum; ``talker`` (N,) two letters (empty for proprietary sentences);
    ``kind`` (N,) the sentence type (``GGA``, ``TTM``, ``VDM``; ``PASHR`` for proprietary ones: ``P``
    and the maker's letters and type); ``received`` (N,) the line's reception time in unix seconds
    (tag block ``c:`` or prefix), NaN without one. ``lines``: lines read, blank ones included.
    """

    files: list[str]
    file: np.ndarray
    line: np.ndarray
    sentence: list[str]
    talker: np.ndarray
    kind: np.ndarray
    received: np.ndarray
    lines: int
    blank_lines: int

    def where(self, *kinds: str) -> np.ndarray:
        """Indices (sorted) of the sentences of these types."""
        return np.flatnonzero(np.isin(self.kind, kinds))

    def fields(self, index: np.ndarray) -> list[list[str]]:
        """The fields of the sentences ``index``: element 0 is the address (``GPGGA``), then the data
        fields, without the checksum."""
        s = self.sentence
        return [s[i][1:-3].split(",") for i in index]


def _prefix_time(prefix: str) -> float:
    """Unix seconds of a logger's timestamp prefix (ISO 8601 or unix seconds)."""
    text = prefix.strip(_SEPARATORS)
    if _UNIX.match(text):
        return float(text)
    if _UNIX_MS.match(text):
        return float(text) / 1000.0
    try:
        stamp = datetime.fromisoformat(text)
    except ValueError:
        raise LineProblem(
            "bad_prefix",
            f"text before the sentence {text[:40]!r} is not a timestamp (ISO 8601 UTC or unix seconds)",
        ) from None
    if stamp.tzinfo is None:
        stamp = stamp.replace(tzinfo=timezone.utc)
    try:
        unix = stamp.timestamp()
    except (OverflowError, ValueError, OSError):  # e.g. 0001-01-01 with a positive UTC offset
        unix = math.nan
    if not 0.0 <= unix <= 1e11:  # as a tag block's time: 1970 to the year 5138
        raise LineProblem(
            "bad_prefix", f"timestamp {text[:40]!r} before the sentence is before 1970 or out of range"
        )
    return unix


def _tag_block(block: str) -> float:
    """Reception time (unix s, NaN without ``c:``) of a tag block's text (between the backslashes)."""
    star = block.rfind("*")
    if star < 0 or not 2 <= len(block) - star <= 3:
        raise LineProblem("bad_tag_block", f"tag block {block[:40]!r} has no checksum")
    x = 0
    for ch in block[:star].encode("latin-1"):
        x ^= ch
    try:
        claimed = int(block[star + 1 :], 16)
    except ValueError:
        claimed = -1
    if claimed != x:
        raise LineProblem("bad_tag_block", f"tag block checksum {block[star + 1 :]!r}, computed {x:02X}")
    for item in block[:star].split(","):
        if item.startswith("c:"):
            try:
                c = float(item[2:])
            except ValueError:
                c = math.nan
            c = c / 1000.0 if c > 1e11 else c
            if not 0.0 <= c <= 1e11:
                raise LineProblem(
                    "bad_tag_block", f"tag block time {item!r} is not unix seconds (or milliseconds)"
                )
            return c
    return math.nan


def line_parts(line: str) -> tuple[float, str]:
    """(reception time in unix s or NaN, sentence) of a line that does not start with ``$`` or ``!``:
    a prefix and/or tag blocks, then the sentence. :class:`LineProblem` when there is none."""
    m = _START.search(line)
    if m is None:
        raise LineProblem("not_a_sentence", f"no '$' or '!' on the line: {line[:40]!r}")
    received = _prefix_time(line[: m.start()]) if m.start() else math.nan
    rest = line[m.start() :]
    while rest.startswith("\\"):
        end = rest.find("\\", 1)
        if end < 0:
            raise LineProblem("bad_tag_block", "tag block not closed by a backslash")
        c = _tag_block(rest[1:end])
        received = c if not math.isnan(c) else received
        rest = rest[end + 1 :]
    if not rest.startswith(("$", "!")):
        raise LineProblem("not_a_sentence", f"no '$' or '!' after the tag block: {rest[:40]!r}")
    return received, rest


#: Octets looked at to tell a binary file from a text log, and the share of control octets (other
#: than tab, CR, LF) above which it is binary.
_HEAD_OCTETS, _BINARY_SHARE = 65536, 0.05


def _check_text(data: bytes, path: Path) -> None:
    """Raise :class:`NmeaImportError` for a binary file (a capture, an archive, ASTERIX): a text log
    has few control octets, a damaged one a few lines of them."""
    head = np.frombuffer(data[:_HEAD_OCTETS], dtype=np.uint8)
    control = ((head < 32) & ~np.isin(head, (9, 10, 13))) | (head == 127)
    if head.size and control.mean() > _BINARY_SHARE:
        raise NmeaImportError(
            f"{path}: not a text NMEA log ({int(control.sum())} of its first {head.size} bytes are "
            "binary control codes)"
        )


def _split_file(
    path: Path, file_index: int, out: dict, rejections: RejectedLedger, bar, max_bytes: int | None = None
) -> tuple[int, int]:
    """Append one file's sentences to ``out`` (lists); lines that hold none go to ``rejections``.
    Returns (lines, blank lines). :class:`NmeaImportError` for a binary file."""
    with open(path, "rb") as f:
        data = f.read() if max_bytes is None else f.read(max_bytes + 1)
    if max_bytes is not None and len(data) > max_bytes:
        data = data[: data.rfind(b"\n", 0, max_bytes) + 1]
        rejections.add(
            file_index,
            "over_limit",
            f"the file exceeds the limit of {max_bytes} bytes (max_bytes, --max-bytes); the lines from "
            "here on are not read",
            line=data.count(b"\n") + 1,
        )
    _check_text(data, path)
    text = data.decode("latin-1")
    del data
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if bar is not None:
        bar.total = (bar.total or 0) + len(lines)
    blank = _split_lines(lines, file_index, out, rejections, bar)
    return len(lines), blank


def _split_lines(
    lines: list[str], file_index: int, out: dict, rejections: RejectedLedger, bar, first_line: int = 1
) -> int:
    """Append the sentences of ``lines`` (numbered from ``first_line``) to ``out`` (lists); lines
    that hold none go to ``rejections``. Returns the number of blank lines."""
    blank = 0
    sentences, numbers, received = out["sentence"], out["line"], out["received"]
    bad_lines, bad_codes, bad_reasons = [], [], []
    nan = math.nan
    for number, raw in enumerate(lines, first_line):
        if bar is not None and number % 20000 == 0:
            bar.update(20000)
        line = raw.strip()
        if not line:
            blank += 1
            continue
        if line[0] == "$" or line[0] == "!":
            sentences.append(line)
            received.append(nan)
        else:
            try:
                t, sentence = line_parts(line)
            except LineProblem as p:
                bad_lines.append(number)
                bad_codes.append(p.code)
                bad_reasons.append(p.reason)
                continue
            sentences.append(sentence)
            received.append(t)
        numbers.append(number)
    if bar is not None:
        bar.update(len(lines) % 20000)
    out["file"].extend([file_index] * (len(numbers) - len(out["file"])))
    for code in set(bad_codes):
        pick = [k for k, c in enumerate(bad_codes) if c == code]
        rejections.add(
            [file_index] * len(pick), code, [bad_reasons[k] for k in pick], line=[bad_lines[k] for k in pick]
        )
    return blank


def checksums_ok(sentences: list[str]) -> tuple[np.ndarray, np.ndarray]:
    """(has a checksum, checksum matches) per sentence, both (N,) bool: the XOR of the characters
    between the start character and ``*`` against the two hex digits after it, for all at once."""
    n = len(sentences)
    if n == 0:
        return np.zeros(0, bool), np.zeros(0, bool)
    lens = np.fromiter(map(len, sentences), dtype=np.int64, count=n)
    buf = np.frombuffer("".join(sentences).encode("latin-1"), dtype=np.uint8)
    ends = np.cumsum(lens)
    starts = ends - lens
    has = (lens >= 4) & (buf[np.maximum(ends - 3, 0)] == ord("*"))
    prefix = np.zeros(buf.size + 1, dtype=np.uint8)
    np.bitwise_xor.accumulate(buf, out=prefix[1:])
    body_end = np.where(has, ends - 3, starts + 1)
    computed = (prefix[body_end] ^ prefix[np.minimum(starts + 1, body_end)]).astype(np.int32)
    claimed = _HEX[buf[np.maximum(ends - 2, 0)]] * 16 + _HEX[buf[np.maximum(ends - 1, 0)]]
    return has, has & (claimed == computed)


def _addresses(sentences: list[str]) -> tuple[np.ndarray, np.ndarray]:
    """(talker, type) per sentence; proprietary sentences (address starting with P): ('', address)."""
    talker, kind = [], []
    for s in sentences:
        comma = s.find(",")
        address = s[1:comma] if comma > 0 else s[1:-3]
        if address[:1] == "P":
            talker.append("")
            kind.append(address)
        else:
            talker.append(address[:2])
            kind.append(address[2:])
    return np.array(talker, dtype=object), np.array(kind, dtype=object)


def read_log(
    paths, rejections: RejectedLedger, progress: bool = False, max_bytes: int | None = None
) -> SentenceLog:
    """Read the log files (in the order given; each line's number counts from 1 in its file) into a
    :class:`SentenceLog` of the sentences with a correct checksum. Lines without a sentence, with a
    bad prefix or tag block, without a checksum or with a wrong one go to ``rejections``.
    ``progress``: a bar of lines read (:func:`registration.core.progress.progress_bar`)."""
    files = [Path(p) for p in paths]
    for p in files:
        if not p.is_file():
            raise ValueError(f"{p}: no such file")
    out: dict[str, list] = {"file": [], "line": [], "sentence": [], "received": []}
    bar = progress_bar(progress, "NMEA lines", unit="line", unit_scale=True)
    lines = blank = 0
    try:
        for k, p in enumerate(files):
            n, b = _split_file(p, k, out, rejections, bar, max_bytes)
            lines += n
            blank += b
    finally:
        bar.close()
    return _sentence_log([str(p) for p in files], out, rejections, lines, blank)


def read_lines(lines: list[str], name: str, rejections: RejectedLedger, first_line: int = 1) -> SentenceLog:
    """The :class:`SentenceLog` of some lines of one log file ``name`` (without their line ends),
    numbered from ``first_line``: a log read piece by piece (a replay of a large file) gives the
    same sentences, line numbers and rejections as :func:`read_log` of the whole."""
    out: dict[str, list] = {"file": [], "line": [], "sentence": [], "received": []}
    blank = _split_lines(lines, 0, out, rejections, None, first_line)
    return _sentence_log([name], out, rejections, len(lines), blank)


def _sentence_log(
    files: list[str], out: dict, rejections: RejectedLedger, lines: int, blank: int
) -> SentenceLog:
    """The :class:`SentenceLog` of the lines split into ``out``: checksums checked (the bad ones
    set aside), talkers and types."""
    file = np.asarray(out["file"], dtype=np.int64)
    line = np.asarray(out["line"], dtype=np.int64)
    received = np.asarray(out["received"], dtype=np.float64)
    sentences = out["sentence"]
    has, ok = checksums_ok(sentences)
    rejections.add(
        file[~has], "no_checksum", "the sentence does not end in '*hh' (a truncated line?)", line=line[~has]
    )
    bad = has & ~ok
    rejections.add(file[bad], "bad_checksum", "the checksum does not match the sentence", line=line[bad])
    keep = np.flatnonzero(ok)
    sentences = [sentences[k] for k in keep]
    talker, kind = _addresses(sentences)
    return SentenceLog(files, file[keep], line[keep], sentences, talker, kind, received[keep], lines, blank)
