"""Pairing of asynchronous plots of two radars into the rows the filter takes (docs/register.md)."""

__all__: list[str] = []
