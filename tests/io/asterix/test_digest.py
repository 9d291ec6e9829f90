"""Record digests (registration.io.asterix.decode.digest) against byte equality: equal octets,
equal digests wherever they lie; distinct octets, distinct digests (on real records, random
records and records one octet or one trailing zero apart)."""

from __future__ import annotations

import numpy as np

from registration.io.asterix.decode.digest import record_digests
from tests.live.running import SAMPLES, datagrams


def _layout(records: list[bytes]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    sizes = np.array([len(r) for r in records], dtype=np.int64)
    end = np.cumsum(sizes)
    buf = np.frombuffer(b"".join(records) + bytes(3), dtype=np.uint8)
    return buf, end - sizes, end


def _agree_with_bytes(records: list[bytes]) -> None:
    digests = record_digests(*_layout(records))
    by_bytes = {r: k for k, r in enumerate(records)}
    by_digest = {d: k for k, d in enumerate(digests.tolist())}
    first_bytes = np.array([by_bytes[r] for r in records])
    first_digest = np.array([by_digest[d] for d in digests.tolist()])
    assert len(by_digest) == len(by_bytes)
    assert np.array_equal(first_bytes, first_digest)


def test_the_sample_datagrams_partition_as_their_octets():
    payloads = datagrams(SAMPLES / "atc.pcap.gz")
    _agree_with_bytes(payloads + payloads[::7])  # every seventh twice


def test_random_records_and_near_misses():
    rng = np.random.default_rng(3)
    records = [rng.integers(0, 256, int(n), dtype=np.uint8).tobytes() for n in rng.integers(0, 90, 20000)]
    near = []
    for r in records[:3000]:
        if r:
            k = int(rng.integers(len(r)))
            near.append(r[:k] + bytes([(r[k] + 1) % 256]) + r[k + 1 :])  # one octet apart
        near.append(r + b"\x00")  # a trailing zero more
        near.append(r + b"\x00\x00\x00\x00\x00\x00\x00\x00")  # a zero word more
    _agree_with_bytes(records + near + records[:500])


def test_the_position_in_the_buffer_does_not_matter():
    rec = bytes(range(1, 30))
    buf = np.frombuffer(b"xx" + rec + b"yyy" + rec + b"z", dtype=np.uint8)
    d = record_digests(buf, np.array([2, 2 + 29 + 3]), np.array([31, 2 + 29 + 3 + 29]))
    assert d[0] == d[1]
    empty_here, empty_there = (record_digests(buf, np.array([a]), np.array([a]))[0] for a in (2, 5))
    assert empty_here == empty_there
