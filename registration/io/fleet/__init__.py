"""The fleet tables as CSV or Parquet files in degrees and metres: their schemas, defined once
(``schema``); reading (one file cell by cell, whole-file unit checks), bad rows and their reasons,
writing; and the tables as a source for the solvers (in memory, a checked folder, an archive read
lazily; ``sources.open_fleet_tables``). See docs/background/fleet-model.md, Files and commands, and
docs/reference/fleet-tables.md."""

__all__: list[str] = []
