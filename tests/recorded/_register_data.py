"""Test data for `registration register`: simulated scenarios written in the file formats."""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import pandas as pd

from registration.online.contract import IS_ANGLE
from registration.online.scenario import ShipMotion, paper_scenario
from registration.recorded import to_file_frame


@lru_cache(maxsize=4)
def scenario(n_steps: int = 300, seed: int = 0, motion: bool = False):
    return paper_scenario(n_steps=n_steps, seed=seed, ship_motion=ShipMotion() if motion else None)


def frame(n_steps: int = 300, seed: int = 0, motion: bool = False) -> pd.DataFrame:
    """A synchronous table in file units (degrees, metres)."""
    return to_file_frame(scenario(n_steps, seed, motion).data)


def tiled(copies: int, n_steps: int = 300) -> pd.DataFrame:
    """The scenario's rows repeated ``copies`` times, time shifted so that it keeps increasing."""
    base = frame(n_steps)
    parts = []
    for k in range(copies):
        part = base.copy()
        part["time_s"] = part["time_s"] + k * n_steps
        parts.append(part)
    return pd.concat(parts, ignore_index=True)


def estimates_from_file(est: pd.DataFrame) -> np.ndarray:
    """(K, 12) estimates in SI units/radians from an estimates table (degrees, metres)."""
    cols = est.columns[2:-1:2]
    return np.stack(
        [np.radians(est[c]) if IS_ANGLE[i] else np.asarray(est[c]) for i, c in enumerate(cols)], axis=1
    )


def in_file_units(values: np.ndarray) -> np.ndarray:
    """Estimates or sigmas (..., 12) in SI units/radians -> degrees/metres, as the outputs hold them."""
    return np.where(IS_ANGLE, np.degrees(values), values)


def file_estimates(est: pd.DataFrame) -> np.ndarray:
    return est.iloc[:, 2:-1:2].to_numpy()


def file_sigmas(est: pd.DataFrame) -> np.ndarray:
    return est.iloc[:, 3:-1:2].to_numpy()
