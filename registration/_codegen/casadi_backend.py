"""The serialized CasADi backend: the hash-checked ``.casadi`` artifacts, evaluated over N points
with ``Function.map`` and in sequence with ``Function.mapaccum`` (no compiler needed)."""

from __future__ import annotations

import numpy as np

from registration._codegen.artifacts import read_artifact

__all__ = ["CasadiKernel", "deserialize"]


def deserialize(data: bytes):
    """The ``casadi.Function`` of a ``.casadi`` artifact (its ``#`` header lines skipped)."""
    import casadi as ca

    lines = [ln for ln in data.decode().splitlines() if ln and not ln.startswith("#")]
    return ca.Function.deserialize("".join(lines))


def _to_dm(prepared, n: int) -> list:
    """Prepared ``(array, batched, core)`` inputs as CasADi matrices, points side by side."""
    import casadi as ca

    dms = []
    for a, batched, core in prepared:
        r = core[0] if core else 1
        c = core[1] if len(core) == 2 else 1
        a2 = a.reshape(n, r, c).transpose(1, 0, 2).reshape(r, n * c) if batched else a.reshape(r, c)
        dms.append(ca.DM(a2))
    return dms


def _by_point(res, n: int, output_shapes):
    """Outputs of a mapped call as ``(n, r, c)`` arrays, one slice per point."""
    import casadi as ca

    res = res if isinstance(res, (list, tuple)) else [res]
    return [
        np.asarray(ca.DM(dm).full()).reshape(r, n, c).transpose(1, 0, 2)
        for dm, (r, c) in zip(res, output_shapes)
    ]


class CasadiKernel:
    """One generated function as its serialized ``casadi.Function``, loaded on first use."""

    def __init__(self, name: str):
        self.name = name
        self._function = None
        self._maps: dict = {}

    def function(self):
        """The deserialized ``casadi.Function`` (artifact hash-checked on first use)."""
        if self._function is None:
            self._function = deserialize(read_artifact(self.name, "casadi"))
        return self._function

    def call(self, prepared, n: int, output_shapes) -> tuple:
        """Evaluate at ``n`` points; outputs shaped (n,), (n, r) or (n, r, c)."""
        if n not in self._maps:
            self._maps = {
                n: self.function().map(n, "serial")
            }  # keep one: big maps are cheap to rebuild, costly to hoard
        arrs = _by_point(self._maps[n](*_to_dm(prepared, n)), n, output_shapes)
        return tuple(
            arr.reshape(n) if (r, c) == (1, 1) else (arr.reshape(n, r) if c == 1 else arr)
            for arr, (r, c) in zip(arrs, output_shapes)
        )

    def scan(self, prepared, n: int, k: int, output_shapes) -> list[np.ndarray]:
        """Evaluate ``n`` steps in sequence, the first ``k`` inputs carried from the first ``k``
        outputs (``mapaccum``); outputs as flat ``(n, r * c)`` buffers, column-major per step."""
        acc = self.function().mapaccum("scan", n, k, {})
        arrs = _by_point(acc(*_to_dm(prepared, n)), n, output_shapes)
        return [arr.transpose(0, 2, 1).reshape(n, r * c) for arr, (r, c) in zip(arrs, output_shapes)]
