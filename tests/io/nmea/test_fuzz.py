"""A damaged log (characters changed, lines cut, joined, repeated, dropped, garbage inserted) never
makes the reader raise: every line is either used, counted as not used, or set aside with a reason."""

from __future__ import annotations

import gzip
import os
import time

import numpy as np
import pytest

from registration.io.nmea import import_nmea
from tests.fuzzing import assert_clean, run_campaign
from tests.io.nmea.bridgelog import PLATFORM, BridgeLogConfig, simulate_bridge_log


def _damage(lines: list[str], rng) -> list[str]:
    out = []
    for line in lines:
        r = rng.random()
        if r < 0.02 and len(line) > 2:  # a character changed
            k = int(rng.integers(len(line)))
            line = line[:k] + chr(int(rng.integers(32, 127))) + line[k + 1 :]
        elif r < 0.04:  # cut short
            line = line[: int(rng.integers(len(line) + 1))]
        elif r < 0.05 and out:  # joined to the line before (a lost line end)
            out[-1] += line
            continue
        elif r < 0.06:
            out.append(line)  # repeated
        elif r < 0.07:
            continue  # dropped
        elif r < 0.08:
            line = "".join(chr(int(c)) for c in rng.integers(0, 256, int(rng.integers(1, 80))))
        out.append(line)
    return out


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_damaged_log_is_read_without_raising(tmp_path, seed):
    log = simulate_bridge_log(BridgeLogConfig(seed=seed, duration_s=60.0, n_vessels=4, n_ais=3))
    lines = _damage(log.lines, np.random.default_rng(seed))
    path = tmp_path / "damaged.nmea"
    path.write_bytes("\n".join(lines).encode("latin-1", errors="replace") + b"\n")
    result = import_nmea(path, PLATFORM, log.sensors)
    # about 8 % of the lines damaged: the rest is used
    assert len(result.navigation) > 0.8 * 591 and len(result.plots) > 0.8 * len(log.plots)
    assert len(result.reference) > 0.7 * len(log.reports)
    summary = result.summary
    counted = sum(n for per_talker in summary["sentences"].values() for n in per_talker.values())
    set_aside_before_typing = result.rejected.code.isin(
        ["not_a_sentence", "bad_prefix", "bad_tag_block", "no_checksum", "bad_checksum", "duplicate"]
    ).sum()
    # every non-blank line is a sentence with a correct checksum, or set aside before it is typed
    assert counted + set_aside_before_typing + summary["blank_lines"] == summary["lines"]
    assert (result.rejected.line >= 1).all() and (result.rejected.line <= summary["lines"]).all()


N_INPUTS = int(os.environ.get("REGISTRATION_FUZZ_N", "300"))
TIME_BOUND_S = float(os.environ.get("REGISTRATION_FUZZ_S", "20"))
#: The reproductions of issue 32/31 for the NMEA reader: logger stamps out of range, a binary file.
_STAMPS = ("0001-01-01T00:00:00+14:00 ", "0001-01-01T00:00:00Z ", "9999-12-31T23:59:59-14:00 ", "1e300 ")


def _mutate_bytes(data: bytes, rng) -> bytes:
    """One to three byte-level mutations: octets overwritten, a stretch cut, inserted or repeated,
    the file cut short, a logger stamp out of range put before a line."""
    out = bytearray(data)
    for _ in range(int(rng.integers(1, 4))):
        n = len(out)
        if n < 4:
            break
        kind = int(rng.integers(0, 6))
        at = int(rng.integers(0, n))
        span = int(rng.integers(1, min(200, n) + 1))
        if kind == 0:
            for k in rng.integers(0, n, size=int(rng.integers(1, 16))):
                out[int(k)] = int(rng.integers(0, 256))
        elif kind == 1:
            del out[at : at + span]
        elif kind == 2:
            out[at:at] = rng.bytes(span)
        elif kind == 3:
            out[at:at] = out[max(at - span, 0) : at]
        elif kind == 4:
            del out[int(rng.integers(n // 2, n + 1)) :]
        else:
            line = out.find(b"\n", at) + 1
            out[line:line] = _STAMPS[int(rng.integers(len(_STAMPS)))].encode()
    return bytes(out)


def test_mutated_logs_never_raise_anything_else(tmp_path):
    """Issue 32 item 5: a seeded, time-bounded fuzz target (``REGISTRATION_FUZZ_N`` inputs, default
    300, within ``REGISTRATION_FUZZ_S`` s, default 20): every outcome is an import or a
    ValueError (NmeaImportError) of one line naming the file."""
    log = simulate_bridge_log(BridgeLogConfig(seed=4, duration_s=30.0, n_vessels=3, n_ais=2))
    seed = ("\n".join(log.lines) + "\n").encode("latin-1", errors="replace")
    ais = next(line for line in log.lines if "AIVDM" in line).split("\\")[-1]
    corpus = [
        b"".join(_STAMPS[0].encode() + x.encode() + b"\n" for x in log.lines),
        seed + (_STAMPS[0] + ais + "\n").encode(),
        bytes(range(256)) * 40,  # binary
        gzip.compress(seed),
    ]
    rng = np.random.default_rng(31)
    start, outcomes = time.perf_counter(), {"imported": 0, "refused": 0}
    inputs = corpus + [_mutate_bytes(seed, rng) for _ in range(max(N_INPUTS - len(corpus), 0))]
    for k, data in enumerate(inputs):
        if time.perf_counter() - start > TIME_BOUND_S:
            break
        path = tmp_path / f"log{k}.nmea"
        path.write_bytes(data)
        try:
            result = import_nmea(path, PLATFORM, log.sensors)
        except ValueError as exc:
            assert str(path) in str(exc) and "\n" not in str(exc), (k, str(exc))
            outcomes["refused"] += 1
        except Exception as exc:
            raise AssertionError(f"input {k}: {type(exc).__name__}: {exc}") from exc
        else:
            assert result.summary["rejected"]["lines"] == len(result.rejected)
            outcomes["imported"] += 1
        path.unlink()
    assert sum(outcomes.values()) >= min(N_INPUTS, 50) and outcomes["imported"] > 0


def test_a_duplicated_feed_imports_as_the_single_feed(tmp_path):
    """Issue 31 item 1: every line of the log twice (a feed recorded twice): the same tables as the
    single log, the copies set aside as ``duplicate`` and counted; ``keep_duplicates`` keeps them."""
    import pandas as pd

    log = simulate_bridge_log(BridgeLogConfig(seed=2, duration_s=60.0, n_vessels=4, n_ais=3))
    single, double = tmp_path / "single.nmea", tmp_path / "double.nmea"
    single.write_text("\n".join(log.lines) + "\n")
    double.write_text("".join(f"{x}\n{x}\n" for x in log.lines))
    once, twice = import_nmea(single, PLATFORM, log.sensors), import_nmea(double, PLATFORM, log.sensors)
    for name in ("plots", "navigation", "reference"):
        pd.testing.assert_frame_equal(getattr(twice, name), getattr(once, name))
    timed = sum(1 for x in log.lines if x.split("\\")[-1][3:6] in ("GGA", "RMC", "ZDA", "TTM", "HRA", "SHR"))
    assert twice.summary["duplicates"]["sentences"] >= timed > 0
    assert "duplicates" not in once.summary
    kept = import_nmea(double, PLATFORM, log.sensors, keep_duplicates=True)
    assert "duplicates" not in kept.summary and "duplicate" not in set(kept.rejected.code)


def test_ten_thousand_mutated_sentences():
    """``REGISTRATION_FUZZ_N`` (default 10 000) mutated lines of every sentence type, 100 to a log,
    in a child process with a time bound per input (tests/fuzzing.py)."""
    report = run_campaign("tests.io.nmea.fuzz_campaigns:sentences")
    assert_clean(report)
    assert report["outcomes"]["lines"] == report["inputs"] and report["outcomes"].get("imported", 0) > 0
