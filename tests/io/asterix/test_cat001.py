"""CAT001 plots and CAT002 service messages against libasterix (the independent encoder and
decoder): the two UAPs of CAT001, the walk record by record (the UAP chosen per record by I001/020
TYP), the fields, the plots imported with their full time of day (I001/141 is truncated to 512 s;
completed from CAT002, across the 512 s wrap and midnight), the command line, and a fuzz smoke."""

from __future__ import annotations

import json
import os
import time

import numpy as np
import pandas as pd
import pytest

from registration.io.asterix import AsterixImportError, decode_file, import_asterix
from registration.io.asterix.decode.scalar import RecordProblem, walk_one
from registration.io.asterix.decode.uap import SUPPORTED_EDITIONS, UAPS, check_editions, uap_for
from registration.io.asterix.decode.walker import walk_records
from registration.io.asterix.tables.plots48 import SHARED_MODE_A
from tests.io.asterix.cat001_data import (
    DATE,
    EDITIONS,
    RADARS,
    block_bounds,
    buffer_of,
    cat001_plot,
    cat001_recording,
    cat002_record,
    item_quantity,
    item_value,
    mutate,
    parse_cat001,
    random_cat001,
    sites,
)
from tests.io.asterix.encode import encode_recording, spec
from tests.io.asterix.libasterix_help import parse_blocks
from tests.io.asterix.test_uap import libasterix_layout

LIBASTERIX_001 = ("1.2", "1.3", "1.4")
FUZZ_N = int(os.environ.get("REGISTRATION_FUZZ_N", "300"))
FUZZ_S = float(os.environ.get("REGISTRATION_FUZZ_S", "8"))


@pytest.fixture(scope="module")
def recorded(tmp_path_factory):
    """(raw path, truth, SITES path) of the CAT001/CAT002 recording."""
    rec, truth = cat001_recording()
    folder = tmp_path_factory.mktemp("cat001")
    path = folder / "legacy.ast"
    path.write_bytes(rec.raw())
    sites_path = folder / "sites.csv"
    sites().to_csv(sites_path, index=False)
    return path, truth, sites_path, rec


@pytest.fixture(scope="module")
def result(recorded):
    return import_asterix(recorded[0], sites(), date=DATE)


# --- UAPs and the walk -------------------------------------------------------------------------


@pytest.mark.parametrize("edition", LIBASTERIX_001)
def test_both_cat001_uaps_match_libasterix(edition):
    from asterix.base import UapItem

    multi = uap_for(1, edition)
    theirs = spec(1, edition).cv_uap
    assert theirs.cv_selector == (["020", "TYP"], {0: "plot", 1: "track"})
    assert multi.names == ("plot", "track") and multi.selector == "020" and multi.selector_mask == 0x80
    for name, mine in zip(multi.names, multi.variants):
        record = theirs.cv_uaps[name]
        expected = [
            (i.cv_non_spare.cv_name, libasterix_layout(i.cv_non_spare.cv_rule.cv_variation))
            if issubclass(i, UapItem)
            else None
            for i in record.cv_items_list
        ]
        assert list(mine.items) == expected, name
        assert mine.fspec_octets == record.cv_fspec_max_bytes


def test_editions_of_cat001_and_cat002():
    assert SUPPORTED_EDITIONS[1] == ("1.1", "1.2", "1.3", "1.4")
    assert SUPPORTED_EDITIONS[2] == ("1.0", "1.1", "1.2")
    assert UAPS[(1, "1.1")].items == UAPS[(1, "1.2")].items  # 1.1: not in libasterix, the UAPs of 1.2
    assert uap_for(1, "1.1").variants[1].items == uap_for(1, "1.2").variants[1].items
    assert check_editions({1: "1.2", "2": "1.0"})[1] == "1.2"
    with pytest.raises(ValueError, match=r"CAT001 edition '1.5' is not supported; supported: 1.1, 1.2"):
        check_editions({1: "1.5"})


@pytest.mark.parametrize("edition", LIBASTERIX_001)
def test_cat001_records_and_items_match_libasterix(edition):
    """Random plots and tracks: every record's bounds, its UAP and every item's bytes as libasterix
    (choosing the UAP by TYP) has them; the one-record walk agrees."""
    rng = np.random.default_rng(int(edition.replace(".", "")))
    data = random_cat001(edition, rng, 12)
    multi = uap_for(1, edition)
    names = tuple(sorted({i[0] for u in multi.variants for i in u.items if i is not None}))
    starts, ends = block_bounds(data)
    rec = walk_records(buffer_of(data), starts, ends, multi, names)
    ref = parse_cat001(data, edition)
    assert rec.bad_start.size == 0 and len(ref) > 40
    assert rec.start.tolist() == [p for p, _, _ in ref]
    assert rec.variant.tolist() == [("plot", "track").index(n) for _, n, _ in ref]
    assert {0, 1} <= set(rec.variant.tolist())
    for r, (pos, _, theirs) in enumerate(ref):
        assert rec.end[r] == pos + len(theirs.unparse()) // 8
        items = {name: nsp.unparse().to_bytes() for name, nsp in theirs.items_regular.items()}
        for name in names:
            offset = int(rec.items[name][r])
            if name not in items:
                assert offset == -1, (r, name)
            else:
                assert data[offset : offset + len(items[name])] == items[name], (r, name)
        end, offsets = walk_one(memoryview(data), pos, int(ends[rec.block[r]]), multi, names)
        assert end == rec.end[r] and offsets == {
            n: int(rec.items[n][r]) for n in names if rec.items[n][r] >= 0
        }


def test_cat001_vector_and_scalar_walks_agree_on_random_bytes():
    rng = np.random.default_rng(11)
    multi = uap_for(1, "1.4")
    blocks = []
    for _ in range(300):
        body = rng.bytes(int(rng.integers(1, 40)))
        blocks.append(bytes([1]) + (len(body) + 3).to_bytes(2, "big") + body)
    data = b"".join(blocks)
    buf = buffer_of(data)
    starts, ends = block_bounds(data)
    rec = walk_records(buf, starts, ends, multi)
    found, bad, mv = [], [], memoryview(buf)
    for s, e in zip(starts.tolist(), ends.tolist()):
        pos = s + 3
        while pos < e:
            try:
                end, _ = walk_one(mv, pos, e, multi)
            except RecordProblem:
                bad.append(pos)
                break
            found.append((pos, end))
            pos = end
    assert list(zip(rec.start.tolist(), rec.end.tolist())) == found
    assert sorted(rec.bad_start.tolist()) == sorted(bad)
    assert len(found) > 20 and len(bad) > 20


def test_a_cat001_record_without_i001_020_is_set_aside(tmp_path):
    good = cat002_record("1.2", 30, 1, 1, 100.0, None)
    block = encode_recording([(100.0, 2, 30, 1, good)], DATE, editions=EDITIONS).blocks[0]
    no020 = bytes([1, 0, 6, 0x80, 30, 1])  # FSPEC: I001/010 only
    path = tmp_path / "no020.ast"
    path.write_bytes(block + no020)
    rejected = import_asterix(path, sites(), date=DATE).rejected
    row = rejected[rejected.category == 1].iloc[0]
    assert row.reason_code == "missing_item" and "no I001/020" in row.reason
    assert row.offset == len(block) + 3


# --- fields, plots and their time -------------------------------------------------------------


def test_decoded_fields_match_libasterix(recorded):
    path, _, _, _ = recorded
    data = path.read_bytes()
    dec = decode_file(path, EDITIONS)
    f, ref = dec.records[1].fields, parse_cat001(data, "1.4")
    assert dec.records[1].offset.tolist() == [p for p, _, _ in ref]
    for k, (_, name, r) in enumerate(ref):
        assert f["typ"][k] == ("plot", "track").index(name) == item_value(r, "020", "TYP")
        assert (f["sac"][k], f["sic"][k]) == (item_value(r, "010", "SAC"), item_value(r, "010", "SIC"))
        assert f["ttod"][k] == item_value(r, "141")
        assert f["ttod"][k] / 128 == item_quantity(r, "s", "141")
        assert f["rho"][k] / 128 == item_quantity(r, "NM", "040", "RHO")
        assert f["theta"][k] * 360 / 65536 == pytest.approx(item_quantity(r, "°", "040", "THETA"), abs=1e-12)
        assert [f[x][k] for x in ("sim", "ssrpsr", "rab")] == [
            item_value(r, "020", x) for x in ("SIM", "SSRPSR", "RAB")
        ]
        if f["has_070"][k]:
            assert [f[x][k] for x in ("m3a_v", "m3a_g", "m3a")] == [
                item_value(r, "070", x) for x in ("V", "G", "MODE3A")
            ]
        assert f["has_090"][k] == (r.get_item("090") is not None)
        if f["has_090"][k]:
            assert f["mode_c"][k] / 4 == item_quantity(r, "FL", "090", "HGT")
    assert f["has_090"].sum() > 50 and (f["mode_c"] < 0).any()
    f2 = dec.records[2].fields
    ref2 = parse_blocks(2, "1.2", bytes(b for b in _only(data, 2)))
    assert len(ref2) == f2["tod"].size > 100
    for k, (_, _, _, r) in enumerate(ref2):
        assert (f2["msg_type"][k], f2["tod"][k]) == (item_value(r, "000"), item_value(r, "030"))
        assert f2["sector"][k] == (item_value(r, "020") or 0) and f2["rotation"][k] == item_value(r, "041")


def _only(data: bytes, cat: int) -> bytes:
    """The data blocks of category ``cat`` of a raw recording, end to end."""
    starts, ends = block_bounds(data)
    return b"".join(data[s:e] for s, e in zip(starts.tolist(), ends.tolist()) if data[s] == cat)


def test_every_plot_equals_libasterix_decoding(recorded, result):
    """Every CAT001 plot imported: range, azimuth, target id and kind as libasterix decodes its
    record; the full time within 1/256 s of the encoder's stamp, and equal to libasterix's truncated
    time modulo 512 s."""
    path, truth, _, _ = recorded
    data = path.read_bytes()
    ref = pd.DataFrame(
        [
            {
                "sensor": {(s, i): n for n, (s, i, _, _) in RADARS.items()}[
                    (item_value(r, "010", "SAC"), item_value(r, "010", "SIC"))
                ],
                "ttod": item_quantity(r, "s", "141"),
                "range_m": item_quantity(r, "NM", "040", "RHO") * 1852.0,
                "bearing_deg": item_quantity(r, "°", "040", "THETA"),
                **_ids(r),
            }
            for _, name, r in parse_cat001(data, "1.4")
            if name == "plot"
        ]
    )
    plots = result.plots
    assert len(plots) == len(ref) == len(truth) > 300
    # the plots (sorted by time) and the encoder's stamps (sorted): the same times
    stamps = np.sort(np.array([t for t, _ in truth]))
    np.testing.assert_allclose(plots["time_s"].to_numpy(), stamps, atol=1 / 256 + 1e-9)
    # each plot matched to its record by radar, truncated time and range (random: unique)
    tod = np.mod(plots["time_s"].to_numpy(), 86400.0)  # the time of day, across midnight
    plots = plots.assign(ttod=np.round(np.mod(tod, 512.0) * 128) / 128)
    merged = plots.merge(
        ref, on=["sensor", "ttod", "range_m"], how="outer", suffixes=("", "_ref"), indicator=True
    )
    assert (merged["_merge"] == "both").all() and len(merged) == len(ref)
    np.testing.assert_allclose(merged["bearing_deg"], merged["bearing_deg_ref"], atol=1e-12)
    assert merged["target"].tolist() == merged["target_ref"].tolist()
    summary = result.summary["plots"]
    assert (summary["mode_a"], summary["without_id"]) == (
        (ref.kind == "mode_a").sum(),
        (ref.kind == "none").sum(),
    )
    assert summary["mode_a"] > 50 and summary["without_id"] > 50
    # across the 512 s wrap of I001/141 (at 86016 s) and midnight (86400 s)
    t = plots["time_s"].to_numpy()
    assert (t < 86016).any() and ((t > 86016) & (t < 86400)).any() and (t > 86400).any()


def _ids(r) -> dict:
    if r.get_item("070") is None:
        return {"target_ref": "", "kind": "none"}
    code = item_value(r, "070", "MODE3A")
    ok = item_value(r, "070", "V") == 0 and item_value(r, "070", "G") == 0 and code not in SHARED_MODE_A
    return {"target_ref": f"A{code:04o}" if ok else "", "kind": "mode_a" if ok else "none"}


def test_time_bases_tracks_and_service_messages_in_the_summary(recorded, result):
    _, truth, _, _ = recorded
    by_radar = {n: sum(1 for _, r in truth if r == n) for n in RADARS}
    assert result.summary["cat001_time"] == {
        "from_cat002": by_radar["A"] + by_radar["B"],
        "from_other_category": by_radar["C"],
        "without_full_time": 0,
        "window_s": [-256.0, 256.0],
    }
    reasons = result.summary["rejected"]["by_reason"]
    assert reasons == {"cat001_track": result.summary["sensors"]["A"]["records"]["001"] - by_radar["A"]}
    a = result.summary["sensors"]["A"]
    assert a["scan_period_s"] == RADARS["A"][3] and a["cat002_messages"] > 0 and a["cat034_messages"] == 0
    assert a["clock_check"]["plots_checked"] > 50 and a["clock_check"]["plots_outside_their_sector"] == 0
    assert abs(a["clock_check"]["median_offset_s"]) < 0.01


def test_plots_without_any_full_time_are_set_aside(tmp_path):
    msgs = [(10.0 + k, 1, 30, 1, cat001_plot("1.4", 30, 1, 10.0 + k, 100, 200)) for k in range(5)]
    path = tmp_path / "alone.ast"
    path.write_bytes(encode_recording(msgs, DATE, editions=EDITIONS).raw())
    res = import_asterix(path, sites(), date=DATE)
    assert len(res.plots) == 0 and res.summary["rejected"]["by_reason"] == {"no_full_time": 5}
    assert res.summary["cat001_time"]["without_full_time"] == 5
    assert "no full time of day came before it" in res.rejected.reason.iloc[0]


def test_the_bases_carry_across_files(recorded, result, tmp_path):
    """The recording cut in two files (the second starts with plots): the plots of one file."""
    _, _, _, rec = recorded
    blocks = rec.blocks
    cut = next(k for k in range(len(blocks) // 2, len(blocks)) if blocks[k][0] == 1)
    first, second = tmp_path / "a.ast", tmp_path / "b.ast"
    first.write_bytes(b"".join(blocks[:cut]))
    second.write_bytes(b"".join(blocks[cut:]))
    both = import_asterix([first, second], sites(), date=DATE)
    pd.testing.assert_frame_equal(both.plots, result.plots)


def test_same_octets_512_s_apart_are_no_duplicates(tmp_path):
    """A fixed clutter plot seen again 512 s later has the same octets (I001/141 wrapped): kept;
    the same block recorded twice: a duplicate."""
    plot = cat001_plot("1.4", 30, 1, 1000.0, 700, 900)
    msgs = [
        (999.0, 2, 30, 1, cat002_record("1.2", 30, 1, 1, 999.0)),
        (1000.0, 1, 30, 1, plot),
        (1511.0, 2, 30, 1, cat002_record("1.2", 30, 1, 1, 1511.0)),
        (1512.0, 1, 30, 1, plot),
    ]
    blocks = encode_recording(msgs, DATE, editions=EDITIONS).blocks
    path = tmp_path / "clutter.ast"
    path.write_bytes(b"".join(blocks) + blocks[-1])
    res = import_asterix(path, sites(), date=DATE)
    assert res.plots["time_s"].tolist() == [1000.0, 1512.0]
    assert res.summary["rejected"]["by_reason"] == {"duplicate": 1}


@pytest.mark.parametrize("editions", [{1: "1.2", 2: "1.0"}, {1: "1.3", 2: "1.1"}])
def test_older_editions(tmp_path, editions):
    msgs = [(1.0, 2, 30, 1, cat002_record(editions[2], 30, 1, 1, 1.0, None, 4.0))]
    msgs += [
        (2.0 + k, 1, 30, 1, cat001_plot(editions[1], 30, 1, 2.0 + k, 100 + k, 200, mode_a=(0o1234, 0, 0)))
        for k in range(4)
    ]
    path = tmp_path / "old.ast"
    path.write_bytes(encode_recording(msgs, DATE, editions=editions).raw())
    res = import_asterix(path, sites(), date=DATE, editions=editions)
    assert res.summary["editions"]["001"] == editions[1] and res.summary["editions"]["002"] == editions[2]
    assert res.plots["time_s"].tolist() == [2.0, 3.0, 4.0, 5.0] and set(res.plots.target) == {"A1234"}


# --- command line and fuzz ---------------------------------------------------------------------


def test_command_line_end_to_end(recorded, result, tmp_path, capsys):
    from registration.cli import main

    path, _, sites_path, _ = recorded
    out = tmp_path / "out"
    argv = [
        "import",
        "asterix",
        str(path),
        "--sites",
        str(sites_path),
        "--out",
        str(out),
        "--date",
        "2024-05-01",
    ]
    assert main([*argv, "--cat001-edition", "1.4", "--cat002-edition", "1.2"]) == 0
    plots = pd.read_csv(out / "plots.csv", keep_default_na=False)
    assert len(plots) == len(result.plots) and set(plots.sensor) == set(RADARS)
    np.testing.assert_allclose(plots["range_m"], result.plots["range_m"])
    summary = json.loads((out / "import_summary.json").read_text())
    assert summary["editions"]["001"] == "1.4" and summary["cat001_time"]["from_cat002"] > 0
    assert main([*argv, "--cat001-edition", "1.9"]) == 2
    assert "invalid choice: '1.9'" in capsys.readouterr().err


def test_fuzz_smoke_of_mutated_cat001_blocks(recorded, tmp_path):
    """A few hundred mutations of CAT001/CAT002 blocks: an import whose totals add up, or an
    AsterixImportError naming the file; never another exception."""
    path, _, _, rec = recorded
    seed = b"".join(rec.blocks[:40])
    rng = np.random.default_rng(1001)
    frame, outcomes, start = sites(), {"imported": 0, "refused": 0}, time.perf_counter()
    for k in range(FUZZ_N):
        if time.perf_counter() - start > FUZZ_S:
            break
        target = tmp_path / f"m{k}.ast"
        target.write_bytes(mutate(seed, rng))
        try:
            res = import_asterix(target, frame, date=DATE, max_rejected_rows=1000)
        except AsterixImportError as exc:
            assert str(exc).startswith(str(target)) and "\n" not in str(exc)
            outcomes["refused"] += 1
        except Exception as exc:
            raise AssertionError(f"input {k}: {type(exc).__name__}: {exc}") from exc
        else:
            assert res.summary["plots"]["total"] == len(res.plots)
            assert res.summary["rejected"]["total"] >= len(res.rejected) - 1
            outcomes["imported"] += 1
        target.unlink()
    assert outcomes["imported"] >= 50
