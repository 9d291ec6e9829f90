#!/usr/bin/env python3
"""Speed of the ASTERIX reader (registration.io.asterix) against libasterix on the same file.

Run from a checkout (the package and libasterix installed)::

    python3 benchmarks/bench_asterix.py                      # 10^6 CAT048 records
    python3 benchmarks/bench_asterix.py --records 200000 --repeat 5

A recording of typical CAT048 plot reports (I048/010, 140, 020, 040, 070, 090, 130, 220, 240,
250, 161, 042, 200, 170: about 45 bytes each, 20 records per data block) is encoded by
libasterix (2000 distinct records, repeated) and written once as a raw file and as a pcap of one
block per UDP datagram, into a temporary folder. Timed (wall clock, median of ``--repeat``
rounds interleaved in alternating order, common.interleave; ratios the median of the rounds'
ratios of records/s; figures in benchmarks/results/asterix.json):

* ``decode_file``: data blocks found and CAT048 records walked and their fields read;
* ``import_asterix``: the whole import (plots table, time axis, summary);
* ``libasterix``: ``RawDatablock.parse`` and ``Cat_048_1_32.cv_uap.parse`` of every block of the
  first ``--lib-records`` records (it is too slow for the whole file), records/s extrapolated.

``--tiny``: 2000 records, to check the script works.
"""

from __future__ import annotations

import argparse
import struct
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd
from common import add_arguments, interleave, median, paired_ratio, write

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


def _libasterix(data: bytes) -> int:
    """libasterix's parse of every block of ``data``; the records it found."""
    import asterix.generated as gen
    from asterix.base import Bits, RawDatablock

    count = 0
    for block in RawDatablock.parse(Bits.from_bytes(data)):
        count += len(gen.Cat_048_1_32.cv_uap.parse(block.get_raw_records()))
    return count


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--records", type=int, default=1_000_000, help="CAT048 records in the file (count)")
    parser.add_argument("--repeat", type=int, default=3, help="timed runs of each reader (count)")
    parser.add_argument("--lib-records", type=int, default=4000, help="records libasterix parses (count)")
    add_arguments(parser)
    args = parser.parse_args(argv)
    if args.tiny:
        args.records, args.repeat, args.lib_records = 400, 1, 100
    rng = np.random.default_rng(0)
    distinct = _records(min(2000, args.records), rng)  # blocks of PER_BLOCK records
    blocks = (distinct * (args.records // (len(distinct) * PER_BLOCK) + 1))[: args.records // PER_BLOCK]
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
        lib_data = b"".join(blocks[: max(1, args.lib_records // PER_BLOCK)])
        n_lib = _libasterix(lib_data)
        contenders = {}
        for name, path in (("raw", raw), ("pcap", pcap)):
            contenders[f"{name} decode_file"] = lambda p=path: decode_file(p)
            contenders[f"{name} import_asterix"] = lambda p=path: import_asterix(p, sites)
        contenders["libasterix"] = lambda: _libasterix(lib_data)
        times, _ = interleave(contenders, args.repeat)
    # seconds per record, so that a ratio compares rates: libasterix parses n_lib records only
    per_record = {k: [x / (n_lib if k == "libasterix" else n) for x in t] for k, t in times.items()}
    figures = {"records_per_s": {}, "over_libasterix": {}}
    for what, t in per_record.items():
        rate = 1 / median(t)
        figures["records_per_s"][what] = rate
        print(f"{what:20s} {rate:12,.0f} records/s ({median(times[what]):.2f} s)")
    for what in per_record:
        if what != "libasterix":
            figures["over_libasterix"][what] = paired_ratio(per_record, "libasterix", what)
    for what in ("decode_file", "import_asterix"):
        print(f"ratio {what} (raw) / libasterix: {figures['over_libasterix']['raw ' + what]:,.0f}")
    sizes = {"records": n, "blocks": len(blocks), "lib_records": n_lib, "repeat": args.repeat}
    write("asterix", args, sizes, figures)


if __name__ == "__main__":
    main()
