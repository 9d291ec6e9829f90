"""Pairing of asynchronous plots of two radars into the rows the filter takes
(docs/howto/register-recorded-files.md)."""

__all__: list[str] = []
