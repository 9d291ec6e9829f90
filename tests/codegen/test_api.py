"""The typed API of the generated functions (generated/api.py, installed as
``registration._generated.api``): one keyword-only wrapper per generated function, named, shaped
and documented as the manifest records, returning a NamedTuple of the named outputs that are the
loader's outputs bit for bit."""

from __future__ import annotations

import hashlib
import inspect
import shutil
from pathlib import Path

import numpy as np
import pytest

from registration import _codegen
from registration._generated import api

REPO = Path(__file__).resolve().parents[2]
FUNCTIONS = _codegen.manifest()["functions"]


def _core(shape: list[int]) -> tuple[int, ...]:
    rows, cols = shape
    return () if (rows, cols) == (1, 1) else ((rows,) if cols == 1 else (rows, cols))


def _inputs(name: str, n: int | None, rng: np.random.Generator) -> dict[str, np.ndarray]:
    """Random inputs of ``name`` (positive, moderate: every function is finite there); scalars at
    their core shape and the rest with a leading axis of ``n`` points when ``n`` is given."""
    out = {}
    for k, port in enumerate(FUNCTIONS[name]["inputs"]):
        core = _core(port["shape"])
        lead = (n,) if n is not None and k % 2 == 0 else ()
        out[port["name"]] = rng.uniform(0.2, 0.6, lead + core)
    scale = {"alt": (1.0e3, 0.0), "r": (1.0e4, 0.0), "p_ecef": (1.0e4, 6.4e6)}
    return {k: v * scale[k][0] + scale[k][1] if k in scale else v for k, v in out.items()}


def test_the_module_is_the_one_in_generated_and_the_manifest_records_its_hash():
    path = Path(api.__file__).resolve()
    assert path == (REPO / "generated" / "api.py").resolve()
    meta = _codegen.manifest()["modules"]["api"]
    assert meta["file"] == "api.py"
    assert hashlib.sha256(path.read_bytes()).hexdigest() == meta["sha256"]
    assert b"DO NOT EDIT" in path.read_bytes()[:200]


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_each_wrapper_has_the_spec_s_named_inputs_outputs_and_units(name):
    fn = getattr(api, name)
    meta = FUNCTIONS[name]
    params = inspect.signature(fn).parameters
    assert list(params) == [p["name"] for p in meta["inputs"]]
    assert all(p.kind is inspect.Parameter.KEYWORD_ONLY for p in params.values())
    result = inspect.signature(fn).return_annotation
    outputs = getattr(api, result)
    assert outputs._fields == tuple(p["name"] for p in meta["outputs"])
    for port in (*meta["inputs"], *meta["outputs"]):
        assert f"{port['name']}: " in fn.__doc__
        assert port["unit"].split(",")[0] in fn.__doc__


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_each_wrapper_gives_the_loader_s_outputs_bit_for_bit(name):
    rng = np.random.default_rng(sum(map(ord, name)))
    for n in (None, 5):
        inputs = _inputs(name, n, rng)
        typed = getattr(api, name)(**inputs)
        plain = _codegen.get(name)(*inputs.values())
        assert len(typed) == len(plain)
        for port, a, b in zip(FUNCTIONS[name]["outputs"], typed, plain):
            assert a.shape == b.shape == (n or 1, *_core(port["shape"]))
            assert np.array_equal(a, b, equal_nan=True), (name, port["name"])
            assert getattr(typed, port["name"]) is a


def test_a_t_variant_wrapper_dispatches_to_the_variant():
    rng = np.random.default_rng(1)
    for t in _codegen.variants("t_variant"):
        inputs = _inputs(f"plot2ecef_{t}", 4, rng)
        by_keyword = api.plot2ecef(t_variant=t, **inputs)
        direct = getattr(api, f"plot2ecef_{t}")(**inputs)
        assert type(by_keyword) is type(direct) is api.Plot2ecefOutputs
        assert np.array_equal(by_keyword.p_ecef, direct.p_ecef)
    with pytest.raises(KeyError):
        api.plot2ecef(t_variant="nonsense", **inputs)


def test_inputs_are_keyword_only_and_named():
    with pytest.raises(TypeError):
        api.geodetic2ecef(0.1, 0.2, 3.0)  # type: ignore[misc]
    with pytest.raises(TypeError):
        api.geodetic2ecef(lat=0.1, lon=0.2, altitude=3.0)  # type: ignore[call-arg]
    with pytest.raises(ValueError, match="input 'lat' must have shape"):
        api.geodetic2ecef(lat=np.zeros(2) * np.zeros((2, 1)), lon=0.2, alt=3.0)


def test_a_hand_edited_api_module_makes_the_check_fail(tmp_path, capsys):
    from derive.__main__ import check

    copy = tmp_path / "generated"
    shutil.copytree(REPO / "generated", copy, ignore=shutil.ignore_patterns("__pycache__"))
    edited = copy / "api.py"
    edited.write_text(edited.read_text().replace("outputs = get(", "outputs = get(  ", 1))
    assert check(REPO / "generated", copy) == 1
    assert "differs: api.py" in capsys.readouterr().out
