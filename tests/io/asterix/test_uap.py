"""The reader's UAP tables (registration/io/asterix/decode/uap.py) against libasterix's, generated from
the asterix-specs definitions: every FRN's item and layout, for every supported edition."""

from __future__ import annotations

import pytest

from registration.io.asterix.decode.uap import (
    DEFAULT_EDITIONS,
    SUPPORTED_EDITIONS,
    Compound,
    Explicit,
    Extended,
    Fixed,
    Repetitive,
    RepetitiveFx,
    check_editions,
    uap_for,
)
from tests.io.asterix.encode import spec

#: The categories of one UAP (CAT001's two are checked in test_cat001.py).
EDITIONS = [(cat, e) for cat, editions in SUPPORTED_EDITIONS.items() for e in editions if cat != 1]


def libasterix_layout(var):
    """The reader's layout (registration.io.asterix.decode.layouts) of a libasterix variation."""
    from asterix.base import Compound as C
    from asterix.base import Element, Group
    from asterix.base import Explicit as E
    from asterix.base import Extended as X
    from asterix.base import Repetitive as R

    if issubclass(var, (Element, Group)):
        assert var.cv_bit_size % 8 == 0
        return Fixed(var.cv_bit_size // 8)
    if issubclass(var, X):
        groups = []
        for g in var.cv_items_list:
            bits = sum(1 if item is None else item[1] for item in g)
            groups.append((bits // 8, g[-1] is None))
        return Extended(tuple(groups))
    if issubclass(var, R):
        if var.cv_rep_bytes is None:
            return RepetitiveFx((var.cv_variation.cv_bit_size + 1) // 8)
        return Repetitive(var.cv_rep_bytes, libasterix_layout(var.cv_variation).octets)
    if issubclass(var, E):
        return Explicit()
    if issubclass(var, C):
        return Compound(
            tuple(None if n is None else libasterix_layout(n.cv_rule.cv_variation) for n in var.cv_items_list)
        )
    raise TypeError(var)


@pytest.mark.parametrize("cat, edition", EDITIONS)
def test_uap_matches_libasterix(cat, edition):
    from asterix.base import UapItem

    theirs = []
    record = spec(cat, edition).cv_uap.cv_record
    for item in record.cv_items_list:
        if issubclass(item, UapItem):
            nsp = item.cv_non_spare
            theirs.append((nsp.cv_name, libasterix_layout(nsp.cv_rule.cv_variation)))
        else:
            theirs.append(None)
    mine = uap_for(cat, edition)
    assert list(mine.items) == theirs
    assert mine.fspec_octets == record.cv_fspec_max_bytes


def test_every_libasterix_edition_of_the_three_categories_is_supported():
    import asterix.generated as gen

    for cat in (48, 34, 21):
        theirs = [f"{s.cv_edition[0]}.{s.cv_edition[1]}" for s in gen.manifest["CATS"][cat]]
        assert list(SUPPORTED_EDITIONS[cat]) == theirs


def test_editions_argument():
    assert check_editions(None) == DEFAULT_EDITIONS
    assert check_editions({21: "0.26"})[21] == "0.26" and check_editions({"48": "1.30"})[48] == "1.30"
    with pytest.raises(ValueError, match=r"CAT048 edition '1.14' is not supported; supported: 1.27, .*1.32"):
        check_editions({48: "1.14"})
    with pytest.raises(ValueError, match="CAT062 is not decoded"):
        check_editions({62: "1.19"})
