#!/usr/bin/env python3
"""Speed of the online registration loop (compiled Kalman step, batch register(), streaming
update()), against the same filter in plain NumPy.

Run from a checkout (the package installed, editable or not)::

    python3 benchmarks/bench_online.py                       # 300 rows and 10^5 rows, both filters
    python3 benchmarks/bench_online.py --long 20000 --json bench_online.json
    python3 benchmarks/bench_online.py --flags               # also the compiler-flags experiment
    REGISTRATION_NATIVE=1 python3 benchmarks/bench_online.py # with the build for this CPU (or =exact)

Data: the paper scenario's 300 rows (``paper_scenario(seed)``), tiled to ``--long`` rows (times
renumbered). Filters: ``RegistrationConfig(linearization=...)`` with ``paper`` (model at the raw
measurements) and ``fitted`` (the default), T ``standard``, Q ``fixed``. Contenders per filter,
at the same rows, median of ``--repeat`` interleaved rounds (A B C, C B A, ...) after one warm-up,
ratios the median of the rounds' ratios:

1. ``register()``, the whole batch call, and the compiled scan alone (its floor);
2. ``OnlineRegistrar.update(row)`` one call per row on the first ``--stream-rows`` rows, and the
   compiled stepper it calls, alone (``stepper.step`` in a loop: the C step plus one ctypes
   call); update() minus that is its Python bookkeeping;
3. ``NumpyFilter``: the same filter in NumPy, written here; only the generated pair model
   (``pseudo_measurement_standard``) is called, per row through ``GeneratedFunction.bind()``
   (``numpy (per-row model)``) or, for ``paper`` only, for all rows up front (``numpy (model
   vectorised)``; the ``fitted`` point depends on the state, so it cannot be).

Every baseline is first checked against ``register()`` to 1e-9 relative. Aims: <= 5 us per row
for ``register()`` amortised and for ``update()``; ``register()`` >= 20x the strongest NumPy
baseline; the script says whether each is met, prints where ``register()``'s and ``update()``'s
time goes (cProfile) and, with ``--flags``, the generated step in a plain C loop built with the
loader's flags and with ``-O3 -march=native``. Every figure goes to benchmarks/results/online.json
(or ``--json FILE``); ``--tiny`` runs in seconds on 1000 rows, to check the script works.
"""

from __future__ import annotations

import argparse
import os
import platform
import sys

import numpy as np
from common import add_arguments, interleave, median, paired_ratio, write
from online_baseline import NumpyFilter  # noqa: E402 (a script beside this one)

import registration
from registration import _codegen
from registration._codegen import cbackend
from registration.online import OnlineRegistrar, RegistrationConfig, register
from registration.online.contract import DATA_COLUMNS, N_STATE
from registration.online.filter import ROW_HIGH, ROW_LOW, STEP_CARRY
from registration.online.scenario import paper_scenario

AIM_US_PER_STEP = 5.0
AIM_RATIO = 20.0
TOLERANCE = 1e-9


# --------------------------------------------------------------------------- data
def scenario_data(n_rows: int, seed: int) -> dict:
    """The paper scenario's 300 rows, tiled to ``n_rows`` rows with increasing timestamps."""
    base = paper_scenario(seed).data
    k = len(base["time"])
    reps = -(-n_rows // k)
    data = {c: np.tile(np.asarray(base[c]), reps)[:n_rows].copy() for c in DATA_COLUMNS[1:]}
    data["time"] = np.arange(n_rows, dtype=float)
    return data


def rows_of(data: dict) -> np.ndarray:
    return np.ascontiguousarray(np.stack([data[c] for c in DATA_COLUMNS[1:]], axis=1))


def compare(reference, other) -> dict:
    """Largest relative difference per output: per state, relative to the largest |value| of that
    state's series (for P: of its diagonal), so tiny cross terms do not inflate the figure."""

    def rel(a, b, scale):
        return float(np.max(np.abs(a - b) / scale))

    sx = np.max(np.abs(reference.estimates), axis=0)
    sx = np.where(sx > 0, sx, 1.0)
    d = np.sqrt(np.max(np.einsum("kii->ki", reference.covariances), axis=0))
    sP = d[:, None] * d[None, :]
    return {
        "estimates": rel(reference.estimates, other["x"], sx[None, :]),
        "covariances": rel(reference.covariances, other["P"], sP[None]),
        "nis": rel(reference.nis, other["nis"], max(1.0, float(np.max(np.abs(reference.nis))))),
        "information": rel(reference.information, other["info"], np.max(np.abs(reference.information))),
    }


# --------------------------------------------------------------------------- timing
def measure(
    contenders: dict, rounds: int, warm: frozenset = frozenset(), cpu: dict | None = None
) -> tuple[dict, dict]:
    """Median seconds per contender over ``rounds`` interleaved rounds (common.interleave) after
    one untimed warm-up (skipped for the labels in ``warm``: already run just before, by the
    correctness check), and every round's seconds (the spread: this machine may be shared);
    ``cpu`` receives every round's CPU seconds."""
    for label, fn in contenders.items():
        if label not in warm:
            fn()
    times, _ = interleave(contenders, rounds, warmup=0, cpu=cpu)
    return {label: median(t) for label, t in times.items()}, times


def streaming(config, rows):
    def go():
        reg = OnlineRegistrar(config)
        for i in range(len(rows)):
            reg.update(rows[i])
        return reg

    return go


def stepper_only(config, rows):
    """The compiled stepper update() calls, alone (made as update() makes it): one ctypes call per row."""

    def go():
        st = _codegen.get(config.step_name).stepper(
            STEP_CARRY,
            "row",
            low=ROW_LOW,
            high=ROW_HIGH,
            finite=("x_new", "P_new"),
            deliver=("x_new", "P_new", "nu", "S", "nis"),
        )
        start = OnlineRegistrar(config)
        for name, value in (
            ("x", start.x),
            ("P", start.P),
            ("info", start.info),
            ("Q", start.process_noise()),
            ("sigma0", np.array(config.sigma0)),
        ):
            st.set(name, value)
        step = st.step
        for i in range(len(rows)):
            step(rows[i])

    return go


def scan_only(config, rows):
    """The compiled scan of the generated Kalman step alone (what register() runs for q_mode fixed)."""
    step = _codegen.get(config.step_name)
    inputs = {
        "x": np.zeros(N_STATE) if config.x0 is None else np.array(config.x0),
        "P": np.diag(np.square(config.prior_sigma)),
        "info": np.zeros((N_STATE, N_STATE)),
        "Q": np.diag(np.square(config.q_sigma)),
        "row": rows,
        "sigma0": np.array(config.sigma0),
    }
    carry = {"x": "x_new", "P": "P_new", "info": "info_new"}  # the step's mapaccum convention

    def go():
        return step.scan(len(rows), carry, inputs, keep_last=("info_new",))

    return go


def profile_breakdown(fn, calls: int, per: int, top: int = 8) -> list[tuple[str, float]]:
    """Where ``fn``'s time goes: cProfile over ``calls`` calls, the callees with the largest
    cumulative time, in us per row (``per`` rows per call). The profiler's own overhead inflates
    Python-heavy parts; the shares, not the absolute figures, are the point."""
    import cProfile
    import pstats

    prof = cProfile.Profile()
    prof.enable()
    for _ in range(calls):
        fn()
    prof.disable()
    stats = pstats.Stats(prof).stats
    total = sum(v[2] for v in stats.values())  # total own time
    rows = []
    for (file, line, name), (_, _, _, cum, _) in stats.items():
        if (
            "registration" in file
            or "numpy" in file
            or name.startswith("<built-in")
            or name.startswith("<method")
        ):
            short = f"{file.split('/')[-1]}:{name}" if not file.startswith("~") else name
            rows.append((short, cum / (calls * per) * 1e6))
    rows.sort(key=lambda t: -t[1])
    return [("total (profiled)", total / (calls * per) * 1e6)] + rows[1 : top + 1]


# --------------------------------------------------------------------------- main
VECTORISED, PER_ROW = "numpy (model vectorised)", "numpy (per-row model)"
BATCH, SCAN = "register() (batch, whole call)", "compiled scan alone"
UPDATE, STEPPER = "OnlineRegistrar.update() per row", "compiled stepper alone, per row"


def bench_size(n_rows: int, seed: int, rounds: int, stream_rows: int, config) -> dict:
    data = scenario_data(n_rows, seed)
    rows = rows_of(data)
    base = NumpyFilter(config)
    flavours = {VECTORISED: True, PER_ROW: False}
    flavours = {k: v for k, v in flavours.items() if v in base.flavours}

    # correctness first: the baselines must compute what register() computes
    ref = register(data, config)
    diffs = {}
    for label, vec in flavours.items():
        d = compare(ref, base.run(rows, vec))
        diffs[label] = d
        if max(d.values()) > TOLERANCE:
            raise SystemExit(
                f"{config.linearization}, {label}: differs from register() by {d} (relative) > {TOLERANCE}: "
                "not the same filter"
            )

    contenders = {BATCH: lambda: register(data, config), SCAN: scan_only(config, rows)}
    for label, vec in flavours.items():
        contenders[label] = (lambda v: lambda: base.run(rows, v))(vec)
    n_stream = min(stream_rows, n_rows)
    contenders[UPDATE] = streaming(config, rows[:n_stream])
    contenders[STEPPER] = stepper_only(config, rows[:n_stream])
    # the baselines' last run (the check) is their warm-up: at 10^5 rows a per-row run takes seconds
    cpu: dict = {}
    mid, times = measure(contenders, rounds, warm=frozenset([BATCH, *flavours]), cpu=cpu)
    per = {k: (n_stream if k in (UPDATE, STEPPER) else n_rows) / 1e6 for k in mid}
    per_row = {k: [x / per[k] for x in t] for k, t in times.items()}
    spread = {
        k: [float(np.min(t)) / per[k], float(np.median(t)) / per[k], float(np.max(t)) / per[k]]
        for k, t in times.items()
    }
    return {
        "rows": n_rows,
        "stream_rows": n_stream,
        "seconds": mid,
        "us_per_step": {k: v / per[k] for k, v in mid.items()},
        "us_per_step_best_median_worst": spread,
        "cpu_us_per_step": {k: median(t) / per[k] for k, t in cpu.items()},
        "ratio_over_batch": {k: paired_ratio(per_row, k, BATCH) for k in per_row},
        "ratio_over_scan": {k: paired_ratio(per_row, k, SCAN) for k in per_row},
        "max_relative_difference_vs_register": diffs,
    }


def aims_of(results: dict, long_n: int, linearization: str) -> dict:
    """The aims for one configuration, at 300 rows and at the long run.

    The ratio is taken against the strongest NumPy baseline the linearisation admits: the
    vectorised one for ``paper``; for ``fitted`` the per-row one (its linearisation point
    depends on the state, so its model cannot be evaluated up front)."""
    strongest = VECTORISED if linearization == "paper" else PER_ROW
    long, short = results[str(long_n)]["us_per_step"], results["300"]["us_per_step"]
    long_ratio, short_ratio = (results[k]["ratio_over_batch"] for k in (str(long_n), "300"))
    long_scan_ratio = results[str(long_n)]["ratio_over_scan"]
    aims = {
        "strongest_numpy_baseline": strongest,
        "batch_us_per_step_long": long[BATCH],
        "batch_us_per_step_300": short[BATCH],
        "scan_us_per_step_long": long[SCAN],
        "aim_us_per_step": AIM_US_PER_STEP,
        "met_us_per_step_long": long[BATCH] <= AIM_US_PER_STEP,
        "met_us_per_step_300": short[BATCH] <= AIM_US_PER_STEP,
        "ratio_vs_strongest_numpy_long": long_ratio[strongest],
        "ratio_vs_strongest_numpy_300": short_ratio[strongest],
        "scan_ratio_vs_strongest_numpy_long": long_scan_ratio[strongest],
        "ratio_vs_per_row_numpy_long": long_ratio[PER_ROW],
        "scan_ratio_vs_per_row_numpy_long": long_scan_ratio[PER_ROW],
        "aim_ratio": AIM_RATIO,
        "update_us_per_step_long": long[UPDATE],
        "update_over_scan_long": long_scan_ratio[UPDATE],
        "update_python_us_per_step_long": long[UPDATE] - long[STEPPER],
        "met_update_us_per_step_long": long[UPDATE] <= AIM_US_PER_STEP,
    }
    aims["met_ratio_long"] = aims["ratio_vs_strongest_numpy_long"] >= AIM_RATIO
    aims["met_ratio_300"] = aims["ratio_vs_strongest_numpy_300"] >= AIM_RATIO
    return aims


def print_aims(aims: dict, long_n: int, linearization: str) -> None:
    yes = {True: "met", False: "NOT met"}
    why = (
        "model vectorised up front"
        if linearization == "paper"
        else "per-row model: the fitted linearisation point depends on the state, so no NumPy code "
        "can evaluate the model up front"
    )
    print(f"Aims, linearization {linearization}:")
    print(
        f"  <= {AIM_US_PER_STEP} us/step amortised, batch register(): {long_n} rows "
        f"{aims['batch_us_per_step_long']:.2f} us "
        f"({yes[aims['met_us_per_step_long']]}); 300 rows {aims['batch_us_per_step_300']:.2f} us "
        f"({yes[aims['met_us_per_step_300']]})"
    )
    print(f"  >= {AIM_RATIO:.0f}x the strongest NumPy baseline ({why}):")
    print(
        f"     register(): {long_n} rows {aims['ratio_vs_strongest_numpy_long']:.1f}x "
        f"({yes[aims['met_ratio_long']]}); "
        f"300 rows {aims['ratio_vs_strongest_numpy_300']:.1f}x ({yes[aims['met_ratio_300']]}); "
        f"the compiled scan alone {aims['scan_ratio_vs_strongest_numpy_long']:.1f}x"
    )
    if linearization == "paper":
        print(
            f"     against the per-row NumPy filter: register() {aims['ratio_vs_per_row_numpy_long']:.1f}x, "
            f"the compiled scan alone {aims['scan_ratio_vs_per_row_numpy_long']:.1f}x"
        )
    print(
        f"  <= {AIM_US_PER_STEP} us/row for update(): {aims['update_us_per_step_long']:.2f} us "
        f"({yes[aims['met_update_us_per_step_long']]}), {aims['update_over_scan_long']:.2f}x the compiled "
        "scan's step; "
        f"Python around the compiled stepper {aims['update_python_us_per_step_long']:.2f} us"
    )


def machine_line() -> str:
    cpu = platform.processor() or ""
    try:
        with open("/proc/cpuinfo") as fh:
            cpu = next((ln.split(":", 1)[1].strip() for ln in fh if ln.startswith("model name")), cpu)
    except OSError:
        pass
    return (
        f"registration {registration.__version__}, backend {_codegen.backend()} ({cbackend.build_mode()} "
        "build), "
        f"numpy {np.__version__}, "
        f"python {platform.python_version()}, {platform.machine()} {cpu}, {os.cpu_count()} CPUs"
    ).replace("  ", " ")


def run_configs(configs: dict, default: str, args) -> dict:
    """Every contender at 300 rows and at the long run, per configuration, with the aims."""
    per_config = {}
    for lin, config in configs.items():
        print(
            f"\n=== linearization {lin}{' (the default)' if lin == default else ''}: {config.step_name} ===\n"
        )
        results = {}
        for n in (300, args.long):
            r = results[str(n)] = bench_size(n, args.seed, args.repeat, args.stream_rows, config)
            us = r["us_per_step"]
            print(
                f"{n} rows (NumPy baselines equal register() to "
                f"{max(max(d.values()) for d in r['max_relative_difference_vs_register'].values()):.1e} "
                "relative)"
            )
            print(
                f"  {'contender':<40}{'us/step':>10}{'time / register()':>19}{'time / scan':>13}"
                f"{'best, worst of ' + str(args.repeat):>24}"
            )
            for label, v in us.items():
                best, _, worst = r["us_per_step_best_median_worst"][label]
                rb, rs = r["ratio_over_batch"][label], r["ratio_over_scan"][label]
                print(f"  {label:<40}{v:10.2f}{rb:18.1f}x{rs:12.1f}x{best:14.2f}{worst:10.2f}")
            print()
        aims = aims_of(results, args.long, lin)
        print_aims(aims, args.long, lin)
        per_config[lin] = {"config": config.to_json(), "results": results, "aims": aims}
    lp, lf = (per_config[k]["results"][str(args.long)]["us_per_step"] for k in ("paper", "fitted"))
    print(
        f"\nfitted / paper cost, {args.long} rows: register() {lf[BATCH] / lp[BATCH]:.2f}x, compiled scan "
        f"{lf[SCAN] / lp[SCAN]:.2f}x, per-row NumPy {lf[PER_ROW] / lp[PER_ROW]:.2f}x\n"
    )
    pair = _codegen.get("pseudo_measurement_standard").casadi.n_instructions()
    for lin, cfg in configs.items():
        n_ins = _codegen.get(cfg.step_name).casadi.n_instructions()
        scan_us = per_config[lin]["results"][str(args.long)]["us_per_step"][SCAN]
        part = (
            f"the pseudo-measurement ({pair}) once"
            if lin == "paper"
            else f"the pseudo-measurement ({pair}) twice, before common subexpressions, plus the MAP plots"
        )
        print(
            f"{cfg.step_name}: {n_ins} CasADi instructions per step ({part}; the Kalman algebra the rest), "
            f"{scan_us:.2f} us per step in the scan: {n_ins / scan_us / 1e3:.1f} G instructions/s."
        )
    return per_config


def profiles(config, data_long: dict, seed: int) -> dict:
    """Where register()'s and update()'s time goes (cProfile; its overhead inflates the
    Python-heavy parts)."""
    data300 = scenario_data(300, seed)
    out = {
        "register_profile_us_per_row_300": profile_breakdown(lambda: register(data300, config), 20, 300),
        "register_profile_us_per_row_long": profile_breakdown(
            lambda: register(data_long, config), 1, len(data_long["time"])
        ),
        "update_profile_us_per_row_300": profile_breakdown(streaming(config, rows_of(data300)), 3, 300),
    }
    titles = (
        "register() on 300 rows",
        f"register() on {len(data_long['time'])} rows",
        "OnlineRegistrar.update() on 300 rows",
    )
    print(f"\nProfile of the default configuration ({config.linearization}):")
    for title, rows in zip(titles, out.values()):
        print(f"{title}, by callee (cProfile, cumulative us per row):")
        for k, v in rows:
            print(f"  {k:<52}{v:10.2f}")
    return {k: dict(v) for k, v in out.items()}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "--long", type=int, default=100_000, help="rows of the long run (tiled scenario; default 10^5)"
    )
    ap.add_argument(
        "--stream-rows",
        type=int,
        default=20_000,
        help="rows fed to OnlineRegistrar.update() in the long run (default 2*10^4)",
    )
    ap.add_argument(
        "--repeat", type=int, default=3, help="timed rounds per contender, interleaved (default 3)"
    )
    ap.add_argument("--seed", type=int, default=0)
    add_arguments(ap)
    ap.add_argument(
        "--flags",
        action="store_true",
        help="also time each configuration's generated step in a plain C loop built with the loader's "
        "flags and with -O3 -march=native",
    )
    args = ap.parse_args(argv)
    if args.tiny:
        args.long, args.stream_rows, args.repeat = 1000, 300, 1
    default = RegistrationConfig().linearization
    configs = {
        lin: RegistrationConfig(linearization=lin) for lin in ("paper", "fitted")
    }  # standard T, fixed Q
    print(machine_line())
    print(
        f"configurations: {', '.join(f'{lin} ({c.step_name})' for lin, c in configs.items())}; "
        f"default RegistrationConfig(): {default}; q_mode fixed; median of {args.repeat} interleaved rounds"
    )
    data_long = scenario_data(args.long, args.seed)
    per_config = run_configs(configs, default, args)
    profile = profiles(configs[default], data_long, args.seed)
    if args.flags:
        from online_flags import flags_experiment

        for lin, cfg in configs.items():
            if args.tiny and lin != default:
                print(f"\n--tiny: the flags experiment of {lin} left out (the default's only)")
                continue
            flags = flags_experiment(
                cfg, rows_of(data_long), register(data_long, cfg).estimates[-1, 3], args.repeat
            )
            per_config[lin]["plain_c_us_per_step"] = flags
            print(
                f"\n{cfg.step_name} in a plain C loop ({args.long} rows, results checked against register()):"
            )
            for k, v in flags.items():
                print(f"  {k:<52}{'build failed' if v is None else f'{v:10.2f}'}")
    sizes = {"rows": [300, args.long], "stream_rows": args.stream_rows, "repeat": args.repeat}
    figures = {
        "line": machine_line(),
        "backend": _codegen.backend(),
        "default_linearization": default,
        "configs": per_config,
        "profile_config": default,
        **profile,
    }
    write("online", args, sizes, figures)
    return 0


if __name__ == "__main__":
    sys.exit(main())
