"""ASTERIX recordings in, fleet tables out (docs/howto/import-asterix.md).

:func:`import_asterix` reads raw ASTERIX recordings (data blocks end to end) and pcap/pcapng
captures of UDP datagrams, gzip-compressed or not, told apart by their content. CAT048 and CAT001
target reports become plots (CAT001's truncated times completed from CAT002), CAT021 ADS-B reports
reference positions, CAT034 and CAT002 service messages give each radar's scan period and a clock
check; SITES (:func:`read_sites`) maps SAC/SIC to sensors and
gives the sites' positions and noise. Bad input inside a file is set aside with its file, byte
offset and reason, never raised; a file that is not ASTERIX or a capture raises
:class:`AsterixImportError`.

Subpackages: ``capture`` (``capture``: file, gzip, format; ``pcap``: packets; ``netstack``: UDP
datagrams; ``blocks``: data blocks), ``decode`` (``layouts``: item and UAP layouts; ``uap``: the UAP
of each edition; ``walker``: the vectorised record walk; ``scalar``: the one-record reference walk;
the items per category in ``decode48``, ``decode34``, ``decode21``, ``decode001``, ``decode002``;
``reader``: one file decoded) and ``tables`` (``plots48``, ``plots01``, ``adsb21``, ``verdicts``,
``timeofday``, ``truncated``, ``service``, ``assemble``, ``sites``, ``fleetfiles``, ``summary``);
beside them ``octets`` (big-endian fields at many byte offsets, read by ``capture`` and ``decode``),
``importer`` (the import) and ``errors``.
"""

from registration.io.asterix.decode.reader import DecodedFile, decode_file
from registration.io.asterix.decode.uap import DEFAULT_EDITIONS, SUPPORTED_EDITIONS
from registration.io.asterix.errors import REASONS, AsterixImportError
from registration.io.asterix.importer import AsterixImport, import_asterix
from registration.io.asterix.tables.sites import check_sites, read_sites

__all__ = [
    "AsterixImport",
    "AsterixImportError",
    "DEFAULT_EDITIONS",
    "DecodedFile",
    "REASONS",
    "SUPPORTED_EDITIONS",
    "check_sites",
    "decode_file",
    "import_asterix",
    "read_sites",
]
