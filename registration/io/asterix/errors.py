"""What the ASTERIX reader refuses and what it sets aside.

:class:`AsterixImportError` is raised, with a one-line message naming the file, only for a file
that is neither an ASTERIX recording nor a pcap/pcapng capture (nor a gzip of one), or that cannot
be read at all. Everything else bad in a file is set aside and listed in
a rejected ledger (:class:`~registration.io.files.ledger.RejectedLedger` of
:data:`LEDGER_COLUMNS`): its file, its byte offset (in the decompressed stream for a gzip file), its
packet number (from 1, captures only), its category, a reason code (:data:`REASONS`) and a reason
in words. The rest of the file is imported.
"""

from __future__ import annotations

from registration.io.files.ledger import LedgerColumns, Location

__all__ = ["AsterixImportError", "LEDGER_COLUMNS", "REASONS", "REJECTED_COLUMNS"]

#: Reason code -> what it means (docs/howto/import-asterix.md lists the same).
REASONS = {
    "truncated_packet": "the capture ends inside a packet record (the rest of the file is lost)",
    "bad_block_length": "a data block whose length field is below 3 (the header itself)",
    "truncated_block": "a data block whose length runs past the end of the file or datagram",
    "unknown_category": "a data block of a category the reader does not decode",
    "fspec_overrun": "an FSPEC that runs past its data block or past the octets its UAP allows",
    "empty_record": "an FSPEC that names no item",
    "spare_frn": "an FSPEC that names a spare FRN of the edition",
    "item_overrun": "an item that runs past the end of its data block",
    "bad_item": "an item whose structure the edition does not allow (too many extension octets, "
    "an explicit length of 0, a spare compound subfield)",
    "missing_item": "a record without an item the reader needs (source, time, position, ...)",
    "bad_time": "a time of day of 24 h or more",
    "no_detection": "a CAT048 report of type 0 or a CAT001 plot of SSR/PSR 0 (no detection)",
    "zero_range": "a CAT048 or CAT001 plot at range 0",
    "test_target": "a test target report (I048/020, I001/020 or I021/040 TST bit)",
    "simulated": "a simulated target report (I048/020, I001/020 or I021/040 SIM bit)",
    "field_monitor": "a report from a field monitor, a fixed transponder (RAB bit)",
    "unknown_sac_sic": "a CAT048, CAT034, CAT001 or CAT002 record whose SAC/SIC is not in SITES",
    "no_address": "a CAT021 report without target address (I021/080)",
    "no_position": "a CAT021 report without WGS-84 position (I021/130, I021/131)",
    "bad_position": "a CAT021 position outside +-90 deg latitude or +-180 deg longitude",
    "no_quality": "a CAT021 report without NACp (I021/090; NUCp for editions 0.2x)",
    "low_nacp": "a CAT021 report with NACp below 7 (NUCp below 6 for editions 0.2x): EPU of 0.3 NM or more",
    "no_geometric_height": "a CAT021 report without geometric height (I021/140)",
    "cat001_track": "a CAT001 track (I001/020 TYP 1): only plots are imported",
    "no_full_time": "a CAT001 plot whose truncated time (I001/141, modulo 512 s) has no full time of day "
    "before it in the stream to complete it (a CAT002 message of its radar, or any record)",
    "duplicate": "a record that repeats an earlier one (same category, SAC/SIC, time of day and octets): "
    "a duplicated feed or a replayed recording",
    "over_limit": "what lies beyond a bound of the import (max_bytes, max_records): not read",
    "not_listed": "the last row of a rejected table cut at max_rejected_rows: how many more were set aside",
}
#: The rejected table's columns: the byte offset in the (decompressed) file, the packet number
#: from 1 and the category (both empty where they do not apply).
LEDGER_COLUMNS = LedgerColumns(
    (Location("offset", "nullable"), Location("packet", "positive"), Location("category", "positive")),
    "reason_code",
    REASONS,
)
#: The columns of the rejected table.
REJECTED_COLUMNS = LEDGER_COLUMNS.names


class AsterixImportError(ValueError):
    """A file that is neither an ASTERIX recording nor a pcap/pcapng capture (nor a gzip of one), or
    that cannot be read. The message is one line naming the file (the command line maps it to exit
    code 2)."""
