"""The User Application Profiles (UAPs) of the ASTERIX categories the reader decodes: for each
category and edition, what item each Field Reference Number (FRN) of a record's FSPEC names and
how long that item is, so that a record can be walked and the items the reader does not use
skipped.

An item's length is one of (EUROCONTROL ASTERIX Part 1, the "variations" of the asterix-specs
definitions):

* ``Fixed(n)``: n octets;
* ``Extended(groups)``: a first part and extensions; each group is (octets, has FX), the FX bit
  (the least significant bit of the group's last octet) set when another group follows;
* ``Repetitive(rep, n)``: a count of ``rep`` octets, then count x n octets;
* ``RepetitiveFx(n)``: n-octet elements, each ending in an FX bit set when another follows;
* ``Explicit()``: a length octet that counts itself (special purpose and reserved expansion fields);
* ``Compound(subitems)``: its own FSPEC (FX chained, one bit per subitem, 7 per octet), then the
  subitems present, each Fixed, Extended or Repetitive; None for a spare subfield bit.

A spare FRN of a UAP is None; so is the random field sequencing (RFS) FRN of CAT001 and CAT002:
a record that uses it is set aside (``spare_frn``). CAT001 has two UAPs, plot and track, chosen
per record by the TYP bit of I001/020 (:class:`MultiUap`). The editions are those of the
asterix-specs definitions that the libasterix package is generated from;
``tests/io/asterix/test_uap.py`` and ``test_cat001.py`` check every table here against
libasterix's (CAT001 edition 1.1, which libasterix lacks, has the UAPs of 1.2). The data blocks
carry no edition, so the caller chooses one per category (:data:`DEFAULT_EDITIONS`, the latest of
each).
"""

from __future__ import annotations

from typing import Mapping

from registration.io.asterix.decode.layouts import (
    Compound,
    Explicit,
    Extended,
    Fixed,
    MultiUap,
    Repetitive,
    RepetitiveFx,
    Uap,
)

__all__ = [
    "Fixed",
    "Extended",
    "Repetitive",
    "RepetitiveFx",
    "Explicit",
    "Compound",
    "Uap",
    "MultiUap",
    "UAPS",
    "MULTI_UAPS",
    "DEFAULT_EDITIONS",
    "SUPPORTED_EDITIONS",
    "uap_for",
    "check_editions",
]


def _x(n: int, last_fx: bool = True) -> Extended:
    """An extended item of n one-octet groups, all with an FX bit (the last one optionally without)."""
    return Extended(tuple((1, True) for _ in range(n - 1)) + ((1, last_fx),))


def _cat048(n020: int) -> tuple:
    f = Fixed
    return (
        ("010", f(2)),
        ("140", f(3)),
        ("020", _x(n020)),
        ("040", f(4)),
        ("070", f(2)),
        ("090", f(2)),
        ("130", Compound(tuple(f(1) for _ in range(7)))),
        ("220", f(3)),
        ("240", f(6)),
        ("250", Repetitive(1, 8)),
        ("161", f(2)),
        ("042", f(4)),
        ("200", f(4)),
        ("170", _x(2)),
        ("210", f(4)),
        ("030", RepetitiveFx(1)),
        ("080", f(2)),
        ("100", f(4)),
        ("110", f(2)),
        ("120", Compound((f(2), Repetitive(1, 6)))),
        ("230", f(2)),
        ("260", f(7)),
        ("055", f(1)),
        ("050", f(2)),
        ("065", f(1)),
        ("060", f(2)),
        ("SP", Explicit()),
        ("RE", Explicit()),
    )


def _cat034() -> tuple:
    f = Fixed
    return (
        ("010", f(2)),
        ("000", f(1)),
        ("030", f(3)),
        ("020", f(1)),
        ("041", f(2)),
        ("050", Compound((f(1), None, None, f(1), f(1), f(2)))),
        ("060", Compound((f(1), None, None, f(1), f(1), f(1)))),
        ("070", Repetitive(1, 2)),
        ("100", f(8)),
        ("110", f(1)),
        ("120", f(8)),
        ("090", f(2)),
        ("RE", Explicit()),
        ("SP", Explicit()),
    )


def _cat021_v0(position_octets: int, frn27: bool) -> tuple:
    f = Fixed
    items = (
        ("010", f(2)),
        ("040", f(2)),
        ("030", f(3)),
        ("130", f(position_octets)),
        ("080", f(3)),
        ("140", f(2)),
        ("090", f(2)),
        ("210", f(1)),
        ("230", f(2)),
        ("145", f(2)),
        ("150", f(2)),
        ("151", f(2)),
        ("152", f(2)),
        ("155", f(2)),
        ("157", f(2)),
        ("160", f(4)),
        ("165", _x(2)),
        ("170", f(6)),
        ("095", f(1)),
        ("032", f(1)),
        ("200", f(1)),
        ("020", f(1)),
        ("220", Compound((f(2), f(2), f(2), f(1)))),
        ("146", f(2)),
        ("148", f(2)),
        ("110", Compound((_x(1), Repetitive(1, 15)))),
    )
    tail = (("070", f(2)), ("131", f(1))) if frn27 else (None, None)
    return items + tail + (None,) * 5 + (("RE", Explicit()), ("SP", Explicit()))


def _cat021_v2(n040: int, n090: int, last271_fx: bool) -> tuple:
    f = Fixed
    return (
        ("010", f(2)),
        ("040", _x(n040)),
        ("161", f(2)),
        ("015", f(1)),
        ("071", f(3)),
        ("130", f(6)),
        ("131", f(8)),
        ("072", f(3)),
        ("150", f(2)),
        ("151", f(2)),
        ("080", f(3)),
        ("073", f(3)),
        ("074", f(4)),
        ("075", f(3)),
        ("076", f(4)),
        ("140", f(2)),
        ("090", _x(n090)),
        ("210", f(1)),
        ("070", f(2)),
        ("230", f(2)),
        ("145", f(2)),
        ("152", f(2)),
        ("200", f(1)),
        ("155", f(2)),
        ("157", f(2)),
        ("160", f(4)),
        ("165", f(2)),
        ("077", f(3)),
        ("170", f(6)),
        ("020", f(1)),
        ("220", Compound((f(2), f(2), f(2), f(1)))),
        ("146", f(2)),
        ("148", f(2)),
        ("110", Compound((_x(1), Repetitive(1, 15)))),
        ("016", f(1)),
        ("008", f(1)),
        ("271", _x(2, last271_fx)),
        ("132", f(1)),
        ("250", Repetitive(1, 8)),
        ("260", f(7)),
        ("400", f(1)),
        ("295", Compound(tuple(f(1) for _ in range(23)))),
        None,
        None,
        None,
        None,
        None,
        ("RE", Explicit()),
        ("SP", Explicit()),
    )


def _cat001_plot() -> tuple:
    f, r = Fixed, RepetitiveFx(1)
    return (
        ("010", f(2)),
        ("020", _x(2)),
        ("040", f(4)),
        ("070", f(2)),
        ("090", f(2)),
        ("130", r),
        ("141", f(2)),
        ("050", f(2)),
        ("120", f(1)),
        ("131", f(1)),
        ("080", f(2)),
        ("100", f(4)),
        ("060", f(2)),
        ("030", r),
        ("150", f(1)),
        None,
        None,
        None,
        None,
        ("SP", Explicit()),
        None,  # random field sequencing: not decoded
    )


def _cat001_track() -> tuple:
    f, r = Fixed, RepetitiveFx(1)
    return (
        ("010", f(2)),
        ("020", _x(2)),
        ("161", f(2)),
        ("040", f(4)),
        ("042", f(4)),
        ("200", f(4)),
        ("070", f(2)),
        ("090", f(2)),
        ("141", f(2)),
        ("130", r),
        ("131", f(1)),
        ("120", f(1)),
        ("170", _x(2)),
        ("210", r),
        ("050", f(2)),
        ("080", f(2)),
        ("100", f(4)),
        ("060", f(2)),
        ("030", r),
        ("SP", Explicit()),
        None,  # random field sequencing: not decoded
        ("150", f(1)),
    )


def _cat002() -> tuple:
    f, r = Fixed, RepetitiveFx(1)
    return (
        ("010", f(2)),
        ("000", f(1)),
        ("020", f(1)),
        ("030", f(3)),
        ("041", f(2)),
        ("050", r),
        ("060", r),
        ("070", Repetitive(1, 2)),
        ("100", f(8)),
        ("090", f(2)),
        ("080", r),
        None,
        ("SP", Explicit()),
        None,  # random field sequencing: not decoded
    )


def _table() -> dict:
    out = {}
    for edition, n020 in (("1.27", 2), ("1.28", 2), ("1.29", 2), ("1.30", 2), ("1.31", 3), ("1.32", 6)):
        out[(48, edition)] = Uap(48, edition, _cat048(n020))
    for edition in ("1.27", "1.28", "1.29"):
        out[(34, edition)] = Uap(34, edition, _cat034())
    for edition, octets, frn27 in (
        ("0.23", 6, False),
        ("0.24", 8, False),
        ("0.25", 8, False),
        ("0.26", 8, True),
    ):
        out[(21, edition)] = Uap(21, edition, _cat021_v0(octets, frn27))
    for edition in ("2.1", "2.2", "2.3", "2.4", "2.5", "2.6", "2.7"):
        n040 = 5 if edition in ("2.6", "2.7") else 3
        n090 = 9 if edition == "2.7" else 4
        out[(21, edition)] = Uap(21, edition, _cat021_v2(n040, n090, edition != "2.1"))
    for edition in ("1.1", "1.2", "1.3", "1.4"):  # the same UAPs in all four
        out[(1, edition)] = Uap(1, edition, _cat001_plot())
    for edition in ("1.0", "1.1", "1.2"):
        out[(2, edition)] = Uap(2, edition, _cat002())
    return out


#: (category, edition) -> :class:`Uap`; for CAT001 the plot UAP (its FRNs 1 and 2, I001/010 and
#: I001/020, are those of the track UAP too), the pair is in :data:`MULTI_UAPS`.
UAPS = _table()
#: (category, edition) -> :class:`MultiUap` of the categories with a UAP per record (CAT001).
MULTI_UAPS = {
    (1, e): MultiUap(1, e, (UAPS[(1, e)], Uap(1, e, _cat001_track())), ("plot", "track"), "020", 0x80)
    for c, e in UAPS
    if c == 1
}
#: Category -> the editions supported, oldest first.
SUPPORTED_EDITIONS = {cat: tuple(e for c, e in UAPS if c == cat) for cat in (48, 34, 21, 1, 2)}
#: The edition used for each category unless the caller says otherwise: the latest. Each is a
#: superset of the earlier ones of its family (more extension octets allowed), except that CAT021
#: editions 0.2x and 2.x differ throughout: a 0.2x feed needs ``editions={21: "0.26"}``. CAT001
#: editions 1.1 to 1.4 share their UAPs, as do CAT002 editions 1.0 to 1.2.
DEFAULT_EDITIONS = {cat: editions[-1] for cat, editions in SUPPORTED_EDITIONS.items()}


def uap_for(category: int, edition: str) -> Uap | MultiUap:
    """The :class:`Uap` of ``category`` (48, 34, 21 or 2) and ``edition`` (e.g. "1.32"); the
    :class:`MultiUap` of CAT001."""
    return MULTI_UAPS.get((category, edition)) or UAPS[(category, edition)]


def check_editions(editions: Mapping[int, str] | Mapping[int | str, str] | None) -> dict:
    """The editions to use per category: :data:`DEFAULT_EDITIONS` updated by ``editions`` (a mapping
    of category number to edition text, or None). ValueError naming the category and the editions
    supported for an unknown category or edition."""
    out = dict(DEFAULT_EDITIONS)
    for cat, edition in dict(editions or {}).items():
        try:
            cat = int(cat)
        except (TypeError, ValueError):
            raise ValueError(
                f"editions: category {cat!r} is not a number; the reader decodes categories "
                f"{sorted(SUPPORTED_EDITIONS)}"
            ) from None
        if cat not in SUPPORTED_EDITIONS:
            raise ValueError(
                f"editions: CAT{cat:03d} is not decoded by the reader; it decodes categories "
                f"{sorted(SUPPORTED_EDITIONS)} (other categories are skipped and counted)"
            )
        if str(edition) not in SUPPORTED_EDITIONS[cat]:
            raise ValueError(
                f"editions: CAT{cat:03d} edition {edition!r} is not supported; supported: "
                f"{', '.join(SUPPORTED_EDITIONS[cat])}"
            )
        out[cat] = str(edition)
    return out
