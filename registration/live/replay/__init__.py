"""``registration replay``: recordings sent as datagrams at their recorded pace (:mod:`.send`),
read a piece at a time (:mod:`.recordings` for captures and raw ASTERIX, :mod:`.nmealog` for NMEA
logs, :mod:`.stream` for gzip or plain files)."""

from registration.live.replay.send import (
    RATE_BATCH,
    Replayer,
    ReplayStats,
    Target,
    Timeline,
    parse_target,
    replay,
)

__all__ = ["Target", "parse_target", "ReplayStats", "Timeline", "Replayer", "replay", "RATE_BATCH"]
