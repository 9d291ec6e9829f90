"""Access to the generated functions (``generated/``) for the runtime: hash-checked artifacts and
what their manifest records (:mod:`.artifacts`), the compiled C backend (:mod:`.cbackend`, its
one-time build in :mod:`.build`, the calls through ctypes in :mod:`.ckernel`), the serialized
CasADi fallback (:mod:`.casadi_backend`), the numpy callables on top (:mod:`.function`) and their
carried-state steppers (:mod:`.stepper`, compiled: :mod:`.cstepper`) and the association's compiled
tracker loop (:mod:`.ctracker`). The runtime calls them by
name with keyword inputs through the typed wrappers ``python -m derive`` emits beside them
(``registration._generated.api``). Users call the capability subpackages, not this one."""

from registration._codegen.artifacts import (
    ArtifactError,
    generated_dir,
    manifest,
    read_artifact,
    variants,
    wgs84,
)
from registration._codegen.cbackend import CFLAGS, compiler
from registration._codegen.ctracker import CompiledTracks, compiled_assignment, compiled_tracks
from registration._codegen.function import BoundCall, GeneratedFunction, backend, get
from registration._codegen.stepper import StepCode

__all__ = [
    "CFLAGS",
    "ArtifactError",
    "BoundCall",
    "CompiledTracks",
    "GeneratedFunction",
    "backend",
    "compiled_assignment",
    "compiled_tracks",
    "compiler",
    "generated_dir",
    "get",
    "manifest",
    "read_artifact",
    "StepCode",
    "variants",
    "wgs84",
]
