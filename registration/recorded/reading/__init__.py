"""Reading recorded files: formats with units in the column names, row checks with a reason for every bad
row, field counts per line, unit checks, sources and streams of rows
(docs/howto/register-recorded-files.md)."""

__all__: list[str] = []
