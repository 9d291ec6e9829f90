"""The NMEA reader's fuzz campaign (:mod:`tests.fuzzing`): mutated sentences in a bridge log.

Each input is one line of a simulated 30 s bridge log (GGA, RMC, ZDA, HDT, PASHR, TTM, AIVDM,
AIVDO; a type drawn first, so the rare ones are fuzzed as often as PASHR) made into another:
octets changed, cut, inserted (then the line fails its checksum, as most damage does), or a field
replaced by an extreme, empty or malformed value, fields dropped or repeated, an AIS payload's
characters changed, with the checksum made right again so that the sentence reaches its parser.
A batch puts :data:`LINES_BATCH` such lines into one log and imports it
(:func:`registration.io.nmea.import_nmea`); the outcome is an import or a one-line ValueError
naming the file."""

from __future__ import annotations

import tempfile
from collections import Counter
from functools import reduce
from pathlib import Path

import numpy as np

from registration.io.nmea import import_nmea
from tests.fuzzing import Campaign, mutate_octets

#: Lines mutated per log imported.
LINES_BATCH = 100
#: What a field becomes.
VALUES = (
    "", "-", "+", "0", "-0", "-1", "1e308", "-1e308", "nan", "inf", "999999999", "9" * 40, "0x1F",
    "12.3.4", "A", "V", "ZZZ", "360.0", "-90", "90.000001", "235959.99", "246060", "000000", "991399",
    "010100", "311399", "\u0663", "00000.0000", "18000.0000", "9000.0000",
)  # fmt: skip
AIS_CHARS = "0123456789:;<=>?@ABCDEFGHIJKLMNOPQRSTUVW`abcdefghijklmnopqrstuvw"


def _with_checksum(body: str) -> str:
    """``body`` (start character, address, fields) with its checksum."""
    check = reduce(lambda a, c: a ^ ord(c), body[1:], 0)
    return f"{body}*{check:02X}"


def _field_mutation(line: str, rng: np.random.Generator) -> str:
    head, sep, sentence = line.rpartition("\\")
    body = sentence.split("*")[0]
    fields = body.split(",")
    for _ in range(int(rng.integers(1, 3))):
        k = int(rng.integers(1, len(fields))) if len(fields) > 1 else 0
        kind = int(rng.integers(0, 5))
        if kind <= 1:
            fields[k] = VALUES[int(rng.integers(len(VALUES)))]
        elif kind == 2 and len(fields) > 2:
            del fields[k]
        elif kind == 3:
            fields.insert(k, fields[k])
        elif len(fields) > 5 and sentence[:1] == "!":  # an AIS payload's characters
            payload = list(fields[5])
            for j in rng.integers(0, max(len(payload), 1), size=int(rng.integers(1, 6))):
                if payload:
                    payload[int(j)] = AIS_CHARS[int(rng.integers(len(AIS_CHARS)))]
            fields[5] = "".join(payload)[: int(rng.integers(0, len(payload) + 2))]
        else:
            fields[k] = fields[k][: int(rng.integers(0, len(fields[k]) + 1))]
    return head + sep + _with_checksum(",".join(fields))


def mutate_line(line: str, rng: np.random.Generator) -> str:
    if rng.random() < 0.7:
        return _field_mutation(line, rng)
    return mutate_octets(line.encode("latin-1"), rng, max_span=16).decode("latin-1").replace("\n", " ")


def sentences(seed: int) -> Campaign:
    from tests.io.nmea.bridgelog import PLATFORM, BridgeLogConfig, simulate_bridge_log

    log = simulate_bridge_log(BridgeLogConfig(seed=4, duration_s=30.0, n_vessels=3, n_ais=2))
    lines = list(log.lines)
    kinds = np.array([x.split("\\")[-1][:6] for x in lines])
    by_kind = [np.flatnonzero(kinds == k) for k in np.unique(kinds)]
    folder = Path(tempfile.mkdtemp(prefix="fuzz-nmea-"))

    def batches(n: int):
        rng = np.random.default_rng(seed)
        for first in range(0, n, LINES_BATCH):
            size = min(LINES_BATCH, n - first)
            rows = [int(rng.choice(by_kind[int(rng.integers(len(by_kind)))])) for _ in range(size)]
            yield [
                (f"line {first + k} (log line {r + 1}, seed {seed})", (r, mutate_line(lines[r], rng)))
                for k, r in enumerate(rows)
            ]

    def check(batch: list) -> Counter:
        text = list(lines)
        for _, (row, new) in batch:
            text[row] = new
        path = folder / "log.nmea"
        path.write_bytes(("\n".join(text) + "\n").encode("latin-1", errors="replace"))
        try:
            result = import_nmea(path, PLATFORM, log.sensors)
        except ValueError as exc:
            assert str(path) in str(exc) and "\n" not in str(exc), str(exc)
            return Counter(refused=1, lines=len(batch))
        assert result.summary["rejected"]["lines"] == len(result.rejected)
        return Counter(imported=1, lines=len(batch), rejected=len(result.rejected))

    return Campaign(batches, check)
