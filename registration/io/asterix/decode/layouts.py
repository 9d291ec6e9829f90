"""The layouts of ASTERIX items and records (EUROCONTROL ASTERIX Part 1, the "variations" of the
asterix-specs definitions): how long an item is, and the User Application Profile (UAP) of a
category and edition, FRN by FRN. The tables themselves are in
:mod:`registration.io.asterix.decode.uap`, which names these again.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Fixed", "Extended", "Repetitive", "RepetitiveFx", "Explicit", "Compound", "Uap", "MultiUap"]


@dataclass(frozen=True)
class Fixed:
    """``octets`` octets."""

    octets: int


@dataclass(frozen=True)
class Extended:
    """Groups of (octets, has FX), read while the previous group's FX bit is set."""

    groups: tuple


@dataclass(frozen=True)
class Repetitive:
    """A count of ``rep`` octets, then count x ``octets``."""

    rep: int
    octets: int


@dataclass(frozen=True)
class RepetitiveFx:
    """Elements of ``octets`` octets, each ending in an FX bit set when another follows."""

    octets: int


@dataclass(frozen=True)
class Explicit:
    """A length octet that counts itself, then the data."""


@dataclass(frozen=True)
class Compound:
    """Its own FSPEC (one bit per subitem, FX chained), then the subitems present (None: spare bit)."""

    subitems: tuple


@dataclass(frozen=True)
class Uap:
    """One category and edition: ``items[frn - 1]`` = (item name, layout) or None for a spare FRN."""

    category: int
    edition: str
    items: tuple

    @property
    def fspec_octets(self) -> int:
        """The most FSPEC octets a record of this UAP can have (7 FRNs per octet)."""
        return -(-len(self.items) // 7)

    def frn(self, name: str) -> int:
        """The FRN (from 1) of item ``name``."""
        for k, item in enumerate(self.items, 1):
            if item is not None and item[0] == name:
                return k
        raise KeyError(f"CAT{self.category:03d} edition {self.edition} has no item {name}")


@dataclass(frozen=True)
class MultiUap:
    """A category of several UAPs chosen per record by one bit of the first octet of an item present
    in all of them (CAT001: plot or track by the TYP bit of I001/020, FRN 2 of both):
    ``variants[k]`` is the UAP of a record whose bit is k, ``names[k]`` its name. A record without
    the selecting item cannot be walked (its UAP is not known)."""

    category: int
    edition: str
    variants: tuple
    names: tuple
    selector: str
    selector_mask: int

    @property
    def fspec_octets(self) -> int:
        """The most FSPEC octets of any variant."""
        return max(u.fspec_octets for u in self.variants)
