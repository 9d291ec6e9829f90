#!/usr/bin/env python3
"""Throughput of the generated frame transforms, against pymap3d, pyproj and a plain C loop.

Run from a checkout (the package installed, editable or not)::

    python3 benchmarks/bench_frames.py                 # 10^6 points
    python3 benchmarks/bench_frames.py --n 200000 --json results.json

Everything is measured in one run, on the same random inputs: one untimed warm-up, then
``--repeat`` rounds interleaved across the contenders of a section in alternating order
(common.interleave), median time kept, ratios the median of the rounds' ratios. On a shared
machine the figures move by 10-20 % between runs; read the ratios. Figures:
benchmarks/results/frames.json; ``--tiny`` runs in seconds on 2000 points. Every output is compared with
ours (column ``max |diff|``), so a fast but wrong path would show.

1. ``geodetic2ecef``: ``registration.core.frames.geodetic2ecef`` (input validation included) and
   the raw ``registration._codegen.get("geodetic2ecef")`` (no validation) against
   ``pymap3d.geodetic2ecef`` (numpy-vectorised, ``deg=False``) and a pyproj ``Transformer``
   EPSG:4979 -> EPSG:4978 (``radians=True``, so no degree conversion is charged to pyproj).
   Aim: faster than pyproj.
2. The full radar plot conversion (geodetic position + attitude + measurement -> target ECEF):
   ``registration.core.frames.plot2ecef`` and the raw ``plot2ecef_standard`` against
   (a) a plain C loop over the same generated code, written and compiled here into a temporary
   folder with the runtime's optimisation flags (the practical limit); (b) the serialized CasADi
   backend (``Function.map``); (c) item-by-item conversion of each point into ``casadi.DM`` on
   ``--dm-n`` points (why that path is avoided). Aim: within 2x of the plain C loop.
3. The fixed per-call cost of the wrappers at N = 1 (not an aim; what a per-plot caller pays).

The plain C harness ``#include``s the shipped ``generated/<name>.c`` (so the body may be inlined),
reads the same inputs from a binary file, calls the function once per point on structure-of-arrays
inputs (as the runtime's batch driver does) and times the loop with ``clock_gettime``. It is built
with ``registration._codegen.CFLAGS`` minus ``-fPIC -shared``. Its second mode calls through a
volatile function pointer, as the runtime's driver (reached by ctypes) must. Needs a C compiler
(``CC``, else cc/gcc/clang); without one those rows are skipped.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from common import Timed, add_arguments, interleave, median, paired_ratio, write

import registration
from registration import _codegen
from registration.core import frames


def make_inputs(n: int, seed: int) -> dict[str, np.ndarray]:
    """Random plots: platforms over the whole globe, heights -500 m .. 100 km, ship-like attitude."""
    rng = np.random.default_rng(seed)
    # uniform on the sphere in latitude (arcsin of a uniform), uniform longitude in [-pi, pi)
    return {
        "lat": np.arcsin(rng.uniform(-1.0, 1.0, n)),
        "lon": rng.uniform(-np.pi, np.pi, n),
        "alt": rng.uniform(-500.0, 1.0e5, n),
        "heading": rng.uniform(0.0, 2 * np.pi, n),
        "pitch": rng.uniform(-0.2, 0.2, n),
        "roll": rng.uniform(-0.4, 0.4, n),
        "r": rng.uniform(500.0, 3.0e5, n),
        "q": rng.uniform(-np.pi, np.pi, n),
        "e": rng.uniform(-0.1, 0.6, n),
    }


GEO_NAMES = ["lat", "lon", "alt"]
PLOT_NAMES = ["lat", "lon", "alt", "heading", "pitch", "roll", "r", "q", "e"]


def timed(fn):
    """A contender timed by common.interleave (perf_counter around the call)."""
    return fn


def once(fn) -> tuple[float, object]:
    """(seconds, output) of one call."""
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def measure(contenders: dict, rounds: int) -> dict:
    """Median time of each contender over ``rounds`` rounds after one untimed warm-up, as
    {label: (median seconds, output, every round's seconds)}. Rounds are interleaved across
    contenders in alternating order (common.interleave), so a change in machine load is spread
    over all of them."""
    times, values = interleave(contenders, rounds)
    return {label: (median(t), values[label], t) for label, t in times.items()}


HARNESS = r"""
/* Benchmark harness (not shipped): plain C loop over one CasADi-generated function. */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "@SOURCE@"
#define N_IN @N_IN@
#define N_OUT_EL @N_OUT_EL@
#define SZ_W @SZ_W@
#define SZ_IW @SZ_IW@
/* one pass over the n points, inputs as structure of arrays */
#define SWEEP(CALL) for (long long i = 0; i < n; ++i) { \
        for (int j = 0; j < N_IN; ++j) arg[j] = in + j * n + i; \
        res[0] = out + N_OUT_EL * i; \
        CALL(arg, res, iw, w, 0); }
typedef int (*gen_fn)(const casadi_real **, casadi_real **, casadi_int *, casadi_real *, int);

static double now_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

int main(int argc, char **argv) {
    if (argc != 6) { fprintf(stderr, "usage: n repeat in.bin out.bin direct|pointer\n"); return 2; }
    long long n = atoll(argv[1]);
    int repeat = atoi(argv[2]);
    int direct = argv[5][0] == 'd';
    /* a volatile function pointer: the compiler cannot inline through it (like the ctypes driver) */
    gen_fn volatile indirect = @FUNC@;
    double *in = malloc(sizeof(double) * (size_t)(N_IN * n));
    double *out = malloc(sizeof(double) * (size_t)(N_OUT_EL * n));
    FILE *f = fopen(argv[3], "rb");
    if (!in || !out || !f || fread(in, sizeof(double), (size_t)(N_IN * n), f) != (size_t)(N_IN * n)) {
        fprintf(stderr, "cannot read inputs\n"); return 1;
    }
    fclose(f);
    const casadi_real *arg[N_IN + 1]; casadi_real *res[2];
    casadi_int iw[SZ_IW + 1]; casadi_real w[SZ_W + 1];
    double best = 1e300;
    for (int rep = 0; rep < repeat + 1; ++rep) { /* first pass: warm-up, untimed */
        double t0 = now_ns();
        if (direct) {
            SWEEP(@FUNC@)
        } else {
            gen_fn fp = indirect;
            SWEEP(fp)
        }
        double dt = now_ns() - t0;
        if (rep > 0 && dt < best) best = dt;
    }
    f = fopen(argv[4], "wb");
    if (!f || fwrite(out, sizeof(double), (size_t)(N_OUT_EL * n), f) != (size_t)(N_OUT_EL * n)) {
        fprintf(stderr, "cannot write outputs\n"); return 1;
    }
    fclose(f);
    printf("%.6f\n", best / (double)n);
    return 0;
}
"""


class PlainC:
    """The plain C loop over one generated function, built into ``tmp``; call ``run(mode)``."""

    def __init__(self, name: str, inputs: list[np.ndarray], tmp: Path):
        cc = _codegen.compiler()
        if cc is None:
            raise RuntimeError("no C compiler (set CC)")
        meta = _codegen.manifest()["functions"][name]
        if any(tuple(p["shape"]) != (1, 1) for p in meta["inputs"]) or len(meta["outputs"]) != 1:
            raise RuntimeError(f"the harness handles scalar inputs and one output only: {name}")
        r, c = meta["outputs"][0]["shape"]
        self.n, self.width = inputs[0].shape[0], r * c
        src = tmp / f"{name}.c"
        src.write_bytes(_codegen.read_artifact(name, "c"))  # the shipped source, hash-checked
        code = HARNESS
        for key, value in (
            ("@SOURCE@", src.name),
            ("@FUNC@", name),
            ("@N_IN@", len(inputs)),
            ("@N_OUT_EL@", self.width),
            ("@SZ_W@", meta["work"]["sz_w"]),
            ("@SZ_IW@", meta["work"]["sz_iw"]),
        ):
            code = code.replace(key, str(value))
        harness = tmp / f"harness_{name}.c"
        harness.write_text(code)
        self.exe = tmp / f"harness_{name}"
        flags = [
            f for f in _codegen.CFLAGS if f not in ("-shared", "-fPIC")
        ]  # the runtime's, for an executable
        cmd = [cc, *flags, "-o", str(self.exe), str(harness), "-lm"]
        proc = subprocess.run(cmd, capture_output=True, text=True, cwd=tmp)
        if proc.returncode != 0:
            raise RuntimeError(f"harness compilation failed: {' '.join(cmd)}\n{proc.stderr}")
        self.command = " ".join(cmd)
        self.in_bin, self.out_bin = tmp / f"{name}.in", tmp / f"{name}.out"
        np.ascontiguousarray(np.stack(inputs)).tofile(self.in_bin)  # SoA: input j at in + j*n

    def runner(self, mode: str, repeat: int = 1):
        """A contender: one process run (untimed warm-up pass + ``repeat`` timed passes)."""

        def run():
            proc = subprocess.run(
                [str(self.exe), str(self.n), str(repeat), str(self.in_bin), str(self.out_bin), mode],
                capture_output=True,
                text=True,
            )
            if proc.returncode != 0:
                raise RuntimeError(f"harness failed: {proc.stderr.strip()}")
            ns = float(proc.stdout.strip())
            out = np.fromfile(self.out_bin, dtype=np.float64).reshape(self.n, self.width)
            return Timed(ns * 1e-9 * self.n, out)

        return run


def casadi_item_by_item(name: str, inputs: list[np.ndarray]) -> np.ndarray:
    """The slow path: every scalar of every point converted to casadi.DM, one call per point."""
    import casadi as ca

    fn = _codegen.GeneratedFunction(name, force_backend="casadi").casadi
    m = inputs[0].shape[0]
    out = np.empty((m, 3))
    for i in range(m):
        res = fn(*[ca.DM(float(a[i])) for a in inputs])
        out[i] = np.asarray(res.full()).ravel()
    return out


def max_abs_diff(a, b) -> float:
    return float(np.max(np.abs(np.asarray(a).reshape(len(b), -1) - np.asarray(b).reshape(len(b), -1))))


def row(label: str, seconds: float, n: int, diff: float | None, note: str = "", rounds=None) -> dict:
    return {
        "method": label,
        "n": n,
        "seconds": seconds,
        "rounds": [seconds] if rounds is None else list(rounds),
        "points_per_s": n / seconds,
        "ns_per_point": seconds / n * 1e9,
        "max_abs_diff_m": diff,
        "note": note,
    }


def print_table(title: str, rows: list[dict], ref_label: str) -> None:
    ref = next(r for r in rows if r["method"] == ref_label)
    print(f"\n{title}")
    print(f"  (x ref = throughput relative to '{ref_label}'; > 1 is faster; max |diff| vs ours, metres)")
    head = (
        f"  {'method':<46} {'N':>9} {'median ms':>10} {'ns/pt':>9} {'points/s':>12} {'x ref':>8} "
        f"{'max |diff|':>11}"
    )
    print(head)
    print("  " + "-" * (len(head) - 2))
    for r in rows:
        diff = "-" if r["max_abs_diff_m"] is None else f"{r['max_abs_diff_m']:.1e}"
        print(
            f"  {r['method']:<46} {r['n']:>9} {r['seconds'] * 1e3:>10.2f} {r['ns_per_point']:>9.1f} "
            f"{r['points_per_s']:>12.3e} {r['points_per_s'] / ref['points_per_s']:>8.2f} {diff:>11}"
        )


PJ, PC = "pyproj Transformer 4979->4978 (radians)", "plain C loop, direct call (inlinable)"
PM = "pymap3d.geodetic2ecef (deg=False)"
OURS_G, RAW_G = "ours: frames.geodetic2ecef (validated)", "ours: _codegen.get('geodetic2ecef') (raw)"
OURS_P, RAW_P = "ours: frames.plot2ecef (validated)", "ours: _codegen.get('plot2ecef_standard') (raw)"


def machine_info() -> dict:
    """Platform, library versions, backend and compiler of this run."""
    import casadi
    import pymap3d
    import pyproj

    return {
        "platform": platform.platform(),
        "machine": platform.machine(),
        "processor": platform.processor() or "?",
        "cpu_count": os.cpu_count(),
        "python": platform.python_version(),
        "numpy": np.__version__,
        "casadi": casadi.__version__,
        "pymap3d": pymap3d.__version__,
        "pyproj": pyproj.__version__,
        "proj": pyproj.proj_version_str,
        "registration": getattr(registration, "__version__", "?"),
        "backend": _codegen.backend(),
        "compiler": _codegen.compiler(),
        "cflags": " ".join(_codegen.CFLAGS),
    }


def bench_geodetic(geo: list[np.ndarray], harness: dict, rep: int) -> list[dict]:
    """Section 1: geodetic2ecef, ours against pymap3d, pyproj and the plain C loop."""
    import pymap3d
    import pyproj

    n = geo[0].shape[0]
    raw_g = _codegen.get("geodetic2ecef")
    tr = pyproj.Transformer.from_crs("EPSG:4979", "EPSG:4978")
    c1 = {
        OURS_G: timed(lambda: frames.geodetic2ecef(*geo)),
        RAW_G: timed(lambda: raw_g(*geo)[0]),
        PM: timed(lambda: np.stack(pymap3d.geodetic2ecef(*geo, deg=False), -1)),
        PJ: timed(lambda: np.stack(tr.transform(*geo, radians=True), -1)),
    }
    if "geodetic2ecef" in harness:
        c1[PC] = harness["geodetic2ecef"].runner("direct")
    res1 = measure(c1, rep)
    ours = res1[OURS_G][1]
    return [row(k, t, n, max_abs_diff(out, ours), rounds=r) for k, (t, out, r) in res1.items()]


def bench_plot(plot: list[np.ndarray], harness: dict, rep: int) -> tuple[list[dict], np.ndarray]:
    """Section 2, compiled paths: plot -> ECEF, ours against the plain C loop (direct and by pointer).
    Returns the rows and our output (the reference of the other paths)."""
    n = plot[0].shape[0]
    raw_p = _codegen.get("plot2ecef_standard")
    c2 = {OURS_P: timed(lambda: frames.plot2ecef(*plot)), RAW_P: timed(lambda: raw_p(*plot)[0])}
    if "plot2ecef_standard" in harness:
        c2[PC] = harness["plot2ecef_standard"].runner("direct")
        c2["plain C loop, via function pointer"] = harness["plot2ecef_standard"].runner("pointer")
    res2 = measure(c2, rep)
    ours_p = res2[OURS_P][1]
    return [row(k, t, n, max_abs_diff(out, ours_p), rounds=r) for k, (t, out, r) in res2.items()], ours_p


def bench_casadi_paths(
    plot: list[np.ndarray], ours_p: np.ndarray, casadi_repeat: int, dm_n: int
) -> list[dict]:
    """Section 2, CasADi paths: the serialized backend (Function.map) and item-by-item casadi.DM."""
    n = plot[0].shape[0]
    cas = _codegen.GeneratedFunction("plot2ecef_standard", force_backend="casadi")
    first, _ = once(lambda: cas(*plot)[0])
    res = measure({"c": timed(lambda: cas(*plot)[0])}, casadi_repeat)["c"]
    rows = [
        row(
            "CasADi serialized, Function.map (backend)",
            res[0],
            n,
            max_abs_diff(res[1], ours_p),
            f"first call incl. map construction {first:.2f} s; median of {casadi_repeat}",
        )
    ]
    m = min(dm_n, n)
    t, out = once(lambda: casadi_item_by_item("plot2ecef_standard", [a[:m] for a in plot]))
    rows.append(
        row(
            "casadi.DM item by item, one call per point",
            t,
            m,
            max_abs_diff(out, ours_p[:m]),
            f"{m} points only, one pass",
        )
    )
    return rows


def bench_per_call(plot: list[np.ndarray], rep: int, calls: int = 2000) -> list[dict]:
    """Section 3: per-call overhead on one plot per call (what a per-plot caller pays)."""
    one = [a[:1] for a in plot]
    raw_p = _codegen.get("plot2ecef_standard")

    def per_call(fn):
        def loop():
            for _ in range(calls):
                fn()

        return timed(loop)

    res3 = measure(
        {
            f"{OURS_P}, N=1": per_call(lambda: frames.plot2ecef(*one)),
            f"{RAW_P}, N=1": per_call(lambda: raw_p(*one)),
        },
        rep,
    )
    return [{"method": k, "calls": calls, "us_per_call": t / calls * 1e6} for k, (t, _, _) in res3.items()]


def print_report(
    n: int, rows1: list[dict], rows2: list[dict], rows3: list[dict], harness_cmd: str | None
) -> None:
    print_table(f"1. geodetic2ecef, {n} random points over the globe (h -500 m .. 100 km)", rows1, PJ)
    ref2 = PC if harness_cmd else RAW_P
    print_table(f"2. radar plot -> target ECEF (plot2ecef_standard), {n} plots", rows2, ref2)
    for r in rows2:
        if r["note"]:
            print(f"  note: {r['method']}: {r['note']}")
    if harness_cmd:
        print(f"  plain C harness built with: {harness_cmd}")
    print("\n3. per-call latency, one plot per call (fixed overhead of the numpy/ctypes wrapper)")
    for r in rows3:
        print(f"  {r['method']:<54} {r['us_per_call']:8.1f} us/call")


def report_aims(rows1: list[dict], rows2: list[dict]) -> dict:
    """Print and return the aims: throughput against pyproj (> 1), time against plain C (<= 2)."""
    by1, by2 = ({r["method"]: r for r in rows} for rows in (rows1, rows2))
    rounds1, rounds2 = ({r["method"]: r["rounds"] for r in rows} for rows in (rows1, rows2))
    aims = {}
    for key in (OURS_G, RAW_G):  # throughput ratio: pyproj's time over ours, median of the rounds
        aims[f"{key} throughput / pyproj"] = paired_ratio(rounds1, PJ, key)
    aims["pymap3d time / ours (validated)"] = paired_ratio(rounds1, PM, OURS_G)
    if PC in by2:
        for key in (OURS_P, RAW_P):
            aims[f"{key} time / plain C"] = paired_ratio(rounds2, key, PC)
    print("\naims:")
    for k, v in aims.items():
        if k.startswith("pymap3d"):
            print(f"  {k:<62} {v:6.2f}x")
            continue
        aim, met = ("> 1", v > 1) if k.endswith("pyproj") else ("<= 2", v <= 2)
        print(f"  {k:<62} {v:6.2f}x  (aim {aim}: {'met' if met else 'NOT met'})")
    return aims


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1_000_000, help="points per batch (default 10^6)")
    ap.add_argument("--repeat", type=int, default=7, help="timed rounds, interleaved (default 7)")
    ap.add_argument("--dm-n", type=int, default=10_000, help="points for the item-by-item casadi.DM path")
    ap.add_argument("--casadi-repeat", type=int, default=2, help="repetitions for the CasADi map backend")
    ap.add_argument("--seed", type=int, default=20110101)
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:
        args.n, args.repeat, args.dm_n, args.casadi_repeat = 2000, 1, 200, 1
    n, rep = args.n, args.repeat
    machine = machine_info()
    print("machine: " + ", ".join(f"{k}={v}" for k, v in machine.items()))
    print(
        f"N = {n}, median of {rep} interleaved rounds (perf_counter; the C harness times itself with "
        "clock_gettime), one untimed warm-up each"
    )

    data = make_inputs(n, args.seed)
    geo = [data[k] for k in GEO_NAMES]
    plot = [data[k] for k in PLOT_NAMES]

    with tempfile.TemporaryDirectory(prefix="bench_frames_") as tmp:
        tmp = Path(tmp)
        harness = {}
        for name, inputs in (("geodetic2ecef", geo), ("plot2ecef_standard", plot)):
            try:
                harness[name] = PlainC(name, inputs, tmp)
            except RuntimeError as exc:
                print(f"plain C harness for {name} unavailable: {exc}")
        rows1 = bench_geodetic(geo, harness, rep)
        rows2, ours_p = bench_plot(plot, harness, rep)
        harness_cmd = harness["plot2ecef_standard"].command if "plot2ecef_standard" in harness else None

    rows2 += bench_casadi_paths(plot, ours_p, args.casadi_repeat, args.dm_n)
    rows3 = bench_per_call(plot, rep)
    print_report(n, rows1, rows2, rows3, harness_cmd)
    aims = report_aims(rows1, rows2)

    figures = {
        "machine": machine,
        "seed": args.seed,
        "geodetic2ecef": rows1,
        "plot2ecef": rows2,
        "per_call": rows3,
        "aims": aims,
    }
    write("frames", args, {"n": n, "repeat": rep, "dm_n": args.dm_n}, figures)
    return 0


if __name__ == "__main__":
    sys.exit(main())
