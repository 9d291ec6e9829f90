"""Which registration states of a fleet the data determine, named in the user's terms.

Input: the information matrix of the free states with the target trajectories eliminated (the Schur
complement of the data alone, at the solution). It is scaled, as in
:mod:`registration.core.observability`, by each state's prior sigma, or by a reference size when the
state has no prior (:data:`registration.fleet.data.layout.REFERENCE_SCALE`: 1 deg, 1 km), so an
eigenvalue ``s`` means a posterior sigma of ``1 / sqrt(s)`` in those units; classes and thresholds are
the core's (unobservable below 0.01, weak below 10).

A known structural degeneracy is named first: on a platform that neither pitches nor rolls, the heading
error and the bearing biases of its sensors rotate every line of sight about the same vertical axis, so
only ``heading error + bearing bias`` of each sensor is identifiable. The direction ``(+1 on the heading
error, -1 on each bearing bias)`` is tested directly: when it lies mostly (more than half, in scaled
units) in the unobservable and weak eigen-directions, it is reported by its own scaled information
``v^T J_s v`` (v the scaled unit vector), the number that the report's ``scaled_information`` carries:
unobservable below 0.01, "barely separated" (weak) below 10, not named at or above 10. Its shares in the
unobservable and weak eigen-directions are reported beside it (:class:`StructuralCombination`). Lever
arms and the earth's curvature give a level platform's heading error a little information of its own, so
the weak case is common. A second structural direction is tested the same way when sensors have time
biases: all time biases moving together (a clock common to the fleet), which only reference positions and
the platforms' own motion fix. Every remaining weak or unobservable direction (orthogonal to the named
ones) is named by its dominant states and, where they are the extended errors of one sensor, explained in
the user's terms (:func:`explain`): a range gain against a range bias (ranges spanning too little), a
time bias against position errors or angle biases (targets all moving the same way), position errors
against range and bearing biases (targets in a narrow sector).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from registration.core.observability import UNOBSERVABLE_BELOW, WEAK_BELOW, Combination, ObservabilityReport
from registration.fleet.data.layout import state_scale

__all__ = ["StructuralCombination", "explain", "fleet_observability"]


@dataclass
class StructuralCombination(Combination):
    """A named structural direction (a level platform's heading error against its bearing biases,
    a clock common to the fleet). As for every :class:`Combination`, ``eigenvalue`` is its scaled
    information ``v^T J_s v`` (v its unit vector in prior-scaled coordinates; dimensionless, the
    number the thresholds 0.01 and 10 apply to). ``null_share`` and ``weak_share``: the shares of
    ``|v|^2`` in the unobservable and in the weak eigen-directions (0..1)."""

    null_share: float = 0.0
    weak_share: float = 0.0

    def to_json(self) -> dict:
        return {
            **super().to_json(),
            "share_in_unobservable_directions": self.null_share,
            "share_in_weak_directions": self.weak_share,
        }


#: States a joint change names in words, the largest first (a terminal line stays under 300
#: characters; the coefficients list them all).
TERMS_SHOWN = 4
#: Why a weak or unobservable direction dominated by these states is hard to see.
_GAIN_BIAS = (
    "range gain and range bias are barely told apart: the plots span too narrow a range of ranges (a gain "
    "times the mean range looks like a bias); ranges farther apart separate them"
)
_TIME = (
    "time bias is barely told apart from position errors or angle biases: the targets all move the same "
    "way, so a clock offset looks like a shift along their track; targets crossing in other directions, "
    "a manoeuvre or a reference separate them"
)
_CLOCK = (
    "time biases move together (a clock common to these sensors): reference positions, or platforms that "
    "move or roll, fix it"
)
_SECTOR = (
    "position errors are barely told apart from range and bearing biases: the targets lie in a narrow "
    "sector, where a shift of the sensor looks like range and bearing biases; targets at other bearings "
    "separate them"
)
_SHIFT = (
    "position errors move together, so the whole picture shifts with them: a reference position, or a sensor "
    "whose position is known (prior 0), fixes it"
)
_ATTITUDE = {"heading_error", "pitch_error", "roll_error"}


def explain(quantities: dict) -> str | None:
    """A reason in the user's terms for a poorly determined direction whose dominant states are
    ``quantities`` {state name: quantity} (``A1:range_gain`` -> ``range_gain``), when they include
    extended errors; None otherwise."""
    q = set(quantities.values())
    sensors = list(dict.fromkeys(n.split(":", 1)[0] for n, k in quantities.items() if k not in _ATTITUDE))
    who = f"sensor{'s' if len(sensors) > 1 else ''} {', '.join(sensors)}"
    if "range_gain" in q and q <= {"range_gain", "range_bias"}:
        return f"{who}: {_GAIN_BIAS}"
    if q == {"time_bias"} and len(sensors) > 1:
        return f"{who}: {_CLOCK}"
    if "time_bias" in q:
        return f"{who}: {_TIME}"
    if len(q) == 1 and q.pop().startswith("position_") and len(sensors) > 1:
        return f"{who}: {_SHIFT}"
    if any(x.startswith("position_") for x in quantities.values()) and {"range_bias", "bearing_bias"} & set(
        quantities.values()
    ):
        return f"{who}: {_SECTOR}"
    return None


def _level_patterns(layout, free: np.ndarray, sensor_platform: np.ndarray, platform_ids, sensor_ids):
    """(platform id, sensor ids, own-unit direction over the free states) per platform with a free
    heading error and free bearing biases."""
    pos = {int(i): k for k, i in enumerate(free)}
    out = []
    for p, pid in enumerate(platform_ids):
        h = int(layout.att_index[p, 0])
        sensors = [s for s in np.flatnonzero(sensor_platform == p) if int(layout.bias_index[s, 1]) in pos]
        if h not in pos or not sensors:
            continue
        v = np.zeros(free.size)
        v[pos[h]] = 1.0
        for s in sensors:
            v[pos[int(layout.bias_index[s, 1])]] = -1.0
        out.append((pid, [sensor_ids[s] for s in sensors], v))
    return out


def _level_text(layout, pid: str, sensors: list, weak: bool) -> str:
    h = f"{pid}:heading_error"
    if weak:
        return (
            f"heading error of platform {pid} and the bearing biases of {', '.join(sensors)} are barely "
            "separated; better determined are the sums "
            + ", ".join(f"{h} + {s}:bearing_bias" for s in sensors)
        )
    if len(sensors) == 1:
        return (
            f"heading error of platform {pid} and bearing bias of sensor {sensors[0]} enter only as their "
            f"sum {h} + {sensors[0]}:bearing_bias"
        )
    return (
        f"heading error of platform {pid} and the bearing biases of its sensors {', '.join(sensors)} enter "
        "only as the sums " + ", ".join(f"{h} + {s}:bearing_bias" for s in sensors)
    )


def _name(
    v_scaled: np.ndarray, d: np.ndarray, names, labels, eigenvalue: float, unobservable: bool
) -> Combination:
    """A generic direction (prior-scaled coordinates) named by its dominant states, with the reason
    of :func:`explain` in front where it has one."""
    comb = _name_states(v_scaled, d, names, labels, eigenvalue, unobservable)
    v = np.abs(v_scaled) / np.abs(v_scaled).max()
    why = explain({names[i]: names[i].split(":", 1)[1] for i in np.flatnonzero(v >= 0.5)})
    if why is None:
        return comb
    return Combination(comb.coefficients, comb.eigenvalue, f"{why} ({comb.text})", comb.identifiable_sum)


def _name_states(
    v_scaled: np.ndarray, d: np.ndarray, names, labels, eigenvalue: float, unobservable: bool
) -> Combination:
    """A generic direction (prior-scaled coordinates) named by its dominant states."""
    v = v_scaled / np.abs(v_scaled).max()
    idx = [i for i in np.argsort(-np.abs(v)) if abs(v[i]) >= 0.15]
    own = v * d / d[idx[0]]  # coefficients in the states' own units
    coeffs = {names[i]: round(float(own[i]), 4) for i in idx}
    if len(idx) == 1:
        return Combination(coeffs, float(eigenvalue), f"{labels[idx[0]]} ({names[idx[0]]})")
    i, j = idx[:2]
    if len(idx) == 2 and abs(abs(own[j]) - 1.0) < 0.05:
        kind, sign = ("difference", "-") if own[j] > 0 else ("sum", "+")
        verb = "enter only as their" if unobservable else "are separated mainly through their"
        return Combination(
            coeffs,
            float(eigenvalue),
            f"{labels[i]} and {labels[j]} {verb} {kind} {names[i]} {sign} {names[j]}",
            (names[i], names[j]) if kind == "sum" else None,
        )
    terms = ", ".join(f"{labels[k]} ({own[k]:+.3g})" for k in idx[:TERMS_SHOWN])
    if len(idx) > TERMS_SHOWN:  # the line stays short; the coefficients hold them all
        terms += f" and {len(idx) - TERMS_SHOWN} smaller"
    head = "the data do not see a joint change of" if unobservable else "poorly determined joint change of"
    return Combination(coeffs, float(eigenvalue), f"{head} {terms} (relative sizes in the states' units)")


def _common_clock(layout, free: np.ndarray):
    """(texts, own-unit direction) of all free time biases moving together, when two or more."""
    pos = {int(i): k for k, i in enumerate(free)}
    idx = [pos[int(i)] for i in layout.time_bias_index if int(i) in pos]
    if len(idx) < 2:
        return []
    v = np.zeros(free.size)
    v[idx] = 1.0
    what = (
        "the time biases of all sensors move together (a clock common to the fleet): only their differences "
        "are determined; reference positions, or platforms that move, fix the common clock"
    )
    return [((what, "barely determined: " + what), v)]


def _named_structural(Js: np.ndarray, null: np.ndarray, weak: np.ndarray, layout, free, patterns):
    """The structural patterns ((unobservable text, weak text), own-unit direction, scaled unit
    direction vs) that lie mostly in the unobservable and weak eigen-directions of the scaled
    information ``Js``: unobservable when more than half of it lies in the unobservable ones (as
    the states' status is judged, :func:`_status`), else weak. The information reported is that of
    the pattern's part in the eigen-directions of its class (normalised), so it lies below that
    class's threshold; the pattern's own ``vs^T Js vs`` can be larger where the data tilt the
    degenerate direction slightly away from the pattern."""
    named = []
    for texts, v, vs in patterns:
        f_null = float(np.sum((null.T @ vs) ** 2))
        f_weak = float(np.sum((weak.T @ vs) ** 2))
        if f_null + f_weak <= 0.5:
            continue
        unobservable = f_null > 0.5
        basis = null if unobservable else np.concatenate([null, weak], axis=1)
        part = basis @ (basis.T @ vs)
        part = part / np.linalg.norm(part)
        info = float(part @ Js @ part)
        coeffs = {layout.names[free[k]]: float(v[k]) for k in np.flatnonzero(v)}
        pair = tuple(coeffs) if len(coeffs) == 2 and texts[2] else None
        comb = StructuralCombination(
            coeffs, info, texts[0] if unobservable else texts[1], pair, f_null, f_weak
        )
        named.append((unobservable, comb, vs))
    return named


def _status(names, null: np.ndarray, weak: np.ndarray) -> dict:
    """Per state: not identifiable (more than 0.3 of it in the unobservable directions), weak (more
    than 0.3 in the weak ones, or more than 0.1 unobservable) or identifiable."""
    p_null = np.linalg.norm(null, axis=1) if null.size else np.zeros(len(names))
    p_weak = np.linalg.norm(weak, axis=1) if weak.size else np.zeros(len(names))
    return {
        name: "not identifiable"
        if p_null[i] > 0.3
        else "weak"
        if (p_weak[i] > 0.3 or p_null[i] > 0.1)
        else "identifiable"
        for i, name in enumerate(names)
    }


def _generic(Js, named_vectors: list, d, names, labels) -> list[tuple[bool, Combination]]:
    """Weak and unobservable directions orthogonal to the named ones, named by their dominant states."""
    n = Js.shape[0]
    if named_vectors:
        w = np.linalg.qr(np.array(named_vectors).T)[0]
        basis = np.linalg.svd(np.eye(n) - w @ w.T)[0][:, : n - w.shape[1]]
    else:
        basis = np.eye(n)
    if basis.shape[1] == 0:
        return []
    eigval, eigvec = np.linalg.eigh(basis.T @ Js @ basis)
    vectors = basis @ eigvec
    null = eigval < UNOBSERVABLE_BELOW
    out = [
        (True, _name(u, d, names, labels, float(u @ Js @ u / (u @ u)), True))
        for u in _simple_basis(vectors[:, null]).T
    ]
    for s_val, u in zip(eigval, vectors.T):
        if UNOBSERVABLE_BELOW <= s_val < WEAK_BELOW:
            out.append((False, _name(u, d, names, labels, s_val, False)))
    return out


def _simple_basis(N: np.ndarray) -> np.ndarray:
    """A basis of span(N) in which each vector has a 1 at its own pivot state and 0 at the others'
    (reduced row echelon form, pivots by QR with column pivoting): a degenerate null space is then
    named as 'these states move together' rather than as arbitrary mixtures."""
    if N.shape[1] == 0:
        return N
    from scipy.linalg import qr

    _, _, piv = qr(N.T, pivoting=True)
    pivots = piv[: N.shape[1]]
    return N @ np.linalg.inv(N[pivots, :])


def fleet_observability(
    information: np.ndarray, free: np.ndarray, layout, sensor_platform, platform_ids, sensor_ids
) -> ObservabilityReport:
    """Classify the free states' directions from their information (n_free x n_free, data only)."""
    names = [layout.names[i] for i in free]
    labels = [layout.labels[i] for i in free]
    d = state_scale(layout)[free]
    Js = d[:, None] * np.asarray(information, dtype=float) * d[None, :]
    Js = 0.5 * (Js + Js.T)
    w, v = np.linalg.eigh(Js) if free.size else (np.zeros(0), np.zeros((0, 0)))
    null, weak = v[:, w < UNOBSERVABLE_BELOW], v[:, (w >= UNOBSERVABLE_BELOW) & (w < WEAK_BELOW)]
    report = ObservabilityReport(singular_values=np.clip(w, 0, None)[::-1])
    found = [
        ((_level_text(layout, pid, sensors, False), _level_text(layout, pid, sensors, True), True), vec)
        for pid, sensors, vec in _level_patterns(layout, free, sensor_platform, platform_ids, sensor_ids)
    ]
    found += [((*texts, False), vec) for texts, vec in _common_clock(layout, free)]
    patterns = [(texts, vec, vec / d / np.linalg.norm(vec / d)) for texts, vec in found]
    named = _named_structural(Js, null, weak, layout, free, patterns)
    for is_unobs, comb, _ in named:
        (report.unobservable if is_unobs else report.weak).append(comb)
    for is_unobs, comb in _generic(Js, [vs for _, _, vs in named], d, names, labels):
        (report.unobservable if is_unobs else report.weak).append(comb)
    report.status.update(_status(names, null, weak))
    return report
