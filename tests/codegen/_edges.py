"""Edge-case points for the generated functions: poles, +-180 deg longitude, zero elevation,
bearings near +-pi, elevation near +-90 deg. Each entry maps input name -> list of values that
replace the random ones in some rows (see :func:`with_edges`)."""

from __future__ import annotations

import numpy as np

PI = np.pi
TINY = 1e-9

EDGE_VALUES = {
    "lat": [PI / 2, -PI / 2, PI / 2 - TINY, 0.0],
    "lon": [PI, -PI, PI - TINY, 0.0],
    "e": [0.0, PI / 2 - 1e-6, -PI / 2 + 1e-6],
    "q": [PI, -PI + TINY, PI - TINY, 0.0],
    "heading": [PI, -PI, 0.0],
    "pitch": [0.0],
    "roll": [0.0],
    "alt": [-500.0, 1.0e5],
}
# vector inputs: entry index -> edge values
VECTOR_EDGES = {
    "nav_a": {0: EDGE_VALUES["lat"], 1: EDGE_VALUES["lon"]},
    "nav_b": {0: EDGE_VALUES["lat"], 1: EDGE_VALUES["lon"]},
    "meas_a": {1: EDGE_VALUES["q"], 2: EDGE_VALUES["e"]},
    "meas_b": {1: EDGE_VALUES["q"], 2: EDGE_VALUES["e"]},
    "att_a": {1: [0.0], 2: [0.0]},
    "att_b": {1: [0.0], 2: [0.0]},
    "polar": {1: [PI, -PI + TINY, PI - TINY, 0.0], 2: [0.0, PI / 2 - 1e-6, -PI / 2 + 1e-6]},
}


def with_edges(spec, inputs: list[np.ndarray], rng: np.random.Generator) -> list[np.ndarray]:
    """Overwrite some rows with edge values; each edge value lands in 5 random rows."""
    inputs = [a.copy() for a in inputs]
    n = inputs[0].shape[0]
    for port, arr in zip(spec.inputs, inputs):
        if arr.ndim == 1 and port.name in EDGE_VALUES:
            for v in EDGE_VALUES[port.name]:
                arr[rng.choice(n, 5, replace=False)] = v
        elif arr.ndim == 2 and port.name in VECTOR_EDGES:
            if port.name == "polar" and arr.shape[1] == 2:
                edges = {1: VECTOR_EDGES["polar"][1]}
            else:
                edges = VECTOR_EDGES[port.name]
            for k, values in edges.items():
                for v in values:
                    arr[rng.choice(n, 5, replace=False), k] = v
    return inputs
