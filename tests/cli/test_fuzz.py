"""Random command lines and random input files through ``registration.cli.main``.

Whatever the options or the input file, the command line answers with a documented exit code
(0, 2 or 3; 1 only from ``register --validate-only``), never a traceback, and writes nothing
outside its ``--out`` folder (each example runs in an empty working folder whose tree is compared
before and after). Sizes are kept small (--steps, --runs, --trials below 30; plots off) so the
examples stay fast.
"""

from __future__ import annotations

import contextlib
import functools
import io
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from registration.cli import main
from registration.recorded import SYNC_COLUMNS

FUZZ = settings(max_examples=12, deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])

#: option values that are not numbers, not finite or out of every range
ODD = st.sampled_from(["0", "-1", "nan", "inf", "-inf", "abc", "", "1,2", "-0"])
#: counts: mostly small and valid, sometimes odd (one_of draws each branch about equally often)
COUNT = st.one_of(st.integers(2, 25).map(str), st.integers(-2, 25).map(str), ODD)


def number(lo: float, hi: float):
    """Mostly a plausible value in [lo, hi], sometimes an odd one."""
    plausible = st.floats(lo, hi, allow_nan=False).map(lambda v: f"{v:.6g}")
    return st.one_of(plausible, plausible, ODD)


def choice(*values):
    return st.one_of(st.sampled_from(values), st.sampled_from(values), st.just("bogus"))


SCENARIO = {
    "--angle-sigma-deg": number(0.01, 25),
    "--range-sigma-m": number(0.1, 500),
    "--steps": COUNT,
    "--ship-motion": st.sampled_from(
        [
            "2,8,5,12",
            "1,1,1,1",
            "0,5,0,5",
            "45,8,5,12",
            "2,0,5,12",
            "2,8,5",
            "a,b,c,d",
            "",
            "nan,8,5,12",
            "2,inf,5,12",
        ]
    ),
    "--linearization": choice("paper", "relinearized", "fitted"),
    "--q-mode": choice("fixed", "adaptive"),
    "--t-variant": choice("standard", "paper"),
    "--seed": COUNT,
}
OPTIONS = {
    "simulate": {**SCENARIO, "--allow-inconsistent": None},
    "montecarlo": {
        **SCENARIO,
        "--runs": COUNT,
        "--include-weak": None,
        "--allow-inconsistent": None,
        "--sum": st.sampled_from(["dC_a+dq_a", "de_a+de_b", "dC_a", "x+y", "dC_a+dC_a", ""]),
    },
    "fuse": {
        "--scenario": st.sampled_from(["1", "2", "3", "x"]),
        "--trials": COUNT,
        "--seed": COUNT,
        "--max-plot-points": COUNT,
        "--baseline-m": number(-1e5, 1e5),
        "--target-range-m": number(-1e3, 2e5),
        "--target-azimuth-deg": number(-400, 400),
        "--target-elevation-deg": number(-95, 95),
        "--sigma-range-m": number(-10, 500),
        "--sigma-azimuth-mrad": number(-1, 20),
        "--sigma-elevation-mrad": number(-1, 20),
        "--second": st.sampled_from(["range", "azimuth", "bearing", "elevation", "range,azimuth", "x", ""]),
        "--sigma-second-range-m": number(-1, 50),
        "--sigma-second-azimuth-mrad": number(-1, 20),
        "--sigma-second-elevation-mrad": number(-1, 20),
    },
    "landing": {
        "--runs": COUNT,
        "--seed": COUNT,
        "--bin-m": number(50, 2000),
        "--plot-bin-m": number(50, 1000),
        "--fusion-rate-hz": number(1, 30),
        "--degree": COUNT,
        "--half-window-s": number(0.05, 1),
        "--ignore-clock-offsets": None,
        "--glide-slope-deg": number(-5, 20),
        "--ground-speed-mps": number(20, 100),
        "--start-range-m": number(100, 3000),
        "--end-range-m": number(-100, 500),
        "--ship-speed-mps": number(-5, 30),
        "--angled-deck-deg": number(-20, 20),
        "--yaw-deg": number(-1, 10),
        "--pitch-period-s": number(-1, 20),
        "--radar-rate-hz": number(1, 40),
        "--radar-sigma-range-m": number(-1, 10),
        "--camera-rate-hz": number(1, 40),
        "--camera-clock-offset-ms": number(-50, 50),
    },
    "schema": {"--json": None},
}
#: always added, so that every example is quick
FAST = {
    "simulate": ["--no-plots", "--steps", "12"],
    "montecarlo": ["--no-plots", "--runs", "2", "--steps", "12"],
    "fuse": ["--no-plots", "--trials", "20"],
    "landing": ["--no-plots", "--runs", "2", "--start-range-m", "400"],
    "schema": [],
}


@st.composite
def command_lines(draw, name: str):
    """FAST first, then random options: a later option
    overrides the fast default (argparse keeps the last)."""
    table = OPTIONS[name]
    argv = [name, *FAST[name]]
    for option in draw(st.lists(st.sampled_from(sorted(table)), max_size=4)):
        argv.append(option)
        if table[option] is not None:
            argv.append(draw(table[option]))
    if draw(st.integers(0, 5)) == 0:
        argv.append(draw(st.sampled_from(["--bogus", "-x", "extra", "--out"])))
    out = draw(st.sampled_from([None, "o", "o/deep/er"]))
    if out is not None and name != "schema":
        argv += ["--out", out]
    if name == "simulate" and draw(st.booleans()):
        argv += [
            "--export",
            f"{out or 'out/simulate'}/" + draw(st.sampled_from(["d.csv", "d.parquet", "d.xlsx", "d"])),
        ]
    return argv


def tree(root: Path) -> set[Path]:
    return {p.relative_to(root) for p in root.rglob("*")}


def out_folder(argv: list[str]) -> Path:
    """The folder the command may write: the last --out value, else out/<command>."""
    values = [argv[i + 1] for i, a in enumerate(argv[:-1]) if a == "--out"]
    return Path(values[-1]) if values else Path("out") / argv[0]


def run_isolated(argv: list[str], files: dict[str, bytes] | None = None) -> tuple[int, str]:
    """``main(argv)`` in an empty working folder (plus ``files``); the exit code and standard error.

    Fails if anything outside the --out folder (or its parents) appears."""
    with tempfile.TemporaryDirectory() as tmp, contextlib.chdir(tmp):
        root = Path(tmp)
        for name, data in (files or {}).items():
            (root / name).write_bytes(data)
        before = tree(root)
        err = io.StringIO()
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            code = main(list(argv))
        out = out_folder(argv)
        stray = [p for p in tree(root) - before if not (p == out or out in p.parents or p in out.parents)]
        assert not stray, (argv, stray)
    return code, err.getvalue()


def check(argv: list[str], code: int, err: str, allowed=(0, 2, 3)) -> None:
    assert code in allowed, (argv, code, err)
    assert "Traceback" not in err, (argv, err)
    if code == 2:
        assert "error" in err, (argv, err)


@pytest.mark.parametrize("name", sorted(OPTIONS))
def test_random_options(name):
    """Random options; sometimes a file already sits where the output folder (or its parent) goes."""

    @FUZZ
    @given(command_lines(name), st.sampled_from([{}, {}, {"o": b"a file"}, {"out": b"a file"}]))
    def fuzz(argv, files):
        code, err = run_isolated(argv, files)
        check(argv, code, err)

    fuzz()


# --------------------------------------------------------------------------- register: random input files
CELL = st.one_of(
    st.floats(-400, 400, allow_nan=False).map(lambda v: f"{v:.4f}"),
    st.integers(0, 2_000_000).map(str),
    st.sampled_from(["", "nan", "inf", "x", "1e400", '"', "0"]),
)
REGISTER_OPTIONS = st.lists(
    st.sampled_from(
        [
            ["--on-bad-row", "skip"],
            ["--on-bad-row", "stop"],
            ["--validate-only"],
            ["--format", "parquet"],
            ["--chunk-rows", "3"],
            ["--chunk-rows", "0"],
            ["--sigma", "50,0.5,0.5"],
            ["--sigma", "-1,0,0"],
            ["--q-mode", "adaptive"],
            ["--observability", "filter"],
            ["--allow-inconsistent"],
        ]
    ),
    max_size=3,
)


@functools.lru_cache(maxsize=1)
def valid_table() -> list[list[str]]:
    """A small simulated synchronous table (header + 24 rows) as CSV cells, the start of the mutations."""
    from registration.online.scenario import paper_scenario
    from registration.recorded import write_table

    with tempfile.TemporaryDirectory() as tmp:
        path = write_table(paper_scenario(seed=3, n_steps=24).data, Path(tmp) / "sim.csv")
        return [line.split(",") for line in path.read_text().splitlines()]


@st.composite
def mutated_tables(draw) -> bytes:
    """The valid table with a few changes: odd cells, a column scaled
    (a unit mistake), dropped or swapped, rows cut or repeated."""
    rows = [list(r) for r in valid_table()]
    width = len(rows[0])
    for _ in range(draw(st.integers(0, 3))):
        if len(rows) < 2 or width < 2:
            break  # nothing left to change
        op = draw(st.sampled_from(["cell", "scale", "drop", "swap", "cut", "repeat"]))
        col = draw(st.integers(0, width - 1))
        if op == "cell":
            rows[draw(st.integers(1, len(rows) - 1))][col] = draw(CELL)
        elif op == "scale":  # e.g. radians in a _deg column, km in an _m column
            k = draw(st.sampled_from([180 / 3.141592653589793, 3.141592653589793 / 180, -1.0, 1e3, 1e-3]))
            rows = [rows[0]] + [
                [f"{float(v) * k:.9g}" if j == col else v for j, v in enumerate(r)] for r in rows[1:]
            ]
        elif op == "drop":
            rows = [[v for j, v in enumerate(r) if j != col] for r in rows]
        elif op == "swap":
            other = draw(st.integers(0, width - 1))
            for r in rows:
                r[col], r[other] = r[other], r[col]
        elif op == "cut":
            rows = rows[: draw(st.integers(1, len(rows)))]
        else:
            i = draw(st.integers(1, len(rows) - 1))
            rows.insert(i, list(rows[i]))
        width = len(rows[0])
    return ("\n".join(",".join(r) for r in rows) + "\n").encode()


@st.composite
def random_tables(draw) -> bytes:
    """A CSV with some of the synchronous columns (any
    order, maybe extra ones) and a few rows of odd cells."""
    columns = draw(
        st.lists(st.sampled_from(list(SYNC_COLUMNS) + ["extra", "time_s"]), max_size=len(SYNC_COLUMNS) + 2)
    )
    rows = draw(st.lists(st.lists(CELL, min_size=len(columns), max_size=len(columns)), max_size=6))
    lines = [",".join(columns)] + [",".join(r) for r in rows]
    return ("\n".join(lines) + draw(st.sampled_from(["", "\n", "\n,,\n"]))).encode()


def register_argv(options, name: str) -> list[str]:
    return ["register", name, "--out", "reg", "--no-plots", "--no-progress", *[a for o in options for a in o]]


@FUZZ
@given(
    data=st.binary(max_size=300),
    name=st.sampled_from(["in.csv", "in.parquet", "in.txt"]),
    options=REGISTER_OPTIONS,
)
def test_register_random_bytes(data, name, options):
    argv = register_argv(options, name)
    code, err = run_isolated(argv, {name: data})
    check(argv, code, err, allowed=(0, 1, 2, 3))


@FUZZ
@given(table=st.one_of(mutated_tables(), mutated_tables(), random_tables()), options=REGISTER_OPTIONS)
def test_register_random_csv_shapes(table, options):
    argv = register_argv(options, "in.csv")
    code, err = run_isolated(argv, {"in.csv": table})
    check(argv, code, err, allowed=(0, 1, 2, 3))
