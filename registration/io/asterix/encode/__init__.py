"""ASTERIX encoders: CAT063 sensor status messages carrying a registration's estimates
(:mod:`~registration.io.asterix.encode.cat063`), on the data-block framing of
:mod:`~registration.io.asterix.encode.blocks`; and CAT048 plots corrected in place by those
estimates (:mod:`~registration.io.asterix.encode.cat048`)."""

from registration.io.asterix.encode.cat048 import CorrectedDatagram, PlotCorrection, correct_cat048
from registration.io.asterix.encode.cat063 import CAT063_EDITIONS, SensorStatus, encode_cat063, status_record

__all__ = [
    "CAT063_EDITIONS",
    "CorrectedDatagram",
    "PlotCorrection",
    "SensorStatus",
    "correct_cat048",
    "encode_cat063",
    "status_record",
]
