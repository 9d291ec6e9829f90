"""The flight levels the import reads, checked field by field against libasterix on random records
(every item present or not, random contents): I048/090 (V, G, flight level in 1/4 FL, two's
complement 14 bits) and I021/145 (flight level in 1/4 FL, 16 bits signed) in every supported
edition. libasterix declares I048/090's flight level signed from edition 1.32 on (unsigned before,
where the reader still reads two's complement, as CAT001's I001/090 and the Mode C range down to
-10 FL need): there the 14 bits are compared."""

from __future__ import annotations

import numpy as np
import pytest

from registration.io.asterix.decode.reader import decode_file
from registration.io.asterix.decode.uap import SUPPORTED_EDITIONS
from tests.io.asterix.cat001_data import item_quantity, item_value
from tests.io.asterix.libasterix_help import parse_blocks, random_blocks


def _decoded(tmp_path, cat: int, edition: str, seed: int):
    data = random_blocks(cat, edition, np.random.default_rng(seed), blocks=12, per_block=8)
    path = tmp_path / f"cat{cat}.ast"
    path.write_bytes(data)
    return decode_file(path, {cat: edition}, framing="netto").records[cat].fields, parse_blocks(
        cat, edition, data
    )


def _signed(r) -> bool:
    from asterix.base import Signed

    return r.get_item("090").variation.get_item("FL").variation.content.cv_signedness is Signed


@pytest.mark.parametrize("edition", SUPPORTED_EDITIONS[48])
def test_i048_090_matches_libasterix(tmp_path, edition):
    f, ref = _decoded(tmp_path, 48, edition, 4800 + len(edition))
    assert f["has_090"].size == len(ref)
    for k, (_, _, _, r) in enumerate(ref):
        assert f["has_090"][k] == (r.get_item("090") is not None)
        if f["has_090"][k]:
            assert (f["mc_v"][k], f["mc_g"][k]) == (item_value(r, "090", "V"), item_value(r, "090", "G"))
            assert f["mode_c"][k] % (1 << 14) == item_value(r, "090", "FL")  # the 14 bits as sent
            if _signed(r):  # libasterix declares the field signed from edition 1.32 on, as CAT001's
                assert f["mode_c"][k] / 4 == item_quantity(r, "FL", "090", "FL")
        else:
            assert f["mode_c"][k] == f["mc_v"][k] == f["mc_g"][k] == 0
    assert f["has_090"].sum() > 10 and (f["mode_c"] < 0).any() and (f["mode_c"] > 0).any()


@pytest.mark.parametrize("edition", SUPPORTED_EDITIONS[21])
def test_i021_145_matches_libasterix(tmp_path, edition):
    f, ref = _decoded(tmp_path, 21, edition, 2100 + int(edition.replace(".", "")))
    assert f["has_145"].size == len(ref)
    for k, (_, _, _, r) in enumerate(ref):
        assert f["has_145"][k] == (r.get_item("145") is not None)
        if f["has_145"][k]:
            assert f["flight_level"][k] / 4 == item_quantity(r, "FL", "145")
        else:
            assert f["flight_level"][k] == 0
    assert f["has_145"].sum() > 10 and (f["flight_level"] < 0).any() and (f["flight_level"] > 0).any()
