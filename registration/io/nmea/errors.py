"""What the NMEA reader refuses: :class:`NmeaImportError` for a log that cannot give a navigation
table at all, and :data:`LEDGER_COLUMNS`, the columns of the rejected ledger
(:class:`~registration.io.files.ledger.RejectedLedger`) of the lines set aside with a reason (bad
input never raises).

Every line set aside is listed once, with its file, its line number (from 1, as an editor shows
it), a reason code and a reason in words. The codes are listed in :data:`REASONS`.
"""

from __future__ import annotations

from registration.io.files.ledger import LedgerColumns, Location

__all__ = ["LEDGER_COLUMNS", "NmeaImportError", "REASONS"]

#: Reason code -> what it means (docs/howto/import-nmea.md lists the same).
REASONS = {
    "not_a_sentence": "no '$' or '!' starts a sentence on the line",
    "bad_prefix": "the text before the sentence is not a timestamp the reader knows",
    "bad_tag_block": "an NMEA 4.10 tag block that is not closed or whose checksum is wrong",
    "no_checksum": "the sentence does not end in '*' and two hex digits (a truncated line?)",
    "bad_checksum": "the checksum does not match the sentence",
    "unknown_type": "a sentence type neither this reader nor pynmea2 knows",
    "too_few_fields": "fewer fields than the sentence type has (a truncated sentence?)",
    "bad_field": "a field the reader needs is empty, not a number or out of range",
    "bad_time": "the UTC time field is empty or not a time of day",
    "no_time": "the sentence has no UTC time field and the line no reception time",
    "invalid_fix": "the receiver marks the fix invalid (GGA quality 0, RMC status V, GNS mode N, THS mode V)",
    "outside_positions": "attitude at a time without position fixes around it to interpolate from",
    "duplicate_time": "a second sample of the same source at the same time",
    "ttm_lost": "TTM status L: the target is lost",
    "ttm_acquiring": "TTM status Q: the target is being acquired (kept with keep_acquiring=True)",
    "ttm_status": "TTM status is not T, Q or L",
    "ttm_no_sensor": "the TTM talker names no sensor of the platform",
    "ttm_no_heading": "a true TTM bearing at a time without heading to convert it to a deck bearing",
    "ais_fragment": "a part of a multi-sentence AIS message whose other parts are missing",
    "ais_decode": "an AIS payload pyais cannot decode",
    "ais_no_time": "an AIS position without a reception time (tag block c: or timestamp prefix)",
    "ais_no_position": "an AIS position report whose position is not available",
    "ais_own_ship": "an AIS position of the own ship (its MMSI is in !AIVDO)",
    "over_limit": "the lines of a file beyond max_bytes: not read",
    "not_listed": "the last row of a rejected table cut at max_rejected_rows: how many more were set aside",
    "duplicate": "a sentence repeating one of the last 200 with the same time (a duplicated feed)",
    "ais_duplicate": "the same AIS report (MMSI, time and position) received again",
    "no_date": "the log gives no date, so AIS reception times cannot be placed",
}


class NmeaImportError(ValueError):
    """The log cannot be imported: no valid position or no valid heading in it. The message is one
    line naming what is missing (the command line maps it to exit code 2)."""


#: The rejected table's columns: ``file``, ``line`` (from 1), ``code``, ``reason``, ordered by file
#: (in the order given) then line; files are named by their index in the list of paths.
LEDGER_COLUMNS = LedgerColumns((Location("line", "int"),), "code", REASONS)
