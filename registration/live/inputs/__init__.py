"""The live service's inputs: ASTERIX datagrams imported as a stream (:mod:`.asterix`), a ship's
NMEA lines imported piece by piece (:mod:`.nmea`, :mod:`.bridge`, its TTM tracks named against AIS
by :mod:`.tracks`), and the TCP connections they may arrive on (:mod:`.tcp`)."""
