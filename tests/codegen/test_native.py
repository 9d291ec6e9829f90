"""The opt-in builds for the local CPU (``REGISTRATION_NATIVE``): ``native`` agrees with the
portable build within its stated tolerance (:data:`NATIVE_RTOL`, on the filter's statistical
scale), ``native-exact`` bit for bit, for the Kalman step with both covariance updates, at the
points of a well-conditioned and of an ill-conditioned run. Skipped if the compiler has no
``-march=native``. Only the two step functions are built natively (a few seconds, then cached).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from registration import _codegen
from registration._codegen import cbackend
from registration.online import RegistrationConfig
from registration.online.contract import DATA_COLUMNS, N_STATE
from registration.online.filter import STEP_CARRY
from registration.online.scenario import paper_scenario

STEPS = ("kalman_step_fitted_standard", "kalman_step_fitted_standard_carlson")
UPDATE = {"kalman_step_fitted_standard": "joseph", "kalman_step_fitted_standard_carlson": "carlson"}
# : prior sigmas: the default, and one with sigmas from 1e-12 rad to 1e5 m and no process noise (cond(P) ~
# 1e37)
PRIORS = {
    "default": {},
    "ill": {"prior_sigma": (1e-12, 1e-3, 1e-12, 1e5, 1e-12, 1e-3) * 2, "q_sigma": (0.0,) * N_STATE},
}
N = 300


def _native_or_skip() -> None:
    cc = _codegen.compiler()
    if cc is None or cbackend.native_target(cc) is None:
        pytest.skip("no C compiler accepting -march=native")


@pytest.fixture(scope="module")
def rows() -> np.ndarray:
    data = paper_scenario(2, n_steps=N).data
    return np.ascontiguousarray(np.stack([np.asarray(data[c]) for c in DATA_COLUMNS[1:]], axis=1))


def _points(name: str, prior: dict, rows: np.ndarray) -> tuple[list, object]:
    """The inputs of every step of a run (each step's carried state as it came in), as the
    compiled kernels take them, and the function."""
    fn = _codegen.get(name)
    cfg = RegistrationConfig(linearization="fitted", covariance_update=UPDATE[name], **prior)
    assert cfg.step_name == name
    start = {
        "x": np.zeros(N_STATE),
        "P": np.diag(np.square(cfg.prior_sigma)),
        "info": np.zeros((N_STATE, N_STATE)),
    }
    run = fn.scan(
        len(rows),
        STEP_CARRY,
        {**start, "Q": np.diag(np.square(cfg.q_sigma)), "row": rows, "sigma0": np.array(cfg.sigma0)},
    )
    carried = [np.concatenate([start[k][None], run[v][:-1]]) for k, v in STEP_CARRY.items()]
    args = [*carried, np.diag(np.square(cfg.q_sigma)), rows, np.array(cfg.sigma0)]
    prepared = []
    for a, (r, c) in zip(args, fn.input_shapes):
        core = () if (r, c) == (1, 1) else ((r,) if c == 1 else (r, c))
        prepared.append((a, a.shape != core, core))
    return prepared, fn


def _evaluate(name: str, prepared: list, fn, lib) -> dict:
    """Every output of ``name`` at the points, from library ``lib``, at its core shape."""
    work = _codegen.manifest()["functions"][name]["work"]
    outs = cbackend.CKernel(name, work, lib).call(prepared, len(prepared[4][0]), fn.output_shapes)
    shaped = {}
    for out_name, buf, (r, c) in zip(fn.output_names, outs, fn.output_shapes):
        shaped[out_name] = (
            buf.reshape(-1) if (r, c) == (1, 1) else (buf if c == 1 else buf.reshape(-1, c, r).swapaxes(1, 2))
        )
    return shaped


def _statistical_difference(ref: dict, other: dict) -> dict:
    """Largest |other - ref| per output on the filter's own scale (see cbackend.NATIVE_RTOL)."""

    def matrix(a, b):
        d = np.sqrt(np.abs(np.einsum("kii->ki", a)))
        return float(np.max(np.abs(a - b) / np.maximum(d[:, :, None] * d[:, None, :], np.finfo(float).tiny)))

    sx = np.sqrt(np.einsum("kii->ki", ref["P_new"]))
    snu = np.sqrt(np.einsum("kii->ki", ref["S"]))
    return {
        "x_new": float(np.max(np.abs(other["x_new"] - ref["x_new"]) / sx)),
        "P_new": matrix(ref["P_new"], other["P_new"]),
        "info_new": matrix(ref["info_new"], other["info_new"]),
        "S": matrix(ref["S"], other["S"]),
        "nu": float(np.max(np.abs(other["nu"] - ref["nu"]) / snu)),
        "nis": float(np.max(np.abs(other["nis"] - ref["nis"]) / np.maximum(1.0, ref["nis"]))),
    }


@pytest.fixture(scope="module")
def portable():
    return cbackend.library_of(sorted(_codegen.manifest()["functions"]))  # the cached portable library


@pytest.mark.parametrize("prior", sorted(PRIORS))
@pytest.mark.parametrize("name", STEPS)
def test_native_build_agrees_within_its_stated_tolerance(name, prior, rows, portable):
    _native_or_skip()
    prepared, fn = _points(name, PRIORS[prior], rows)
    if prior == "ill":
        assert np.linalg.cond(prepared[1][0][-1]) > 1e25  # the run is as ill-conditioned as claimed
    ref = _evaluate(name, prepared, fn, portable)
    diff = _statistical_difference(ref, _evaluate(name, prepared, fn, cbackend.library_of(STEPS, "native")))
    assert max(diff.values()) <= cbackend.NATIVE_RTOL, diff


@pytest.mark.parametrize("name", STEPS)
def test_native_exact_build_equals_the_portable_one_bit_for_bit(name, rows, portable):
    _native_or_skip()
    prepared, fn = _points(name, PRIORS["ill"], rows)
    ref = _evaluate(name, prepared, fn, portable)
    exact = _evaluate(name, prepared, fn, cbackend.library_of(STEPS, "native-exact"))
    for key, value in ref.items():
        np.testing.assert_array_equal(exact[key], value, err_msg=key)


def test_the_tolerance_check_sees_a_difference_of_its_own_size(rows, portable):
    prepared, fn = _points(STEPS[0], PRIORS["ill"], rows)
    ref = _evaluate(STEPS[0], prepared, fn, portable)
    moved = dict(
        ref, x_new=ref["x_new"] + 2 * cbackend.NATIVE_RTOL * np.sqrt(np.einsum("kii->ki", ref["P_new"]))
    )
    assert _statistical_difference(ref, ref) == dict.fromkeys(ref, 0.0)
    assert _statistical_difference(ref, moved)["x_new"] > cbackend.NATIVE_RTOL


@pytest.mark.parametrize(
    "value, mode",
    [
        (None, "portable"),
        ("", "portable"),
        ("0", "portable"),
        ("off", "portable"),
        ("1", "native"),
        ("True", "native"),
        ("exact", "native-exact"),
    ],
)
def test_the_environment_variable_selects_the_build(monkeypatch, value, mode):
    if value is None:
        monkeypatch.delenv(cbackend.NATIVE_ENV, raising=False)
    else:
        monkeypatch.setenv(cbackend.NATIVE_ENV, value)
    assert cbackend.build_mode() == mode


def test_a_bad_environment_value_or_mode_is_refused(monkeypatch):
    monkeypatch.setenv(cbackend.NATIVE_ENV, "fast")
    with pytest.raises(ValueError, match="REGISTRATION_NATIVE must be 0, 1 or exact.*'fast'"):
        cbackend.build_mode()
    with pytest.raises(ValueError, match="build mode must be one of"):
        cbackend.cflags("O3")


def test_each_build_has_its_own_cache_key():
    sources = [("f.c", b"int f(void) { return 0; }")]
    keys = {
        mode: cbackend.cache_key(
            "cc", sources, cbackend.cflags(mode), "" if mode == "portable" else "-march=x"
        )
        for mode in cbackend.BUILD_MODES
    }
    assert len(set(keys.values())) == len(keys)
    assert keys["portable"] == cbackend.cache_key(
        "cc", sources
    )  # the portable key is the one the loader always used
    assert (
        cbackend.cache_key("cc", sources, cbackend.cflags("native"), "-march=y") != keys["native"]
    )  # another CPU


def test_a_compiler_without_march_native_gives_no_native_library(monkeypatch):
    monkeypatch.setattr(cbackend, "native_target", lambda cc: None)
    with pytest.raises(_codegen.ArtifactError, match="does not accept -march=native"):
        cbackend.library_of(["geodetic2ecef"], "native")


def test_native_request_without_a_native_build_falls_back_to_the_portable_one(monkeypatch, portable):
    portable_of = cbackend.library_of

    def no_native(names, mode="portable"):
        if mode != "portable":
            raise _codegen.ArtifactError("the C compiler cc does not accept -march=native")
        return portable_of(names, mode)

    monkeypatch.setattr(cbackend, "library_of", no_native)
    monkeypatch.setenv(cbackend.NATIVE_ENV, "1")
    with pytest.warns(RuntimeWarning, match="REGISTRATION_NATIVE: no native build .*-march=native.*portable"):
        lib = cbackend.library.__wrapped__()
    assert lib is portable
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        monkeypatch.setenv(cbackend.NATIVE_ENV, "0")
        assert cbackend.library.__wrapped__() is portable
