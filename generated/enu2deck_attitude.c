/*
 * GENERATED FILE - DO NOT EDIT BY HAND.
 * Produced by `python -m derive` from the sympy derivations in derive/.
 * Edit derive/ and regenerate; `python -m derive --check` verifies freshness.
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) enu2deck_attitude_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void enu2deck_attitude_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int enu2deck_attitude_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int enu2deck_attitude_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 3, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};

/* enu2deck_attitude:(R_enu_deck[3x3])->(attitude[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1;
  a0=arg[0]? arg[0][3] : 0;
  a1=arg[0]? arg[0][4] : 0;
  a0=atan2(a0,a1);
  if (res[0]!=0) res[0][0]=a0;
  a0=arg[0]? arg[0][5] : 0;
  a0=asin(a0);
  if (res[0]!=0) res[0][1]=a0;
  a0=arg[0]? arg[0][2] : 0;
  a0=(-a0);
  a1=arg[0]? arg[0][8] : 0;
  a0=atan2(a0,a1);
  if (res[0]!=0) res[0][2]=a0;
  return 0;
}

CASADI_SYMBOL_EXPORT int enu2deck_attitude(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int enu2deck_attitude_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void enu2deck_attitude_release(int mem) {
}

CASADI_SYMBOL_EXPORT void enu2deck_attitude_incref(void) {
}

CASADI_SYMBOL_EXPORT void enu2deck_attitude_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int enu2deck_attitude_n_in(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_int enu2deck_attitude_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real enu2deck_attitude_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* enu2deck_attitude_name_in(casadi_int i) {
  switch (i) {
    case 0: return "R_enu_deck";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* enu2deck_attitude_name_out(casadi_int i) {
  switch (i) {
    case 0: return "attitude";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* enu2deck_attitude_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* enu2deck_attitude_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int enu2deck_attitude_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 1;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int enu2deck_attitude_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 1*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


