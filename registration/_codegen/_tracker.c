/*
 * Compiled driver of the association's per-sensor tracker (hand-written runtime code; the filter's
 * mathematics are the generated cv_start, cv_predict, cv_gate and cv_update, passed in as function
 * pointers). The loop, the gating and the assignment follow, step for step, the numpy tracker of
 * registration/fleet/association/grouping/tracks.py, which is its reference:
 *
 *  - steps: step k holds scan k of every sensor (plots sorted by sensor within a step);
 *  - the open tracks of the sensors that step are predicted to their sensor's scan time;
 *  - each (track, plot of the same sensor) pair passes a cheap bound first
 *    (|v|^2 < gate * (trace P-_pp + trace R), since d2 >= |v|^2 / trace S), then cv_gate;
 *    a track's no-match cost is (gate + the least log det S of its pairs past the bound) / 2 and a
 *    pair's cost (d2 + log det S) / 2 if d2 < gate;
 *  - a pair that is its track's and its plot's only pair is taken alone if it beats the no-match
 *    cost; the other pairs go to one rectangular assignment (rows: their tracks in track order,
 *    columns: their plots in step order, then one no-match column per row; `forbidden` elsewhere),
 *    solved by the shortest augmenting path algorithm of D. F. Crouse, "On implementing 2D
 *    rectangular assignment algorithms", IEEE Trans. Aerospace and Electronic Systems 52(4), 2016,
 *    in the column order and tie rule of scipy.optimize.linear_sum_assignment, so that the
 *    pairs equal scipy's even where two assignments cost the same;
 *  - paired tracks are updated, the others miss a scan; a plot left over opens a track (new ids in
 *    step order); tracks that missed more than max_missed scans in a row are closed, the others
 *    keep their order.
 *
 * A pair whose d2 or log det is not finite (a covariance that is not positive definite) is no pair.
 *
 * Returns 0, -1 if memory ran out, -2 if an assignment had no finite cost left (cannot happen with
 * the pairs kept), or 1 + the index of the generated function whose flag was non-zero (0 start,
 * 1 predict, 2 gate, 3 update).
 */
#include <math.h>
#include <stdlib.h>
/* No fused multiply-add in this file: the bound and the costs must round as the numpy reference
 * does (the generated functions are the same compiled code in both). */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif
#include <string.h>
#include <time.h>

typedef long long int casadi_int;
typedef int (*casadi_fn)(const double **arg, double **res, casadi_int *iw, double *w, int mem);

typedef struct {
    casadi_fn f[4]; /* start, predict, gate, update */
    const double **arg;
    double **res;
    casadi_int *iw;
    double *w;
} tracker_filter;

typedef struct {
    long long n, cap, next_id;
    long long *sensor, *id, *missed;
    double *t, *x, *P;
} track_set;

static int grow(void **p, size_t size, long long cap)
{
    void *q = realloc(*p, size * (size_t)(cap > 0 ? cap : 1));
    if (!q) return -1;
    *p = q;
    return 0;
}

static int tracks_reserve(track_set *T, long long need)
{
    if (need <= T->cap) return 0;
    long long cap = T->cap ? T->cap : 64;
    while (cap < need) cap *= 2;
    if (grow((void **)&T->sensor, sizeof(long long), cap) || grow((void **)&T->id, sizeof(long long), cap) ||
        grow((void **)&T->missed, sizeof(long long), cap) || grow((void **)&T->t, sizeof(double), cap) ||
        grow((void **)&T->x, 6 * sizeof(double), cap) || grow((void **)&T->P, 36 * sizeof(double), cap))
        return -1;
    T->cap = cap;
    return 0;
}

static void tracks_free(track_set *T)
{
    free(T->sensor); free(T->id); free(T->missed); free(T->t); free(T->x); free(T->P);
}

static int call(tracker_filter *F, int which, const double *in0, const double *in1, const double *in2,
                const double *in3, double *out0, double *out1)
{
    F->arg[0] = in0; F->arg[1] = in1; F->arg[2] = in2; F->arg[3] = in3;
    F->res[0] = out0; F->res[1] = out1;
    return F->f[which](F->arg, F->res, F->iw, F->w, 0) ? which + 1 : 0;
}

/* The rectangular assignment (nr <= nc) of cost (row-major nr x nc, finite): col4row (nr); returns 0,
 * or -2 when a row finds no finite column (scipy's "infeasible"). Work: u (nr), v, spc, (nc)
 * doubles; path, row4col, remaining (nc) and SR (nr), SC (nc) chars. */
static int assign(long long nr, long long nc, const double *cost, long long *col4row, double *u,
                   double *v, double *spc, long long *path, long long *row4col, long long *remaining,
                   char *SR, char *SC)
{
    if (nr <= 0 || nc <= 0) return 0;
    for (long long i = 0; i < nr; ++i) { u[i] = 0.0; col4row[i] = -1; }
    for (long long j = 0; j < nc; ++j) { v[j] = 0.0; row4col[j] = -1; path[j] = -1; }
    for (long long cur = 0; cur < nr; ++cur) {
        long long n_rem = nc, i = cur, sink = -1;
        double min_val = 0.0;
        for (long long it = 0; it < nc; ++it) remaining[it] = nc - it - 1;
        memset(SR, 0, (size_t)nr);
        memset(SC, 0, (size_t)nc);
        for (long long j = 0; j < nc; ++j) spc[j] = INFINITY;
        while (sink == -1) {
            long long index = -1;
            double lowest = INFINITY;
            SR[i] = 1;
            for (long long it = 0; it < n_rem; ++it) {
                long long j = remaining[it];
                double r = min_val + cost[i * nc + j] - u[i] - v[j];
                if (r < spc[j]) { path[j] = i; spc[j] = r; }
                if (spc[j] < lowest || (spc[j] == lowest && row4col[j] == -1)) { lowest = spc[j]; index = it; }
            }
            min_val = lowest;
            if (index < 0 || !(min_val < INFINITY)) return -2;
            long long j = remaining[index];
            if (row4col[j] == -1) sink = j; else i = row4col[j];
            SC[j] = 1;
            remaining[index] = remaining[--n_rem];
        }
        u[cur] += min_val;
        for (long long r = 0; r < nr; ++r)
            if (SR[r] && r != cur) u[r] += min_val - spc[col4row[r]];
        for (long long j = 0; j < nc; ++j)
            if (SC[j]) v[j] -= min_val - spc[j];
        long long j = sink;
        for (;;) {
            long long r = path[j];
            row4col[j] = r;
            long long tmp = col4row[r]; col4row[r] = j; j = tmp;
            if (r == cur) break;
        }
    }
    return 0;
}

/* The assignment alone (for tests against scipy): col4row (nr) of cost (nr x nc row-major, nr <= nc,
 * finite). Returns 0, -1 if memory ran out, -2 if a row has no finite cost. */
int registration_assign(long long nr, long long nc, const double *cost, long long *col4row)
{
    double *u = malloc(sizeof(double) * (size_t)(nr + 2 * nc + 1));
    long long *idx = malloc(sizeof(long long) * (size_t)(3 * nc + 1));
    char *flags = malloc((size_t)(nr + nc + 1));
    int status = (u && idx && flags) ? 0 : -1;
    if (!status)
        status = assign(nr, nc, cost, col4row, u, u + nr, u + nr + nc, idx, idx + nc, idx + 2 * nc, flags, flags + nr);
    free(u); free(idx); free(flags);
    return status;
}

/* Scratch of one step, grown as needed: per live track (L), per plot of the step (M), per pair past
 * the bound (K), per assignment column (C + R <= M + L) and the assignment matrix. */
typedef struct {
    long long cap_l, cap_m, cap_k, cap_c, cap_mat;
    long long *live, *n_of_track, *row_of, *match_of_track, *rows, *col4row; /* L */
    double *xp, *Pp, *best, *u;                                              /* L */
    char *SR;                                                                /* L */
    long long *n_of_plot, *col_of, *match_of_plot, *cols;                    /* M */
    long long *pair_l, *pair_j;                                              /* K */
    double *pair_cost;                                                       /* K */
    long long *path, *row4col, *remaining;                                   /* C */
    double *v, *spc;                                                         /* C */
    char *SC;                                                                /* C */
    double *matrix;
} scratch;

#define GROW(field, n, size) grow((void **)&S->field, (size), (n))

static long long doubled(long long cap, long long need)
{
    long long c = cap ? cap : 64;
    while (c < need) c *= 2;
    return c;
}

static int scratch_reserve(scratch *S, long long L, long long M, long long K, long long C, long long mat)
{
    if (L > S->cap_l) {
        long long c = doubled(S->cap_l, L);
        size_t ll = sizeof(long long), d = sizeof(double);
        if (GROW(live, c, ll) || GROW(n_of_track, c, ll) || GROW(row_of, c, ll) || GROW(match_of_track, c, ll) ||
            GROW(rows, c, ll) || GROW(col4row, c, ll) || GROW(xp, c, 6 * d) || GROW(Pp, c, 36 * d) ||
            GROW(best, c, d) || GROW(u, c, d) || GROW(SR, c, 1))
            return -1;
        S->cap_l = c;
    }
    if (M > S->cap_m) {
        long long c = doubled(S->cap_m, M);
        size_t ll = sizeof(long long);
        if (GROW(n_of_plot, c, ll) || GROW(col_of, c, ll) || GROW(match_of_plot, c, ll) || GROW(cols, c, ll))
            return -1;
        S->cap_m = c;
    }
    if (K > S->cap_k) {
        long long c = doubled(S->cap_k, K);
        if (GROW(pair_l, c, sizeof(long long)) || GROW(pair_j, c, sizeof(long long)) ||
            GROW(pair_cost, c, sizeof(double)))
            return -1;
        S->cap_k = c;
    }
    if (C > S->cap_c) {
        long long c = doubled(S->cap_c, C);
        size_t ll = sizeof(long long), d = sizeof(double);
        if (GROW(path, c, ll) || GROW(row4col, c, ll) || GROW(remaining, c, ll) || GROW(v, c, d) ||
            GROW(spc, c, d) || GROW(SC, c, 1))
            return -1;
        S->cap_c = c;
    }
    if (mat > S->cap_mat) {
        long long c = doubled(S->cap_mat, mat);
        if (GROW(matrix, c, sizeof(double))) return -1;
        S->cap_mat = c;
    }
    return 0;
}

static void scratch_free(scratch *S)
{
    void *all[] = {S->live, S->n_of_track, S->row_of, S->match_of_track, S->rows, S->col4row, S->xp, S->Pp,
                   S->best, S->u, S->SR, S->n_of_plot, S->col_of, S->match_of_plot, S->cols, S->pair_l,
                   S->pair_j, S->pair_cost, S->path, S->row4col, S->remaining, S->v, S->spc, S->SC, S->matrix};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; ++k) free(all[k]);
}

/* The pairs of one step past the bound and inside the gate, the no-match costs; -1 out of memory,
 * else the flag of call(). Plots of the step: step[0..m), their sensors sorted; lo/hi: the step's
 * plot range of each sensor. */
static int step_pairs(tracker_filter *F, scratch *S, const track_set *T, long long n_live, const long long *step,
                      long long m, const long long *lo, const long long *hi, const double *p, const double *cov,
                      const double *trace, double gate, long long *n_pairs)
{
    long long k = 0;
    for (long long l = 0; l < n_live; ++l) {
        long long tr = S->live[l], s = T->sensor[tr];
        const double *xp = S->xp + 6 * l, *Pp = S->Pp + 36 * l;
        double trP = Pp[0] + Pp[7] + Pp[14];
        S->best[l] = INFINITY;
        S->n_of_track[l] = 0;
        if (scratch_reserve(S, 0, 0, k + (hi[s] - lo[s]), 0, 0)) return -1;
        for (long long j = lo[s]; j < hi[s]; ++j) {
            long long plot = step[j];
            const double *z = p + 3 * plot;
            double v0 = z[0] - xp[0], v1 = z[1] - xp[1], v2 = z[2] - xp[2];
            if (!(v0 * v0 + v1 * v1 + v2 * v2 < gate * (trP + trace[plot]))) continue;
            double d2, logdet;
            int flag = call(F, 2, xp, Pp, z, cov + 9 * plot, &d2, &logdet);
            if (flag) return flag;
            if (!isfinite(d2) || !isfinite(logdet)) continue;
            if (logdet < S->best[l]) S->best[l] = logdet;
            if (d2 < gate) {
                S->pair_l[k] = l; S->pair_j[k] = j; S->pair_cost[k] = 0.5 * (d2 + logdet);
                ++k;
            }
        }
    }
    (void)m;
    *n_pairs = k;
    return 0;
}

/* Pairs taken (match_of_track[l] = j, match_of_plot[j] = l; -1 where none) from the step's pairs. */
static int step_assign(scratch *S, long long n_live, long long m, long long n_pairs, double gate, double forbidden,
                       long long *n_calls, double *seconds)
{
    for (long long l = 0; l < n_live; ++l) { S->n_of_track[l] = 0; S->match_of_track[l] = -1; S->row_of[l] = -1; }
    for (long long j = 0; j < m; ++j) { S->n_of_plot[j] = 0; S->match_of_plot[j] = -1; S->col_of[j] = -1; }
    for (long long k = 0; k < n_pairs; ++k) { S->n_of_track[S->pair_l[k]]++; S->n_of_plot[S->pair_j[k]]++; }
    long long R = 0, C = 0;
    for (long long k = 0; k < n_pairs; ++k) {
        long long l = S->pair_l[k], j = S->pair_j[k];
        if (S->n_of_track[l] == 1 && S->n_of_plot[j] == 1) {
            if (S->pair_cost[k] < 0.5 * (gate + S->best[l])) { S->match_of_track[l] = j; S->match_of_plot[j] = l; }
        } else {
            if (S->row_of[l] < 0) { S->row_of[l] = R; S->rows[R++] = l; } /* pairs come in track order */
            S->col_of[j] = -2; /* marked; numbered below, in step order */
        }
    }
    if (R == 0) return 0;
    for (long long j = 0; j < m; ++j)
        if (S->col_of[j] == -2) { S->col_of[j] = C; S->cols[C++] = j; }
    long long nc = C + R;
    if (scratch_reserve(S, 0, 0, 0, nc, R * nc)) return -1;
    double *A = S->matrix;
    for (long long i = 0; i < R * nc; ++i) A[i] = forbidden;
    for (long long r = 0; r < R; ++r) A[r * nc + C + r] = 0.5 * (gate + S->best[S->rows[r]]);
    for (long long k = 0; k < n_pairs; ++k) {
        long long l = S->pair_l[k], j = S->pair_j[k];
        if (!(S->n_of_track[l] == 1 && S->n_of_plot[j] == 1))
            A[S->row_of[l] * nc + S->col_of[j]] = S->pair_cost[k];
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int status = assign(R, nc, A, S->col4row, S->u, S->v, S->spc, S->path, S->row4col, S->remaining, S->SR, S->SC);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    *seconds += (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    ++*n_calls;
    if (status) return status;
    for (long long r = 0; r < R; ++r) {
        long long c = S->col4row[r];
        if (c < C && A[r * nc + c] < forbidden) {
            S->match_of_track[S->rows[r]] = S->cols[c];
            S->match_of_plot[S->cols[c]] = S->rows[r];
        }
    }
    return 0;
}

/* The tracks of every sensor's plots (module comment). Plots: p (N x 3, m), cov (N x 3 x 3, m^2,
 * column-major), trace (N, m^2: of cov), time (N, s), sensor (N, 0 .. n_sensors - 1). Steps: plot
 * indices step_plots, step s being step_plots[bounds[s] .. bounds[s + 1]) sorted by sensor.
 * Out: track (N): the track id of each plot; stats[0] += seconds in the assignment; calls[0] += the
 * assignments solved. */
int registration_tracks(casadi_fn start, casadi_fn predict, casadi_fn gate_fn, casadi_fn update,
                        const double **arg, double **res, casadi_int *iw, double *w,
                        long long n_steps, const long long *bounds, const long long *step_plots,
                        const double *p, const double *cov, const double *trace, const double *time,
                        const long long *sensor, long long n_sensors,
                        double gate, double forbidden, double accel_sigma, double max_speed, long long max_missed,
                        long long *track, double *seconds, long long *calls)
{
    tracker_filter F = {{start, predict, gate_fn, update}, arg, res, iw, w};
    track_set T;
    scratch S;
    memset(&T, 0, sizeof T);
    memset(&S, 0, sizeof S);
    int status = 0;
    long long *stamp = calloc((size_t)(n_sensors > 0 ? n_sensors : 1), sizeof(long long));
    long long *lo = calloc((size_t)(n_sensors > 0 ? n_sensors : 1), sizeof(long long));
    long long *hi = calloc((size_t)(n_sensors > 0 ? n_sensors : 1), sizeof(long long));
    double *scan_time = calloc((size_t)(n_sensors > 0 ? n_sensors : 1), sizeof(double));
    if (!stamp || !lo || !hi || !scan_time) { status = -1; goto done; }
    for (long long st = 0; st < n_steps; ++st) {
        const long long *step = step_plots + bounds[st];
        long long m = bounds[st + 1] - bounds[st];
        for (long long j = 0; j < m; ++j) {
            long long s = sensor[step[j]];
            if (stamp[s] != st + 1) { stamp[s] = st + 1; lo[s] = j; }
            hi[s] = j + 1;
            scan_time[s] = time[step[j]];
        }
        long long n_live = 0;
        if (scratch_reserve(&S, T.n, m, 0, 0, 0)) { status = -1; goto done; }
        for (long long k = 0; k < T.n; ++k)
            if (stamp[T.sensor[k]] == st + 1) S.live[n_live++] = k;
        for (long long l = 0; l < n_live; ++l) {
            long long k = S.live[l];
            double dt = scan_time[T.sensor[k]] - T.t[k];
            if ((status = call(&F, 1, T.x + 6 * k, T.P + 36 * k, &dt, &accel_sigma, S.xp + 6 * l, S.Pp + 36 * l)))
                goto done;
        }
        long long n_pairs = 0;
        if ((status = step_pairs(&F, &S, &T, n_live, step, m, lo, hi, p, cov, trace, gate, &n_pairs))) goto done;
        if ((status = step_assign(&S, n_live, m, n_pairs, gate, forbidden, calls, seconds))) goto done;
        for (long long l = 0; l < n_live; ++l) {
            long long k = S.live[l], j = S.match_of_track[l];
            if (j < 0) { T.missed[k] += 1; continue; }
            long long plot = step[j];
            if ((status = call(&F, 3, S.xp + 6 * l, S.Pp + 36 * l, p + 3 * plot, cov + 9 * plot, T.x + 6 * k,
                               T.P + 36 * k)))
                goto done;
            T.t[k] = time[plot];
            T.missed[k] = 0;
            track[plot] = T.id[k];
        }
        if (tracks_reserve(&T, T.n + m)) { status = -1; goto done; }
        for (long long j = 0; j < m; ++j) {
            if (S.match_of_plot[j] >= 0) continue;
            long long plot = step[j], k = T.n++;
            if ((status = call(&F, 0, p + 3 * plot, cov + 9 * plot, &max_speed, NULL, T.x + 6 * k, T.P + 36 * k)))
                goto done;
            T.sensor[k] = sensor[plot];
            T.id[k] = T.next_id++;
            T.t[k] = time[plot];
            T.missed[k] = 0;
            track[plot] = T.id[k];
        }
        long long kept = 0;
        for (long long k = 0; k < T.n; ++k) {
            if (T.missed[k] > max_missed) continue;
            if (kept != k) {
                T.sensor[kept] = T.sensor[k]; T.id[kept] = T.id[k]; T.missed[kept] = T.missed[k];
                T.t[kept] = T.t[k];
                memcpy(T.x + 6 * kept, T.x + 6 * k, 6 * sizeof(double));
                memcpy(T.P + 36 * kept, T.P + 36 * k, 36 * sizeof(double));
            }
            ++kept;
        }
        T.n = kept;
    }
done:
    free(stamp); free(lo); free(hi); free(scan_time);
    tracks_free(&T);
    scratch_free(&S);
    return status;
}
