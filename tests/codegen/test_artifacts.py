"""What the runtime reads from the manifest instead of retyping it: variant names, WGS-84
constants, hash-checked artifact bytes."""

from __future__ import annotations

import hashlib

import pytest
import sympy as sp

from registration import _codegen


def test_variants_are_the_ones_derive_emits():
    from derive import geodesy, kalman

    assert _codegen.variants("linearization") == tuple(kalman.LINEARIZATIONS)
    assert _codegen.variants("t_variant") == tuple(geodesy.T_VARIANTS)
    assert _codegen.variants("linearization") == ("paper", "relinearized", "fitted")
    assert _codegen.variants("t_variant") == ("standard", "paper")


def test_every_variant_has_its_generated_functions():
    functions = _codegen.manifest()["functions"]
    for t in _codegen.variants("t_variant"):
        assert f"plot2ecef_{t}" in functions and f"information_step_{t}" in functions
        for lin in _codegen.variants("linearization"):
            assert f"kalman_step_{lin}_{t}" in functions


def test_unknown_variant_kind_is_refused():
    with pytest.raises(ValueError, match="unknown variant kind 'linearisation'"):
        _codegen.variants("linearisation")


def test_wgs84_is_derive_s_constants():
    from derive.constants import WGS84_A, WGS84_B, WGS84_E2, WGS84_F

    w = _codegen.wgs84()
    assert w == {
        "wgs84_a_m": float(WGS84_A),
        "wgs84_b_m": float(WGS84_B),
        "wgs84_f": float(WGS84_F),
        "wgs84_e2": float(WGS84_E2),
    }
    assert w["wgs84_a_m"] == 6378137.0
    assert w["wgs84_f"] == float(1 / sp.Rational("298.257223563"))
    w["wgs84_a_m"] = 0.0
    assert _codegen.wgs84()["wgs84_a_m"] == 6378137.0  # callers get a copy


def test_read_artifact_returns_the_checked_bytes():
    meta = _codegen.manifest()["functions"]["geodetic2ecef"]["artifacts"]["c"]
    data = _codegen.read_artifact("geodetic2ecef", "c")
    assert hashlib.sha256(data).hexdigest() == meta["sha256"]
    assert data == (_codegen.generated_dir() / meta["file"]).read_bytes()


def test_unknown_function_is_refused():
    with pytest.raises(_codegen.ArtifactError, match="no generated function named 'geodetic2ecf'"):
        _codegen.read_artifact("geodetic2ecf", "c")


def test_compiler_flags_and_compiler_are_public():
    assert _codegen.CFLAGS == ["-O2", "-fPIC", "-shared"]
    cc = _codegen.compiler()
    assert cc is None or isinstance(cc, str) and cc
