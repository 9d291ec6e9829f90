"""Plots the fleet reader sets aside in both ``on_bad_row`` modes, with a note giving their count:
no cell of theirs is wrong, they only cannot be used
(:data:`~registration.io.fleet.reading.rejects.SET_ASIDE_CODES`):
a plot outside its platform's navigation time span (``outside_navigation``: a bridge log cut after
a TTM ends so) and a plot row equal in every column to an earlier one (``duplicate``: a recorder
that writes each plot twice would count it twice in the solve). A run stops only when no plot is
left."""

from __future__ import annotations

import numpy as np

from registration.io.fleet.reading.rejects import SET_ASIDE_CODES, BadRows, RejectedRow

__all__ = ["check_duplicates", "set_aside_notes", "stopping_rows"]


def check_duplicates(plots: dict, bad: BadRows) -> None:
    """A plot row equal in every column to an earlier one is set aside (``duplicate``): a recorder
    that writes each plot twice would count it twice in the solve."""
    import pandas as pd

    frame = pd.DataFrame({k: np.asarray(v) for k, v in plots.items()})
    if frame.empty:
        return
    twice = frame.duplicated(keep="first").to_numpy()
    if not twice.any():
        return
    first = frame.groupby(list(frame.columns), dropna=False, sort=False).ngroup().to_numpy()
    earliest = {int(g): int(r) for r, g in reversed(list(enumerate(first)))}
    bad.add(
        "*",
        "duplicate",
        twice,
        lambda r: f"the same plot as row {bad.file_row(earliest[int(first[r])])}, in every column",
    )


def set_aside_notes(rejected: list[RejectedRow], plots_path) -> list[str]:
    """One note per reason of :data:`SET_ASIDE_CODES` with plots set aside, giving their count."""
    what = {
        "outside_navigation": "outside their platform's navigation time span",
        "duplicate": "exactly duplicated (the first of each kept)",
    }
    notes = []
    for code in SET_ASIDE_CODES:
        n = sum(1 for r in rejected if r.code == code and r.file == str(plots_path))
        if n:
            notes.append(f"{plots_path}: {n} plot row(s) {what[code]} set aside ({code}; see rejected.csv)")
    return notes


def stopping_rows(rejected: list[RejectedRow]) -> list[RejectedRow]:
    """The rows set aside that stop a run in stop mode: all but :data:`SET_ASIDE_CODES` (and the
    references of targets left without plots by them)."""
    set_aside = any(r.code in SET_ASIDE_CODES for r in rejected)
    return [
        r
        for r in rejected
        if r.code not in SET_ASIDE_CODES and not (set_aside and r.code == "unknown_target")
    ]
