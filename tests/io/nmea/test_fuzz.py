"""A damaged log (characters changed, lines cut, joined, repeated, dropped, garbage inserted) never
makes the reader raise: every line is either used, counted as not used, or set aside with a reason."""

from __future__ import annotations

import numpy as np
import pytest

from registration.io.nmea import import_nmea
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
        ["not_a_sentence", "bad_prefix", "bad_tag_block", "no_checksum", "bad_checksum"]
    ).sum()
    # every non-blank line is a sentence with a correct checksum, or set aside before it is typed
    assert counted + set_aside_before_typing + summary["blank_lines"] == summary["lines"]
    assert (result.rejected.line >= 1).all() and (result.rejected.line <= summary["lines"]).all()
