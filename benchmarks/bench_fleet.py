#!/usr/bin/env python3
"""Speed of batch fleet registration against scipy.optimize.least_squares on the same residuals.

Run from a checkout::

    python3 benchmarks/bench_fleet.py                 # 8 sensors x 10 targets x 1000 s at 1 Hz
    python3 benchmarks/bench_fleet.py --duration 200 --repeats 5 --json out.json
    python3 benchmarks/bench_fleet.py --tiny          # seconds: does it still run?

Problem: the default fleet's three ships and shore site with eight sensors, each sampling every
target once a second at its own time offset (80 000 plots over 1000 s; 3-D and 2-D radars and
a passive angle sensor), ten targets (one reference), errors of 1 deg and 300 m, 20 s cubic
target windows. Both solvers start from the same point (zero errors, the window means of the plot
positions, i.e. after :mod:`registration.fleet.batch.initial`) and minimise the same sum of squares of
whitened residuals (plots, reference positions; no priors): the residuals and the sparse Jacobian
given to least_squares are the rows of the generated ``fleet_rows_4`` (the function the batch
solver uses), over the free states and the active window coefficients. least_squares runs its
trust-region reflective method with the LSMR sub-solver (the only choice for 6000 unknowns; the
dense one would hold a 240 000 x 6000 Jacobian). Attempts, in order, until one reaches the
batch optimum (states within SAME_OPTIMUM_SIGMA batch sigmas, sum of squares within
SAME_OPTIMUM_COST):

1. all defaults (tolerances 1e-8; LSMR's own tolerances 1e-6, so its steps are inexact);
2. the default tolerances with LSMR solving to 1e-10 (on 100 s of data this reaches the optimum
   to 3e-4 sigma in 5 evaluations, where attempt 1 stops 0.03 sigma away);
3. tolerances 1e-10 and LSMR to 1e-10.

Every attempt is printed (at most MAX_NFEV evaluations each); the first attempt that reached the
optimum is the one timed against the batch solver.

Timed, interleaved over ``--repeats`` rounds (common.interleave; figures are medians, ratios the
median of the rounds' ratios): :func:`registration.fleet.solve_batch` end to end (checks,
windows, both Levenberg-Marquardt phases, covariance, fused targets, observability), the solver
alone (the two phases, from the same start as least_squares), and least_squares. Before the ratio
is printed both optima are compared: the costs, and the states in units of the batch sigma. The
machine's load average is printed too. Figures: benchmarks/results/fleet.json.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from common import add_arguments, interleave, median, paired_ratio, summary, write
from scipy import sparse
from scipy.optimize import least_squares

from registration.fleet import BatchOptions, fleet_scenario, solve_batch
from registration.fleet.batch.blocks import make_blocks
from registration.fleet.batch.design import make_design
from registration.fleet.batch.initial import initial_coefficients
from registration.fleet.batch.normal import evaluate
from registration.fleet.batch.solver import fit
from registration.fleet.simulation.scenario import SHIPS, SITE, TARGETS, FleetConfig
from registration.fleet.simulation.tracks import Circle, Line

SENSORS_8 = {
    "A-3D": ("A", (25.0, np.radians(0.15), np.radians(0.2)), 1.0, 0.0, (0.0, 20.0, 25.0)),
    "A-ESM": ("A", (np.nan, np.radians(0.3), np.radians(0.3)), 1.0, 0.35, (2.0, 5.0, 30.0)),
    "B-3D": ("B", (30.0, np.radians(0.2), np.radians(0.25)), 1.0, 0.83, (0.0, 15.0, 20.0)),
    "B-2D": ("B", (40.0, np.radians(0.2), np.nan), 1.0, 0.11, (0.0, -10.0, 18.0)),
    "C-3D": ("C", (20.0, np.radians(0.1), np.radians(0.15)), 1.0, 0.21, (0.0, 25.0, 30.0)),
    "C-2D": ("C", (40.0, np.radians(0.25), np.nan), 1.0, 0.62, (0.0, -30.0, 22.0)),
    "S-2D": ("S", (30.0, np.radians(0.1), np.nan), 1.0, 0.47, (0.0, 0.0, 10.0)),
    "S-3D": ("S", (30.0, np.radians(0.1), np.radians(0.1)), 1.0, 0.93, (0.0, 5.0, 12.0)),
}
TARGETS_10 = {
    **TARGETS,
    "T6": Line(40e3, -40e3, np.radians(300.0), 200.0, 6000.0),
    "T7": Circle(-25e3, 5e3, 6e3, 120.0, 2000.0, 1.0),
    "T8": Line(-50e3, -10e3, np.radians(80.0), 15.0, 5.0),
    "T9": Circle(30e3, 30e3, 12e3, 230.0, 9000.0, 5.0),
    "T10": Line(0.0, -45e3, np.radians(10.0), 250.0, 10000.0),
}
CONFIG = FleetConfig(SHIPS, SITE, SENSORS_8, TARGETS_10, "T1")
#: Both solvers reached the same optimum when their states differ by less than this many batch
#: sigmas and their sums of squares by less than this (chi-square units).
SAME_OPTIMUM_SIGMA = 0.05
SAME_OPTIMUM_COST = 0.1
MAX_NFEV = 200


def scipy_problem(design, free):
    """Residual and sparse-Jacobian callables over [free states, active coefficients]."""
    blk = design.blocks
    q = 3 * blk.n_coef
    active = np.flatnonzero(np.repeat(blk.coef_mask, 3, axis=1).reshape(-1))  # of the B*q coefficients
    rows = np.flatnonzero(design.weight.reshape(-1) > 0)  # measured (plot, channel) rows
    plot_of_row = rows // 3
    col_of_coef = np.full(blk.n_blocks * q, -1)
    col_of_coef[active] = free.size + np.arange(active.size)
    state_col = np.full(design.n_state + 1, -1)
    state_col[free] = np.arange(free.size)
    coef_cols = col_of_coef[(design.block[plot_of_row, None] * q + np.arange(q)[None, :])]  # (R, q)
    state_cols = state_col[
        np.concatenate([design.att_state, design.bias_state], axis=1)[plot_of_row]
    ]  # (R, 6)
    n_ref = design.ref_p.shape[0]
    ref_cols = col_of_coef[blk.ref_block[:, None] * q + np.arange(q)[None, :]]  # (R', q)
    n_cols = free.size + active.size

    def unpack(theta):
        x = np.zeros(design.n_state)
        x[free] = theta[: free.size]
        c = np.zeros(blk.n_blocks * q)
        c[active] = theta[free.size :]
        return x, c.reshape(blk.n_blocks, blk.n_coef, 3)

    cache = {}

    def residuals(theta):
        ev = evaluate(design, *unpack(theta))
        cache["ev"], cache["theta"] = ev, theta.copy()
        return np.concatenate([ev.e.reshape(-1)[rows], ev.e_ref.reshape(-1)])

    def jacobian(theta):
        ev = cache["ev"] if np.array_equal(cache.get("theta"), theta) else evaluate(design, *unpack(theta))
        Z = ev.Z.reshape(-1, ev.Z.shape[2])[rows]  # (R, q + 7)
        values = [Z[:, :q], Z[:, q : q + 6]]
        cols = [coef_cols, state_cols]
        r_idx = [np.repeat(np.arange(rows.size), q), np.repeat(np.arange(rows.size), 6)]
        # reference residuals (y - p) w: d/dc = -basis w (per axis)
        ref_rows = rows.size + np.arange(3 * n_ref).reshape(n_ref, 3)
        for a in range(3):
            vals = -(
                blk.ref_basis[:, :, None] * design.ref_weight[:, None, None] * np.eye(3)[a][None, None, :]
            ).reshape(n_ref, q)
            values.append(vals)
            cols.append(ref_cols)
            r_idx.append(np.repeat(ref_rows[:, a], q))
        v = np.concatenate([x.reshape(-1) for x in values])
        c = np.concatenate([x.reshape(-1) for x in cols])
        r = np.concatenate(r_idx)
        keep = (c >= 0) & (v != 0)
        return sparse.csr_matrix((v[keep], (r[keep], c[keep])), shape=(rows.size + 3 * n_ref, n_cols))

    return residuals, jacobian, unpack


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "--duration", type=float, default=1000.0, help="seconds of data (1 Hz per sensor and target)"
    )
    parser.add_argument("--repeats", type=int, default=3, help="interleaved rounds")
    add_arguments(parser)
    args = parser.parse_args(argv)
    if args.tiny:
        args.duration, args.repeats = 20.0, 1

    sc = fleet_scenario(3, duration_s=args.duration, config=CONFIG)
    problem = sc.problem()
    options = BatchOptions()
    result = solve_batch(problem, options)  # warm-up: compiled library, scipy.stats import
    fitted = fit(problem, options)

    design = make_design(problem, make_blocks(problem, options.window_s, options.degree))
    free = problem.layout.free
    residuals, jacobian, unpack = scipy_problem(design, free)
    theta0 = np.concatenate(
        [
            np.zeros(free.size),
            initial_coefficients(design).reshape(-1)[
                np.flatnonzero(np.repeat(design.blocks.coef_mask, 3, axis=1).reshape(-1))
            ],
        ]
    )
    cost_batch = float(fitted.evaluation.cost)
    sizes = {
        "duration_s": args.duration,
        "plots": problem.n_plots,
        "states": int(free.size),
        "windows": design.blocks.n_blocks,
        "repeats": args.repeats,
    }
    out = {
        "load_average_before": os.getloadavg(),
        "OPENBLAS_NUM_THREADS": os.environ.get("OPENBLAS_NUM_THREADS"),
        "batch_iterations": fitted.iterations,
        "cost_batch": cost_batch,
        "least_squares": [],
    }
    contenders = {"solve_batch": lambda: solve_batch(problem, options), "fit": lambda: fit(problem, options)}
    for tol, lsmr_tol in ((1e-8, None), (1e-8, 1e-10), (1e-10, 1e-10)):
        tr_options = {} if lsmr_tol is None else {"atol": lsmr_tol, "btol": lsmr_tol}

        def run_least_squares(tol=tol, tr_options=tr_options):
            return least_squares(
                residuals,
                theta0,
                jac=jacobian,
                method="trf",
                tr_solver="lsmr",
                x_scale="jac",
                ftol=tol,
                xtol=tol,
                gtol=tol,
                tr_options=tr_options,
                max_nfev=MAX_NFEV,
            )

        ls, t_ls = _timed(run_least_squares)
        x_ls, _ = unpack(ls.x)
        attempt = {
            "tolerance": tol,
            "lsmr_tolerance": lsmr_tol,
            "seconds": t_ls,
            "nfev": int(ls.nfev),
            "status": int(ls.status),
            "cost": float(2 * ls.cost),
            "max_state_difference_in_sigma": float(
                np.abs((x_ls - result.estimate)[free] / result.sigma[free]).max()
            ),
        }
        attempt["same_optimum"] = bool(
            attempt["max_state_difference_in_sigma"] < SAME_OPTIMUM_SIGMA
            and abs(attempt["cost"] - cost_batch) < SAME_OPTIMUM_COST
        )
        out["least_squares"].append(attempt)
        print("least_squares", attempt, flush=True)
        if attempt["same_optimum"]:
            contenders["least_squares"] = run_least_squares
            break
    # the attempt just run is the warm-up of least_squares; solve_batch and fit ran above
    cpu: dict[str, list[float]] = {}
    times, _ = interleave(contenders, args.repeats, warmup=0, cpu=cpu)
    out["seconds"] = summary(times)
    out["cpu_seconds"] = summary(cpu)
    out["solve_batch_s"] = median(times["solve_batch"])
    out["solver_only_s"] = median(times["fit"])
    if "least_squares" in times:
        out["ratio_least_squares_over_solver"] = paired_ratio(times, "least_squares", "fit")
        out["ratio_least_squares_over_solve_batch"] = paired_ratio(times, "least_squares", "solve_batch")
        out["cpu_ratio_least_squares_over_solver"] = paired_ratio(cpu, "least_squares", "fit")
        out["cpu_ratio_least_squares_over_solve_batch"] = paired_ratio(cpu, "least_squares", "solve_batch")
    out["load_average_after"] = os.getloadavg()
    for key, value in {**sizes, **out}.items():
        if key != "least_squares":
            print(f"{key:36s} {value}")
    write("fleet", args, sizes, out)
    return out


def _timed(fn):
    t0 = time.perf_counter()
    value = fn()
    return value, time.perf_counter() - t0


if __name__ == "__main__":
    main()
