"""The run state of a recorded-data run survives a checkpoint bit for bit."""

from __future__ import annotations

import numpy as np

from registration.online import OnlineRegistrar, RegistrationConfig
from registration.online.contract import ROW_COLUMNS
from registration.recorded import load_checkpoint, save_checkpoint
from registration.recorded.reading.rowcheck import Rejection
from registration.recorded.run.runstate import PassPosition, RunState

from ._register_data import scenario


def _equal(a, b) -> bool:
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_equal(a[k], b[k]) for k in a)
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(_equal(x, y) for x, y in zip(a, b))
    if isinstance(a, np.ndarray):
        return a.shape == np.shape(b) and np.array_equal(a, b)
    return type(a) is type(b) and a == b


def test_run_state_round_trips_through_a_checkpoint_exactly(tmp_path):
    config = RegistrationConfig(q_mode="adaptive")
    data = scenario(40).data
    rows = np.stack([data[c] for c in ROW_COLUMNS], axis=1)
    state = RunState(
        OnlineRegistrar(config),
        phase="observability",
        filter_pass=PassPosition(40, float(data["time"][-1])),
        obs_pass=PassPosition(20, 19.0),
        rows_read=41,
        rows_accepted=39,
        filter_rejected={7},
    )
    result = state.registrar.update_block(rows, data["time"])
    state.add_registered(data["time"], result["nis"], rows[:, :3] * 1e-3, rows[:, 9:12] * 1e-3)
    state.add_rejections(
        [
            Rejection("f.csv", 7, "*", "filter_non_finite", "step not finite", "{}"),
            Rejection(
                "f.csv",
                12,
                "a_lat_deg",
                "out_of_range",
                "value 95.0 is outside [-90, 90] deg (latitude)",
                "{}",
            ),
        ]
    )
    state.obs_info, state.obs_used = np.full((12, 12), 1 / 3), 20
    marks = {"estimates": [100, 3], "positions": [200, 3], "rejected": [50, 2]}
    save_checkpoint(tmp_path / "c.ckpt", state.to_checkpoint("f" * 64, marks))
    payload = load_checkpoint(tmp_path / "c.ckpt")
    back = RunState.from_checkpoint(payload, config)
    assert _equal(back.to_checkpoint("f" * 64, marks), state.to_checkpoint("f" * 64, marks))
    assert back.first_rejection == "row 7, column '*': step not finite" and back.rejected == {
        "filter_non_finite": 1,
        "out_of_range": 1,
    }
    # the restored filter continues exactly like the original one
    more = np.ascontiguousarray(rows[::-1])
    times = data["time"][-1] + 1.0 + np.arange(len(more))
    a, b = state.registrar.update_block(more, times), back.registrar.update_block(more, times)
    assert np.array_equal(a["x"], b["x"]) and np.array_equal(a["P"], b["P"])
