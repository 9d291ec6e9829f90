"""GeneratedFunction.scan_runs (many independent scans in one call) and the carried-state stepper,
on both backends: each must give bit for bit what the plain scan gives."""

from __future__ import annotations

import numpy as np
import pytest

from registration import _codegen
from registration._codegen import StepCode
from registration._codegen.function import GeneratedFunction

STEP = "kalman_step_fitted_standard"
CARRY = {"x": "x_new", "P": "P_new", "info": "info_new"}
RUNS, N = 3, 25


def _backends():
    out = ["casadi"]
    if _codegen.backend() == "c":
        out.insert(0, "c")
    return out


@pytest.fixture(scope="module")
def rows():
    """(RUNS, N, 18) rows of the paper scenario, one seed per run."""
    from registration.online.contract import DATA_COLUMNS
    from registration.online.scenario import paper_scenario

    return np.stack(
        [
            np.stack([paper_scenario(s, n_steps=N).data[c] for c in DATA_COLUMNS[1:]], axis=1)
            for s in range(RUNS)
        ]
    )


def _inputs(rows):
    from registration.online import RegistrationConfig

    cfg = RegistrationConfig()
    return {
        "x": np.zeros(12),
        "P": np.diag(np.square(cfg.prior_sigma)),
        "info": np.zeros((12, 12)),
        "Q": np.diag(np.square(cfg.q_sigma)),
        "row": rows,
        "sigma0": np.array(cfg.sigma0),
    }


@pytest.mark.parametrize("backend", _backends())
def test_scan_runs_equals_one_scan_per_run(rows, backend):
    fn = GeneratedFunction(STEP, force_backend=backend)
    inputs = _inputs(rows)
    x0 = np.arange(RUNS * 12, dtype=float).reshape(RUNS, 12) * 1e-4  # a per-run initial state
    out = fn.scan_runs(RUNS, N, CARRY, {**inputs, "x": x0}, keep_last=("info_new", "S"))
    assert out["x_new"].shape == (RUNS, N, 12) and out["P_new"].shape == (RUNS, N, 12, 12)
    assert (
        out["info_new"].shape == (RUNS, 12, 12)
        and out["S"].shape == (RUNS, 3, 3)
        and out["nis"].shape == (RUNS, N)
    )
    for r in range(RUNS):
        one = fn.scan(N, CARRY, {**inputs, "x": x0[r], "row": rows[r]}, keep_last=("info_new", "S"))
        for name, value in one.items():
            np.testing.assert_array_equal(out[name][r], value, err_msg=f"{backend} {name} run {r}")


@pytest.mark.parametrize("backend", _backends())
def test_scan_runs_takes_a_per_run_constant_input(rows, backend):
    """information_step with one estimate x per run, the same at every step."""
    fn = GeneratedFunction("information_step_standard", force_backend=backend)
    x = np.linspace(-1e-3, 1e-3, RUNS * 12).reshape(RUNS, 12)
    sigma0 = np.array([50.0, 0.01, 0.01] * 2)
    out = fn.scan_runs(
        RUNS,
        N,
        {"info": "info_new"},
        {"info": np.zeros((12, 12)), "x": x, "row": rows, "sigma0": sigma0},
        keep_last=("info_new",),
    )
    for r in range(RUNS):
        one = fn.scan(
            N,
            {"info": "info_new"},
            {"info": np.zeros((12, 12)), "x": x[r], "row": rows[r], "sigma0": sigma0},
            keep_last=("info_new",),
        )
        np.testing.assert_array_equal(out["info_new"][r], one["info_new"])


def test_scan_runs_rejects_inputs_of_the_wrong_shape(rows):
    fn = _codegen.get(STEP)
    inputs = _inputs(rows)
    with pytest.raises(ValueError, match="'row' must have shape"):
        fn.scan_runs(RUNS, N, CARRY, {**inputs, "row": rows[0]})  # (N, 18) is ambiguous: refused
    with pytest.raises(ValueError, match="'x' must have shape"):
        fn.scan_runs(
            RUNS, N, CARRY, {**inputs, "x": np.zeros((RUNS, N, 12))}
        )  # a carried input has no step axis
    with pytest.raises(ValueError, match="missing input 'sigma0'"):
        fn.scan_runs(RUNS, N, CARRY, {k: v for k, v in inputs.items() if k != "sigma0"})
    with pytest.raises(ValueError, match="carried inputs must be the first"):
        fn.scan_runs(RUNS, N, {"P": "P_new"}, inputs)


def _stepper(fn, inputs, low=None, high=None):
    st = fn.stepper(
        CARRY, "row", low=low, high=high, finite=("x_new", "P_new"), deliver=("x_new", "P_new", "nis")
    )
    for name in ("x", "P", "info", "Q", "sigma0"):
        st.set(name, inputs[name])
    return st


@pytest.mark.parametrize("backend", _backends())
def test_stepper_steps_equal_the_scan(rows, backend):
    fn = GeneratedFunction(STEP, force_backend=backend)
    inputs = _inputs(rows[0])
    ref = fn.scan(N, CARRY, inputs)
    st = _stepper(fn, inputs)
    for i in range(N):
        assert st.step(rows[0, i]) == StepCode.OK
        x, P, nis = st.results()
        np.testing.assert_array_equal(x, ref["x_new"][i])
        np.testing.assert_array_equal(P, ref["P_new"][i])
        assert nis == ref["nis"][i] and isinstance(nis, float)
        x[:] = 0.0  # the results are the caller's: the state is not touched
    np.testing.assert_array_equal(st.get("x"), ref["x_new"][-1])
    np.testing.assert_array_equal(st.get("info"), ref["info_new"][-1])


@pytest.mark.parametrize("backend", _backends())
def test_stepper_refuses_out_of_bounds_and_non_finite_steps_without_touching_the_state(rows, backend):
    fn = GeneratedFunction(STEP, force_backend=backend)
    inputs = _inputs(rows[0])
    low, high = np.full(18, -1e6), np.full(18, 1e6)
    low[[6, 15]] = 1.0  # ranges
    high[[6, 15]] = 1e305
    st = _stepper(fn, inputs, low, high)
    assert st.step(rows[0, 0]) == StepCode.OK
    state = {name: st.get(name) for name in ("x", "P", "info")}
    for bad, code in (
        (np.nan, StepCode.OUT_OF_BOUNDS),
        (0.5, StepCode.OUT_OF_BOUNDS),
        (np.inf, StepCode.OUT_OF_BOUNDS),
        (1e300, StepCode.NON_FINITE),
    ):
        row = rows[0, 1].copy()
        row[6] = bad
        assert st.step(row) == code, bad
        for name, value in state.items():
            np.testing.assert_array_equal(st.get(name), value, err_msg=f"{backend} {name} after {bad}")
    row = rows[0, 1].copy()
    row[6] = 0.5
    assert st.step(row, check=False) == StepCode.OK  # the bounds can be skipped for a value checked elsewhere
    assert not np.array_equal(st.get("x"), state["x"])


def test_stepper_set_checks_shapes():
    st = _codegen.get(STEP).stepper(CARRY, "row")
    with pytest.raises(ValueError, match=r"input 'P': expected shape \(12, 12\)"):
        st.set("P", np.zeros(12))
    with pytest.raises(ValueError, match="non-carried input"):
        _codegen.get(STEP).stepper(CARRY, "x")


def test_stepper_reads_an_asymmetric_matrix_input_in_its_own_orientation():
    """Q may be asymmetric (adaptive mode): set() must store it column-major, as the batch call does."""
    fn = _codegen.get(STEP)
    rng = np.random.default_rng(0)
    inputs = _inputs(np.zeros((1, 18)))
    Q = np.diag(np.square(np.full(12, 1e-3))) + 1e-7 * rng.normal(size=(12, 12))
    row = np.array(
        [0.35, 2.0, 20.0, 2.6, 0.0, 0.0, 5e4, 0.3, 0.03, 0.35, 2.01, 20.0, 5.8, 0.0, 0.0, 5e4, -0.2, 0.03]
    )
    ref = fn(inputs["x"], inputs["P"], inputs["info"], Q, row, inputs["sigma0"])
    st = _stepper(fn, {**inputs, "Q": Q})
    assert st.step(row) == StepCode.OK
    x, P, _ = st.results()
    np.testing.assert_array_equal(x, ref[0][0])
    np.testing.assert_array_equal(P, ref[1][0])
    np.testing.assert_array_equal(st.get("Q"), Q)


@pytest.mark.parametrize("backend", _backends())
def test_advance_gives_the_scan_s_results_as_the_caller_s_arrays_across_blocks(rows, backend):
    """advance() = step() + results(), as a dict under the deliver keys; in the C backend its arrays
    are rows of blocks the compiled step fills: every row stays the step's own, across block ends,
    with step() calls and refused steps in between."""
    from registration._codegen.cstepper import BLOCK_ROWS

    fn = GeneratedFunction(STEP, force_backend=backend)
    stream = rows.reshape(-1, 18)
    stream = np.concatenate([stream] * (-(-2 * BLOCK_ROWS // len(stream)) + 1))[: 2 * BLOCK_ROWS + 7]
    inputs = _inputs(stream)
    ref = fn.scan(len(stream), CARRY, inputs)
    low, high = np.full(18, -1e6), np.full(18, 1e6)
    low[[6, 15]], high[[6, 15]] = 1.0, 1e305
    st = fn.stepper(
        CARRY,
        "row",
        low=low,
        high=high,
        finite=("x_new", "P_new"),
        deliver={"x": "x_new", "P": "P_new", "nis": "nis"},
    )
    for name in ("x", "P", "info", "Q", "sigma0"):
        st.set(name, inputs[name])
    outs = []
    for i, row in enumerate(stream):
        if i % 10 == 3:
            bad = row.copy()
            bad[6] = np.nan
            assert st.advance(bad) == StepCode.OUT_OF_BOUNDS  # a code, nothing delivered, the state kept
        if i % 17 == 5:
            assert st.step(row) == StepCode.OK
            outs.append(st.results())  # a dict too, of new arrays
        else:
            outs.append(st.advance(row))
        assert set(outs[-1]) == {"x", "P", "nis"} and isinstance(outs[-1]["nis"], float)
    outs[0]["x"][:] = 0.0  # a caller writing into one row's arrays touches no other row, nor the state
    outs[1]["P"][:] = 0.0
    np.testing.assert_array_equal(np.array([o["x"] for o in outs[1:]]), ref["x_new"][1:])
    np.testing.assert_array_equal(np.array([o["P"] for o in outs[2:]]), ref["P_new"][2:])
    np.testing.assert_array_equal(outs[0]["P"], ref["P_new"][0])
    np.testing.assert_array_equal([o["nis"] for o in outs], ref["nis"])
    np.testing.assert_array_equal(st.get("x"), ref["x_new"][-1])


@pytest.mark.parametrize("backend", _backends())
def test_the_stepper_keeps_the_last_values_of_an_output(rows, backend):
    """keep(): the compiled step copies each successful step's output into a ring; kept() gives the
    last `length` of them oldest first (a refused step adds nothing); set_kept() replaces them."""
    fn = GeneratedFunction(STEP, force_backend=backend)
    stream = rows.reshape(-1, 18)
    inputs = _inputs(stream)
    ref = fn.scan(len(stream), CARRY, inputs)["x_new"]
    low, high = np.full(18, -1e6), np.full(18, 1e6)
    low[[6, 15]], high[[6, 15]] = 1.0, 1e305
    st = _stepper(fn, inputs, low, high)
    st.keep("x_new", 7)
    assert st.kept().shape == (0, 12)
    for i, row in enumerate(stream):
        assert st.step(row) == StepCode.OK
        bad = row.copy()
        bad[6] = np.nan
        assert st.step(bad) == StepCode.OUT_OF_BOUNDS
        np.testing.assert_array_equal(st.kept(), ref[max(0, i - 6) : i + 1])
    st.set_kept(ref[:3])
    np.testing.assert_array_equal(st.kept(), ref[:3])
    st.step(stream[0])
    assert len(st.kept()) == 4
    with pytest.raises(ValueError, match="at most 7 values of size 12"):
        st.set_kept(np.zeros((8, 12)))
    with pytest.raises(ValueError, match="keep\\(\\) takes a vector output, got 'P_new'"):
        st.keep("P_new", 3)
    with pytest.raises(ValueError, match="length must be at least 1"):
        st.keep("x_new", 0)
