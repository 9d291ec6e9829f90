"""Without Stone Soup, importing registration.interop.stonesoup fails with the install command."""

import importlib
import sys

import pytest


def test_missing_stonesoup_gives_the_install_command(monkeypatch):
    for name in list(sys.modules):
        if name.startswith("registration.interop.") or name == "stonesoup" or name.startswith("stonesoup."):
            monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "stonesoup", None)  # "import stonesoup" now raises ImportError
    with pytest.raises(ImportError, match=r'pip install "sensor-registration\[stonesoup\]"'):
        importlib.import_module("registration.interop.stonesoup")


def test_the_world_frame_needs_no_stonesoup(monkeypatch):
    for name in list(sys.modules):
        if name.startswith("registration.interop."):
            monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "stonesoup", None)
    world = importlib.import_module("registration.interop.world")
    assert world.LocalFrame(0.6, 0.2).origin == (0.6, 0.2, 0.0)


def test_with_stonesoup_the_module_imports():
    module = importlib.import_module("registration.interop.stonesoup")
    assert tuple(int(v) for v in module.STONESOUP_VERSION.split(".")[:2]) >= (1, 9)
