"""Building the shared library of the generated C code, once per cache key (see
:mod:`registration._codegen.cbackend`).

Each C source is compiled on its own, as many at a time as this process may use CPUs, largest
first (the twelve Kalman steps take most of the CPU time; started first, the build ends with
the small files), then the objects are linked. The first build takes 11-25 s on this project's
2-core machine and up to about a minute on a slow or single core, so it is announced on standard
error before it starts (:data:`BUILD_MESSAGE`, in logs too) and its end is reported with its
duration; while the sources compile, a progress bar (by bytes of source compiled, about
proportional to the time) shows on standard error when it is a terminal.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from concurrent.futures import ThreadPoolExecutor, as_completed
from pathlib import Path

from registration._codegen.artifacts import ArtifactError

__all__ = ["BUILD_MESSAGE", "build_library", "build_workers"]

#: Printed on standard error before a build ({folder}: the cache folder it goes into).
BUILD_MESSAGE = (
    "registration: compiling the generated C code once (10 s to a minute, by machine; later runs load it "
    "from {folder})..."
)


def build_workers() -> int:
    """How many compilers run at once: the CPUs this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def _progress(total_bytes: int, files: int):
    """A tqdm bar over the bytes of source compiled, on standard error only when it is a terminal.

    The rule of :mod:`registration.core.progress`, drawn at once (the build is the first thing a
    run does); its own bar because ``_codegen`` is the bottom layer and may not import ``core``."""
    from tqdm import tqdm

    try:
        terminal = sys.stderr.isatty()
    except (AttributeError, ValueError):
        terminal = False
    return tqdm(
        total=total_bytes,
        file=sys.stderr,
        disable=not terminal,
        leave=False,
        unit="B",
        unit_scale=True,
        desc=f"compiling 0/{files} files",
        bar_format="{desc}: {percentage:3.0f}%|{bar}| [{elapsed}<{remaining}]",
    )


def _compile_all(cc: str, flags: list[str], jobs: list[tuple[Path, Path, int]]) -> list:
    """Compile each ``(source, object, size in bytes)`` job, largest first, in parallel, with the
    progress bar; the failed compiler runs (CompletedProcess), empty if none failed."""

    def compile_one(job):
        src, obj, _size = job
        return subprocess.run([cc, *flags, "-c", str(src), "-o", str(obj)], capture_output=True, text=True)

    jobs = sorted(jobs, key=lambda job: -job[2])
    failed = []
    with (
        _progress(sum(size for *_rest, size in jobs), len(jobs)) as bar,
        ThreadPoolExecutor(max_workers=build_workers()) as pool,
    ):
        futures = {pool.submit(compile_one, job): job for job in jobs}
        for done, future in enumerate(as_completed(futures), start=1):
            proc = future.result()
            if proc.returncode != 0:
                failed.append(proc)
            bar.set_description_str(f"compiling {done}/{len(jobs)} files", refresh=False)
            bar.update(futures[future][2])
    return failed


def build_library(
    cc: str, drivers: Sequence[Path], sources: list[tuple[str, bytes]], lib_path: Path, flags: list[str]
) -> None:
    """Compile the ``drivers`` (C files) and ``sources`` ((file name, bytes) pairs) with ``flags``
    (``-shared`` is left for the link), link them into ``lib_path`` (published atomically: concurrent builders
    never see half a file); ArtifactError on failure. Says so on standard error before and after."""
    lib_path.parent.mkdir(parents=True, exist_ok=True)
    print(BUILD_MESSAGE.format(folder=lib_path.parent.parent), file=sys.stderr, flush=True)
    started = time.perf_counter()
    flags = [f for f in flags if f != "-shared"]
    with tempfile.TemporaryDirectory(dir=lib_path.parent) as tmp_name:
        tmp = Path(tmp_name)
        jobs = [(driver, tmp / f"driver{i}.o", driver.stat().st_size) for i, driver in enumerate(drivers)]
        for i, (fname, data) in enumerate(sources, start=1):
            (tmp / fname).write_bytes(data)
            jobs.append((tmp / fname, tmp / f"{i}.o", len(data)))
        failed = _compile_all(cc, flags, jobs)
        if failed:
            raise ArtifactError(f"C compilation failed: {failed[0].stderr.strip()[:2000]}")
        out = tmp / "lib.so"
        objects = [str(obj) for _src, obj, _size in jobs]  # link order: drivers, then sources
        proc = subprocess.run(
            [cc, "-shared", "-o", str(out), *objects, "-lm"], capture_output=True, text=True
        )
        if proc.returncode != 0:
            raise ArtifactError(f"C link failed: {proc.stderr.strip()[:2000]}")
        os.replace(out, lib_path)
    print(
        f"registration: compiled in {time.perf_counter() - started:.0f} s into {lib_path.parent}",
        file=sys.stderr,
        flush=True,
    )
