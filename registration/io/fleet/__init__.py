"""The fleet tables as CSV or Parquet files in degrees and metres: reading (one file cell by cell, whole-file unit checks), bad rows and their reasons, writing (docs/fleet.md, Files and commands)."""

__all__: list[str] = []
