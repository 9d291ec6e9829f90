"""Readers and writers of real data formats and of the package's own table files.

Layer: beside ``recorded`` and ``interop``, above the capabilities (``fleet``, ``online``, ...),
below ``cli``. Subpackages:

- ``files``: table files in general (CSV/Parquet by suffix, exact writing and the one folder
  writer, the fields of every CSV line counted from the raw bytes, the reason codes of rejected
  rows, the rejected ledger, the one error for a file that cannot be read);
- ``imports``: the import contract, :class:`~registration.io.imports.ImportResult`, that every
  importer of a recording gives;
- ``output``: output folders published whole, checkpoints;
- ``fleet``: the fleet's table files (plots, navigation, sensors, platforms, reference) in degrees
  and metres: :func:`read_fleet_tables`, :func:`write_fleet_tables`;
- ``asterix``: EUROCONTROL ASTERIX recordings (CAT048 plots, CAT034 service messages, CAT021
  ADS-B references);
- ``nmea``: NMEA 0183 bridge logs and AIS.
"""

from registration.io.fleet.reading.read import FleetTables, read_fleet_tables
from registration.io.fleet.write import write_fleet_tables

__all__ = ["FleetTables", "read_fleet_tables", "write_fleet_tables"]
