"""``python -m derive [--check] [--out DIR]``: regenerate ``generated/`` or verify it is fresh."""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if os.environ.get("PYTHONHASHSEED") != "0":  # sympy's term order must not depend on hash seeds
        env = dict(os.environ, PYTHONHASHSEED="0")
        os.execve(sys.executable, [sys.executable, "-m", "derive", *argv], env)

    from .emit import GENERATED_DIR, compare_dirs, emit_all
    from .registry import CONSTANTS, all_specs

    parser = argparse.ArgumentParser(prog="python -m derive", description=__doc__)
    parser.add_argument("--check", action="store_true", help="regenerate into a temporary folder and compare")
    parser.add_argument("--out", type=Path, default=GENERATED_DIR, help="output folder (default: generated/)")
    args = parser.parse_args(argv)

    specs = all_specs()
    if args.check:
        with tempfile.TemporaryDirectory() as tmp:
            fresh = Path(tmp) / "generated"
            emit_all(specs, fresh, CONSTANTS)
            problems = compare_dirs(fresh, args.out)
        if problems:
            print(f"generated/ is STALE ({len(problems)} problem(s)):")
            for p in problems:
                print(f"  {p}")
            print("Run `python -m derive` to regenerate, then commit generated/.")
            return 1
        print(f"generated/ is fresh: {len(specs)} functions match derive/.")
        return 0
    manifest = emit_all(specs, args.out, CONSTANTS)
    print(f"wrote {len(manifest['functions'])} functions to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
