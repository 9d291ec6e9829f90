"""libasterix as the independent reference: random records of any supported edition (every item
present or not, random contents, random lengths of extended, repetitive, explicit and compound
items), and each record's and item's bytes as libasterix parses them."""

from __future__ import annotations

import numpy as np

from tests.io.asterix.encode import spec

__all__ = ["random_items", "random_record", "random_blocks", "parse_blocks"]


def _random_value(var, rng: np.random.Generator, depth: int = 0):
    from asterix.base import Compound, Element, Explicit, Extended, Group, Repetitive

    if issubclass(var, (Element, Group)):
        return (
            int(rng.integers(0, 2 ** min(var.cv_bit_size, 62)))
            if var.cv_bit_size <= 62
            else int.from_bytes(rng.bytes((var.cv_bit_size + 7) // 8), "big") % 2**var.cv_bit_size
        )
    if issubclass(var, Extended):
        n = int(rng.integers(1, len(var.cv_items_list) + 1))
        return tuple(int(rng.integers(0, 2 ** _group_bits(g))) for g in var.cv_items_list[:n])
    if issubclass(var, Repetitive):
        n = int(rng.integers(0 if var.cv_rep_bytes else 1, 4))
        return [_random_value(var.cv_variation, rng, depth + 1) for _ in range(n)]
    if issubclass(var, Explicit):
        return rng.bytes(int(rng.integers(0, 6)))
    if issubclass(var, Compound):
        subs = [n for n in var.cv_items_list if n is not None]
        chosen = [n for n in subs if rng.random() < 0.5] or subs[:1]
        return {n.cv_name: _random_value(_variation(n), rng, depth + 1) for n in chosen}
    raise TypeError(var)


def _group_bits(group) -> int:
    """Bits of an extended item's group without its FX bit."""
    return sum(item[1] for item in group if item is not None)


def _variation(nsp):
    rule = nsp.cv_rule
    return rule.cv_variation if hasattr(rule, "cv_variation") else rule.cv_default_variation


def random_items(record, rng: np.random.Generator, p_item: float = 0.4) -> dict:
    """Random items of the libasterix record class ``record`` (each present with probability
    ``p_item``, at least one) and contents: the argument of ``record.create``."""
    from asterix.base import UapItem

    names = [i.cv_non_spare for i in record.cv_items_list if issubclass(i, UapItem)]
    chosen = [n for n in names if rng.random() < p_item] or names[:1]
    return {n.cv_name: _random_value(_variation(n), rng) for n in chosen}


def random_record(cat: int, edition: str, rng: np.random.Generator, p_item: float = 0.4):
    """A record of random items (each present with probability ``p_item``, at least one) and contents."""
    record = spec(cat, edition).cv_uap.cv_record
    return record.create(random_items(record, rng, p_item))


def random_blocks(cat: int, edition: str, rng: np.random.Generator, blocks: int, per_block: int) -> bytes:
    """Data blocks of random records, end to end."""
    s = spec(cat, edition)
    return b"".join(
        s.create([random_record(cat, edition, rng) for _ in range(int(rng.integers(1, per_block + 1)))])
        .unparse()
        .to_bytes()
        for _ in range(blocks)
    )


def parse_blocks(cat: int, edition: str, data: bytes) -> list:
    """Per record, libasterix's parse: (start offset, end offset, {item name: item bytes}, record)."""
    from asterix.base import Bits, RawDatablock

    s = spec(cat, edition)
    out, offset = [], 0
    for block in RawDatablock.parse(Bits.from_bytes(data)):
        records = s.cv_uap.parse(block.get_raw_records())
        assert not isinstance(records, ValueError), records
        pos = offset + 3
        for rec in records:
            size = len(rec.unparse()) // 8
            items = {name: nsp.unparse().to_bytes() for name, nsp in rec.items_regular.items()}
            out.append((pos, pos + size, items, rec))
            pos += size
        offset += len(block.unparse()) // 8
    return out
