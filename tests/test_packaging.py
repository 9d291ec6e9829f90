"""The wheel must contain every runtime package and the generated artifacts."""

import tomllib
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent


def test_every_runtime_package_is_listed_in_pyproject():
    cfg = tomllib.loads((REPO / "pyproject.toml").read_text())["tool"]["setuptools"]
    listed = set(cfg["packages"])
    found = {
        ".".join(p.parent.relative_to(REPO).parts)
        for p in (REPO / "registration").rglob("__init__.py")
        if "__pycache__" not in p.parts
    }
    assert found <= listed, f"packages missing from pyproject.toml: {sorted(found - listed)}"
    assert cfg["package-dir"]["registration._generated"] == "generated"
    data = cfg["package-data"]["registration._generated"]
    assert {"*.c", "*.casadi", "manifest.json"} <= set(data)
    assert {"_batch.c", "_tracker.c"} <= set(cfg["package-data"]["registration._codegen"])


def test_casadi_and_sympy_are_pinned_exactly():
    deps = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]["dependencies"]
    pins = {d.split("==")[0]: d for d in deps if "==" in d}
    assert "casadi" in pins and "sympy" in pins


def test_the_mit_licence_is_there_and_goes_into_the_wheel():
    """Before: pyproject.toml declared MIT but there was no LICENSE file to ship."""
    project = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]
    assert project["license"] == "MIT" and project["license-files"] == ["LICENSE"]
    text = (REPO / "LICENSE").read_text()
    assert text.startswith("MIT License") and "Copyright (c) 2026 the sensor-registration authors" in text
    assert 'THE SOFTWARE IS PROVIDED "AS IS"' in text


def test_the_live_page_goes_into_the_wheel():
    """The page's three files are package data of registration.live, and every file in its folder is
    one the service serves (a stray file would ship but never be reachable)."""
    from registration.live.http.assets import CONTENT_TYPES

    cfg = tomllib.loads((REPO / "pyproject.toml").read_text())["tool"]["setuptools"]
    assert "registration.live" in cfg["packages"]
    globs = cfg["package-data"]["registration.live"]
    web = REPO / "registration" / "live" / "web"
    shipped = {p.relative_to(web.parent).as_posix() for g in globs for p in web.parent.glob(g) if p.is_file()}
    assert shipped == {f"web/{name}" for name in CONTENT_TYPES}


def test_playwright_is_in_the_test_extra():
    extra = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]["optional-dependencies"]["test"]
    assert any(d.startswith("playwright") for d in extra)
