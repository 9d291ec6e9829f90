"""The vectorised record walk against libasterix, record by record and item by item, on random
records of every supported edition; the one-record reference walk against the vectorised one on
random bytes; the decoded fields of the standard recording against libasterix's values."""

from __future__ import annotations

import numpy as np
import pytest

from registration.io.asterix.decode.scalar import RecordProblem, walk_one
from registration.io.asterix.decode.uap import SUPPORTED_EDITIONS, uap_for
from registration.io.asterix.decode.walker import walk_records
from registration.io.asterix.octets import PAD
from tests.io.asterix.libasterix_help import parse_blocks, random_blocks

#: The categories of one UAP (CAT001's two are checked in test_cat001.py).
EDITIONS = [(cat, e) for cat, editions in SUPPORTED_EDITIONS.items() for e in editions if cat != 1]


def _buffer(data: bytes) -> np.ndarray:
    buf = np.zeros(len(data) + PAD, dtype=np.uint8)
    buf[: len(data)] = np.frombuffer(data, dtype=np.uint8)
    return buf


def _block_bounds(data: bytes) -> tuple[np.ndarray, np.ndarray]:
    starts, p = [], 0
    while p < len(data):
        starts.append(p)
        p += int.from_bytes(data[p + 1 : p + 3], "big")
    starts = np.array(starts, dtype=np.int64)
    return starts, np.append(starts[1:], len(data))


@pytest.mark.parametrize("cat, edition", EDITIONS)
def test_records_and_items_match_libasterix(cat, edition):
    """Every record's bounds and every item's bytes (read or skipped by the reader) as libasterix has them."""
    rng = np.random.default_rng(cat * 100 + int(edition.replace(".", "")))
    data = random_blocks(cat, edition, rng, blocks=6, per_block=8)
    uap = uap_for(cat, edition)
    names = tuple(item[0] for item in uap.items if item is not None)
    starts, ends = _block_bounds(data)
    rec = walk_records(_buffer(data), starts, ends, uap, names)
    ref = parse_blocks(cat, edition, data)
    assert rec.bad_start.size == 0
    assert list(zip(rec.start.tolist(), rec.end.tolist())) == [(a, b) for a, b, _, _ in ref]
    for r, (_, _, items, _) in enumerate(ref):
        for name in names:
            offset = int(rec.items[name][r])
            if name not in items:
                assert offset == -1, (r, name)
            else:
                assert data[offset : offset + len(items[name])] == items[name], (r, name)
        end, offsets = walk_one(memoryview(data), int(rec.start[r]), int(ends[rec.block[r]]), uap, names)
        assert end == rec.end[r] and offsets == {
            n: int(rec.items[n][r]) for n in names if rec.items[n][r] >= 0
        }


@pytest.mark.parametrize("cat, edition", [(48, "1.32"), (21, "2.6"), (21, "0.23"), (34, "1.29")])
def test_vector_and_scalar_walks_agree_on_random_bytes(cat, edition):
    """Random record bytes behind valid block headers: the same records found, the same record found bad."""
    rng = np.random.default_rng(7)
    uap = uap_for(cat, edition)
    blocks = []
    for _ in range(300):
        body = rng.bytes(int(rng.integers(1, 60)))
        blocks.append(bytes([cat]) + (len(body) + 3).to_bytes(2, "big") + body)
    data = b"".join(blocks)
    buf = _buffer(data)
    starts, ends = _block_bounds(data)
    rec = walk_records(buf, starts, ends, uap)
    found, bad, mv = [], [], memoryview(buf)
    for s, e in zip(starts.tolist(), ends.tolist()):
        pos = s + 3
        while pos < e:
            try:
                end, _ = walk_one(mv, pos, e, uap)
            except RecordProblem:
                bad.append(pos)
                break
            found.append((pos, end))
            pos = end
    assert list(zip(rec.start.tolist(), rec.end.tolist())) == found
    assert sorted(rec.bad_start.tolist()) == sorted(bad)
    assert len(found) > 20 and len(bad) > 20  # both kinds occur


def _value(rec, *path):
    item = rec.get_item(path[0])
    if item is None:
        return None
    var = item.variation
    for name in path[1:]:
        sub = var.get_item(name)
        if sub is None:
            return None
        var = sub.variation
    return var.unparse().to_uinteger() if hasattr(var, "unparse") else var


def test_decoded_fields_match_libasterix(files):
    """The standard recording's CAT048, CAT034, CAT021 fields, record by record."""
    from registration.io.asterix import decode_file
    from tests.io.asterix.encode import spec

    dec = decode_file(files["raw"])
    data = files["raw"].read_bytes()
    from asterix.base import Bits, RawDatablock

    per_cat = {48: [], 34: [], 21: []}
    offset = 0
    for block in RawDatablock.parse(Bits.from_bytes(data)):
        cat = block.get_category()
        pos = offset + 3
        for r in spec(cat, {48: "1.32", 34: "1.29", 21: "2.7"}[cat]).cv_uap.parse(block.get_raw_records()):
            per_cat[cat].append((pos, r))
            pos += len(r.unparse()) // 8
        offset += len(block.unparse()) // 8
    f48 = dec.records[48].fields
    assert dec.records[48].offset.tolist() == [p for p, _ in per_cat[48]]
    for k, (_, r) in enumerate(per_cat[48]):
        assert (f48["sac"][k], f48["sic"][k]) == (_value(r, "010", "SAC"), _value(r, "010", "SIC"))
        assert f48["tod"][k] == _value(r, "140")
        assert (f48["rho"][k], f48["theta"][k]) == (_value(r, "040", "RHO"), _value(r, "040", "THETA"))
        assert f48["typ"][k] == _value(r, "020", "TYP") and f48["sim"][k] == _value(r, "020", "SIM")
        assert f48["rab"][k] == _value(r, "020", "RAB") and f48["tst"][k] == (_value(r, "020", "TST") or 0)
        assert f48["address"][k] == (_value(r, "220") or 0)
        if f48["has_070"][k]:
            assert [f48[x][k] for x in ("m3a_v", "m3a_g", "m3a_l", "m3a")] == [
                _value(r, "070", x) for x in ("V", "G", "L", "MODE3A")
            ]
    f34 = dec.records[34].fields
    for k, (_, r) in enumerate(per_cat[34]):
        assert (f34["msg_type"][k], f34["tod"][k]) == (_value(r, "000"), _value(r, "030"))
        assert f34["sector"][k] == (_value(r, "020") or 0) and f34["rotation"][k] == (_value(r, "041") or 0)
    f21 = dec.records[21].fields
    for k, (_, r) in enumerate(per_cat[21]):
        assert f21["address"][k] == _value(r, "080")
        assert f21["tod"][k] == next(
            v for v in (_value(r, "071"), _value(r, "073"), _value(r, "077")) if v is not None
        )
        if _value(r, "090", "NACP") is not None:
            assert f21["nacp"][k] == _value(r, "090", "NACP")
        if _value(r, "140") is not None:
            assert f21["height"][k] == r.get_item("140").variation.content.as_quantity("ft") / 6.25
        lat = r.get_item("131") or r.get_item("130")
        assert f21["lat_deg"][k] == pytest.approx(
            lat.variation.get_item("LAT").variation.content.as_quantity("°"), abs=1e-12
        )


def test_chunks_do_not_change_the_result(files, monkeypatch):
    """Blocks walked a few hundred bytes at a time give the records of one walk."""
    from registration.io.asterix import decode_file
    from registration.io.asterix.decode import reader

    whole = decode_file(files["pcapng"])
    monkeypatch.setattr(reader, "CHUNK_BYTES", 300)
    chunked = decode_file(files["pcapng"])
    for cat in (48, 34, 21):
        assert chunked.records[cat].offset.tolist() == whole.records[cat].offset.tolist()
        for key, values in whole.records[cat].fields.items():
            np.testing.assert_array_equal(chunked.records[cat].fields[key], values, err_msg=key)


@pytest.mark.parametrize("edition", ["0.23", "0.24", "0.26", "2.1"])
def test_cat021_of_other_editions(tmp_path, edition):
    """CAT021 reports encoded in an older edition and imported with ``editions={21: edition}``."""
    import datetime as dt

    from registration.io.asterix import import_asterix
    from tests.io.asterix.encode import cat021_record, cat048_record, encode_recording
    from tests.io.asterix.scenario import sites_frame

    old = edition.startswith("0.")
    quality = [9, 8, 5] if old else [10, 8, 5]  # NUCp (0.2x) or NACp; the last is too low
    messages = [(10.0, 48, 10, 1, cat048_record("1.32", 10, 1, 10.0, 100, 0, address=0xABC123))]
    for k, q in enumerate(quality):
        t = 11.0 + k
        messages.append(
            (
                t,
                21,
                20,
                1,
                cat021_record(
                    edition,
                    20,
                    1,
                    t,
                    address=0xABC123,
                    lat_deg=-33.5 + k,
                    lon_deg=151.25,
                    height_ft_raw=2000,
                    nacp=q,
                    gva=None,
                    hires=False,
                    sim=0,
                ),
            )
        )
    messages.append(
        (
            14.0,
            21,
            20,
            1,
            cat021_record(
                edition,
                20,
                1,
                14.0,
                address=0xABC123,
                lat_deg=1,
                lon_deg=1,
                height_ft_raw=1,
                nacp=9,
                sim=1,
                gva=None,
                hires=False,
            ),
        )
    )
    (tmp_path / "old.ast").write_bytes(
        encode_recording(messages, dt.date(2024, 5, 1), editions={21: edition}).raw()
    )
    result = import_asterix(tmp_path / "old.ast", sites_frame(), editions={21: edition})
    ref = result.reference
    lsb = 180 / 2 ** (25 if edition in ("0.24", "0.26") else 23)
    np.testing.assert_allclose(ref["lat_deg"], [-33.5, -32.5], atol=lsb)
    np.testing.assert_allclose(ref["time_s"], [11.0, 12.0])
    epu = [3.0, 10.0] if old else [10.0, 92.6]  # NUCp 9, 8: 3 m, 10 m; NACp 10, 8: 10 m, 0.05 NM
    np.testing.assert_allclose(ref["sigma_m"], np.array(epu) / 2.4477, rtol=1e-4)
    np.testing.assert_allclose(
        ref["sigma_up_m"], 2 * np.array(epu) / 2.4477, rtol=1e-4
    )  # no GVA in these editions
    assert result.rejected.groupby("reason_code").size().to_dict() == {"low_nacp": 1, "simulated": 1}
