"""``registration fuse``: the paper's dissimilar-dimension fusion scenarios, with honest rows beside them.

Prints one table (analytic and Monte Carlo GDOP per estimator, beside the paper's figure) and writes into
``--out DIR`` (default ``out/fuse``) ``summary.json``, ``measurements.png`` (like the paper's Fig. 3/5:
geometry, radar points and pseudo-measurement points) and ``fused.png`` (like Fig. 4/6: fused points of
the paper's method and of the optimal fuser), all with 2-sigma covariance ellipses.

Units at this edge: metres, degrees (``_deg``) for positions of the target, milliradians
(``_mrad``) for angle standard deviations (the paper quotes them in mrad).
"""

from __future__ import annotations

import argparse

import numpy as np

from registration.cli.errors import prepare_out, writing
from registration.cli.options import add_no_plots, add_out, add_seed
from registration.cli.staging import staged_outputs
from registration.fusion import COMPONENTS, parse_components
from registration.fusion.evaluation import ROW_LABELS, FusionEvaluation, evaluate
from registration.fusion.scenarios import paper_scenario
from registration.io.files.jsonfile import write_json

#: What `registration fuse` writes into --out (the outputs of an earlier run there are replaced whole).
FUSE_OUTPUTS = frozenset({"summary.json", "measurements.png", "fused.png"})

HELP = (
    "fuse a radar with a remote bearing-only or range-only sensor (paper scenarios 1 and 2): GDOP, CRLB, "
    "optimal fuser"
)


def _per_scenario(value) -> str:
    """``default: scenario 1 X, scenario 2 Y`` for a parameter
    ``value(scenario)`` (number or text) of the paper's scenarios."""

    def text(v) -> str:
        return v if isinstance(v, str) else f"{v:g}"

    return "default: " + ", ".join(f"scenario {n} {text(value(paper_scenario(n)))}" for n in (1, 2))


def _second_sigma(component: str, scale: float):
    """The second sensor's standard deviation of ``component`` times ``scale``, or 'not measured'."""

    def value(sc):
        sig = dict(zip(sc.components, sc.sigma_second))
        return float(sig[component]) * scale if component in sig else "not measured"

    return value


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--scenario",
        type=int,
        choices=(1, 2),
        default=1,
        help="the paper's scenario: 1 radar + passive bearing sensor, 2 radar + laser range finder; "
        "the options below override its parameters",
    )
    parser.add_argument(
        "--trials",
        type=int,
        default=1000,
        metavar="N",
        help="Monte Carlo measurement pairs (the paper's count; at least 2)",
    )
    add_seed(parser, 0, "random seed of the measurement noise")
    add_out(parser, "fuse", "summary.json, measurements.png and fused.png")
    add_no_plots(parser)
    parser.add_argument(
        "--max-plot-points", type=int, default=2000, metavar="N", help="points drawn per set in the plots"
    )
    _add_geometry_options(parser)
    _add_sensor_options(parser)


def _add_geometry_options(parser: argparse.ArgumentParser) -> None:
    """Where the second site and the target lie (default: the scenario's)."""
    g = parser.add_argument_group("geometry (radar A at the origin, azimuth counter-clockwise from +x)")
    g.add_argument(
        "--baseline-m",
        type=float,
        default=None,
        metavar="M",
        help="second site B at (L, 0[, 0]) metres; " + _per_scenario(lambda sc: sc.site_second_loc[0]),
    )
    g.add_argument(
        "--site-second-m",
        type=float,
        nargs="+",
        default=None,
        metavar="XYZ",
        help="second site B anywhere: X Y [Z] metres (Z only in 3-D); default: on the x axis (--baseline-m)",
    )
    g.add_argument(
        "--target-range-m",
        type=float,
        default=None,
        metavar="M",
        help="true target range from the radar, m; " + _per_scenario(lambda sc: sc.target_polar[0]),
    )
    g.add_argument(
        "--target-azimuth-deg",
        type=float,
        default=None,
        metavar="DEG",
        help="true target azimuth from the radar, deg; "
        + _per_scenario(lambda sc: np.degrees(sc.target_polar[1])),
    )
    g.add_argument(
        "--target-elevation-deg",
        type=float,
        default=None,
        metavar="DEG",
        help="true target elevation from the radar, deg; giving it makes the problem 3-D; default: 2-D",
    )


def _add_sensor_options(parser: argparse.ArgumentParser) -> None:
    """The radar's and the second sensor's noise, and what the second sensor measures (default: the
    scenario's)."""
    s = parser.add_argument_group("sensors")
    s.add_argument(
        "--sigma-range-m",
        type=float,
        default=None,
        metavar="M",
        help="radar range standard deviation, m; " + _per_scenario(lambda sc: sc.sigma_radar[0]),
    )
    s.add_argument(
        "--sigma-azimuth-mrad",
        type=float,
        default=None,
        metavar="MRAD",
        help="radar azimuth standard deviation, mrad; " + _per_scenario(lambda sc: sc.sigma_radar[1] * 1e3),
    )
    s.add_argument(
        "--sigma-elevation-mrad",
        type=float,
        default=None,
        metavar="MRAD",
        help="radar elevation standard deviation, mrad (3-D only); default: the azimuth's",
    )
    s.add_argument(
        "--second",
        type=str,
        default=None,
        metavar="COMPONENTS",
        help="components the second sensor measures, comma separated: range, azimuth (bearing), "
        "elevation (3-D); " + _per_scenario(lambda sc: ",".join(sc.components)),
    )
    s.add_argument(
        "--sigma-second-range-m",
        type=float,
        default=None,
        metavar="M",
        help="second sensor range standard deviation, m; " + _per_scenario(_second_sigma("range", 1.0)),
    )
    s.add_argument(
        "--sigma-second-azimuth-mrad",
        type=float,
        default=None,
        metavar="MRAD",
        help="second sensor azimuth standard deviation, mrad; "
        + _per_scenario(_second_sigma("azimuth", 1e3)),
    )
    s.add_argument(
        "--sigma-second-elevation-mrad",
        type=float,
        default=None,
        metavar="MRAD",
        help="second sensor elevation standard deviation, mrad (3-D); default: none, the paper's scenarios "
        "are 2-D (required when --second includes elevation)",
    )


# --------------------------------------------------------------------------- scenario from options
def _check_numbers(args) -> None:
    """Finite numbers everywhere, standard deviations and
    the target range > 0 (ValueError naming the option)."""
    if args.seed < 0:
        raise ValueError(f"--seed: expected an integer >= 0, got {args.seed}")
    for name, value in vars(args).items():
        values = value if isinstance(value, list) else [value]
        if any(isinstance(v, float) and not np.isfinite(v) for v in values):
            raise ValueError(f"--{name.replace('_', '-')}: expected finite numbers, got {value}")
        if (name.startswith("sigma_") or name == "target_range_m") and value is not None and not value > 0:
            raise ValueError(f"--{name.replace('_', '-')}: expected a value > 0, got {value}")


def _scenario_from_args(args):
    base = paper_scenario(args.scenario)
    changes = {}
    dim = 3 if args.target_elevation_deg is not None else base.dim
    target = list(base.target_polar)
    if args.target_range_m is not None:
        target[0] = args.target_range_m
    if args.target_azimuth_deg is not None:
        target[1] = np.radians(args.target_azimuth_deg)
    if dim == 3:
        target = target[:2] + [np.radians(args.target_elevation_deg)]
    if args.target_range_m is not None or args.target_azimuth_deg is not None or dim != base.dim:
        changes["target_polar"] = np.array(target, dtype=float)

    site = list(base.site_second_loc) + [0.0] * (dim - base.dim)
    if args.baseline_m is not None and args.site_second_m is not None:
        raise ValueError("--baseline-m and --site-second-m: give one of them, not both")
    if args.baseline_m is not None:
        site = [args.baseline_m] + [0.0] * (dim - 1)
    if args.site_second_m is not None:
        if len(args.site_second_m) != dim:
            raise ValueError(
                f"--site-second-m: expected {dim} coordinates (m) for a {dim}-D problem, got "
                f"{len(args.site_second_m)}"
            )
        site = list(args.site_second_m)
    if args.baseline_m is not None or args.site_second_m is not None or dim != base.dim:
        changes["site_second_loc"] = np.array(site, dtype=float)
        changes["site_radar_loc"] = np.zeros(dim)

    sig_r = list(base.sigma_radar)
    if args.sigma_range_m is not None:
        sig_r[0] = args.sigma_range_m
    if args.sigma_azimuth_mrad is not None:
        sig_r[1] = args.sigma_azimuth_mrad * 1e-3
    if dim == 3:
        el = args.sigma_elevation_mrad * 1e-3 if args.sigma_elevation_mrad is not None else sig_r[1]
        sig_r = sig_r[:2] + [el]
    elif args.sigma_elevation_mrad is not None:
        raise ValueError("--sigma-elevation-mrad: only for a 3-D problem (give --target-elevation-deg)")
    if args.sigma_range_m is not None or args.sigma_azimuth_mrad is not None or dim != base.dim:
        changes["sigma_radar"] = np.array(sig_r, dtype=float)

    given = {
        "range": args.sigma_second_range_m,
        "azimuth": None if args.sigma_second_azimuth_mrad is None else args.sigma_second_azimuth_mrad * 1e-3,
        "elevation": None
        if args.sigma_second_elevation_mrad is None
        else args.sigma_second_elevation_mrad * 1e-3,
    }
    base_sig = dict(zip(base.components, base.sigma_second))
    try:
        comps = (
            tuple(base.components)
            if args.second is None
            else tuple(COMPONENTS[dim][i] for i in parse_components(args.second, dim))
        )
    except ValueError as exc:
        raise ValueError(f"--second: {exc}") from exc
    sig_b = []
    for c in comps:
        if given[c] is not None:
            sig_b.append(given[c])
        elif c in base_sig:
            sig_b.append(base_sig[c])
        else:
            unit = "m" if c == "range" else "mrad"
            raise ValueError(f"--sigma-second-{c}-{unit}: needed because the second sensor measures {c}")
    for c, v in given.items():
        if v is not None and c not in comps:
            raise ValueError(
                f"--sigma-second-{c}-{'m' if c == 'range' else 'mrad'}: the second sensor does not measure "
                f"{c} (see --second)"
            )
    if args.second is not None or any(v is not None for v in given.values()):
        changes["components"] = comps
        changes["sigma_second"] = np.array(sig_b, dtype=float)
    return base.with_changes(**changes) if changes else base


# --------------------------------------------------------------------------- table
def _fmt(v) -> str:
    return "-" if v is None else f"{v:.1f}"


def format_table(ev: FusionEvaluation) -> str:
    """The table the command prints: analytic and Monte Carlo GDOP (m) per row, beside the paper's."""
    se = ev.monte_carlo_se_m
    head = f"{ev.scenario.name}  ({ev.trials} Monte Carlo pairs, seed {ev.seed})"
    cols = f"{'':38s} {'analytic':>10s} {'Monte Carlo':>18s} {'paper':>8s}"
    lines = [head, "GDOP = sqrt(trace of position covariance), metres", cols, "-" * len(cols)]
    for r in ev.rows:
        mc = r["monte_carlo_gdop_m"]
        mc_s = "-" if mc is None else f"{mc:.1f} +- {se[r['name']]:.1f}"
        paper_s = ev.scenario.paper_printed.get(r["name"]) or _fmt(r["paper_gdop_m"])
        lines.append(
            f"{ROW_LABELS[r['name']]:38s} {_fmt(r['analytic_gdop_m']):>10s} {mc_s:>18s} {paper_s:>8s}"
        )
    d = ev.details
    lines.append("")
    lines.append(
        "improvement over radar (Monte Carlo): paper method "
        f"x{d['improvement_over_radar']['paper_actual']:.2f}, optimal "
        f"x{d['improvement_over_radar']['optimal']:.2f}; CRLB/paper-method GDOP = "
        f"{d['efficiency_paper_vs_crlb']:.3f}"
    )
    lines.append(
        f"claimed covariance below the CRLB: {'YES' if ev.claimed_below_crlb else 'no'}"
        f" (in {100 * ev.claimed_below_crlb_fraction:.0f}% of the trials)"
    )
    for w in ev.warnings:
        lines.append(f"warning: {w}")
    for n in ev.scenario.notes:
        lines.append(f"note: {n}")
    return "\n".join(lines)


# --------------------------------------------------------------------------- entry point
def run(args) -> int:
    if args.trials < 2:
        raise ValueError(f"--trials: expected at least 2 Monte Carlo pairs, got {args.trials}")
    if args.max_plot_points < 1:
        raise ValueError(f"--max-plot-points: expected a positive count, got {args.max_plot_points}")
    _check_numbers(args)
    sc = _scenario_from_args(args)
    out = prepare_out(args.out)
    ev = evaluate(sc, trials=args.trials, seed=args.seed)
    print(format_table(ev))
    with staged_outputs(out, "registration fuse", FUSE_OUTPUTS) as folder:
        written = [folder.path / "summary.json"]
        with writing(written[0]):
            write_json(written[0], ev.to_json())
        if not args.no_plots:
            from registration.fusion.plots import write_plots

            with writing(folder.path):
                written += write_plots(ev, folder.path, args.max_plot_points)
    print("wrote " + ", ".join(str(folder.final(p)) for p in written))
    return 0
