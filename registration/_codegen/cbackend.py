"""The compiled C backend: build the shipped C sources once into a cached shared library and
call the generated functions through ctypes with numpy buffers passed by pointer.

The library holds every generated function plus the hand-written drivers (:data:`DRIVERS`): the
batch and scan loops of ``_batch.c`` and the association's tracker loop of ``_tracker.c``. It
is built once per source hash in a per-user cache (``$REGISTRATION_CACHE_DIR``, else
``$XDG_CACHE_HOME`` or ``~/.cache``, subfolder ``sensor-registration``), keyed by the sources,
the driver, the compiler, the flags and the platform; the build (:mod:`registration._codegen.build`)
compiles the sources in parallel and says so on standard error. Values cross the boundary in
CasADi's layout: float64, column-major per point (the calls: :mod:`registration._codegen.ckernel`).

Builds (``$REGISTRATION_NATIVE``, see :func:`build_mode`): ``portable`` (:data:`CFLAGS`, the
default), whose results equal the serialized CasADi functions to the backend tests' 1e-12; and
two for the local CPU (``-march=native``), opt-in: ``native`` (``REGISTRATION_NATIVE=1``), the
fastest, where the compiler may fuse a multiply and an add into one instruction (one rounding
instead of two), so results differ from the portable build's by rounding, within
:data:`NATIVE_RTOL`; and ``native-exact`` (``REGISTRATION_NATIVE=exact``), which forbids that
fusion (``-ffp-contract=off``) and so rounds every operation as the portable build does: the
same results bit for bit, a little less speed. Each build has its own cache key, which for the
native ones also holds what ``-march=native`` means on this machine, so a cache shared between
machines never hands one CPU's build to another.
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import platform
import shutil
import subprocess
import sys
import warnings
from functools import lru_cache
from pathlib import Path

from registration._codegen.artifacts import ArtifactError, manifest, read_artifact
from registration._codegen.build import build_library

__all__ = [
    "BUILD_MODES",
    "CFLAGS",
    "DRIVERS",
    "NATIVE_CFLAGS",
    "NATIVE_ENV",
    "NATIVE_RTOL",
    "build_mode",
    "cache_root",
    "cflags",
    "compiler",
    "library",
    "library_of",
    "native_target",
]

#: Compiler flags of the portable shared library (each source is compiled with these minus ``-shared``;
#: the build itself, announced on standard error: :mod:`registration._codegen.build`).
CFLAGS = ["-O2", "-fPIC", "-shared"]
#: Flags of the opt-in builds for the local CPU, by build mode.
NATIVE_CFLAGS = {
    "native": ["-O3", "-march=native", "-fPIC", "-shared"],
    "native-exact": ["-O3", "-march=native", "-ffp-contract=off", "-fPIC", "-shared"],
}
#: Build modes, and the values of ``$REGISTRATION_NATIVE`` that select them.
BUILD_MODES = ("portable", "native", "native-exact")
_MODE_OF_ENV = {
    "": "portable",
    "0": "portable",
    "false": "portable",
    "no": "portable",
    "off": "portable",
    "1": "native",
    "true": "native",
    "yes": "native",
    "on": "native",
    "exact": "native-exact",
}
#: Stated tolerance of the ``native`` build against the portable one for the Kalman step, per
#: step at the same inputs, on the filter's own statistical scale: each estimate within
#: ``NATIVE_RTOL`` of its standard deviation (sqrt of the diagonal of the new P), each entry of
#: P, the information and S within ``NATIVE_RTOL * sqrt(M_ii * M_jj)``, each innovation within
#: ``NATIVE_RTOL`` of its standard deviation (from S), the NIS within ``NATIVE_RTOL * max(1, NIS)``.
#: Why this scale: a fused multiply-add changes one rounding by at most half a unit (2^-53
#: relative) of the values it combines; the ill-conditioned P of a filter is mostly a diagonal
#: scaling (angles in rad next to ranges in m, sigmas from 1e-12 to 1e5), and the step's outputs
#: measured in standard deviations do not change under such a scaling, so the difference on this
#: scale does not grow with cond(P). Measured over 3000 steps each of the default prior and of
#: priors with cond(P) up to 1e37 (cond(S) up to 3e4), Joseph and Carlson, ``paper`` and
#: ``fitted``: at most 7.6e-12 (the NIS; the innovation 5.3e-12: it is a difference of ECEF
#: positions of about 6.4e6 m, whose rounding, ~1e-9 m, it inherits, so for innovation sigmas
#: well below a metre its figure would grow as 1/sigma). The stated bound leaves a factor of 13.
NATIVE_RTOL = 1e-10
#: The environment variable that selects the build.
NATIVE_ENV = "REGISTRATION_NATIVE"
#: The hand-written drivers compiled into the library: the batch, scan and step loops, and the
#: association's tracker loop (:mod:`registration._codegen.ctracker`).
DRIVERS = (Path(__file__).with_name("_batch.c"), Path(__file__).with_name("_tracker.c"))
LIBRARY_NAME = "libregistration_generated.so"


def build_mode() -> str:
    """The build ``$REGISTRATION_NATIVE`` asks for: ``portable`` if unset, empty or 0 (false, no,
    off); ``native`` if 1 (true, yes, on); ``native-exact`` if ``exact``; ValueError otherwise."""
    value = os.environ.get(NATIVE_ENV, "")
    mode = _MODE_OF_ENV.get(value.strip().lower())
    if mode is None:
        raise ValueError(
            f"{NATIVE_ENV} must be 0, 1 or exact (0/1 also as false/true, no/yes, off/on), got {value!r}"
        )
    return mode


def cflags(mode: str = "portable") -> list[str]:
    """The compiler flags of build ``mode`` (one of :data:`BUILD_MODES`)."""
    if mode not in BUILD_MODES:
        raise ValueError(f"build mode must be one of {', '.join(BUILD_MODES)}, got {mode!r}")
    return list(CFLAGS if mode == "portable" else NATIVE_CFLAGS[mode])


@lru_cache(maxsize=None)
def native_target(cc: str) -> str | None:
    """What ``-march=native`` means for ``cc`` on this machine (the options the compiler driver
    expands it to, paths left out), or None if ``cc`` does not accept ``-march=native``."""
    try:
        proc = subprocess.run(
            [cc, "-march=native", "-###", "-x", "c", "-c", os.devnull, "-o", os.devnull],
            capture_output=True,
            text=True,
            timeout=60,
        )
    except (OSError, subprocess.SubprocessError):
        return None
    if proc.returncode != 0:
        return None
    return " ".join(t for t in (proc.stdout + proc.stderr).split() if "/" not in t)


def cache_root() -> Path:
    """The folder holding the compiled libraries, one subfolder per cache key."""
    if os.environ.get("REGISTRATION_CACHE_DIR"):
        return Path(os.environ["REGISTRATION_CACHE_DIR"])
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "sensor-registration"


def compiler() -> str | None:
    """The C compiler to use: ``$CC``, else cc, gcc or clang on the PATH; None if there is none."""
    return os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")


def cache_key(
    cc: str, sources: list[tuple[str, bytes]], flags: list[str] | None = None, target: str = ""
) -> str:
    """Key of the library built by ``cc`` with ``flags`` (default :data:`CFLAGS`) from ``sources``
    ((file name, bytes) pairs) and the drivers; ``target`` what ``-march=native`` means, if used."""
    key = hashlib.sha256()
    for fname, data in sources:
        key.update(fname.encode() + data)
    for driver in DRIVERS:
        key.update(driver.read_bytes())
    key.update(
        " ".join([cc, *(CFLAGS if flags is None else flags), platform.machine(), sys.platform]).encode()
    )
    if target:
        key.update(target.encode())
    return key.hexdigest()[:24]


def library_of(names, mode: str = "portable") -> ctypes.CDLL:
    """A shared library of the generated functions ``names`` and the drivers, built with the flags
    of ``mode`` (built if not cached, loaded once per process); ArtifactError if impossible (no
    compiler, or a native mode and the compiler does not accept ``-march=native``)."""
    cflags(mode)  # checks the mode
    return _library_of(tuple(names), mode)


@lru_cache(maxsize=None)
def _library_of(names: tuple[str, ...], mode: str) -> ctypes.CDLL:
    cc = compiler()
    if cc is None:
        raise ArtifactError("no C compiler found (set CC)")
    target = "" if mode == "portable" else native_target(cc)
    if target is None:
        raise ArtifactError(f"the C compiler {cc} does not accept -march=native")
    flags = cflags(mode)
    sources = [(f"{n}.c", read_artifact(n, "c")) for n in names]
    lib_path = cache_root() / cache_key(cc, sources, flags, target) / LIBRARY_NAME
    if not lib_path.exists():
        build_library(cc, DRIVERS, sources, lib_path, flags)
    lib = ctypes.CDLL(str(lib_path))
    lib.registration_batch.restype = ctypes.c_int
    lib.registration_scan.restype = ctypes.c_longlong
    lib.registration_scan_runs.restype = ctypes.c_longlong
    lib.registration_step.restype = ctypes.c_int
    lib.registration_tracks.restype = ctypes.c_int
    lib.registration_assign.restype = ctypes.c_int
    return lib


@lru_cache(maxsize=1)
def library() -> ctypes.CDLL:
    """The shared library of every generated function, built as :func:`build_mode` asks (built if
    not cached); ArtifactError if impossible. A native build that cannot be made (a compiler
    without ``-march=native``) falls back to the portable one, with a warning."""
    names = tuple(sorted(manifest()["functions"]))
    mode = build_mode()
    if mode != "portable":
        try:
            return library_of(names, mode)
        except ArtifactError as exc:
            warnings.warn(
                f"{NATIVE_ENV}: no {mode} build ({exc}); using the portable one", RuntimeWarning, stacklevel=2
            )
    return library_of(names)
