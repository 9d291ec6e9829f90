"""Compiler-flags experiment for bench_online.py (not shipped): the generated Kalman step in a plain
C loop built with the loader's flags and with ``-O3 -march=native``, timed per step."""

from __future__ import annotations

import numpy as np

from registration import _codegen
from registration.online.contract import N_STATE

HARNESS = r"""
/* Benchmark harness (not shipped): the generated Kalman step in a plain C loop, x, P, info carried. */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "@SOURCE@"
static double now_ns(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e9 + t.tv_nsec;
}
int main(int argc, char **argv) {
    long n = atol(argv[1]); int repeat = atoi(argv[2]);
    double *in = malloc(sizeof(double) * (size_t)(18 * n + 12 + 3 * 144 + 6));
    FILE *f = fopen(argv[3], "rb");
    size_t n_in = (size_t)(18 * n + 12 + 3 * 144 + 6);
    if (!in || !f || fread(in, sizeof(double), n_in, f) != n_in) return 1;
    fclose(f);
    double *rows = in, *x0 = in + 18 * n, *P0 = x0 + 12, *info0 = P0 + 144, *Q = info0 + 144, *s0 = Q + 144;
    double *xo = malloc(sizeof(double) * 12 * (size_t)n), *Po = malloc(sizeof(double) * 144 * (size_t)n);
    double x[12], P[144], info[144], info2[144], nu[3], S[9], nis, w[@SZ_W@ + 1];
    casadi_int iw[@SZ_IW@ + 1];
    double best = 1e300;
    for (int rep = 0; rep <= repeat; ++rep) {
        memcpy(x, x0, sizeof x); memcpy(P, P0, sizeof P); memcpy(info, info0, sizeof info);
        double t0 = now_ns();
        for (long i = 0; i < n; ++i) {
            const double *arg[6] = {x, P, info, Q, rows + 18 * i, s0};
            double *res[6] = {xo + 12 * i, Po + 144 * i, info2, nu, S, &nis};
            @FUNC@(arg, res, iw, w, 0);
            memcpy(x, xo + 12 * i, sizeof x);
            memcpy(P, Po + 144 * i, sizeof P);
            memcpy(info, info2, sizeof info);
        }
        double dt = (now_ns() - t0) / (double)n;
        if (rep > 0 && dt < best) best = dt;
    }
    printf("%.6f %.17g\n", best / 1e3, xo[12 * (n - 1) + 3]);
    return 0;
}
"""


def flags_experiment(config, rows: np.ndarray, reference_last: np.ndarray, repeat: int) -> dict:
    """The same generated step in a plain C loop, built with the loader's flags and with more
    aggressive (non-portable) ones: how much of the step's cost a compiler setting could remove."""
    import subprocess
    import tempfile
    from pathlib import Path

    cc = _codegen.compiler()
    if cc is None:
        return {}
    name = config.step_name
    work = _codegen.manifest()["functions"][name]["work"]
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        (tmp / f"{name}.c").write_bytes(_codegen.read_artifact(name, "c"))  # the shipped source, hash-checked
        code = HARNESS.replace("@SOURCE@", f"{name}.c").replace("@FUNC@", name)
        code = code.replace("@SZ_W@", str(work["sz_w"])).replace("@SZ_IW@", str(work["sz_iw"]))
        (tmp / "harness.c").write_text(code)
        x0 = np.zeros(N_STATE) if config.x0 is None else np.array(config.x0)
        # matrices in column-major order (CasADi's), all symmetric here anyway
        blob = np.concatenate(
            [
                rows.ravel(),
                x0,
                np.diag(np.square(config.prior_sigma)).ravel(),
                np.zeros(N_STATE * N_STATE),
                np.diag(np.square(config.q_sigma)).ravel(),
                np.array(config.sigma0),
            ]
        )
        blob.astype("<f8").tofile(tmp / "in.bin")
        loader_flags = [f for f in _codegen.CFLAGS if f not in ("-shared", "-fPIC")]
        for label, flags in (
            ("plain C, loader flags " + " ".join(loader_flags), loader_flags),
            ("plain C, -O3 -march=native", ["-O3", "-march=native"]),
        ):
            exe = tmp / ("h" + str(len(out)))
            proc = subprocess.run(
                [cc, *flags, "-o", str(exe), str(tmp / "harness.c"), "-lm"], capture_output=True, text=True
            )
            if proc.returncode != 0:
                out[label] = None
                continue
            res = subprocess.run(
                [str(exe), str(len(rows)), str(repeat), str(tmp / "in.bin")], capture_output=True, text=True
            )
            us, last = (float(v) for v in res.stdout.split())
            if not np.isclose(last, reference_last, rtol=1e-9):
                raise SystemExit(f"{label}: last dr_a estimate {last} != register()'s {reference_last}")
            out[label] = us
    return out
