"""The fleet tables reader's fuzz campaign (:mod:`tests.fuzzing`): mutated rows of the plots and
reference files, read with ``on_bad_row="skip"`` and built into a problem.

Each input is one row of the built-in fleet's 60 s tables made into another: a cell replaced by a
value of :data:`tests.fleet.test_fuzz_tables.CELLS` (extreme numbers, text, NaN, empty, huge
strings), the row repeated, or every cell of it emptied. A plot keeps a target id (a plot without
one makes the run an association, whose reading the whole-file campaign covers). A batch applies
:data:`ROWS_BATCH` of them to one copy of the tables (skip mode sets the bad rows aside one by one,
so one read tests them all). The outcome is a problem, or a one-line ValueError naming a file
(and, for a cell, its row and column); never another exception, never a RuntimeWarning. The
mutations of whole files (columns dropped, the navigation, sensors and platforms files) are in
:mod:`tests.fleet.test_fuzz_tables`."""

from __future__ import annotations

import csv
import io
import random
import re
import tempfile
import warnings
from collections import Counter
from pathlib import Path

from registration.io.fleet.reading.read import needs_association, read_fleet_tables
from tests.fuzzing import Campaign

#: Rows mutated per read.
ROWS_BATCH = 250
NAMES = ("plots", "navigation", "sensors", "platforms", "reference")
#: What a plot's target id becomes (a text that reads as an id).
IDS = ("T9", "0", "-1", "1e308", "x" * 5000, "\u00e9\u202e", '"', "T1 ", "t1")
#: The files whose bad rows skip mode sets aside.
MUTATED = ("plots", "reference")


def _write(path: Path, header: list, rows: list) -> None:
    text = io.StringIO()
    csv.writer(text, lineterminator="\n").writerows([header, *rows])
    path.write_text(text.getvalue(), encoding="utf-8")


def tables(seed: int) -> Campaign:
    from registration.fleet import fleet_scenario
    from registration.io.fleet.write import write_fleet_tables
    from tests.fleet.test_fuzz_tables import CELLS

    folder = Path(tempfile.mkdtemp(prefix="fuzz-fleet-"))
    s = fleet_scenario(0, duration_s=60.0)
    write_fleet_tables(folder, s.plots, s.navigation, s.sensors, s.platforms, s.references, "csv")
    base = {}
    for name in MUTATED:
        with open(folder / f"{name}.csv", newline="", encoding="utf-8") as f:
            lines = list(csv.reader(f))
        base[name] = (lines[0], lines[1:])
    paths = {n: folder / f"{n}.csv" for n in NAMES}

    def batches(n: int):
        rng = random.Random(seed)
        for first in range(0, n, ROWS_BATCH):
            batch = []
            for k in range(first, min(first + ROWS_BATCH, n)):
                name = rng.choice(MUTATED)
                header, rows = base[name]
                r, kind, column = rng.randrange(len(rows)), rng.random(), rng.randrange(len(header))
                value = rng.choice(CELLS)
                if name == "plots" and header[column] == "target":  # an id still (none: association)
                    value = rng.choice(IDS)
                what = ("cell", column, value) if kind < 0.8 else (("repeat",) if kind < 0.9 else ("empty",))
                batch.append((f"{name} row {r} {what[0]} (input {k}, seed {seed})", (name, r, what)))
            yield batch

    def check(batch: list) -> Counter:
        rows = {name: [list(x) for x in base[name][1]] for name in MUTATED}
        extra: dict = {name: [] for name in MUTATED}
        for _, (name, r, what) in batch:
            if what[0] == "cell":
                rows[name][r][what[1]] = what[2]
            elif what[0] == "repeat":
                extra[name].append(list(rows[name][r]))
            else:  # every cell emptied but a plot's target id
                keep = base[name][0].index("target") if name == "plots" else -1
                rows[name][r] = [v if j == keep else "" for j, v in enumerate(rows[name][r])]
        for name in MUTATED:
            _write(paths[name], base[name][0], rows[name] + extra[name])
        with warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)
            try:
                read = read_fleet_tables(*(paths[n] for n in NAMES), on_bad_row="skip")
                if needs_association(read.plots):  # an empty row kept? `fleet register` associates
                    return Counter(association=1, rows=len(batch), set_aside=len(read.rejected))
                read.problem()
            except ValueError as exc:
                text = str(exc)
                assert "\n" not in text and any(str(p) in text for p in paths.values()), text
                if re.search(r"\brow \d+\b", text):
                    assert "column" in text, text
                return Counter(refused=1, rows=len(batch))
        return Counter(read=1, rows=len(batch), set_aside=len(read.rejected))

    return Campaign(batches, check)
