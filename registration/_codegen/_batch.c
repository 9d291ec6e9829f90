/*
 * Batch driver for CasADi-generated functions (hand-written runtime code, no mathematics).
 *
 * Evaluates one generated function at n points in a plain C loop. Input j of point i starts at
 * in_ptr[j] + i * in_stride[j] (a stride of 0 broadcasts one value to every point); output j of
 * point i is written at out_ptr[j] + i * out_stride[j]. arg/res/iw/w are the work buffers the
 * generated function asks for (sizes from its *_work() query, recorded in the manifest).
 */
typedef long long int casadi_int;
typedef int (*casadi_fn)(const double **arg, double **res, casadi_int *iw, double *w, int mem);

int registration_batch(casadi_fn f, long long n,
                       int n_in, const double *const *in_ptr, const long long *in_stride,
                       int n_out, double *const *out_ptr, const long long *out_stride,
                       const double **arg, double **res, casadi_int *iw, double *w)
{
    for (long long i = 0; i < n; ++i) {
        for (int j = 0; j < n_in; ++j) arg[j] = in_ptr[j] + i * in_stride[j];
        for (int j = 0; j < n_out; ++j) res[j] = out_ptr[j] + i * out_stride[j];
        int flag = f(arg, res, iw, w, 0);
        if (flag) return flag;
    }
    return 0;
}

/*
 * Scan (accumulate) driver: evaluates f n times in sequence. Input j with carry_from[j] >= 0 takes,
 * from the second step on, a copy of output carry_from[j] of the previous step (copied into scratch
 * first, so inputs never alias outputs); in_size[j] is its length in doubles. An output stride of 0
 * keeps only the last step's value. Stops at the first step whose flag is non-zero and returns
 * that step's index + 1 (0 when all steps succeeded).
 */
long long registration_scan(casadi_fn f, long long n,
                            int n_in, const double *const *in_ptr, const long long *in_stride,
                            const int *carry_from, const long long *in_size,
                            int n_out, double *const *out_ptr, const long long *out_stride,
                            const double **arg, double **res, casadi_int *iw, double *w, double *scratch)
{
    for (long long i = 0; i < n; ++i) {
        double *s = scratch;
        for (int j = 0; j < n_in; ++j) {
            int c = carry_from[j];
            if (c >= 0 && i > 0) {
                const double *src = out_ptr[c] + (i - 1) * out_stride[c];
                for (long long k = 0; k < in_size[j]; ++k) s[k] = src[k];
                arg[j] = s;
                s += in_size[j];
            } else {
                arg[j] = in_ptr[j] + i * in_stride[j];
            }
        }
        for (int j = 0; j < n_out; ++j) res[j] = out_ptr[j] + i * out_stride[j];
        if (f(arg, res, iw, w, 0)) return i + 1;
    }
    return 0;
}

/*
 * Batched scan: `runs` independent sequences of n steps each (e.g. Monte Carlo runs), one after
 * the other, each as in registration_scan. Input j of run r, step i starts at
 * in_ptr[j] + r * in_run_stride[j] + i * in_stride[j]; output j at
 * out_ptr[j] + r * out_run_stride[j] + i * out_stride[j]. A carried input starts every run from
 * that run's own initial value. in_base and out_base are n_in and n_out pointer slots (work
 * space). Returns 0 when every step succeeded, else r * n + i + 1 for the first failing step i of
 * the first failing run r (the runs after it are not evaluated).
 */
long long registration_scan_runs(casadi_fn f, long long runs, long long n,
                                 int n_in, const double *const *in_ptr, const long long *in_run_stride,
                                 const long long *in_stride, const int *carry_from, const long long *in_size,
                                 int n_out, double *const *out_ptr, const long long *out_run_stride,
                                 const long long *out_stride,
                                 const double **in_base, double **out_base,
                                 const double **arg, double **res, casadi_int *iw, double *w, double *scratch)
{
    for (long long r = 0; r < runs; ++r) {
        for (int j = 0; j < n_in; ++j) in_base[j] = in_ptr[j] + r * in_run_stride[j];
        for (int j = 0; j < n_out; ++j) out_base[j] = out_ptr[j] + r * out_run_stride[j];
        long long failed = registration_scan(f, n, n_in, in_base, in_stride, carry_from, in_size,
                                             n_out, out_base, out_stride, arg, res, iw, w, scratch);
        if (failed) return r * n + failed;
    }
    return 0;
}

/*
 * One step of a function whose first n_carry inputs are a state carried from its first n_carry
 * outputs (a streaming filter), with persistent buffers: in_ptr[j] holds input j, out_ptr[j]
 * receives output j (never aliasing an input). in_size/out_size are their lengths in doubles.
 *
 * Before evaluating, input check_in (if >= 0) is compared element-wise with [low, high]; a value
 * outside, or NaN, returns REGISTRATION_STEP_OUT_OF_BOUNDS without evaluating. After evaluating,
 * the outputs listed in finite_out[0 .. n_finite) must hold only finite values, else
 * REGISTRATION_STEP_NON_FINITE is returned and the state is left as it was. A non-zero flag of f
 * returns REGISTRATION_STEP_FAILED. On success the first n_carry outputs are copied into the
 * first n_carry inputs (the new state), each output deliver_out[m] (m < n_deliver) is copied to
 * deliver_ptr[m], which then advances past it (the caller's results of consecutive steps land in
 * consecutive rows of its arrays; it resets the pointers before they run out), output ring_out
 * (if >= 0) is copied into row ring_count % ring_len of the ring (the last ring_len values, for a
 * caller that keeps a window of them), ring_count is incremented, and 0 is returned.
 */
#define REGISTRATION_STEP_OUT_OF_BOUNDS 1
#define REGISTRATION_STEP_NON_FINITE 2
#define REGISTRATION_STEP_FAILED 3

typedef struct {
    casadi_fn f;
    int n_in, n_out, n_carry, check_in, n_finite;
    double *const *in_ptr;
    double *const *out_ptr;
    const long long *in_size;
    const long long *out_size;
    const double *low;
    const double *high;
    const int *finite_out;
    const double **arg;
    double **res;
    casadi_int *iw;
    double *w;
    int n_deliver;
    const int *deliver_out;
    double **deliver_ptr;
    int ring_out, ring_len;
    double *ring;
    long long ring_count;
} registration_stepper;

int registration_step(registration_stepper *s)
{
    if (s->check_in >= 0) {
        const double *v = s->in_ptr[s->check_in];
        for (long long k = 0; k < s->in_size[s->check_in]; ++k)
            if (!(v[k] >= s->low[k] && v[k] <= s->high[k])) return REGISTRATION_STEP_OUT_OF_BOUNDS;
    }
    for (int j = 0; j < s->n_in; ++j) s->arg[j] = s->in_ptr[j];
    for (int j = 0; j < s->n_out; ++j) s->res[j] = s->out_ptr[j];
    if (s->f(s->arg, s->res, s->iw, s->w, 0)) return REGISTRATION_STEP_FAILED;
    for (int m = 0; m < s->n_finite; ++m) {
        const double *v = s->out_ptr[s->finite_out[m]];
        for (long long k = 0; k < s->out_size[s->finite_out[m]]; ++k)
            if (!(v[k] - v[k] == 0.0)) return REGISTRATION_STEP_NON_FINITE;  /* inf - inf and NaN are NaN */
    }
    for (int j = 0; j < s->n_carry; ++j) {
        double *dst = s->in_ptr[j];
        const double *src = s->out_ptr[j];
        for (long long k = 0; k < s->in_size[j]; ++k) dst[k] = src[k];
    }
    for (int m = 0; m < s->n_deliver; ++m) {
        int j = s->deliver_out[m];
        double *dst = s->deliver_ptr[m];
        const double *src = s->out_ptr[j];
        for (long long k = 0; k < s->out_size[j]; ++k) dst[k] = src[k];
        s->deliver_ptr[m] = dst + s->out_size[j];
    }
    if (s->ring_out >= 0) {
        long long size = s->out_size[s->ring_out];
        double *dst = s->ring + (s->ring_count % s->ring_len) * size;
        const double *src = s->out_ptr[s->ring_out];
        for (long long k = 0; k < size; ++k) dst[k] = src[k];
    }
    s->ring_count += 1;
    return 0;
}
