"""One record walked octet by octet in plain Python: the reference the vectorised walk
(:mod:`registration.io.asterix.decode.walker`) is tested against, and the explanation, in words, of a
record the vectorised walk found bad (which item, what is wrong, where).
"""

from __future__ import annotations

from typing import Sequence

from registration.io.asterix.decode.uap import (
    Compound,
    Explicit,
    Extended,
    Fixed,
    MultiUap,
    Repetitive,
    RepetitiveFx,
    Uap,
)

__all__ = ["RecordProblem", "select_uap", "walk_one", "explain_record"]


class RecordProblem(Exception):
    """A record that cannot be walked: ``code`` (a reason code of
    :data:`~registration.io.asterix.errors.REASONS`) and the reason in words."""

    def __init__(self, code: str, reason: str) -> None:
        super().__init__(reason)
        self.code = code


def _size(data: Sequence[int], at: int, layout: object, name: str) -> int:
    """Octets of the item ``name`` of ``layout`` at ``at``; RecordProblem for a malformed one."""
    if isinstance(layout, Fixed):
        return layout.octets
    if isinstance(layout, Extended):
        size = 0
        for k, (octets, fx) in enumerate(layout.groups):
            size += octets
            if not fx or not data[at + size - 1] & 1:
                return size
        raise RecordProblem(
            "bad_item",
            f"item {name} has the FX bit set in its last octet allowed "
            f"({len(layout.groups)} groups in this edition)",
        )
    if isinstance(layout, RepetitiveFx):
        size = layout.octets
        while data[at + size - 1] & 1:
            size += layout.octets
        return size
    if isinstance(layout, Repetitive):
        count = int.from_bytes(bytes(data[at : at + layout.rep]), "big")
        return layout.rep + count * layout.octets
    if isinstance(layout, Explicit):
        if data[at] == 0:
            raise RecordProblem(
                "bad_item", f"explicit item {name} has length 0 (at least 1: the length octet)"
            )
        return data[at]
    if isinstance(layout, Compound):
        present, size = _fspec_items(data, at, len(layout.subitems), f"compound item {name}")
        for k in present:
            sub = layout.subitems[k - 1] if k <= len(layout.subitems) else None
            if sub is None:
                raise RecordProblem("bad_item", f"compound item {name} sets spare subfield {k}")
            size += _size(data, at + size, sub, f"{name} subfield {k}")
        return size
    raise TypeError(f"unknown item layout {layout!r}")


#: Octet -> the item bits set in it as FSPEC positions from 1 (bit 8 is 1, bit 2 is 7; FX left out).
_FSPEC_BITS = tuple(tuple(k + 1 for k in range(7) if octet & (0x80 >> k)) for octet in range(256))


def _fspec_items(data: Sequence[int], at: int, n: int, what: str) -> tuple[list, int]:
    """(FRNs set, FSPEC octets) of the FSPEC at ``at`` of something with n items."""
    octets = -(-n // 7)
    present: list[int] = []
    j = 0
    while True:
        octet = data[at + j]
        present += [7 * j + k for k in _FSPEC_BITS[octet]]
        j += 1
        if not octet & 1:
            return present, j
        if j == octets:
            raise RecordProblem(
                "fspec_overrun" if what == "record" else "bad_item",
                f"the FSPEC of the {what} has the FX bit set in its octet {octets}, the last its "
                f"{n} items allow",
            )


def select_uap(data: Sequence[int], pos: int, end: int, uap: MultiUap) -> Uap:
    """The variant of ``uap`` the record at ``pos`` names by its selecting item (CAT001: I001/020
    TYP, 0 plot, 1 track); RecordProblem without that item."""
    first = uap.variants[0]
    try:
        present, size = _fspec_items(data, pos, max(len(u.items) for u in uap.variants), "record")
    except IndexError:
        present, size = None, 0
    if present is None or pos + size > end:
        raise RecordProblem(
            "fspec_overrun", f"the FSPEC runs past the end of the data block ({end - pos} bytes left)"
        )
    frn = first.frn(uap.selector)
    if frn not in present:
        raise RecordProblem(
            "missing_item",
            f"no I{uap.category:03d}/{uap.selector}: the record's UAP "
            f"({' or '.join(uap.names)}) is not known",
        )
    at = pos + size + sum(first.items[k - 1][1].octets for k in present if k < frn)
    return uap.variants[1 if at < end and data[at] & uap.selector_mask else 0]


def walk_one(
    data: Sequence[int], pos: int, end: int, uap: Uap | MultiUap, wanted: tuple = ()
) -> tuple[int, dict]:
    """The record of ``uap`` at ``pos`` in a data block ending at ``end``: (its end, the offsets of
    the wanted items present). RecordProblem when it cannot be walked."""
    if isinstance(uap, MultiUap):
        uap = select_uap(data, pos, end, uap)
    try:
        present, size = _fspec_items(data, pos, len(uap.items), "record")
    except IndexError:  # the FSPEC runs past the data
        present, size = None, 0
    if present is None or pos + size > end:
        raise RecordProblem(
            "fspec_overrun", f"the FSPEC runs past the end of the data block ({end - pos} bytes left)"
        )
    if not present:
        raise RecordProblem("empty_record", "the FSPEC names no item")
    cursor, offsets = pos + size, {}
    items, n_items = uap.items, len(uap.items)
    for k in present:
        item = items[k - 1] if k <= n_items else None
        if item is None:
            raise RecordProblem(
                "spare_frn", f"the FSPEC sets FRN {k}, spare in CAT{uap.category:03d} edition {uap.edition}"
            )
        name, layout = item
        if type(layout) is Fixed:  # most items: no call
            size = layout.octets
        else:
            try:
                size = _size(data, cursor, layout, f"I{uap.category:03d}/{name}")
            except IndexError:
                size = end - cursor + 1
        if cursor + size > end:
            raise RecordProblem(
                "item_overrun",
                f"item I{uap.category:03d}/{name} (FRN {k}) needs {size} bytes, "
                f"{end - cursor} left in the data block",
            )
        if name in wanted:
            offsets[name] = cursor
        cursor += size
    return cursor, offsets


def explain_record(data: Sequence[int], pos: int, end: int, uap: Uap | MultiUap) -> tuple[str, str]:
    """(reason code, reason) of a record found bad; the reason names the first problem."""
    try:
        walk_one(data, pos, end, uap)
    except RecordProblem as problem:
        return problem.code, str(problem)
    return "bad_item", "the record does not decode"  # the vectorised and the scalar walk disagree
