"""Write the sample recordings of this folder: an ASTERIX capture of three radars with ADS-B
(``atc.pcap.gz``, ``SITES.csv``) and an NMEA 0183 bridge log with ARPA and AIS (``bridge.log``,
``sensors.csv``), both simulated with known errors and encoded by independent encoders (libasterix
for ASTERIX; pynmea2 and pyais for NMEA and AIS), never by this package's readers. The true errors
are written to ``truth.json``.

Run from the checkout with the test extra installed (``pip install -e ".[test]"``)::

    python3 examples/recordings/make.py [FOLDER]

(default FOLDER: this folder). The output is the same byte for byte on every run.
"""

from __future__ import annotations

import gzip
import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1]))  # the checkout: the encoders live with the tests

from tests.io.asterix.atc import atc_truth, encode_atc  # noqa: E402
from tests.io.nmea.bridgelog import simulate_bridge_log  # noqa: E402
from tests.io.nmea.truth import BridgeLogConfig  # noqa: E402

SEED = 11
DURATION_S = 300.0


def main(folder: Path = HERE) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    atc = atc_truth(SEED, duration_s=DURATION_S)
    recording = encode_atc(atc.plots, atc.adsb, atc.sites, atc.date, atc.scans)
    (folder / "atc.pcap.gz").write_bytes(gzip.compress(recording.pcap(), 9, mtime=0))
    atc.sites.to_csv(folder / "SITES.csv", index=False)
    log = simulate_bridge_log(BridgeLogConfig(seed=SEED, duration_s=DURATION_S))
    log.write(folder / "bridge.log")
    log.write_sensors(folder / "sensors.csv")
    truth = {
        "asterix": {k: float(v) for k, v in atc.truth.items()},
        "asterix_units": "range_bias m, range_gain 1, bearing_bias rad, time_bias s",
        "nmea": {"range_bias_m": 60.0, "bearing_bias_deg": 0.6, "clock_offset_s": 0.8},
    }
    (folder / "truth.json").write_text(json.dumps(truth, indent=2) + "\n")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE)
