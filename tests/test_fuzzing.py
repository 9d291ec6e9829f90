"""The fuzz harness (tests/fuzzing.py) finds what it must: an input that hangs, named within its
time bound, inside a batch and alone; an input that raises, named with its exception."""

from __future__ import annotations

import time
from collections import Counter

from tests.fuzzing import Campaign, run_campaign


def _campaign(bad: int, hang: bool, batch: int) -> Campaign:
    def batches(n: int):
        for first in range(0, n, batch):
            yield [(f"input {k}", k) for k in range(first, min(first + batch, n))]

    def check(items: list) -> Counter:
        for _, k in items:
            if k == bad:
                if hang:
                    while True:  # a reader's loop that never ends
                        pass
                raise KeyError(k)
        return Counter(ok=len(items))

    return Campaign(batches, check)


def hangs_in_a_batch(seed: int) -> Campaign:
    return _campaign(bad=7, hang=True, batch=4)


def raises_alone(seed: int) -> Campaign:
    return _campaign(bad=5, hang=False, batch=1)


def test_a_hang_in_a_batch_is_named():
    t0 = time.perf_counter()
    report = run_campaign("tests.test_fuzzing:hangs_in_a_batch", 20, per_input_s=0.5, total_s=120)
    assert report["failures"][0]["input"] == "input 7"
    assert report["failures"][0]["what"].startswith("hang: more than 0.5 s")
    assert time.perf_counter() - t0 < 60


def test_an_exception_is_named_and_the_rest_still_run():
    report = run_campaign("tests.test_fuzzing:raises_alone", 20, per_input_s=5.0, total_s=120)
    assert [f["input"] for f in report["failures"]] == ["input 5"]
    assert report["failures"][0]["what"] == "KeyError: 5"
    assert report["inputs"] == 20 and report["outcomes"] == {"ok": 19}
