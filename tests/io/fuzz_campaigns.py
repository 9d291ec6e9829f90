"""The SITES reader's fuzz campaign (:mod:`tests.fuzzing`): the mutations of
:mod:`tests.io.test_fuzz_sites` (cells replaced by extreme numbers, text, NaN, empty, huge
strings; rows duplicated or dropped; columns dropped or repeated), one table per call of
:func:`registration.io.asterix.tables.sites.read_sites`. Every outcome is a table or a one-line
ValueError naming the file, and a cell's row with its column; no RuntimeWarning."""

from __future__ import annotations

import csv
import io
import random
import re
import tempfile
import warnings
from collections import Counter
from pathlib import Path

from registration.io.asterix.tables.sites import read_sites
from tests.fuzzing import Campaign


def _table() -> tuple[list, list]:
    from tests.io.test_fuzz_sites import base

    frame = base()
    return list(frame.columns), frame.astype(str).values.tolist()


def mutate_rows(header: list, rows: list, rng: random.Random, cells: tuple) -> tuple[list, list]:
    """One to three mutations of copies of a table of text cells (header, rows)."""
    header, rows = list(header), [list(r) for r in rows]
    for _ in range(rng.randint(1, 3)):
        kind = rng.random()
        if kind < 0.6 and rows:
            rows[rng.randrange(len(rows))][rng.randrange(len(header))] = rng.choice(cells)
        elif kind < 0.75 and rows:
            rows.append(list(rows[rng.randrange(len(rows))]))
        elif kind < 0.85 and rows:
            del rows[rng.randrange(len(rows))]
        elif kind < 0.9:  # a column repeated, its header too
            k, j = rng.randrange(len(header)), rng.randrange(len(header) + 1)
            header.insert(j, header[k])
            for r in rows:
                r.insert(j, r[k])
        elif kind < 0.95 and len(header) > 1:
            k = rng.randrange(len(header))
            del header[k]
            for r in rows:
                del r[k]
        elif rows:
            k, value = rng.randrange(len(header)), rng.choice(cells)
            for r in rows:
                r[k] = value
    return header, rows


def sites(seed: int) -> Campaign:
    from tests.io.test_fuzz_sites import CELLS

    header, rows = _table()
    folder = Path(tempfile.mkdtemp(prefix="fuzz-sites-"))

    def batches(n: int):
        for k in range(n):
            rng = random.Random(seed * 1_000_003 + k)
            yield [(f"SITES {k} (seed {seed})", mutate_rows(header, rows, rng, CELLS))]

    def check(batch: list) -> Counter:
        ((_, (head, body)),) = batch
        text = io.StringIO()
        csv.writer(text, lineterminator="\n").writerows([head, *body])
        path = folder / "SITES.csv"
        path.write_text(text.getvalue(), encoding="utf-8")
        with warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)
            try:
                read_sites(path)
            except ValueError as exc:
                message = str(exc)
                assert "\n" not in message and message.startswith(f"{path}: "), message
                if re.search(r"\brow \d+\b", message):
                    assert "column" in message, message
                return Counter(refused=1)
        return Counter(read=1)

    return Campaign(batches, check)
