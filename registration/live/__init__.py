"""Live data: the recordings replayed to the network as they were received (``replay``), and the
service that listens to UDP ASTERIX and NMEA 0183 (docs/howto/replay.md)."""
