"""The subsample of the solves between association passes (``registration.fleet.association.solves``):
every k-th window of each labelled target, with all its plots and reference positions, and its
last window, on the batch's own window grid."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from registration.fleet.association.solves import thin_windows
from registration.fleet.batch.blocks import target_spans, window_grid, window_of
from registration.fleet.data.known_targets import References


def _refs(target, time) -> References:
    n = len(target)
    p = np.arange(3 * n, dtype=float).reshape(n, 3)
    return References(np.asarray(target, dtype=object), np.asarray(time, float), p, np.full(n, 10.0))


def _case():
    """Target A: plots every 4 s over 0-396 s (20 windows of 19.8 s); B: every 5 s over 1000-1395 s;
    references of A every second, one of a target no plot has."""
    ta = np.arange(0.0, 400.0, 4.0)
    tb = np.arange(1000.0, 1400.0, 5.0)
    time = np.r_[ta, tb]
    labels = np.r_[np.full(ta.size, "A", dtype=object), np.full(tb.size, "B", dtype=object)]
    labels[3] = ""  # a plot without a label stays without one
    refs = _refs(["A"] * 397 + ["C"], np.r_[np.arange(0.0, 397.0), 50.0])
    return labels, SimpleNamespace(time=time), refs


def test_few_plots_and_references_are_kept_as_they_are():
    labels, problem, refs = _case()
    out, kept = thin_windows(labels, problem, refs, 20.0, cap=1000)
    assert out is labels and kept is refs


def test_whole_windows_are_kept_on_the_batch_grid():
    labels, problem, refs = _case()
    out, kept = thin_windows(labels, problem, refs, 20.0, cap=100)  # 397 references of A: k = 4
    for name in ("A", "B"):
        t = problem.time[labels == name]
        t0, t1 = target_spans(np.zeros(t.size, dtype=np.int64), t, 1)
        count, length, _ = window_grid(t0, t1, 20.0)
        w = window_of(t0, count, length, np.zeros(t.size, dtype=np.int64), t)
        expect = (w % 4 == 0) | (w == count[0] - 1)
        np.testing.assert_array_equal(out[labels == name] == name, expect)
        assert expect.sum() < t.size and out[labels == name][-1] == name  # thinned; the last window kept
    assert out[3] == ""
    # the references of A in the windows kept, every field with them; none of C (no plot is C's)
    assert set(kept.target) == {"A"}
    ta = problem.time[labels == "A"]
    t0, t1 = np.array([ta.min()]), np.array([ta.max()])
    count, length, _ = window_grid(t0, t1, 20.0)
    wr = window_of(t0, count, length, np.zeros(kept.time.size, dtype=np.int64), kept.time)
    inside = kept.time <= t1[0]
    assert ((wr[inside] % 4 == 0) | (wr[inside] == count[0] - 1)).all()
    np.testing.assert_array_equal(kept.p_ecef[:, 0], 3 * kept.time)  # position i of A is at time i
    assert np.isin(np.arange(0.0, 20.0), kept.time).all()  # window 0 whole
