"""NMEA 0183 bridge logs and AIS -> the fleet tables of one platform (docs/howto/import-nmea.md).

:func:`import_nmea` reads the logs: the navigation (GGA/GNS/RMC positions, ``$PASHR``/HDT/THS
attitude, ZDA/RMC dates), the radar's TTM tracked targets as plots (range and deck bearing), and
the AIS position reports of other vessels (through pyais) as reference positions. It returns an
:class:`NmeaImport` of DataFrames in the fleet file columns. :func:`read_sensors` reads and checks
a sensors file with its optional ``talker`` column.

Modules: ``lines`` (prefixes, tag blocks, checksums), ``fields`` (the fast field split),
``fixes``, ``attitude``, ``clock`` (one time axis, midnight rollover), ``navigation``, ``ttm``,
``ais`` (assembly, pyais decoding), ``reference`` (AIS positions and sigmas), ``sensors``,
``summary``, ``errors``, ``importer``.
"""

from registration.io.nmea.errors import REASONS, NmeaImportError
from registration.io.nmea.importer import NmeaImport, import_nmea
from registration.io.nmea.reference import AisSigmas
from registration.io.nmea.sensors import check_sensors, read_sensors

__all__ = [
    "AisSigmas",
    "NmeaImport",
    "NmeaImportError",
    "REASONS",
    "check_sensors",
    "import_nmea",
    "read_sensors",
]
