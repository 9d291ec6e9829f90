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
