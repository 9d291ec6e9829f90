"""Without Stone Soup, importing registration.interop.stonesoup fails with the install command."""

import importlib
import sys

import pytest

import registration.interop


def forget_interop_modules(monkeypatch, also_stonesoup: bool) -> None:
    """Drop registration.interop's submodules (and Stone Soup's) from the import cache for this test only."""
    for name in list(sys.modules):
        if name.startswith("registration.interop."):
            monkeypatch.setattr(
                registration.interop, name.rsplit(".", 1)[1], sys.modules[name], raising=False
            )
            monkeypatch.delitem(sys.modules, name)
        elif also_stonesoup and (name == "stonesoup" or name.startswith("stonesoup.")):
            monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "stonesoup", None)  # "import stonesoup" now raises ImportError


def test_missing_stonesoup_gives_the_install_command(monkeypatch):
    forget_interop_modules(monkeypatch, also_stonesoup=True)
    with pytest.raises(ImportError, match=r"pip install stonesoup"):
        importlib.import_module("registration.interop.stonesoup")


def test_the_world_frame_needs_no_stonesoup(monkeypatch):
    forget_interop_modules(monkeypatch, also_stonesoup=False)
    world = importlib.import_module("registration.interop.world")
    assert world.LocalFrame(0.6, 0.2).origin == (0.6, 0.2, 0.0)


def test_with_stonesoup_the_module_imports():
    module = importlib.import_module("registration.interop.stonesoup")
    assert tuple(int(v) for v in module.STONESOUP_VERSION.split(".")[:2]) >= (1, 9)
    assert module.LocalFrame is sys.modules["registration.interop.world"].LocalFrame
