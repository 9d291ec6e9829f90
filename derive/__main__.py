"""``python -m derive [--out DIR]``: regenerate ``generated/`` from the derivations.
``python -m derive --check [--fresh DIR]``: regenerate elsewhere and verify ``generated/`` matches."""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from pathlib import Path


def check(fresh: Path, target: Path) -> int:
    """Print whether ``target`` matches the fresh generation ``fresh``: 0 if it does, 1 if stale."""
    from .emit import MANIFEST_NAME, compare_dirs

    problems = compare_dirs(fresh, target)
    if problems:
        print(f"generated/ is STALE ({len(problems)} problem(s)):")
        for p in problems:
            print(f"  {p}")
        print("Run `python -m derive` to regenerate, then commit generated/.")
        return 1
    n = len(json.loads((fresh / MANIFEST_NAME).read_text())["functions"])
    print(f"generated/ is fresh: {n} functions match derive/.")
    return 0


def parse_args(argv: list[str]) -> argparse.Namespace:
    from .emit import GENERATED_DIR

    parser = argparse.ArgumentParser(prog="python -m derive", description=__doc__)
    parser.add_argument("--check", action="store_true", help="regenerate into a temporary folder and compare")
    parser.add_argument("--out", type=Path, default=GENERATED_DIR, help="output folder (default: generated/)")
    parser.add_argument(
        "--fresh",
        type=Path,
        metavar="DIR",
        help="with --check: write the fresh generation to DIR and keep it (to inspect differences)",
    )
    args = parser.parse_args(argv)
    if args.fresh is not None and not args.check:
        parser.error("--fresh only goes with --check")
    if args.fresh is not None and args.fresh.resolve() == args.out.resolve():
        parser.error("--fresh must differ from --out (the folder being checked)")
    return args


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if os.environ.get("PYTHONHASHSEED") != "0":  # sympy's term order must not depend on hash seeds
        env = dict(os.environ, PYTHONHASHSEED="0")
        os.execve(sys.executable, [sys.executable, "-m", "derive", *argv], env)

    from .emit import emit_all
    from .registry import CONSTANTS, VARIANTS, all_specs

    args = parse_args(argv)
    specs = all_specs()
    if not args.check:
        manifest = emit_all(specs, args.out, CONSTANTS, VARIANTS)
        print(f"wrote {len(manifest['functions'])} functions to {args.out}")
        return 0
    if args.fresh is not None:
        emit_all(specs, args.fresh, CONSTANTS, VARIANTS)
        return check(args.fresh, args.out)
    with tempfile.TemporaryDirectory() as tmp:
        fresh = Path(tmp) / "generated"
        emit_all(specs, fresh, CONSTANTS, VARIANTS)
        return check(fresh, args.out)


if __name__ == "__main__":
    sys.exit(main())
