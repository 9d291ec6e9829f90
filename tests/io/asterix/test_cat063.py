"""The CAT063 encoder against libasterix, the independent encoder: for random sensor statuses in
editions 1.6 and 1.7, libasterix's record of the same raw values is byte for byte ours, and
libasterix's parse of our data blocks gives back each value to its LSB."""

from __future__ import annotations

import math

import numpy as np
import pytest

from registration.io.asterix.encode import CAT063_EDITIONS, SensorStatus, encode_cat063, status_record
from registration.io.asterix.encode.blocks import fspec

pytest.importorskip("asterix")  # libasterix (the test extra)

NM_M = 1852.0
AZ_LSB = 360.0 / 65536.0


def _spec(edition: str):
    import asterix.generated as gen

    major, minor = edition.split(".")
    return getattr(gen, f"Cat_063_{major}_{minor}")


def _random_status(rng: np.random.Generator, k: int) -> SensorStatus:
    def maybe(value):
        return value if rng.random() < 0.7 else None

    return SensorStatus(
        name=f"R{k}",
        sac=int(rng.integers(0, 256)),
        sic=int(rng.integers(0, 256)),
        time_of_day_s=float(rng.uniform(0, 86400)),
        state=str(rng.choice(["operational", "degraded", "initialisation", "not_connected"])),
        time_bias_s=maybe(float(rng.uniform(-30, 30))),
        ssr_range_gain=maybe(float(rng.uniform(-3e-3, 3e-3))),
        ssr_range_bias_m=maybe(float(rng.uniform(-2000, 2000))),
        ssr_azimuth_bias_rad=maybe(float(rng.uniform(-0.05, 0.05))),
        psr_range_gain=maybe(float(rng.uniform(-3e-3, 3e-3))),
        psr_range_bias_m=maybe(float(rng.uniform(-2000, 2000))),
        psr_azimuth_bias_rad=maybe(float(rng.uniform(-0.05, 0.05))),
        psr_nogo=bool(rng.random() < 0.2),
        ssr_nogo=bool(rng.random() < 0.2),
    )


def _raw(value: float, lsb: float, bits: int = 16) -> int:
    return round(value / lsb) & ((1 << bits) - 1)


def _libasterix_record(s: SensorStatus, edition: str, sac: int, sic: int):
    con = {"operational": 0, "degraded": 1, "initialisation": 2, "not_connected": 3}[s.state]
    items: dict = {
        "010": (("SAC", sac), ("SIC", sic)),
        "015": 7,
        "030": round(s.time_of_day_s * 128) % (86400 * 128),
        "050": (("SAC", s.sac), ("SIC", s.sic)),
        "060": ((con << 5) | (int(s.psr_nogo) << 4) | (int(s.ssr_nogo) << 3),),
    }
    if s.time_bias_s is not None:
        items["070"] = _raw(s.time_bias_s, 1e-3)
    for item, gain, bias in (
        ("080", s.ssr_range_gain, s.ssr_range_bias_m),
        ("090", s.psr_range_gain, s.psr_range_bias_m),
    ):
        if gain is not None or bias is not None:
            items[item] = (_raw(gain or 0.0, 1e-5), _raw((bias or 0.0) / NM_M, 1 / 128))
    if s.ssr_azimuth_bias_rad is not None:
        items["081"] = _raw(math.degrees(s.ssr_azimuth_bias_rad), AZ_LSB)
    if s.psr_azimuth_bias_rad is not None:
        items["091"] = _raw(math.degrees(s.psr_azimuth_bias_rad), AZ_LSB)
    return _spec(edition).cv_record.create(items)


@pytest.mark.parametrize("edition", CAT063_EDITIONS)
@pytest.mark.parametrize("seed", range(4))
def test_each_record_is_libasterix_s_record_of_the_same_values_byte_for_byte(edition, seed):
    rng = np.random.default_rng(seed)
    for k in range(50):
        s = _random_status(rng, k)
        ours = status_record(s, sac=25, sic=200, service_id=7)
        theirs = _libasterix_record(s, edition, 25, 200).unparse().to_bytes()
        assert ours == theirs, (s, ours.hex(), theirs.hex())


@pytest.mark.parametrize("edition", CAT063_EDITIONS)
def test_libasterix_parses_our_blocks_and_reads_every_value_to_its_lsb(edition):
    from asterix.base import Bits, RawDatablock

    rng = np.random.default_rng(11)
    statuses = [_random_status(rng, k) for k in range(3000)]  # more than one data block
    data = encode_cat063(statuses, sac=25, sic=200)
    blocks = RawDatablock.parse(Bits.from_bytes(data))
    assert not isinstance(blocks, ValueError) and len(blocks) > 1
    records = []
    for block in blocks:
        assert block.get_category() == 63
        parsed = _spec(edition).cv_uap.parse(block.get_raw_records())
        assert not isinstance(parsed, ValueError), parsed
        records += parsed
    assert len(records) == len(statuses)
    for s, rec in zip(statuses, records, strict=True):
        items = rec.items_regular
        assert items["050"].unparse().to_bytes() == bytes([s.sac, s.sic])
        if s.ssr_azimuth_bias_rad is None:
            assert "081" not in items
        else:
            raw = int.from_bytes(items["081"].unparse().to_bytes(), "big", signed=True)
            assert abs(raw * AZ_LSB - math.degrees(s.ssr_azimuth_bias_rad)) <= AZ_LSB / 2 + 1e-12
        if s.time_bias_s is not None:
            raw = int.from_bytes(items["070"].unparse().to_bytes(), "big", signed=True)
            assert abs(raw * 1e-3 - s.time_bias_s) <= 0.5e-3 + 1e-12


def test_a_value_the_item_cannot_hold_is_an_error_naming_the_sensor_and_item():
    s = SensorStatus(name="R7", sac=1, sic=2, time_of_day_s=0.0, ssr_range_bias_m=300 * NM_M)
    with pytest.raises(ValueError, match=r"R7: I063/080 SSR range bias"):
        status_record(s, 25, 200)
    with pytest.raises(ValueError, match="state"):
        status_record(SensorStatus(name="R7", sac=1, sic=2, time_of_day_s=0.0, state="fine"), 25, 200)


def test_fspec_sets_one_bit_per_item_and_fx_between_octets():
    assert fspec([1, 2, 3, 4, 5]) == bytes([0b11111000])
    assert fspec([1, 8]) == bytes([0b10000001, 0b10000000])
    assert fspec([10]) == bytes([0b00000001, 0b00100000])
