"""The ASTERIX reader's fuzz campaigns (:mod:`tests.fuzzing`), on data libasterix encoded.

* :func:`datagrams`: mutated datagrams of CAT048, CAT034, CAT021 (the standard recording) and
  CAT001, CAT002 (the legacy recording), decoded as the reader decodes a capture's datagrams
  (``capture_from_datagrams``, ``decode_capture``, ``assemble_file``), many per call.
* :func:`recordings`: mutated whole recordings, one per call (``decode_file``, ``assemble_file``):
  raw, pcap, pcapng, gzip, the recorder framings (GPS, IOSS, IOSS with sequence numbers, ORADIS,
  RFF, HDLC) and a raw CAT001/CAT002 file. A file the reader refuses raises its one-line
  AsterixImportError naming the file."""

from __future__ import annotations

import gzip
import tempfile
from collections import Counter
from pathlib import Path

import numpy as np

from registration.io.asterix.capture.capture import capture_from_datagrams
from registration.io.asterix.decode.reader import decode_capture, decode_file
from registration.io.asterix.decode.uap import check_editions
from registration.io.asterix.errors import LEDGER_COLUMNS, AsterixImportError
from registration.io.asterix.tables.assemble import SiteLookup, assemble_file
from registration.io.asterix.tables.duplicates import StreamChecks
from registration.io.asterix.tables.timeofday import Unwrapper
from registration.io.asterix.tables.truncated import TruncatedClock
from registration.io.files.ledger import RejectedLedger
from tests.fuzzing import Campaign, mutate_octets

#: Datagrams decoded per call.
DATAGRAM_BATCH = 250


def _seed_data():
    from tests.io.asterix.cat001_data import cat001_recording
    from tests.io.asterix.scenario import DATE, sites_frame, standard_recording

    return standard_recording(duration=12.0), cat001_recording()[0], sites_frame(), DATE


def _rows(decoded, sites, date, ledger) -> Counter:
    """The import's rows of a decoded capture; what was decoded and set aside, checked to add up."""
    editions = check_editions(None)
    lookup = SiteLookup(sites["sac"].to_numpy(), sites["sic"].to_numpy())
    names = sites["sensor"].astype(str).to_numpy()
    rows = assemble_file(
        decoded, Unwrapper(date), lookup, names, editions, ledger, StreamChecks(), TruncatedClock()
    )
    records = sum(r.size for r in decoded.records.values())
    plots = int(rows.plots["time_s"].size) if rows.plots else 0
    assert plots <= records, (plots, records)
    offsets = ledger.frame()["offset"].to_numpy() if ledger.count() else np.zeros(0)
    assert ((offsets >= 0) & (offsets <= decoded.capture.size)).all(), offsets
    return Counter(records=records, plots=plots, rejected=ledger.count())


def datagrams(seed: int) -> Campaign:
    standard, legacy, sites, date = _seed_data()
    payloads = [b"".join(bytes(rec.blocks[i]) for i in g) for rec in (standard,) for g in rec.datagrams]
    payloads += [bytes(b) for b in legacy.blocks]

    def batches(n: int):
        rng = np.random.default_rng(seed)
        for first in range(0, n, DATAGRAM_BATCH):
            size = min(DATAGRAM_BATCH, n - first)
            picks = rng.integers(0, len(payloads), size)
            yield [
                (f"datagram {first + k} (seed {seed})", mutate_octets(payloads[int(p)], rng))
                for k, p in enumerate(picks)
            ]

    def check(batch: list) -> Counter:
        data = [d for _, d in batch]
        cap = capture_from_datagrams(data, [8600] * len(data), "udp://fuzz")
        ledger = RejectedLedger(LEDGER_COLUMNS)
        decoded = decode_capture(cap, None, ledger, refuse_non_asterix=False)
        return _rows(decoded, sites, date, ledger) + Counter(datagrams=len(batch))

    return Campaign(batches, check)


def recording_seeds() -> dict[str, bytes]:
    """name -> a small valid recording of each form the reader tells apart."""
    from tests.io.asterix.test_framings import WRAPPERS

    standard, legacy, _, _ = _seed_data()
    blocks, times = [bytes(b) for b in standard.blocks[:16]], list(standard.times[:16])
    from tests.io.asterix.encode import Recording

    small = Recording(standard.blocks[:16], standard.times[:16], [], standard.date)
    small.datagrams = [g for g in standard.datagrams if max(g) < 16]
    out = {"raw": small.raw(), "pcap": small.pcap(), "pcapng": small.pcapng()}
    out["gz"] = gzip.compress(out["raw"], mtime=0)
    out.update({name: wrap(blocks, times) for name, wrap in WRAPPERS.items()})
    out["cat001"] = b"".join(bytes(b) for b in legacy.blocks[:24])
    return out


def recordings(seed: int) -> Campaign:
    _, _, sites, date = _seed_data()
    seeds = recording_seeds()
    names = sorted(seeds)
    folder = Path(tempfile.mkdtemp(prefix="fuzz-asterix-"))

    def batches(n: int):
        rng = np.random.default_rng(seed)
        for k in range(n):
            name = names[int(rng.integers(len(names)))]
            yield [(f"recording {k} ({name}, seed {seed})", mutate_octets(seeds[name], rng))]

    def check(batch: list) -> Counter:
        ((_, data),) = batch
        path = folder / "input.rec"
        path.write_bytes(data)
        ledger = RejectedLedger(LEDGER_COLUMNS)
        try:
            decoded = decode_file(path, None, ledger)
        except AsterixImportError as exc:
            assert str(exc).startswith(str(path)) and "\n" not in str(exc), str(exc)
            return Counter(refused=1)
        return _rows(decoded, sites, date, ledger) + Counter(read=1)

    return Campaign(batches, check)
