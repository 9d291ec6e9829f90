"""The benchmark figures of docs/results.md are those of the committed benchmarks/results/*.json:
``python -m benchmarks.tables`` rewrites them, and this test fails when the two differ."""

from __future__ import annotations

import json

from benchmarks.tables import BLOCK, DOC, RENDERERS, RESULTS, render_file


def test_docs_match_the_committed_json():
    text, expected = render_file(DOC)
    assert text == expected, (
        "docs/results.md differs from benchmarks/results/*.json: run python -m benchmarks.tables"
    )


def test_every_block_has_a_renderer_and_its_json():
    names = [m["name"] for m in BLOCK.finditer(DOC.read_text())]
    assert names, "docs/results.md has no generated block"
    for name in names:
        assert name in RENDERERS, name
        assert (RESULTS / f"{name.split('.')[0]}.json").exists(), name


def test_committed_json_is_a_full_run():
    for path in RESULTS.glob("*.json"):
        doc = json.loads(path.read_text())
        assert doc["tiny"] is False, f"{path.name} holds a --tiny run"
        assert doc["benchmark"] == path.stem
