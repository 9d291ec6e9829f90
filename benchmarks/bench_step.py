#!/usr/bin/env python3
"""Speed of the compiled Kalman step per covariance update: Joseph against Carlson, one run.

Run from a checkout (the package installed, editable or not)::

    python3 benchmarks/bench_step.py                    # 10^5 steps, every linearisation
    python3 benchmarks/bench_step.py --steps 1000000    # also the 10^6-step positive-definiteness check

Data: the paper scenario's 300 rows (``paper_scenario(seed)``) tiled to ``--steps`` rows, T
``standard``, the default fixed Q. Each step runs in the compiled scan (the loader's portable
flags, ``registration._codegen.CFLAGS``) with x, P, info carried and only the last outputs kept,
so the figure is the step itself plus the scan's copies, in us per step: median of ``--repeat``
interleaved rounds (common.interleave) after one warm-up; ratios are medians of the rounds'
ratios. Figures: benchmarks/results/step.json; ``--tiny``: 1000 steps, no native builds. Printed
per linearisation: us/step for each update, the ratio Joseph / Carlson, whether the 1 us aim is
met, and the largest difference of the final P (relative to its diagonal scale) between the two.

The same steps are then timed in the builds for the local CPU (``REGISTRATION_NATIVE``, see
``registration._codegen.cbackend``): ``native`` (-O3 -march=native, within ``NATIVE_RTOL`` of the
portable results on the filter's statistical scale) and ``native-exact`` (the same without
multiply-add fusion: bit for bit the portable results), all in this one run, printed with their
ratios to the portable build and, for the run's last step, the largest difference from the
portable build on that scale (``--no-native`` skips them; the first run builds the libraries).

With ``--ill`` the prior is ill conditioned (prior sigmas spanning 1e-9 rad to 1e4 m, no process
noise, so the condition number of P grows as the filter converges) and the script checks after
the run that every carried P of the Carlson step has a Cholesky factor and no NaN.
"""

from __future__ import annotations

import argparse
import platform
import time

import numpy as np
from common import add_arguments, interleave, median, paired_ratio, write

from registration import _codegen
from registration._codegen import cbackend, ckernel
from registration.online import RegistrationConfig
from registration.online.contract import DATA_COLUMNS, N_STATE
from registration.online.filter import STEP_CARRY
from registration.online.scenario import paper_scenario

AIM_US = 1.0
UPDATES = ("joseph", "carlson")


def tiled_rows(n: int, seed: int) -> np.ndarray:
    """(n, 18) rows: the paper scenario's rows repeated."""
    base = paper_scenario(seed).data
    rows = np.stack([np.asarray(base[c]) for c in DATA_COLUMNS[1:]], axis=1)
    return np.ascontiguousarray(np.tile(rows, (-(-n // len(rows)), 1))[:n])


def inputs_of(config: RegistrationConfig, rows: np.ndarray) -> dict:
    return {
        "x": np.zeros(N_STATE),
        "P": np.diag(np.square(config.prior_sigma)),
        "info": np.zeros((N_STATE, N_STATE)),
        "Q": np.diag(np.square(config.q_sigma)),
        "row": rows,
        "sigma0": np.array(config.sigma0),
    }


def run(config: RegistrationConfig, rows: np.ndarray, keep_all: bool = False) -> dict:
    keep = () if keep_all else ("x_new", "P_new", "info_new", "nu", "S", "nis")
    return _codegen.get(config.step_name).scan(len(rows), STEP_CARRY, inputs_of(config, rows), keep_last=keep)


def time_steps(configs: dict, rows: np.ndarray, rounds: int) -> dict:
    """Median us per step over ``rounds`` interleaved rounds after one warm-up, per label, in
    wall time and (``cpu <label>``) in CPU time; the median of the rounds' ratios Joseph / Carlson."""
    cpu: dict = {}
    contenders = {label: (lambda c=cfg: run(c, rows)) for label, cfg in configs.items()}
    times, _ = interleave(contenders, rounds, cpu=cpu)
    return (
        {label: median(t) / len(rows) * 1e6 for label, t in times.items()}
        | {f"cpu {label}": median(t) / len(rows) * 1e6 for label, t in cpu.items()}
        | {"joseph/carlson": paired_ratio(times, "joseph", "carlson")}
    )


def kernel_run(config: RegistrationConfig, rows: np.ndarray, lib) -> dict:
    """The compiled scan of ``config``'s step from library ``lib``, only the last outputs kept
    (as :func:`run`, through the kernel directly so that several builds run in one process)."""
    fn = _codegen.get(config.step_name)
    work = _codegen.manifest()["functions"][fn.name]["work"]
    prepared = []
    for name, (r, c) in zip(fn.input_names, fn.input_shapes):
        a = np.asarray(inputs_of(config, rows)[name], dtype=np.float64)
        core = () if (r, c) == (1, 1) else ((r,) if c == 1 else (r, c))
        prepared.append((a, a.shape != core, core))
    outs = ckernel.CKernel(fn.name, work, lib).scan(
        prepared, len(rows), len(STEP_CARRY), [True] * len(fn.output_names), fn.output_shapes
    )
    return {
        name: buf.reshape(c, r).T if c > 1 else buf.reshape(-1)
        for name, buf, (r, c) in zip(fn.output_names, outs, fn.output_shapes)
    }


def time_builds(configs: dict, rows: np.ndarray, libs: dict, rounds: int) -> tuple[dict, dict]:
    """Median us per step over ``rounds`` interleaved rounds after one warm-up, per (label,
    build); and the median ratio portable / build per (label, build)."""
    contenders = {
        f"{label} {mode}": (lambda c=configs[label], lib=libs[mode]: kernel_run(c, rows, lib))
        for label in configs
        for mode in libs
    }
    times, _ = interleave(contenders, rounds)
    us = {
        (label, mode): median(times[f"{label} {mode}"]) / len(rows) * 1e6
        for label in configs
        for mode in libs
    }
    ratio = {
        (label, mode): paired_ratio(times, f"{label} portable", f"{label} {mode}")
        for label in configs
        for mode in libs
    }
    return us, ratio


def sigma_difference(ref: dict, other: dict) -> float:
    """Largest difference of the last step's x (in its sigmas) and P (in sqrt(P_ii P_jj))."""
    sx = np.sqrt(np.diag(ref["P_new"]))
    return max(
        float(np.max(np.abs(other["x_new"] - ref["x_new"]) / sx)), p_difference(ref["P_new"], other["P_new"])
    )


def native_table(rows: np.ndarray, rounds: int) -> dict:
    """Portable against the native builds, per step, per linearisation and covariance update."""
    cc = _codegen.compiler()
    if cc is None or cbackend.native_target(cc) is None:
        print("native builds: skipped (no C compiler accepting -march=native)")
        return {}
    figures = {}
    names = sorted(_codegen.manifest()["functions"])
    t0 = time.perf_counter()
    libs = {mode: cbackend.library_of(names, mode) for mode in cbackend.BUILD_MODES}
    print(
        f"\nbuilds for this CPU ({time.perf_counter() - t0:.1f} s to build or load): "
        + "; ".join(f"{m} {' '.join(cbackend.cflags(m))}" for m in cbackend.BUILD_MODES)
    )
    print(
        f"{'linearisation':14s} {'update':8s} {'portable us':>12s} {'native us':>10s} {'ratio':>6s} "
        f"{'exact us':>9s} "
        f"{'ratio':>6s} {'native d/sigma':>15s} {'exact d':>8s}"
    )
    for lin in _codegen.variants("linearization"):
        cfgs = {u: RegistrationConfig(linearization=lin, covariance_update=u) for u in UPDATES}
        us, ratio = time_builds(cfgs, rows, libs, rounds)
        for u, cfg in cfgs.items():
            ref = kernel_run(cfg, rows, libs["portable"])
            d_native = sigma_difference(ref, kernel_run(cfg, rows, libs["native"]))
            exact = kernel_run(cfg, rows, libs["native-exact"])
            same = all(np.array_equal(exact[k], ref[k]) for k in ref)
            p, n, e = us[u, "portable"], us[u, "native"], us[u, "native-exact"]
            rn, re = ratio[u, "native"], ratio[u, "native-exact"]
            print(
                f"{lin:14s} {u:8s} {p:12.3f} {n:10.3f} {rn:6.2f} {e:9.3f} {re:6.2f} {d_native:15.1e} "
                f"{'0 (same)' if same else 'DIFFERS':>8s}"
            )
            figures[f"{lin} {u}"] = {
                "us_per_step": {"portable": p, "native": n, "native-exact": e},
                "portable_over": {"native": rn, "native-exact": re},
                "native_difference_in_sigma": d_native,
                "exact_same_bits": same,
            }
    print(
        f"native d/sigma: the last step's largest difference from the portable build after {len(rows)} steps "
        f"(the stated per-step tolerance is {cbackend.NATIVE_RTOL:g}; over a run, differences may accumulate)"
    )
    return figures


def p_difference(a: np.ndarray, b: np.ndarray) -> float:
    """max |a - b| / sqrt(a_ii a_jj): the difference of two covariances on the scale of a."""
    d = np.sqrt(np.diag(a))
    return float(np.max(np.abs(a - b) / np.outer(d, d)))


def positive_definite_all(P: np.ndarray) -> tuple[bool, float]:
    """(every P in the (K, 12, 12) stack is finite and has a Cholesky factor, largest condition number)."""
    if not np.isfinite(P).all():
        return False, float("nan")
    try:
        np.linalg.cholesky(P)
    except np.linalg.LinAlgError:
        return False, float("nan")
    return True, float(np.linalg.cond(P[-1]))


def ill_config(update: str) -> RegistrationConfig:
    prior = (1e-9, 1e-9, 1e-9, 1e4, 1e-9, 1e-9) * 2
    return RegistrationConfig(
        linearization="fitted", prior_sigma=prior, q_sigma=(0.0,) * N_STATE, covariance_update=update
    )


def ill_run(update: str, rows: np.ndarray, chunk: int = 100_000) -> tuple[bool, float, float]:
    """The ill-conditioned run in chunks of ``chunk`` steps, x, P, info carried across chunks;
    returns (every P finite with a Cholesky factor, final cond(P), seconds)."""
    cfg = ill_config(update)
    fn = _codegen.get(cfg.step_name)
    inputs = inputs_of(cfg, rows[:0])
    ok, cond, t0 = True, float("nan"), time.perf_counter()
    for start in range(0, len(rows), chunk):
        inputs["row"] = rows[start : start + chunk]
        out = fn.scan(len(inputs["row"]), STEP_CARRY, inputs, keep_last=("info_new",))
        good, cond = positive_definite_all(out["P_new"])
        ok &= good
        if not good:
            break
        inputs.update(x=out["x_new"][-1], P=out["P_new"][-1], info=out["info_new"])
    return ok, cond, time.perf_counter() - t0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--steps", type=int, default=100_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--ill", action="store_true", help="also the ill-conditioned positive-definiteness check")
    ap.add_argument("--no-native", action="store_true", help="skip the builds for the local CPU")
    add_arguments(ap)
    args = ap.parse_args(argv)
    if args.tiny:  # the native builds take minutes to compile on a first run: left out
        args.steps, args.repeat, args.no_native = 1000, 1, True
    figures: dict = {"flags": " ".join(_codegen.CFLAGS), "portable": {}}
    rows = tiled_rows(args.steps, args.seed)
    print(
        f"{platform.machine()} {platform.processor() or ''} flags {' '.join(_codegen.CFLAGS)}; {args.steps} "
        "steps"
    )
    print(
        f"{'linearisation':14s} {'joseph us':>10s} {'carlson us':>11s} {'ratio':>6s} {'aim<=1us':>9s} "
        f"{'max dP (final)':>15s}"
    )
    for lin in _codegen.variants("linearization"):
        cfgs = {u: RegistrationConfig(linearization=lin, covariance_update=u) for u in UPDATES}
        us = time_steps(cfgs, rows, args.repeat)
        dP = p_difference(run(cfgs["joseph"], rows)["P_new"], run(cfgs["carlson"], rows)["P_new"])
        print(
            f"{lin:14s} {us['joseph']:10.3f} {us['carlson']:11.3f} {us['joseph/carlson']:6.2f} "
            f"{'met' if us['carlson'] <= AIM_US else 'NOT met':>9s} {dP:15.2e}"
        )
        figures["portable"][lin] = {**us, "max_dP_final": dP}
    if args.no_native:
        print("native builds: left out (--no-native or --tiny)")
    else:
        figures["native"] = native_table(rows, args.repeat)
    if args.ill:
        figures["ill"] = {}
        for update in UPDATES:
            ok, cond, sec = ill_run(update, rows)
            print(
                f"ill-conditioned {update}: {args.steps} steps in {sec:.2f} s, "
                f"every P finite with a Cholesky factor: {ok}; final cond(P) {cond:.2e}"
            )
            figures["ill"][update] = {"positive_definite": ok, "final_cond": cond, "seconds": sec}
    write("step", args, {"steps": args.steps, "repeat": args.repeat}, figures)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
