"""The subsamples of the solves between association passes (``registration.fleet.association.solves``):
every k-th plot of each target and sensor, every k-th reference position of each labelled target,
first and last kept, so that a target keeps its span (its windows)."""

from __future__ import annotations

import numpy as np

from registration.fleet.association.solves import thin_references
from registration.fleet.data.known_targets import References


def _refs(rng, counts: dict[str, int]) -> References:
    target = np.concatenate([np.full(n, name, dtype=object) for name, n in counts.items()])
    time = np.concatenate([rng.permutation(np.arange(n, dtype=float)) for n in counts.values()])
    n = target.size
    return References(target, time, rng.normal(size=(n, 3)), np.full(n, 10.0), np.full(n, 20.0))


def test_few_references_are_kept_as_they_are():
    refs = _refs(np.random.default_rng(1), {"A": 30, "B": 20})
    assert thin_references(refs, np.array(["A", "", "B"], dtype=object), cap=50) is refs


def test_each_labelled_target_keeps_every_kth_position_and_its_span():
    rng = np.random.default_rng(2)
    refs = _refs(rng, {"A": 1000, "B": 401, "C": 700})
    labels = np.array(["A", "B", "", "A"], dtype=object)  # C is no plot's target: not needed
    out = thin_references(refs, labels, cap=500)  # 1401 positions of A and B: k = 3
    assert set(out.target) == {"A", "B"}
    for name, n in (("A", 1000), ("B", 401)):
        t = np.sort(out.time[out.target == name])
        expected = np.union1d(np.arange(0, n, 3), [n - 1])
        assert np.array_equal(t, expected)
    # every field follows its position
    i = np.flatnonzero(refs.target == "A")
    j = np.flatnonzero(out.target == "A")
    by_time = dict(zip(refs.time[i], refs.p_ecef[i, 0]))
    assert all(by_time[t] == x for t, x in zip(out.time[j], out.p_ecef[j, 0]))
    assert (out.up_sigma == 20.0).all() and out.offset is not None
