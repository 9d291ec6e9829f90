"""The radar error model's further terms for the ATC simulator (tests/io/asterix/atc.py): each
radar's primary (PSR) channel with range and azimuth biases of its own, SSR replies missed now and
then (the plot is then primary-only), an azimuth eccentricity per radar and a step of one radar's
azimuth bias at a time. :class:`RadarModel` says which; :func:`apply_model` adds them to the
simulator's plot arrays and gives their truth in the fleet's state names and SI units.

Everything here draws from random generators of its own (seeded by the scenario's seed), so the
simulator's other draws, and so its plots without a model, are unchanged.

The terms, on a plot of radar ``R`` at true bearing θ, stamped time t:

* bearing += ``a sin θ + b cos θ`` (``eccentricity_deg[R] = (a, b)``; states ``R:eccentricity_sin``,
  ``R:eccentricity_cos``, rad; every radar of the scenario has them, 0 where not given); θ is the
  true bearing, where the registration's model takes the measured one: they differ by the azimuth
  bias and noise, which moves b by a times the bias (0.0008 deg at most here, about a fifth of a
  600 s period's sigma or less),
* bearing += ``size`` for t >= T (t as encoded, in 1/128 s) on both channels of ``bearing_step =
  (R, T, size)`` (the antenna's azimuth reference: ``R:bearing_bias`` and ``R.psr:bearing_bias``
  step at T, reported time),
* a primary-only plot (an aircraft without transponder, or an SSR reply missed: a share
  ``missed_ssr`` of the Mode S and Mode A/C plots, drawn per plot) with ``psr_errors``: the range
  and azimuth biases of the channel ``R.psr`` instead of the radar's (drawn per radar: the radar's
  plus 40-120 m and 0.05-0.2 deg of random sign); its range gain and clock are the radar's.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["PSR_SUFFIX", "RadarModel", "apply_model"]

#: The sensor id of a radar's primary channel: the radar's and this.
PSR_SUFFIX = ".psr"


@dataclass(frozen=True)
class RadarModel:
    """Which further terms the simulator adds (module docstring): ``psr_errors`` (the primary
    channel's own biases), ``missed_ssr`` (share of SSR plots that become primary-only, 0-1),
    ``eccentricity_deg`` (radar -> (a, b) deg), ``bearing_step`` ((radar, time s as stamped, size
    deg) or None)."""

    psr_errors: bool = False
    missed_ssr: float = 0.0
    eccentricity_deg: dict = field(default_factory=dict)
    bearing_step: tuple | None = None


def apply_model(
    plots: dict, true_bearing_deg: np.ndarray, truth: dict, model: RadarModel, seed: int, errors_seed: int
) -> dict:
    """Add ``model``'s terms to ``plots`` (the simulator's arrays, changed in place: ``range_m``,
    ``bearing_deg``, ``kind``, ``mode_a``) and its states to ``truth`` (name -> SI value, from the
    start of the run); returns the steps: state name -> (time s as stamped, size SI)."""
    radars = sorted({k.split(":")[0] for k in truth if ":" in k and "." not in k})
    erng = np.random.default_rng([errors_seed, 0x5053])  # the radars' errors: 'PS'
    prng = np.random.default_rng([seed, 0x4D53])  # the missed replies: 'MS'
    radar = np.asarray(plots["radar"]).astype(str)
    kind = np.asarray(plots["kind"]).astype(object)
    ssr = kind != "primary"
    missed = ssr & (prng.random(kind.size) < model.missed_ssr)
    kind[missed] = "primary"
    plots["kind"] = kind.astype(str)
    plots["mode_a"] = np.where(plots["kind"] == "mode_a", plots["mode_a"], -1)
    primary = plots["kind"] == "primary"
    r = np.array(plots["range_m"], dtype=float)
    b = np.array(plots["bearing_deg"], dtype=float)
    theta = np.radians(np.asarray(true_bearing_deg, dtype=float))
    for name in radars:
        sign = erng.choice([-1.0, 1.0], 2)
        d_range = sign[0] * erng.uniform(40.0, 120.0) if model.psr_errors else 0.0
        d_bearing = np.radians(sign[1] * erng.uniform(0.05, 0.2)) if model.psr_errors else 0.0
        psr = name + PSR_SUFFIX
        truth[f"{psr}:range_bias"] = truth[f"{name}:range_bias"] + d_range
        truth[f"{psr}:bearing_bias"] = truth[f"{name}:bearing_bias"] + d_bearing
        truth[f"{psr}:range_gain"] = truth[f"{name}:range_gain"]
        mine = (radar == name) & primary
        r[mine] += d_range
        b[mine] += np.degrees(d_bearing)
        if model.eccentricity_deg:
            a_deg, b_deg = model.eccentricity_deg.get(name, (0.0, 0.0))
            truth[f"{name}:eccentricity_sin"] = np.radians(a_deg)
            truth[f"{name}:eccentricity_cos"] = np.radians(b_deg)
            here = radar == name
            b[here] += a_deg * np.sin(theta[here]) + b_deg * np.cos(theta[here])
    steps = {}
    if model.bearing_step is not None:
        name, t_step, size_deg = model.bearing_step
        stamped = np.round(np.asarray(plots["time_s"], dtype=float) * 128.0) / 128.0  # as encoded
        after = (radar == name) & (stamped >= t_step)
        b[after] += size_deg
        for state in (f"{name}:bearing_bias", f"{name}{PSR_SUFFIX}:bearing_bias"):
            steps[state] = (float(t_step), float(np.radians(size_deg)))
    plots["range_m"] = r
    plots["bearing_deg"] = b % 360.0
    return steps
