"""Which AIS vessel a radar's TTM track is: the batch association
(:func:`~registration.fleet.associate_and_register`, as ``fleet register`` runs it on imported
tables) run again and again on the recent data of a stream.

Every ``every_s`` seconds of data (a grid from the first plot's time, so that the runs, and the
labels, do not depend on how the stream was cut into pieces), the association runs on the plots,
navigation and references of the ``span_s`` seconds up to that time; at a feed's end (no line for
a while) once more on its tail. A track whose plots there it labelled with one vessel (at least
:data:`MIN_SHARE` of them) is that vessel from then on; a track it left without a vessel (with at
least :data:`MIN_PLOTS` plots there) loses its label, so that a track number the radar gives to
another target later is associated anew. The plots of a track are used by the estimator once the
track has a label; before, they are counted (``unassociated``), not used.
"""

from __future__ import annotations

from collections import Counter

import numpy as np

from registration.live.inputs.rows import concat_rows

__all__ = ["TrackLabels", "WINDOW_S", "EVERY_S", "MIN_SHARE", "MIN_PLOTS"]

#: Seconds of data the association looks at.
WINDOW_S = 240.0
#: Seconds of data between two runs.
EVERY_S = 30.0
#: The share of a track's plots in the window that must carry one label for the track to take it.
MIN_SHARE = 0.8
#: A track with at least this many plots in the window and no label loses the one it had.
MIN_PLOTS = 5
_NAV = ("time", "platform", "lat", "lon", "alt", "heading", "pitch", "roll")


def _since(table: dict | None, t0: float) -> dict | None:
    if table is None:
        return None
    keep = table["time"] >= t0
    return {k: v[keep] for k, v in table.items()} if keep.any() else None


class TrackLabels:
    """The labels of the tracks of one ship's sensors (module docstring). ``sensors``, ``platforms``:
    the ship's tables (SI); ``window_s`` the association's windows (the filter's epochs)."""

    def __init__(
        self, sensors, platforms, window_s: float, every_s: float = EVERY_S, span_s: float = WINDOW_S
    ):
        self.sensors, self.platforms = sensors, platforms
        self.window_s, self.every_s, self.span_s = window_s, every_s, span_s
        self.labels: dict[tuple[str, str], str] = {}
        self._plots: dict | None = None
        self._nav: dict | None = None
        self._refs: dict | None = None
        self._targets: dict | None = None
        self._next: float | None = None
        self._ran_to = -np.inf
        self.runs = 0
        self.failures: Counter = Counter()
        self.note = ""

    def add(self, plots, navigation, references, targets) -> None:
        """A piece's tables (SI; None where empty): kept for the last ``span_s`` seconds."""
        self._plots = concat_rows([self._plots, plots])
        self._nav = concat_rows([self._nav, navigation])
        self._refs = concat_rows([self._refs, references])
        if targets is not None:
            self._targets = concat_rows(
                [self._targets, {**targets, "time": np.zeros(len(targets["target"]))}]
            )
        if self._plots is None:
            return
        if self._next is None:  # the first run: a grid of data time from the first plot
            self._next = float(self._plots["time"].min()) + min(self.every_s, self.span_s / 2)
        t0 = min(float(self._plots["time"].max()), self._next) - self.span_s  # what the next run needs
        self._plots, self._refs = _since(self._plots, t0), _since(self._refs, t0)
        if self._nav is not None and self._nav["time"].size > 1:
            first = max(int(np.searchsorted(self._nav["time"], t0 - 10.0)) - 1, 0)
            self._nav = {k: v[first:] for k, v in self._nav.items()}

    def due(self) -> bool:
        """Whether the data reached the time of the next run."""
        return (
            self._plots is not None
            and self._next is not None
            and float(self._plots["time"].max()) >= self._next
        )

    @property
    def next_time(self) -> float:
        """The data time (s) of the next run of the grid (inf before any plot)."""
        return np.inf if self._next is None else self._next

    def behind(self) -> bool:
        """Whether plots came after the last run's time (a final run at a feed's end would see them)."""
        return self._plots is not None and float(self._plots["time"].max()) > self._ran_to

    def run(self, final: bool = False) -> int:
        """Associate the data of the ``span_s`` seconds up to the next run's time (up to the latest
        plot when ``final``: the end of a feed) and update the labels; returns the tracks labelled.
        The runs' times are a grid of data time, so the labels do not depend on how the stream was
        cut into pieces (on the machine's load)."""
        from registration.fleet import AssociationOptions, associate_and_register

        plots = self._plots
        assert plots is not None and self._next is not None
        at = float(plots["time"].max()) if final else self._next
        self._next = max(self._next, at) + self.every_s if final else self._next + self.every_s
        self._ran_to = at
        if self._nav is None or self._refs is None:
            return 0
        inside = (plots["time"] >= at - self.span_s) & (plots["time"] <= at)
        inside &= (plots["time"] >= self._nav["time"][0]) & (plots["time"] <= self._nav["time"][-1])
        plots = {k: v[inside] for k, v in plots.items()}
        if plots["time"].size == 0:
            return 0
        refs = self._refs
        refs = {k: v[refs["time"] <= at] for k, v in refs.items()}
        targets = None if self._targets is None else {k: v for k, v in self._targets.items() if k != "time"}
        self.runs += 1
        try:
            result = associate_and_register(
                plots,
                self.sensors,
                self._nav,
                self.platforms,
                refs,
                AssociationOptions(window_s=self.window_s),
                targets=targets,
            )
        except (ValueError, np.linalg.LinAlgError) as exc:
            self.failures[type(exc).__name__] += 1
            self.note = f"association of the last {self.span_s:g} s: {exc}"
            return 0
        self._learn(plots, result.labels.astype(str), set(np.asarray(refs["target"]).astype(str).tolist()))
        return len(self.labels)

    def _learn(self, plots: dict, labels: np.ndarray, vessels: set) -> None:
        keys = np.char.add(np.char.add(plots["sensor"].astype(str), "\t"), plots["track"].astype(str))
        for key in np.unique(keys).tolist():
            mine = labels[keys == key]
            sensor, track = key.split("\t")
            named = mine[np.isin(mine, list(vessels))]
            if named.size:
                values, counts = np.unique(named, return_counts=True)
                best = int(np.argmax(counts))
                if counts[best] >= MIN_SHARE * mine.size:
                    self.labels[(sensor, track)] = str(values[best])
                    continue
            if mine.size >= MIN_PLOTS:
                self.labels.pop((sensor, track), None)

    def label(self, sensor: np.ndarray, track: np.ndarray) -> np.ndarray:
        """(N,) the target of each plot's (sensor, track); '' where the track has none yet."""
        return np.array(
            [
                self.labels.get((s, k), "")
                for s, k in zip(sensor.astype(str).tolist(), track.astype(str).tolist())
            ],
            dtype=object,
        ).astype(str)
