#!/usr/bin/env python3
"""Speed of the ASTERIX reader (registration.io.asterix) against libasterix on the same file.

Run from a checkout (the package and libasterix installed)::

    python3 benchmarks/bench_asterix.py                      # 10^6 CAT048 records
    python3 benchmarks/bench_asterix.py --records 200000 --repeat 5

A recording of typical CAT048 plot reports (I048/010, 140, 020, 040, 070, 090, 130, 220, 240,
250, 161, 042, 200, 170: about 45 bytes each, 20 records per data block) is encoded by
libasterix (2000 distinct records, repeated) and written once as a raw file and as a pcap of one
block per UDP datagram, into a temporary folder. Timed (wall clock, best of ``--repeat``):

* ``decode_file``: data blocks found and CAT048 records walked and their fields read;
* ``import_asterix``: the whole import (plots table, time axis, summary);
* ``libasterix``: ``RawDatablock.parse`` and ``Cat_048_1_32.cv_uap.parse`` of every block of the
  first ``--lib-records`` records (it is too slow for the whole file), records/s extrapolated.
"""

from __future__ import annotations

import argparse
import struct
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd

from registration.io.asterix import decode_file, import_asterix

PER_BLOCK = 20


def _records(n: int, rng) -> list:
    import asterix.generated as gen

    spec = gen.Cat_048_1_32
    out = []
    for k in range(n):
        items = {
            "010": (("SAC", 1), ("SIC", 2)),
            "140": int(36000 * 128 + k * 13),
            "020": (0b1010000,),
            "040": (("RHO", int(rng.integers(1, 60000))), ("THETA", int(rng.integers(0, 65536)))),
            "070": (("V", 0), ("G", 0), ("L", 0), 0, ("MODE3A", int(rng.integers(0, 4096)))),
            "090": 0x0123,
            "130": {"SRL": 3, "SAM": 200, "APD": 7},
            "220": int(rng.integers(0, 2**24)),
            "240": 0x123456789ABC,
            "250": [0x1122334455667788],
            "161": k % 4096,
            "042": 0x01020304,
            "200": 0x0A0B0C0D,
            "170": (0x40,),
        }
        out.append(spec.cv_record.create(items))
    return [spec.create(out[i : i + PER_BLOCK]).unparse().to_bytes() for i in range(0, n, PER_BLOCK)]


def _pcap(blocks: list) -> bytes:
    out = [struct.pack("<IHHiIII", 0xA1B2C3D4, 2, 4, 0, 0, 65535, 1)]
    head = bytes(12) + b"\x08\x00"
    for k, block in enumerate(blocks):
        udp = struct.pack("!HHHH", 40000, 8600, 8 + len(block), 0) + block
        ip = struct.pack(
            "!BBHHHBBH4s4s", 0x45, 0, 20 + len(udp), k & 0xFFFF, 0x4000, 64, 17, 0, bytes(4), bytes(4)
        )
        frame = head + ip + udp
        out.append(
            struct.pack("<IIII", 1714557600 + k // 100, (k % 100) * 10000, len(frame), len(frame)) + frame
        )
    return b"".join(out)


def _best(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def _libasterix_rate(blocks: list, n_records: int) -> float:
    import asterix.generated as gen
    from asterix.base import Bits, RawDatablock

    data = b"".join(blocks[: max(1, n_records // PER_BLOCK)])
    start = time.perf_counter()
    count = 0
    for block in RawDatablock.parse(Bits.from_bytes(data)):
        count += len(gen.Cat_048_1_32.cv_uap.parse(block.get_raw_records()))
    return count / (time.perf_counter() - start)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--records", type=int, default=1_000_000, help="CAT048 records in the file (count)")
    parser.add_argument("--repeat", type=int, default=3, help="timed runs of each reader (count)")
    parser.add_argument("--lib-records", type=int, default=4000, help="records libasterix parses (count)")
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    distinct = _records(2000, rng)
    blocks = (distinct * (args.records // 2000 + 1))[: args.records // PER_BLOCK]
    n = len(blocks) * PER_BLOCK
    sites = pd.DataFrame(
        {
            "sensor": ["R1"],
            "sac": [1],
            "sic": [2],
            "lat_deg": [45.0],
            "lon_deg": [5.0],
            "alt_m": [100.0],
            "sigma_range_m": [30.0],
            "sigma_bearing_deg": [0.1],
        }
    )
    with tempfile.TemporaryDirectory() as folder:
        raw, pcap = Path(folder) / "plots.ast", Path(folder) / "plots.pcap"
        raw.write_bytes(b"".join(blocks))
        pcap.write_bytes(_pcap(blocks))
        print(
            f"{n} CAT048 records, {len(blocks)} data blocks: raw {raw.stat().st_size / 1e6:.1f} MB, "
            f"pcap {pcap.stat().st_size / 1e6:.1f} MB"
        )
        lib = _libasterix_rate(blocks, args.lib_records)
        best = {}
        for name, path in (("raw", raw), ("pcap", pcap)):
            best[name, "decode_file"] = _best(lambda: decode_file(path), args.repeat)
            best[name, "import_asterix"] = _best(lambda: import_asterix(path, sites), args.repeat)
        for (name, what), t in best.items():
            print(f"{name:5s} {what:15s}{n / t:12,.0f} records/s ({t:.2f} s)")
        print(f"libasterix           {lib:12,.0f} records/s ({args.lib_records} records)")
        for what in ("decode_file", "import_asterix"):
            print(f"ratio {what} (raw) / libasterix: {n / best['raw', what] / lib:,.0f}")


if __name__ == "__main__":
    main()
