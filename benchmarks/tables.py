"""The benchmark figures of docs/results.md, generated from the committed JSON of the benchmarks.

    python -m benchmarks.tables            # rewrite the marked blocks of docs/results.md
    python -m benchmarks.tables --check    # exit 1 if docs/results.md differs from what the JSON gives

A block is the text between ``<!-- bench:NAME -->`` and ``<!-- /bench:NAME -->``; NAME is a
renderer of RENDERERS, which reads benchmarks/results/<file>.json (the part of NAME before any
dot). Everything outside the blocks is left as it is. tests/benchmarks/test_results_tables.py
fails when the docs and the JSON disagree, so a figure cannot be edited by hand or go stale
after a new measurement without the other following.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
import textwrap
from collections.abc import Callable
from pathlib import Path

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"
DOC = HERE.parent / "docs" / "results.md"
BLOCK = re.compile(r"<!-- bench:(?P<name>[\w.-]+) -->(?P<body>.*?)<!-- /bench:(?P=name) -->", re.DOTALL)

__all__ = ["BLOCK", "DOC", "RENDERERS", "load", "render", "render_file"]


def load(name: str) -> dict:
    """benchmarks/results/<name>.json."""
    doc = json.loads((RESULTS / f"{name}.json").read_text())
    if doc.get("tiny"):
        raise ValueError(f"{name}.json holds a --tiny run: its figures mean nothing")
    return doc


def num(x: float) -> str:
    """Three significant figures at most, no exponent: 239, 23.9, 2.39, 0.239."""
    x = float(x)
    if abs(x) >= 100:
        return f"{x:,.0f}".replace(",", " ")
    if abs(x) >= 10:
        return f"{x:.1f}"
    if abs(x) >= 1:
        return f"{x:.2f}"
    if abs(x) >= 0.1:
        return f"{x:.2f}"
    return f"{x:.2g}" if abs(x) >= 0.01 else f"{x:.1g}"


def cnt(n: int) -> str:
    """An integer with a space between thousands: 189 973."""
    return f"{int(n):,}".replace(",", " ")


def span(values: list[float]) -> str:
    """The range of the rounds: lowest–highest (one figure when they round alike)."""
    lo, hi = num(min(values)), num(max(values))
    return lo if lo == hi else f"{lo}–{hi}"


def measured(doc: dict) -> str:
    """When, where and under what load."""
    m = doc["machine"]
    return (
        f"measured {doc['date'][:10]} on {m['cpus']} CPUs under a load average of "
        f"{m['load_average'][0]:.1f}; `benchmarks/results/{doc['benchmark']}.json`"
    )


def _cpu(f: dict) -> str:
    """The CPU-time figures of an association run, if it has them."""
    if "cpu_seconds" not in f:
        return ""
    c = f["cpu_seconds"]
    return (
        f"; in CPU time, less sensitive to the load, {num(c['association']['median'])} s against "
        f"{num(c['true_ids']['median'])} s, {num(f['cpu_ratio_over_true_ids'])}×"
    )


def association(doc: dict) -> str:
    f, s = doc["figures"], doc["sizes"]
    a, ids = f["seconds"]["association"], f["seconds"]["true_ids"]
    return (
        f"association and registration of {s['sensors']} radars × {s['targets']} targets × "
        f"{s['duration_s']:g} s without target ids, with clutter ({cnt(s['plots'])} plots): "
        f"{num(a['median'])} s (median of {s['repeats']} interleaved rounds; rounds {span(a['rounds'])} s; "
        f"aim ≤ 10 s), {num(f['ratio_over_true_ids'])}× the registration of the same plots with their "
        f"true ids ({num(ids['median'])} s; the median of the rounds' ratios); the assignments "
        f"take {100 * f['assignment_share']:.1f} % of it, the registration about "
        f"{100 * f['registration_share']:.0f} %{_cpu(f)} ({measured(doc)})"
    )


def association_prose(doc: dict) -> str:
    f, s = doc["figures"], doc["sizes"]
    a, ids = f["seconds"]["association"], f["seconds"]["true_ids"]
    return (
        f"{s['sensors']} radars × {s['targets']} targets × {s['duration_s']:g} s with clutter "
        f"({cnt(s['plots'])} plots) takes {num(a['median'])} s against {num(ids['median'])} s with true ids "
        f"({num(f['ratio_over_true_ids'])}×, the median of {s['repeats']} interleaved rounds' "
        f"ratios{_cpu(f)}; {measured(doc)}). Its join passes settle ({f['join_passes']} passes); "
        f"{100 * f['error_rate']:.2f} % of the plots are wrong, and the estimates lie within "
        f"{f['max_estimate_difference_in_sigma']:.2f} σ of the ids run."
    )


SCAN, BATCH = "compiled scan alone", "register() (batch, whole call)"
PER_ROW, VECTORISED = "numpy (per-row model)", "numpy (model vectorised)"
UPDATE, STEPPER = "OnlineRegistrar.update() per row", "compiled stepper alone, per row"


def _online_long(doc: dict, lin: str) -> dict:
    rows = doc["sizes"]["rows"]
    return doc["figures"]["configs"][lin]["results"][str(rows[-1])]


def online(doc: dict) -> str:
    s = doc["sizes"]
    f, p = _online_long(doc, "fitted"), _online_long(doc, "paper")
    fa, pa = (doc["figures"]["configs"][lin]["aims"] for lin in ("fitted", "paper"))
    cpu = "cpu_us_per_step" in f

    def cell(r: dict, key: str) -> str:
        """CPU time (wall time) where the run has both, else the wall time."""
        wall = num(r["us_per_step"][key])
        return f"{num(r['cpu_us_per_step'][key])} ({wall})" if cpu else wall

    uf, up = (_Cells(r, cell) for r in (f, p))
    rows = [
        ("compiled scan (the whole Kalman step in generated C, one loop)", uf[SCAN], up[SCAN]),
        ("whole `register()` call", uf[BATCH], up[BATCH]),
        ("NumPy filter, model per row", uf[PER_ROW], up[PER_ROW]),
        (
            "NumPy filter, model vectorised up front",
            "– (the linearisation point depends on the state)",
            up[VECTORISED],
        ),
        (f"streaming `OnlineRegistrar.update()` ({cnt(s['stream_rows'])} rows)", uf[UPDATE], up[UPDATE]),
        ("the compiled stepper `update()` calls, alone", uf[STEPPER], up[STEPPER]),
    ]
    lines = [
        "",
        f"  | µs per step, {cnt(s['rows'][-1])} rows (median of {s['repeat']} interleaved rounds"
        f"{'; CPU time (wall time)' if cpu else ''}) | `fitted` (default) | `paper` |",
        "  |---|---:|---:|",
        *(f"  | {a} | {b} | {c} |" for a, b, c in rows),
        "",
        textwrap.fill(
            "Ratios (the median of the rounds' ratios): the compiled scan is "
            f"{num(fa['scan_ratio_vs_per_row_numpy_long'])}× the NumPy filter of the same kind for `fitted`; "
            f"for `paper` {num(pa['scan_ratio_vs_per_row_numpy_long'])}× the per-row one and "
            f"{num(pa['scan_ratio_vs_strongest_numpy_long'])}× the one that evaluates the model for all rows "
            f"up front. The whole `register()` call is {num(fa['ratio_vs_strongest_numpy_long'])}× "
            f"(`fitted`) and {num(pa['ratio_vs_strongest_numpy_long'])}× (`paper`) the strongest NumPy "
            f"filter; at 300 rows its fixed costs make it {num(fa['batch_us_per_step_300'])} µs "
            f"(`fitted`) and {num(pa['batch_us_per_step_300'])} µs (`paper`) per row. `update()` is "
            f"{num(fa['update_over_scan_long'])}× the scan's step for `fitted`, "
            f"{num(fa['update_python_us_per_step_long'])} µs of it the Python around the compiled "
            f"stepper ({measured(doc)}).",
            100,
            initial_indent="  ",
            subsequent_indent="  ",
            break_on_hyphens=False,
        ),
        "",
    ]
    return "\n".join(lines)


class _Cells:
    """r[key] -> the table cell of one contender."""

    def __init__(self, r: dict, cell: Callable[[dict, str], str]):
        self.r, self.cell = r, cell

    def __getitem__(self, key: str) -> str:
        return self.cell(self.r, key)


def online_step(doc: dict) -> str:
    r = _online_long(doc, "fitted")
    if "cpu_us_per_step" in r:
        return (
            f"{num(r['cpu_us_per_step'][SCAN])} µs per step compiled (CPU time, median of the "
            f"interleaved rounds; `benchmarks/results/online.json`)"
        )
    return f"{num(r['us_per_step'][SCAN])} µs per step compiled (median; `benchmarks/results/online.json`)"


def _fleet_cpu(f: dict) -> str:
    """The CPU-time figures of a fleet run, if it has them (BLAS threads count more than once)."""
    if "cpu_seconds" not in f or "cpu_ratio_least_squares_over_solve_batch" not in f:
        return ""
    c = f["cpu_seconds"]
    return (
        f"; in CPU time {num(c['solve_batch']['median'])} s end to end, "
        f"{num(c['fit']['median'])} s the solver, {num(c['least_squares']['median'])} s "
        f"least_squares: {num(f['cpu_ratio_least_squares_over_solve_batch'])}× and "
        f"{num(f['cpu_ratio_least_squares_over_solver'])}×"
    )


def fleet(doc: dict) -> str:
    f, s = doc["figures"], doc["sizes"]
    sb, fit, ls = (f["seconds"][k] for k in ("solve_batch", "fit", "least_squares"))
    return (
        f"fleet batch maximum likelihood, 8 sensors × 10 targets × {s['duration_s']:g} s "
        f"({cnt(s['plots'])} plots): {num(sb['median'])} s end to end (rounds {span(sb['rounds'])} s), "
        f"the solver alone {num(fit['median'])} s, and "
        f"{num(f['ratio_least_squares_over_solve_batch'])}× faster end to end "
        f"({num(f['ratio_least_squares_over_solver'])}× the solver alone) than "
        f"`scipy.optimize.least_squares` solving the same residuals to the same optimum "
        f"({num(ls['median'])} s; medians of {s['repeats']} interleaved rounds and of their ratios; "
        f"sum of squares {f['cost_batch']:.5f}{_fleet_cpu(f)}; {measured(doc)})"
    )


def fleet_online(doc: dict) -> str:
    f = doc["figures"]
    two = f["two_ship_paper_scenario"]
    return (
        f"the online fleet filter on the same {cnt(doc['sizes']['plots'])} plots (20 s windows): "
        f"{num(f['whole_table_us_per_plot'])} µs per plot for the whole table (aim ≤ 10 µs), "
        f"{num(f['streaming_1s_chunks_us_per_plot'])} µs when fed one second of plots per `update()` "
        f"call (each call checks its rows first), against {num(f['solve_batch_us_per_plot'])} µs per "
        f"plot for `solve_batch` in the same run ({num(f['ratio_online_over_batch'])}× and "
        f"{num(f['ratio_streaming_over_batch'])}× its time, medians of the rounds' ratios); "
        f"{'the same' if f['streamed_equals_whole_bit_for_bit'] else 'NOT the same'} estimate bit for "
        f"bit either way, within {num(f['max_difference_from_batch_in_batch_sigma'])} batch σ of the "
        f"batch's. On the paper's two-ship scenario the fleet filter takes "
        f"{num(two['fleet_online_us_per_plot'])} µs per plot against "
        f"{num(two['register_us_per_plot'])} µs for `register()` ({measured(doc)})"
    )


def step(doc: dict) -> str:
    p = doc["figures"]["portable"]
    cpu = "cpu carlson" in p["paper"]

    def us(lin: str, update: str) -> str:
        """CPU time (wall time) where the run has both, else the wall time."""
        wall = num(p[lin][update])
        return f"{num(p[lin]['cpu ' + update])} ({wall})" if cpu else wall

    parts = [
        f"{us(lin, 'carlson')} against {us(lin, 'joseph')} µs per step (`{lin}`)"
        for lin in ("paper", "fitted")
    ]
    text = (
        f"Carlson against Joseph{', CPU time (wall time)' if cpu else ''}: {parts[0]}, {parts[1]}; "
        f"Joseph / Carlson "
        f"{num(p['paper']['joseph/carlson'])} and {num(p['fitted']['joseph/carlson'])} (medians of "
        f"{doc['sizes']['repeat']} interleaved rounds and of their ratios)"
    )
    native = doc["figures"].get("native") or {}
    if native:
        fj, fc = native.get("fitted joseph"), native.get("fitted carlson")
        if fj and fc:
            text += (
                f". The builds for the local CPU, `fitted`, wall time: native "
                f"{num(fj['us_per_step']['native'])} / {num(fc['us_per_step']['native'])} µs (Joseph / "
                f"Carlson), exact {num(fj['us_per_step']['native-exact'])} / "
                f"{num(fc['us_per_step']['native-exact'])} µs; native {num(fj['portable_over']['native'])}× "
                f"and exact {num(fj['portable_over']['native-exact'])}× faster than portable for Joseph"
            )
    return f"{text} ({measured(doc)})"


def fusion(doc: dict) -> str:
    f = doc["figures"]
    rate = f["million_pairs_per_s"]
    paper = rate["paper method: registration.fusion.fuse_paper"]
    optimal = rate["optimal (ML): registration.fusion.fuse_optimal"]
    r = f["ratio_library_over_numpy"]
    return (
        f"`fuse_paper` {num(paper)} M pairs/s, `fuse_optimal` {num(optimal)} M pairs/s; a plain-NumPy "
        f"version specialised to scenario 1's components is {num(r['paper'])}× (paper method) and "
        f"{num(r['optimal'])}× (ML) faster (medians of {doc['sizes']['repeats']} interleaved rounds' "
        f"ratios; {measured(doc)})"
    )


def frames(doc: dict) -> str:
    f = doc["figures"]
    g = {r["method"]: r for r in f["geodetic2ecef"]}
    p = {r["method"]: r for r in f["plot2ecef"]}
    aims = f["aims"]
    ours_g = next(r for k, r in g.items() if k.startswith("ours: frames"))
    ours_p = next(r for k, r in p.items() if k.startswith("ours: frames"))
    raw_p = next(r for k, r in p.items() if k.startswith("ours: _codegen"))
    plain = p.get("plain C loop, direct call (inlinable)")
    pyproj = next(v for k, v in aims.items() if k.startswith("ours: frames") and k.endswith("pyproj"))
    text = (
        f"`geodetic2ecef`: {num(ours_g['ns_per_point'])} ns/point, {num(pyproj)}× pyproj's throughput "
        f"and {num(aims['pymap3d time / ours (validated)'])}× pymap3d's. Full radar plot → ECEF "
        f"conversion (`plot2ecef`): {num(raw_p['ns_per_point'])} ns/plot raw, "
        f"{num(ours_p['ns_per_point'])} ns with input validation"
    )
    if plain is not None:
        raw_ratio = next(
            v for k, v in aims.items() if k.startswith("ours: _codegen") and k.endswith("plain C")
        )
        val_ratio = next(v for k, v in aims.items() if k.startswith("ours: frames") and k.endswith("plain C"))
        text += (
            f"; a plain C loop over the same generated code takes {num(plain['ns_per_point'])} ns "
            f"(ratio {num(raw_ratio)} raw, {num(val_ratio)} validated; aim ≤ 2)"
        )
    return (
        f"{text} (medians of {doc['sizes']['repeat']} interleaved rounds and of their ratios, "
        f"{cnt(doc['sizes']['n'])} points; {measured(doc)})"
    )


def _register_seconds(f: dict, rows: int) -> float:
    """The median seconds of the montecarlo benchmark's register() over ``rows`` rows."""
    return float(f["seconds"][f"register(), {rows} rows"]["median"])


def montecarlo(doc: dict) -> str:
    f, s = doc["figures"], doc["sizes"]
    return (
        f"`registration montecarlo --runs {s['runs']} --no-plots`: {num(f['cli_seconds'])} s end to end, "
        f"against {num(_register_seconds(f, 300 * s['runs']))} s for one "
        f"`register()` call over the same {cnt(300 * s['runs'])} rows: "
        f"{num(f['cli_over_register'])}× "
        f"(aim ≤ 3×); the batch is {num(f['batch_vs_run_by_run'])}× faster than the run-by-run loop it "
        f"replaced at {s['legacy_runs']} runs (medians of {s['repeat']} interleaved rounds' ratios; "
        f"{measured(doc)})"
    )


def asterix(doc: dict) -> str:
    f, s = doc["figures"], doc["sizes"]
    rate, over = f["records_per_s"], f["over_libasterix"]
    return (
        f"ASTERIX, {cnt(s['records'])} CAT048 records imported at {cnt(rate['raw import_asterix'])} "
        f"records/s raw and {cnt(rate['pcap import_asterix'])} from pcap, against "
        f"{cnt(rate['libasterix'])}/s for libasterix's parse alone ({num(over['raw import_asterix'])}×; "
        f"`benchmarks/bench_asterix.py`, medians of {s['repeat']} interleaved rounds and of their "
        f"ratios; {measured(doc)})"
    )


def nmea(doc: dict) -> str:
    f, s = doc["figures"], doc["sizes"]
    sec = f["seconds"]
    return (
        f"NMEA, {s['duration_s']:g} s of a bridge log ({cnt(s['lines'])} lines) in "
        f"{num(sec['import_nmea']['median'])} s against {num(sec['pynmea2.parse baseline']['median'])} s "
        f"for a bare `pynmea2.parse` of every line ({num(f['import_over_baseline'])}×; "
        f"`benchmarks/bench_nmea.py`, medians of {s['repeat']} interleaved rounds and of their "
        f"ratios; {measured(doc)})"
    )


def register(doc: dict) -> str:
    runs = doc["figures"]

    def case(name: str) -> list[dict]:
        return [r for r in runs if r["case"] == name]

    csv, pq = case("stream csv in -> csv out"), case("stream parquet in -> parquet out")
    plots = case("stream csv in -> csv out, with plots")
    sizes = sorted({r["rows"] for r in csv})
    peak = {k: span([r["peak_mib"] for r in v]) for k, v in (("csv", csv), ("pq", pq))}
    rate = {k: span([r["rows"] / r["seconds"] / 1e3 for r in v]) for k, v in (("csv", csv), ("pq", pq))}
    text = (
        f"measured peak RSS {peak['csv']} MiB (CSV) / {peak['pq']} MiB (Parquet) from {cnt(sizes[0])} to "
        f"{cnt(sizes[-1])} rows, at {rate['csv']} k rows/s (CSV) and {rate['pq']} k rows/s (Parquet) for "
        f"the whole command"
    )
    if plots:
        big = max(plots, key=lambda r: r["rows"])
        without = next(r for r in csv if r["rows"] == big["rows"])
        text += (
            f"; with the plots on (the default) the peak is {num(big['peak_mib'])} MiB against "
            f"{num(without['peak_mib'])} MiB without them at {cnt(big['rows'])} rows (CSV)"
        )
    return f"{text} (`benchmarks/bench_register.py`, {measured(doc)})"


RENDERERS: dict[str, Callable[[dict], str]] = {
    "register": register,
    "asterix": asterix,
    "nmea": nmea,
    "association": association,
    "association.prose": association_prose,
    "online": online,
    "online.step": online_step,
    "fleet": fleet,
    "fleet_online": fleet_online,
    "step": step,
    "fusion": fusion,
    "frames": frames,
    "montecarlo": montecarlo,
}


def render(text: str) -> str:
    """``text`` with every marked block rewritten from the JSON."""

    def block(m: re.Match) -> str:
        name = m["name"]
        if name not in RENDERERS:
            raise KeyError(f"no renderer for the block bench:{name}")
        body = RENDERERS[name](load(name.split(".")[0]))
        return f"<!-- bench:{name} -->{body}<!-- /bench:{name} -->"

    return BLOCK.sub(block, text)


def render_file(path: Path = DOC) -> tuple[str, str]:
    """(the file's text, what the JSON gives)."""
    text = path.read_text()
    return text, render(text)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true", help="only compare; exit 1 when they differ")
    parser.add_argument("--doc", type=Path, default=DOC, help="the file (default docs/results.md)")
    args = parser.parse_args(argv)
    text, new = render_file(args.doc)
    if args.check:
        if text != new:
            print(f"{args.doc} differs from benchmarks/results/*.json: run python -m benchmarks.tables")
            return 1
        return 0
    if text != new:
        args.doc.write_text(new)
        print(f"rewrote the benchmark blocks of {args.doc}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
