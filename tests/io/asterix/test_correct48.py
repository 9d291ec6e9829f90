"""CAT048 plots corrected in place (registration.io.asterix.encode.cat048) against libasterix, the
independent encoder and decoder: datagrams are built with libasterix, corrected, and decoded again
with libasterix. RHO, THETA and the time of day must be the model's corrected values to the
nearest LSB; every other item, record, block and octet must be as it was."""

from __future__ import annotations

import math

import numpy as np
import pytest

from registration.io.asterix.encode.cat048 import CorrectedDatagram, PlotCorrection, correct_cat048
from tests.io.asterix.encode import cat021_record, cat034_record, cat048_record, spec
from tests.io.asterix.libasterix_help import parse_blocks

pytest.importorskip("asterix")  # libasterix (the test extra)

NM_M = 1852.0
DAY_RAW = 86400 * 128
THETA_LSB_DEG = 360.0 / 65536.0
#: Corrections tried, zero among them; (1, 2) and (3, 4) are corrected, (9, 9) never.
CORRECTIONS = [
    PlotCorrection(),
    PlotCorrection(range_bias_m=150.0, range_gain=2e-3, azimuth_bias_rad=0.01, time_bias_s=0.75),
    PlotCorrection(range_bias_m=-420.0, range_gain=-5e-4, azimuth_bias_rad=-0.2, time_bias_s=-3.2),
    PlotCorrection(range_bias_m=37.3, azimuth_bias_rad=math.radians(359.0), time_bias_s=86399.0),
]


def _block(edition: str, records: list) -> bytes:
    return spec(48, edition).create(records).unparse().to_bytes()


def _random_records(rng: np.random.Generator, n: int, sources, edition: str = "1.32") -> list:
    """CAT048 reports of random sources, values and items (some with the items the walk must
    skip: compound, repetitive, extended, explicit), times near midnight too."""
    out = []
    for _ in range(n):
        sac, sic = sources[int(rng.integers(len(sources)))]
        t_s = float(rng.choice([rng.uniform(0, 86400), rng.uniform(86390, 86400), rng.uniform(0, 10)]))
        out.append(
            cat048_record(
                edition,
                sac,
                sic,
                t_s,
                int(rng.integers(0, 65536)),
                int(rng.integers(0, 65536)),
                address=int(rng.integers(0, 1 << 24)) if rng.random() < 0.7 else None,
                mode_a=int(rng.integers(0, 4096)) if rng.random() < 0.7 else None,
                tst=int(rng.integers(0, 2)) if rng.random() < 0.5 else None,
                extras=bool(rng.random() < 0.5),
            )
        )
    return out


def _fields(rec) -> tuple[int, int, int]:
    """(RHO, THETA, time of day) raw, as libasterix reads them."""
    i040 = rec.get_item("040").variation
    return (i040.get_item("RHO").as_uint(), i040.get_item("THETA").as_uint(), rec.get_item("140").as_uint())


def _expected(rho: int, theta: int, tod: int, c: PlotCorrection) -> tuple[float, float, float]:
    """The model's corrected values, exact, in LSBs: range in NM, azimuth in degrees."""
    rho_nm = (rho / 256.0 - c.range_bias_m / NM_M) / (1.0 + c.range_gain)
    theta_deg = theta * THETA_LSB_DEG - math.degrees(c.azimuth_bias_rad)
    return rho_nm * 256.0, theta_deg / THETA_LSB_DEG, tod - c.time_bias_s * 128.0


def _circular(a: float, b: float, period: float) -> float:
    return abs((a - b + period / 2) % period - period / 2)


def _check(before: list, after: list, corrections: dict) -> int:
    """Each record of ``after`` against ``before`` (parse_blocks of each); returns the corrected."""
    assert len(before) == len(after)
    n = 0
    for (s0, e0, items0, rec0), (s1, e1, items1, rec1) in zip(before, after, strict=True):
        assert (s0, e0) == (s1, e1)
        assert items1.keys() == items0.keys()
        source = tuple(items0["010"])
        c = corrections.get(source)
        if c is None:  # not corrected: every item as it was
            assert items1 == items0
            continue
        n += 1
        for name in items0.keys() - {"040", "140"}:
            assert items1[name] == items0[name], name
        rho, theta, tod = _expected(*_fields(rec0), c)
        got_rho, got_theta, got_tod = _fields(rec1)
        if 0 <= rho <= 65535:
            assert abs(got_rho - rho) <= 0.5 + 1e-6, (got_rho, rho)
        else:
            assert got_rho == (0 if rho < 0 else 65535)
        assert _circular(got_theta, theta, 65536) <= 0.5 + 1e-6, (got_theta, theta)
        assert _circular(got_tod, tod, DAY_RAW) <= 0.5 + 1e-6, (got_tod, tod)
        assert 0 <= got_tod < DAY_RAW
    return n


@pytest.mark.parametrize("k", range(len(CORRECTIONS)))
def test_rho_theta_and_time_are_corrected_to_the_lsb_and_nothing_else_changes(k):
    rng = np.random.default_rng(k)
    sources = [(1, 2), (3, 4), (9, 9)]
    corrections = {(1, 2): CORRECTIONS[k], (3, 4): CORRECTIONS[(k + 1) % len(CORRECTIONS)]}
    for _ in range(20):
        data = _block("1.32", _random_records(rng, int(rng.integers(1, 15)), sources))
        result = correct_cat048(data, corrections)
        assert isinstance(result, CorrectedDatagram)
        assert len(result.data) == len(data)
        assert result.data[:3] == data[:3]  # the block header
        before, after = parse_blocks(48, "1.32", data), parse_blocks(48, "1.32", result.data)
        assert _check(before, after, corrections) == result.corrected
        assert result.records == len(before) and result.unwalkable == 0


def test_zero_corrections_return_the_input_unchanged():
    rng = np.random.default_rng(7)
    data = _block("1.32", _random_records(rng, 30, [(1, 2), (3, 4)]))
    result = correct_cat048(data, {(1, 2): PlotCorrection(), (3, 4): PlotCorrection()})
    assert result.data == data
    assert (result.records, result.corrected, result.clamped, result.unwalkable) == (30, 30, 0, 0)
    assert correct_cat048(data, {}).data == data


def test_other_sources_and_categories_are_unchanged_byte_for_byte_in_a_datagram_of_several_blocks():
    rng = np.random.default_rng(3)
    c = CORRECTIONS[1]
    b48a = _block("1.32", _random_records(rng, 8, [(1, 2), (9, 9)]))
    b34 = spec(34, "1.29").create([cat034_record("1.29", 1, 2, 2, 100.0, 64, 4.0, extras=True)])
    b21 = spec(21, "2.6").create(
        [
            cat021_record("2.6", 1, 2, 100.0, address=7, lat_deg=50.0, lon_deg=4.0, height_ft_raw=400, nacp=9)
            for _ in range(3)
        ]
    )
    b48b = _block("1.32", _random_records(rng, 5, [(1, 2)]))
    b48c = _block("1.32", _random_records(rng, 4, [(9, 9)]))
    parts = [b48a, b34.unparse().to_bytes(), b21.unparse().to_bytes(), b48b, b48c]
    data = b"".join(parts)
    result = correct_cat048(data, {(1, 2): c})
    assert len(result.data) == len(data) and result.records == 17 and result.unwalkable == 0
    ends = np.cumsum([len(p) for p in parts])
    out = [result.data[a:b] for a, b in zip([0, *ends[:-1]], ends)]
    assert out[1] == parts[1] and out[2] == parts[2] and out[4] == parts[4]
    corrected = 0
    for k in (0, 3):
        before, after = parse_blocks(48, "1.32", parts[k]), parse_blocks(48, "1.32", out[k])
        corrected += _check(before, after, {(1, 2): c})
        for (s, e, items, _), (_, _, items1, _) in zip(before, after):
            if tuple(items["010"]) == (9, 9):
                assert out[k][s:e] == parts[k][s:e]
    assert corrected == result.corrected > 0


def test_a_range_outside_the_item_is_clamped_and_counted():
    records = [
        cat048_record("1.32", 1, 2, 10.0, 65500, 0),  # + 100 NM: beyond 65535/256 NM
        cat048_record("1.32", 1, 2, 10.0, 100, 0),  # - 100 NM: below 0
        cat048_record("1.32", 1, 2, 10.0, 30000, 0),  # inside
    ]
    data = _block("1.32", records)
    far = correct_cat048(data, {(1, 2): PlotCorrection(range_bias_m=-100 * NM_M)})
    near = correct_cat048(data, {(1, 2): PlotCorrection(range_bias_m=100 * NM_M)})
    rho_far = [_fields(r[3])[0] for r in parse_blocks(48, "1.32", far.data)]
    rho_near = [_fields(r[3])[0] for r in parse_blocks(48, "1.32", near.data)]
    assert rho_far == [65535, 100 + 100 * 256, 30000 + 100 * 256] and far.clamped == 1
    assert rho_near == [65500 - 100 * 256, 0, 30000 - 100 * 256] and near.clamped == 1


def test_a_datagram_cut_anywhere_keeps_its_length_and_corrects_only_the_whole_records():
    rng = np.random.default_rng(5)
    c = {(1, 2): CORRECTIONS[2]}
    data = _block("1.32", _random_records(rng, 6, [(1, 2)])) + _block(
        "1.32", _random_records(rng, 3, [(1, 2)])
    )
    full = correct_cat048(data, c).data
    records = parse_blocks(48, "1.32", data)
    ends = [e for _, e, _, _ in records]
    block_end = int.from_bytes(data[1:3], "big")
    for cut in range(len(data)):
        result = correct_cat048(data[:cut], c)
        whole = max([e for e in ends if e <= cut], default=0)
        assert result.data == full[:whole] + data[whole:cut], cut
        assert result.corrected == sum(e <= cut for e in ends)
        # cut inside a block or its header: the record cut, or the missing rest, counts once
        assert result.unwalkable == (0 if cut in (0, block_end) else 1), cut


def test_a_record_that_cannot_be_walked_leaves_the_rest_of_its_block_and_is_counted():
    rng = np.random.default_rng(9)
    c = {(1, 2): CORRECTIONS[1]}
    first = _block("1.32", _random_records(rng, 5, [(1, 2)]))
    second = _block("1.32", _random_records(rng, 2, [(1, 2)]))
    records = parse_blocks(48, "1.32", first)
    bad = bytearray(first)
    bad[records[2][0]] = 0x00  # the third record's FSPEC names no item
    result = correct_cat048(bytes(bad) + second, c)
    clean = correct_cat048(first + second, c).data
    cut = records[2][0]
    assert result.data[:cut] == clean[:cut]
    assert result.data[cut : len(first)] == bytes(bad[cut:])
    assert result.data[len(first) :] == clean[len(first) :]
    assert (result.records, result.corrected, result.unwalkable) == (
        5,
        4,
        1,
    )  # 2 walked, 1 bad, 2 in the next block
    spare = bytearray(first)
    spare[records[1][0]] = 0x01  # FX set in every octet: an FSPEC longer than the UAP allows
    spare[records[1][0] + 1 : records[1][0] + 4] = b"\x01\x01\x01"
    result = correct_cat048(bytes(spare), c)
    assert result.data[records[1][0] :] == bytes(spare[records[1][0] :])
    assert (result.records, result.corrected, result.unwalkable) == (2, 1, 1)


def test_a_block_length_below_three_ends_the_walk_and_is_counted():
    block = _block("1.32", _random_records(np.random.default_rng(1), 2, [(1, 2)]))
    data = block + bytes([48, 0, 2]) + block
    result = correct_cat048(data, {(1, 2): CORRECTIONS[1]})
    assert result.data[len(block) :] == data[len(block) :]
    assert result.data[: len(block)] == correct_cat048(block, {(1, 2): CORRECTIONS[1]}).data
    assert (result.records, result.corrected, result.unwalkable) == (2, 2, 1)


def test_an_older_edition_and_the_checks_of_the_arguments():
    rng = np.random.default_rng(2)
    data = _block("1.27", _random_records(rng, 6, [(1, 2)], edition="1.27"))
    c = {(1, 2): CORRECTIONS[1]}
    result = correct_cat048(data, c, edition="1.27")
    assert _check(parse_blocks(48, "1.27", data), parse_blocks(48, "1.27", result.data), c) == 6
    with pytest.raises(ValueError, match="edition '0.9'"):
        correct_cat048(data, c, edition="0.9")
    with pytest.raises(ValueError, match="range_gain"):
        PlotCorrection(range_gain=-1.0)
    with pytest.raises(ValueError, match="time_bias_s"):
        PlotCorrection(time_bias_s=math.nan)


def test_an_invalid_time_of_day_is_left_as_it_is():
    record = cat048_record("1.32", 1, 2, 0.0, 1000, 1000)
    data = bytearray(_block("1.32", [record]))
    at = data.index(bytes([1, 2])) + 2  # I048/140 follows I048/010
    data[at : at + 3] = (DAY_RAW + 5).to_bytes(3, "big")
    result = correct_cat048(bytes(data), {(1, 2): CORRECTIONS[1]})
    assert result.data[at : at + 3] == data[at : at + 3]
    assert result.data[at + 3 :] != data[at + 3 :]  # I048/040 still corrected
