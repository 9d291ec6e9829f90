"""``registration landing``: radar/camera fusion along a simulated carrier approach.

Simulates Monte Carlo runs of the default approach (every parameter can be changed below),
time-aligns both sensors to common fusion instants, moves the radar into the camera's polar frame
with its covariance and fuses (Wang, Liu & Gao 2017, eqs. 7-12), and prints the 3-D position RMSE
in range bins for radar only, camera angles with radar range, and fused (plus the joint update).

Writes into ``--out DIR`` (default ``out/landing``): ``summary.json`` (``bins``: ``range_min_m,
range_max_m, rmse_radar_m, rmse_camera_m, rmse_fused_m`` and more) and, unless ``--no-plots``,
``attitude.png`` (Fig. 1), ``variance_ratios.png`` (Figs. 2-3), ``rmse.png`` (Fig. 4) and
``fused_polar.png`` (Fig. 5); an earlier run's outputs there are replaced only once all are written
(:mod:`registration.cli.staging`).

Units at this edge: metres, seconds, degrees (``_deg``), milliradians (``_mrad``) for angle noise
and milliseconds (``_ms``) for clock offsets; SI and radians inside.
"""

from __future__ import annotations

import argparse
import time
from dataclasses import replace

import numpy as np

from registration.cli.errors import prepare_out, writing
from registration.cli.options import add_no_plots, add_out, add_seed
from registration.cli.staging import staged_outputs
from registration.io.files.jsonfile import write_json
from registration.landing import (
    FUSION_METHODS,
    LandingConfig,
    LandingScenario,
    MonteCarloResult,
    default_bin_edges,
    default_geometry,
    default_scenario,
    monte_carlo,
    regroup,
    with_overrides,
)
from registration.landing.plots import METHOD_LABELS, write_plots

#: What `registration landing` writes into --out (the outputs of an earlier run there are replaced whole).
LANDING_OUTPUTS = frozenset(
    {"summary.json", "attitude.png", "variance_ratios.png", "rmse.png", "fused_polar.png"}
)

HELP = (
    "simulate a carrier approach and fuse the landing radar with the centreline camera: position RMSE by "
    "range bin, plots"
)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_out(parser, "landing", "summary.json and the PNG plots")
    add_no_plots(parser)
    parser.add_argument(
        "--runs",
        type=int,
        default=200,
        metavar="N",
        help="Monte Carlo runs of the whole approach (at least 2)",
    )
    add_seed(parser, 1, "random seed of the simulated measurements")
    parser.add_argument(
        "--bin-m", type=float, default=500.0, metavar="M", help="range-bin width of the printed table, m"
    )
    parser.add_argument(
        "--plot-bin-m",
        type=float,
        default=100.0,
        metavar="M",
        help="range-bin width of the RMSE plot, m (must divide --bin-m)",
    )
    p = parser.add_argument_group("processing")
    p.add_argument(
        "--fusion-rate-hz",
        type=float,
        default=10.0,
        metavar="HZ",
        help="rate of the common fusion instants, Hz",
    )
    p.add_argument(
        "--degree", type=int, default=2, metavar="N", help="polynomial degree of the time alignment"
    )
    p.add_argument(
        "--half-window-s",
        type=float,
        default=0.25,
        metavar="S",
        help="half-width of the time-alignment window, s",
    )
    p.add_argument(
        "--ignore-clock-offsets",
        action="store_true",
        help="process as if both clocks had no offset (shows what an uncalibrated clock costs)",
    )
    s = parser.add_argument_group("scenario")
    for flag, default, metavar, text in _scenario_options(default_scenario()):
        s.add_argument(flag, type=float, default=default, metavar=metavar, help=text)


def _scenario_options(d: LandingScenario) -> list[tuple[str, float, str, str]]:
    """The scenario options, every one a float: (flag, default from ``d``, metavar, help), in the
    order of --help."""
    rows = [
        ("--glide-slope-deg", np.degrees(d.approach.glide_slope_rad), "DEG", "glide slope, deg"),
        ("--ground-speed-mps", d.approach.ground_speed_mps, "M/S", "aircraft ground speed, m/s"),
        ("--start-range-m", d.approach.start_range_m, "M", "start, m along the path to touchdown"),
        ("--end-range-m", d.approach.end_range_m, "M", "end, m along the path to touchdown"),
        ("--ship-speed-mps", d.ship.speed_mps, "M/S", "carrier speed, m/s"),
        ("--angled-deck-deg", np.degrees(d.geometry.angled_deck_rad), "DEG", "angled-deck angle, deg"),
    ]
    for axis, amp, per in (
        ("yaw", d.ship.yaw_amplitude_rad, d.ship.yaw_period_s),
        ("pitch", d.ship.pitch_amplitude_rad, d.ship.pitch_period_s),
        ("roll", d.ship.roll_amplitude_rad, d.ship.roll_period_s),
    ):
        rows.append((f"--{axis}-deg", np.degrees(amp), "DEG", f"{axis} amplitude, deg"))
        rows.append((f"--{axis}-period-s", per, "S", f"{axis} period, s"))
    clock = "clock offset (its clock reads true time + offset), ms"
    return rows + [
        ("--radar-rate-hz", d.radar.rate_hz, "HZ", "radar rate, Hz"),
        ("--radar-sigma-range-m", d.radar.sigma_range_m, "M", "radar range noise standard deviation, m"),
        (
            "--radar-sigma-angle-mrad",
            d.radar.sigma_azimuth_rad * 1e3,
            "MRAD",
            "radar azimuth and elevation noise standard deviation, mrad",
        ),
        ("--radar-clock-offset-ms", d.radar.clock_offset_s * 1e3, "MS", f"radar {clock}"),
        ("--camera-rate-hz", d.camera.rate_hz, "HZ", "camera rate, Hz"),
        (
            "--camera-sigma-angle-mrad",
            d.camera.sigma_azimuth_rad * 1e3,
            "MRAD",
            "camera azimuth and elevation noise standard deviation, mrad",
        ),
        ("--camera-clock-offset-ms", d.camera.clock_offset_s * 1e3, "MS", f"camera {clock}"),
    ]


def scenario_from_args(args: argparse.Namespace) -> LandingScenario:
    """The default scenario with the command-line overrides applied (degrees -> radians here)."""
    sc = default_scenario()
    sc = with_overrides(
        sc,
        approach=dict(
            glide_slope_rad=float(np.radians(args.glide_slope_deg)),
            ground_speed_mps=args.ground_speed_mps,
            start_range_m=args.start_range_m,
            end_range_m=args.end_range_m,
        ),
        ship=dict(
            speed_mps=args.ship_speed_mps,
            yaw_amplitude_rad=float(np.radians(args.yaw_deg)),
            yaw_period_s=args.yaw_period_s,
            pitch_amplitude_rad=float(np.radians(args.pitch_deg)),
            pitch_period_s=args.pitch_period_s,
            roll_amplitude_rad=float(np.radians(args.roll_deg)),
            roll_period_s=args.roll_period_s,
        ),
        radar=dict(
            rate_hz=args.radar_rate_hz,
            sigma_range_m=args.radar_sigma_range_m,
            sigma_azimuth_rad=args.radar_sigma_angle_mrad * 1e-3,
            sigma_elevation_rad=args.radar_sigma_angle_mrad * 1e-3,
            clock_offset_s=args.radar_clock_offset_ms * 1e-3,
        ),
        camera=dict(
            rate_hz=args.camera_rate_hz,
            sigma_azimuth_rad=args.camera_sigma_angle_mrad * 1e-3,
            sigma_elevation_rad=args.camera_sigma_angle_mrad * 1e-3,
            clock_offset_s=args.camera_clock_offset_ms * 1e-3,
        ),
    )
    return replace(sc, geometry=default_geometry(float(np.radians(args.angled_deck_deg))))


def _check_args(args: argparse.Namespace) -> None:
    """Reject impossible options before the simulation (ValueError naming the option)."""
    for name, value in vars(args).items():
        if isinstance(value, float) and not np.isfinite(value):
            raise ValueError(f"--{name.replace('_', '-')}: expected a finite number, got {value}")
    if args.seed < 0:
        raise ValueError(f"--seed: expected an integer >= 0, got {args.seed}")
    if args.runs < 2:
        raise ValueError(f"--runs: expected at least 2 Monte Carlo runs, got {args.runs}")
    for name in ("bin_m", "plot_bin_m", "fusion_rate_hz", "half_window_s", "radar_rate_hz", "camera_rate_hz"):
        if not getattr(args, name) > 0:
            raise ValueError(f"--{name.replace('_', '-')}: expected > 0, got {getattr(args, name)}")
    for name in ("radar_sigma_range_m", "radar_sigma_angle_mrad", "camera_sigma_angle_mrad"):
        if not getattr(args, name) > 0:
            raise ValueError(
                f"--{name.replace('_', '-')}: expected a standard deviation > 0, got {getattr(args, name)}"
            )
    for name in ("yaw_period_s", "pitch_period_s", "roll_period_s", "ground_speed_mps"):
        if not getattr(args, name) > 0:
            raise ValueError(f"--{name.replace('_', '-')}: expected > 0, got {getattr(args, name)}")
    if not args.ship_speed_mps >= 0:
        raise ValueError(f"--ship-speed-mps: expected >= 0 m/s, got {args.ship_speed_mps}")
    if not args.start_range_m > args.end_range_m >= 0:
        raise ValueError(
            f"--start-range-m, --end-range-m: expected start > end >= 0 m, got {args.start_range_m}, "
            f"{args.end_range_m}"
        )
    ratio = args.bin_m / args.plot_bin_m
    if abs(ratio - round(ratio)) > 1e-9:
        raise ValueError(f"--plot-bin-m ({args.plot_bin_m} m) must divide --bin-m ({args.bin_m} m)")


def _table(mc: MonteCarloResult) -> str:
    heads = ["range bin (m)", "radar (m)", "camera+radar r (m)", "fused (m)"]
    keys = ["radar", "camera", "paper"]
    if "information" in mc.methods:
        heads.append("joint (m)")
        keys.append("information")
    rows = [f"{heads[0]:>15}  " + "  ".join(f"{h:>18}" for h in heads[1:])]
    rm = {k: mc.rmse(k) for k in keys}
    for b in range(mc.bin_edges_m.size - 1):
        lo, hi = mc.bin_edges_m[b], mc.bin_edges_m[b + 1]
        rows.append(f"{lo:>6.0f} - {hi:<6.0f}  " + "  ".join(f"{rm[k][b]:>18.3f}" for k in keys))
    return "\n".join(rows)


def _config(args: argparse.Namespace, sc: LandingScenario) -> LandingConfig:
    """The processing options; the scenario's clock offsets unless --ignore-clock-offsets."""
    offsets = dict(radar_clock_offset_s=0.0, camera_clock_offset_s=0.0) if args.ignore_clock_offsets else {}
    return sc.config(
        fusion_rate_hz=args.fusion_rate_hz,
        degree=args.degree,
        half_window_s=args.half_window_s,
        methods=FUSION_METHODS,
        **offsets,
    )


def _evaluate(
    args: argparse.Namespace, sc: LandingScenario, config: LandingConfig
) -> tuple[MonteCarloResult, MonteCarloResult]:
    """Monte Carlo statistics in --plot-bin-m bins (for the plot) and in --bin-m bins (table, JSON)."""
    top = default_bin_edges(sc, args.bin_m)
    fine_edges = np.arange(0.0, top[-1] + args.plot_bin_m / 2, args.plot_bin_m)
    fine = monte_carlo(sc, config, runs=args.runs, seed=args.seed, bin_edges_m=fine_edges, progress=True)
    return fine, regroup(fine, top)


def _report(
    args: argparse.Namespace, sc: LandingScenario, config: LandingConfig, mc: MonteCarloResult
) -> tuple[dict, np.ndarray]:
    """Print the RMSE table, the mean NEES and the paired z-scores; return NEES per method and z per bin."""
    print(
        f"registration landing: {args.runs} Monte Carlo runs of a {sc.duration_s:.1f} s approach (closure "
        f"{sc.closure_speed_mps:.1f} m/s), {mc.t.size} fusion instants per run at {config.fusion_rate_hz:g} "
        "Hz"
    )
    print("3-D position RMSE in the touchdown frame by range to the touchdown point:")
    print(_table(mc))
    nees = {m: float(np.nansum(mc.nees_sum[m]) / (mc.count.sum() * mc.runs)) for m in mc.methods}
    print(
        "mean NEES (3 when the predicted covariance is right): "
        + ", ".join(f"{METHOD_LABELS[m]} {v:.2f}" for m, v in nees.items())
    )
    z = mc.paired_z("paper", "camera")
    print(f"fused vs camera+radar range: paired z-score per bin (runs independent) min {np.nanmin(z):.1f}")
    return nees, z


def _bins_json(mc: MonteCarloResult, z: np.ndarray) -> list[dict]:
    """One record per range bin: RMSE per method (m), instants, z-score, polar RMSE and NEES."""
    bins = []
    for b in range(mc.bin_edges_m.size - 1):
        prm = {m: mc.polar_rmse(m)[b] for m in mc.methods}
        bins.append(
            {
                "range_min_m": float(mc.bin_edges_m[b]),
                "range_max_m": float(mc.bin_edges_m[b + 1]),
                "rmse_radar_m": float(mc.rmse("radar")[b]),
                "rmse_camera_m": float(mc.rmse("camera")[b]),
                "rmse_fused_m": float(mc.rmse("paper")[b]),
                "rmse_fused_information_m": float(mc.rmse("information")[b]),
                "instants": int(mc.count[b] * mc.runs),
                "z_fused_vs_camera": float(z[b]),
                "polar_rmse_about_camera": {
                    m: {
                        "range_m": float(v[0]),
                        "azimuth_mrad": float(v[1] * 1e3),
                        "elevation_mrad": float(v[2] * 1e3),
                    }
                    for m, v in prm.items()
                },
                "nees": {m: float(mc.nees(m)[b]) for m in mc.methods},
            }
        )
    return bins


def _scenario_json(sc: LandingScenario) -> dict:
    """The scenario at the edge's units (deg, mrad, ms)."""
    g = sc.geometry
    return {
        "glide_slope_deg": float(np.degrees(sc.approach.glide_slope_rad)),
        "ground_speed_mps": sc.approach.ground_speed_mps,
        "closure_speed_mps": sc.closure_speed_mps,
        "start_range_m": sc.approach.start_range_m,
        "end_range_m": sc.approach.end_range_m,
        "duration_s": sc.duration_s,
        "ship_speed_mps": sc.ship.speed_mps,
        "yaw_deg": float(np.degrees(sc.ship.yaw_amplitude_rad)),
        "yaw_period_s": sc.ship.yaw_period_s,
        "pitch_deg": float(np.degrees(sc.ship.pitch_amplitude_rad)),
        "pitch_period_s": sc.ship.pitch_period_s,
        "roll_deg": float(np.degrees(sc.ship.roll_amplitude_rad)),
        "roll_period_s": sc.ship.roll_period_s,
        "angled_deck_deg": float(np.degrees(g.angled_deck_rad)),
        "l_touchdown_deck_m": g.l_touchdown_deck_m.tolist(),
        "l_radar_deck_m": g.l_radar_deck_m.tolist(),
        "l_camera_deck_m": g.l_camera_deck_m.tolist(),
        "radar": {
            "rate_hz": sc.radar.rate_hz,
            "sigma_range_m": sc.radar.sigma_range_m,
            "sigma_angle_mrad": sc.radar.sigma_azimuth_rad * 1e3,
            "clock_offset_ms": sc.radar.clock_offset_s * 1e3,
        },
        "camera": {
            "rate_hz": sc.camera.rate_hz,
            "sigma_angle_mrad": sc.camera.sigma_azimuth_rad * 1e3,
            "clock_offset_ms": sc.camera.clock_offset_s * 1e3,
        },
    }


def run(args: argparse.Namespace) -> int:
    _check_args(args)
    sc = scenario_from_args(args)
    config = _config(args, sc)
    out = prepare_out(args.out)
    start = time.perf_counter()
    fine, mc = _evaluate(args, sc, config)
    elapsed = time.perf_counter() - start
    nees, z = _report(args, sc, config, mc)
    bins = _bins_json(mc, z)
    with staged_outputs(out, "registration landing", LANDING_OUTPUTS) as folder:
        files = []
        if not args.no_plots:
            with writing(folder.path):
                files = write_plots(folder.path, mc, fine)
        summary = _summary(args, sc, config, elapsed, bins, nees, files)
        with writing(folder.path / "summary.json"):
            write_json(folder.path / "summary.json", summary)
    plots = f" and {', '.join(files)}" if files else ""
    print(f"wrote {folder.final(folder.path / 'summary.json')}{plots} ({elapsed:.1f} s Monte Carlo)")
    return 0


def _summary(
    args: argparse.Namespace,
    sc: LandingScenario,
    config: LandingConfig,
    elapsed: float,
    bins: list[dict],
    nees: dict,
    files: list[str],
) -> dict:
    """summary.json: the command, the RMSE per range bin and method (m), NEES, scenario, processing."""
    return {
        "command": "registration landing",
        "runs": args.runs,
        "seed": args.seed,
        "elapsed_s": round(elapsed, 3),
        "methods": {
            "radar": "rmse_radar_m",
            "camera angles + radar range": "rmse_camera_m",
            "fused eq. 12": "rmse_fused_m",
            "fused joint update": "rmse_fused_information_m",
        },
        "bins": bins,
        "mean_nees": nees,
        "scenario": _scenario_json(sc),
        "processing": {
            "fusion_rate_hz": config.fusion_rate_hz,
            "degree": config.degree,
            "half_window_s": config.half_window_s,
            "radar_clock_offset_ms": config.radar_clock_offset_s * 1e3,
            "camera_clock_offset_ms": config.camera_clock_offset_s * 1e3,
        },
        "plots": files,
    }
