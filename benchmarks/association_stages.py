"""Where an association's time goes, by stage: one extra run of
:func:`~registration.fleet.associate_and_register` with its stages timed from outside.

The stages are the functions :mod:`registration.fleet.association.associate` calls in turn
(confirmation of targets, naming by references, the units' tracks, the join passes, the single
plots, the outlier stage); each is wrapped in that module's namespace for the one run and
restored after it. The registration solves (``Registrar.solve``) are timed too and counted in the
stage that called them, so each stage's time is given whole and as its own share without its
solves. The library is not changed: a renamed stage fails here loudly (AttributeError).

Used by ``bench_association.py``; alone::

    python3 benchmarks/association_stages.py --duration 300
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from contextlib import contextmanager
from dataclasses import dataclass, field

#: The stages, in the order the association runs them, by their names in its module.
STAGES = (
    "confirm_targets",
    "name_by_references",
    "make_units",
    "join_units",
    "single_plots_stage",
    "outlier_stage",
)


@dataclass
class StageTimes:
    """Seconds per stage (whole, its solves included) and of the solves each stage called; the
    solves outside every stage (the ids' and the anchors' registrations, the final one) under
    ``"other"``; ``total`` the whole run (the rest: the checks, the problem and the report)."""

    whole: dict[str, float] = field(default_factory=dict)
    solves: dict[str, float] = field(default_factory=dict)
    total: float = 0.0

    def lines(self) -> list[str]:
        out = [f"{'stage':22s} {'whole s':>8s} {'solves s':>9s} {'own s':>7s} {'own %':>6s}"]
        for name in (*STAGES, "other"):
            whole = self.whole.get(name, 0.0)
            solves = self.solves.get(name, 0.0)
            own = whole - solves if name != "other" else 0.0
            out.append(
                f"{name:22s} {whole:8.2f} {solves:9.2f} {own:7.2f} {100 * own / max(self.total, 1e-12):6.1f}"
            )
        rest = self.total - sum(self.whole.get(name, 0.0) for name in (*STAGES, "other"))
        share = 100 * rest / max(self.total, 1e-12)
        out.append(f"{'rest (checks, report)':22s} {rest:8.2f} {0.0:9.2f} {rest:7.2f} {share:6.1f}")
        out.append(f"{'total':22s} {self.total:8.2f}")
        return out


@contextmanager
def _timed_stages(times: StageTimes):
    from registration.fleet.association import associate, solves

    current: list[str] = ["other"]
    originals: dict[str, Callable] = {name: getattr(associate, name) for name in STAGES}
    solve = solves.Registrar.solve

    def stage(name: str, fn: Callable) -> Callable:
        def wrapped(*args, **kwargs):
            current.append(name)
            t0 = time.perf_counter()
            try:
                return fn(*args, **kwargs)
            finally:
                times.whole[name] = times.whole.get(name, 0.0) + time.perf_counter() - t0
                current.pop()

        return wrapped

    def timed_solve(self, *args, **kwargs):
        t0 = time.perf_counter()
        try:
            return solve(self, *args, **kwargs)
        finally:
            times.solves[current[-1]] = times.solves.get(current[-1], 0.0) + time.perf_counter() - t0

    for name, fn in originals.items():
        setattr(associate, name, stage(name, fn))
    solves.Registrar.solve = timed_solve
    try:
        yield
    finally:
        for name, fn in originals.items():
            setattr(associate, name, fn)
        solves.Registrar.solve = solve


def stage_times(run: Callable[[], object]) -> StageTimes:
    """The stages of the association that ``run()`` does, timed (module docstring)."""
    times = StageTimes()
    with _timed_stages(times):
        t0 = time.perf_counter()
        run()
        times.total = time.perf_counter() - t0
    times.whole["other"] = times.solves.get("other", 0.0)
    return times


def main(argv=None) -> StageTimes:
    from bench_association import scenario

    from registration.fleet import associate_and_register

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--duration", type=float, default=1000.0, help="seconds of data")
    args = parser.parse_args(argv)
    sim = scenario(duration_s=args.duration)
    sc = sim.scenario
    times = stage_times(lambda: associate_and_register(sim.plots, sc.sensors, sc.navigation, sc.platforms))
    print("\n".join(times.lines()))
    return times


if __name__ == "__main__":
    main()
