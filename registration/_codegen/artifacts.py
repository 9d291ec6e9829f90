"""The generated artifacts of this copy of the package and what their manifest records.

Finds ``generated/`` (source checkout) or the installed ``registration/_generated``, reads
``manifest.json``, and hands out artifact bytes only after checking their sha256 against it.
Also exposes the manifest's derivation facts the runtime must not retype: the variant names
derive emitted and the WGS-84 constants.
"""

from __future__ import annotations

import hashlib
import json
from functools import lru_cache
from pathlib import Path

__all__ = ["ArtifactError", "generated_dir", "manifest", "read_artifact", "variants", "wgs84"]


class ArtifactError(RuntimeError):
    """A generated artifact is missing, tampered with, or does not match the manifest."""


@lru_cache(maxsize=1)
def generated_dir() -> Path:
    """The artifacts of *this* copy of the package: ``generated/`` beside it in a source checkout,
    else the installed ``registration/_generated`` (never another checkout's editable install)."""
    package = Path(__file__).resolve().parent.parent
    for path in (package / "_generated", package.parent / "generated"):
        if (path / "manifest.json").exists():
            return path
    try:
        from importlib.resources import files

        path = Path(str(files("registration._generated")))
        if (path / "manifest.json").exists():
            return path
    except ImportError:
        pass
    raise ArtifactError(
        "cannot find the generated artifacts (registration/_generated or generated/manifest.json); "
        "run `python -m derive` in a source checkout and reinstall"
    )


@lru_cache(maxsize=1)
def manifest() -> dict:
    """The parsed ``manifest.json`` of :func:`generated_dir` (read once per process)."""
    return json.loads((generated_dir() / "manifest.json").read_text())


def read_artifact(name: str, kind: str) -> bytes:
    """The bytes of function ``name``'s artifact of ``kind`` ("c" source or "casadi" serialized),
    after checking their sha256 against the manifest; ArtifactError if unknown, missing or changed."""
    meta = manifest()["functions"].get(name)
    if meta is None:
        raise ArtifactError(f"no generated function named {name!r}; known: {sorted(manifest()['functions'])}")
    art = meta["artifacts"][kind]
    path = generated_dir() / art["file"]
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise ArtifactError(f"generated artifact {path} is missing: {exc}") from exc
    digest = hashlib.sha256(data).hexdigest()
    if digest != art["sha256"]:
        raise ArtifactError(
            f"generated artifact {path} does not match manifest.json (sha256 {digest[:12]}... != "
            f"{art['sha256'][:12]}...): it was edited or is stale; run `python -m derive` and reinstall"
        )
    return data


def variants(kind: str) -> tuple[str, ...]:
    """The variant names derive emitted functions for, in derive's order: kind "linearization"
    (Kalman step linearizations) or "t_variant" (ENU -> ECEF rotation variants)."""
    known = manifest().get("variants", {})
    if kind not in known:
        raise ValueError(f"unknown variant kind {kind!r}; the manifest records {sorted(known)}")
    return tuple(known[kind])


def wgs84() -> dict[str, float]:
    """The WGS-84 constants derive used, as recorded in the manifest: ``wgs84_a_m`` (semi-major
    axis, m), ``wgs84_b_m`` (semi-minor axis, m), ``wgs84_f`` (flattening), ``wgs84_e2``
    (first eccentricity squared). A new dict on each call."""
    return {k: float(v) for k, v in manifest()["constants"].items() if k.startswith("wgs84_")}
