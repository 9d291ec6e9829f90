#!/usr/bin/env python3
"""Speed of the CAT048 plot correction (``registration.io.asterix.encode.correct_cat048``) on
datagrams of 10 plots, the live service's unit of work (about 1000 datagrams a second).

Run from a checkout (the package and libasterix installed)::

    python3 benchmarks/bench_correct.py                     # 500 datagrams of 10 plots, 7 rounds
    python3 benchmarks/bench_correct.py --datagrams 2000 --repeat 11

``--datagrams`` distinct datagrams, each one CAT048 data block of ``--per-datagram`` typical plot
reports (I048/010, 140, 020, 040, 070, 090, 130, 220, 240, 250, 161, 042, 200, 170: about 45
bytes each), are encoded by libasterix, of two radars of which one is corrected. Timed (wall
clock, rounds interleaved in alternating order, common.interleave; per datagram, the median of
the rounds; ratio the median of the rounds' ratios):

* ``correct_cat048``: every datagram corrected (walk, arithmetic, re-encoding);
* ``decode baseline``: every datagram decoded by the project's reader, as ``decode_file`` does a
  chunk of data blocks (zero-padded buffer, ``walk_records``, ``decode048``): the reader is
  vectorised over the blocks of a file, so on one datagram its numpy calls' fixed cost dominates.

Printed: us per datagram, the share of one core at 1000 datagrams a second, the ratio.
Figures: benchmarks/results/correct.json. ``--tiny``: 10 datagrams, one round.
"""

from __future__ import annotations

import argparse

import numpy as np
from common import add_arguments, interleave, median, paired_ratio, summary, write

from registration.io.asterix.decode.decode48 import WANTED, decode048
from registration.io.asterix.decode.uap import DEFAULT_EDITIONS, uap_for
from registration.io.asterix.decode.walker import walk_records
from registration.io.asterix.encode import PlotCorrection, correct_cat048
from registration.io.asterix.octets import PAD

CORRECTIONS = {
    (1, 2): PlotCorrection(range_bias_m=120.0, range_gain=4e-4, azimuth_bias_rad=0.004, time_bias_s=0.3)
}


def _datagram(rng: np.random.Generator, n: int, k0: int) -> bytes:
    """One CAT048 data block of ``n`` typical plot reports by libasterix, from radars 1/2 and 1/3."""
    import asterix.generated as gen

    spec = gen.Cat_048_1_32
    records = []
    for k in range(k0, k0 + n):
        items = {
            "010": (("SAC", 1), ("SIC", 2 + k % 2)),
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
        records.append(spec.cv_record.create(items))
    return spec.create(records).unparse().to_bytes()


def _correct_all(datagrams: list[bytes]) -> int:
    return sum(correct_cat048(d, CORRECTIONS).corrected for d in datagrams)


def _decode_all(datagrams: list[bytes]) -> int:
    uap = uap_for(48, DEFAULT_EDITIONS[48])
    n = 0
    for d in datagrams:
        buf = np.zeros(len(d) + PAD, dtype=np.uint8)
        buf[: len(d)] = np.frombuffer(d, dtype=np.uint8)
        rec = walk_records(buf, np.array([0]), np.array([len(d)]), uap, WANTED)
        n += int(decode048(buf, rec)["rho"].size)
    return n


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--datagrams", type=int, default=500, help="distinct datagrams (default 500)")
    ap.add_argument("--per-datagram", type=int, default=10, help="plots per datagram (default 10)")
    ap.add_argument("--repeat", type=int, default=7, help="rounds, alternated (default 7)")
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:
        args.datagrams, args.repeat = 10, 1
    rng = np.random.default_rng(1)
    datagrams = [_datagram(rng, args.per_datagram, k * args.per_datagram) for k in range(args.datagrams)]
    octets = sum(map(len, datagrams)) / len(datagrams)
    print(f"{len(datagrams)} datagrams of {args.per_datagram} CAT048 plots, {octets:.0f} bytes each")
    times, values = interleave(
        {
            "correct_cat048": lambda: _correct_all(datagrams),
            "decode baseline": lambda: _decode_all(datagrams),
        },
        args.repeat,
    )
    assert values["correct_cat048"] > 0 and values["decode baseline"] == args.datagrams * args.per_datagram
    per = {name: 1e6 * median(ts) / len(datagrams) for name, ts in times.items()}
    for name, us in per.items():
        best = 1e6 * min(times[name]) / len(datagrams)
        print(
            f"  {name:16s} median {us:8.1f} us/datagram  best {best:8.1f}  "
            f"({us / 10:.1f} % of a core at 1000/s)"
        )
    ratio = paired_ratio(times, "correct_cat048", "decode baseline")
    print(f"correct / decode baseline: {ratio:.3f}")
    figures = {
        "seconds_per_datagram": summary(times, per=len(datagrams)),
        "us_per_datagram": per,
        "core_share_at_1000_per_s": {name: us / 1e6 * 1000 for name, us in per.items()},
        "correct_over_decode": ratio,
    }
    sizes = {
        "datagrams": args.datagrams,
        "per_datagram": args.per_datagram,
        "bytes_per_datagram": octets,
        "repeat": args.repeat,
    }
    write("correct", args, sizes, figures)


if __name__ == "__main__":
    main()
