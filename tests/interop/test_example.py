"""docs/examples/stonesoup_tracking.py: Stone Soup tracks
the registered detections better than the raw ones."""

import importlib.util
from pathlib import Path

EXAMPLE = Path(__file__).resolve().parents[2] / "docs" / "examples" / "stonesoup_tracking.py"


def load_example():
    spec = importlib.util.spec_from_file_location("stonesoup_tracking", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_registered_detections_give_a_lower_mean_ospa_than_raw_ones(tmp_path):
    metrics = load_example().main(png=str(tmp_path / "ospa.png"), duration_s=30.0)
    assert metrics["registered"] < metrics["raw"]
    assert metrics["tracks_registered"] == metrics["targets"]  # one track per target once registered
    png = tmp_path / "ospa.png"
    assert png.stat().st_size > 10_000 and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
