"""The package's layering, checked on the source: no import cycle, no private name imported
across modules, no library module importing the CLI, and small modules and functions."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "registration"
MAX_MODULE_LINES = 400
MAX_FUNCTION_LINES = 80


def _modules() -> dict[str, Path]:
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE.parent).with_suffix("")
        name = ".".join(rel.parts).removesuffix(".__init__")
        out[name] = path
    return out


MODULES = _modules()


def _imports(name: str, path: Path) -> list[tuple[str, str | None, int]]:
    """(module imported, name imported from it or None,
    line) for every import of the package, at any depth."""
    out = []
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            out += [(a.name, None, node.lineno) for a in node.names if a.name.split(".")[0] == "registration"]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join(parts + ([base] if base else []))
            if base.split(".")[0] == "registration":
                for a in node.names:
                    full = f"{base}.{a.name}"
                    out.append((full, None, node.lineno) if full in MODULES else (base, a.name, node.lineno))
    return out


def _graph() -> dict[str, set[str]]:
    graph = {m: set() for m in MODULES}
    for m, path in MODULES.items():
        for target, _, _ in _imports(m, path):
            while target not in MODULES and "." in target:
                target = target.rpartition(".")[0]
            if target in MODULES and target != m:
                graph[m].add(target)
    return graph


def _is_cli(m: str) -> bool:
    """The command line and the entry points that run it (``python -m registration``)."""
    return m == "registration.cli" or m.startswith("registration.cli.") or m.endswith(".__main__")


def test_the_checker_sees_the_package():
    assert "registration.online.filter" in MODULES and "registration.cli" in MODULES
    assert "registration.core.frames" in _graph()["registration.frames"]


def test_no_import_cycle():
    """A package's __init__ importing its own submodules is not a cycle; anything else is."""
    graph = _graph()
    state: dict[str, int] = {}
    cycles = []

    def visit(m, stack):
        state[m] = 1
        for t in sorted(graph[m]):
            if state.get(t) == 1:
                cycle = stack[stack.index(t) :] + [t]
                if not all(x == t or x.startswith(t + ".") or t.startswith(x + ".") for x in cycle):
                    cycles.append(" -> ".join(cycle))
            elif t not in state:
                visit(t, stack + [t])
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            visit(m, [m])
    assert not cycles, cycles


def test_no_private_name_imported_across_modules():
    bad = [
        f"{m}:{line} imports {target}.{what}"
        for m, path in MODULES.items()
        for target, what, line in _imports(m, path)
        if what and what.startswith("_") and not what.startswith("__") and target != m
    ]
    assert not bad, bad


def test_no_library_module_imports_the_cli():
    graph = _graph()
    bad = [f"{m} -> {t}" for m, targets in graph.items() if not _is_cli(m) for t in targets if _is_cli(t)]
    assert not bad, bad


def test_modules_and_functions_are_small():
    long_modules = [
        f"{p.relative_to(PACKAGE.parent)}: {n} lines"
        for p in MODULES.values()
        if (n := p.read_text().count("\n")) > MAX_MODULE_LINES
    ]
    long_functions = []
    for p in MODULES.values():
        for node in ast.walk(ast.parse(p.read_text())):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                n = node.end_lineno - node.lineno + 1
                if n > MAX_FUNCTION_LINES:
                    long_functions.append(
                        f"{p.relative_to(PACKAGE.parent)}:{node.lineno} {node.name}: {n} lines"
                    )
    assert not long_modules and not long_functions, long_modules + long_functions


@pytest.mark.parametrize(
    "source, problem",
    [
        ("from registration.online.filter import _CARRY\n", "private"),
        ("from registration.cli import main\n", "cli"),
    ],
)
def test_the_checks_catch_a_planted_violation(tmp_path, monkeypatch, source, problem):
    planted = tmp_path / "registration" / "core" / "planted.py"
    planted.parent.mkdir(parents=True)
    planted.write_text(source)
    monkeypatch.setitem(MODULES, "registration.core.planted", planted)
    check = (
        test_no_private_name_imported_across_modules
        if problem == "private"
        else test_no_library_module_imports_the_cli
    )
    with pytest.raises(AssertionError):
        check()


def test_the_cycle_check_catches_a_planted_cycle(tmp_path, monkeypatch):
    folder = tmp_path / "registration" / "core"
    folder.mkdir(parents=True)
    for here, there in (("left", "right"), ("right", "left")):
        (folder / f"{here}.py").write_text(f"def f():\n    from registration.core.{there} import f\n")
        monkeypatch.setitem(MODULES, f"registration.core.{here}", folder / f"{here}.py")
    with pytest.raises(AssertionError, match="left"):
        test_no_import_cycle()
