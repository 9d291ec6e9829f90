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
  #define CASADI_PREFIX(ID) enu2ecef_rotation_standard_ ## ID
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
CASADI_SYMBOL_EXPORT void enu2ecef_rotation_standard_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int enu2ecef_rotation_standard_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int enu2ecef_rotation_standard_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {1, 1, 1};
static const casadi_int casadi_s1[3] = {3, 3, 1};

/* enu2ecef_rotation_standard:(lat,lon)->(R_ecef_enu[3x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4;
  a0=arg[1]? arg[1][0] : 0;
  a1=sin(a0);
  a2=(-a1);
  if (res[0]!=0) res[0][0]=a2;
  a0=cos(a0);
  if (res[0]!=0) res[0][1]=a0;
  a2=0.;
  if (res[0]!=0) res[0][2]=a2;
  a2=arg[0]? arg[0][0] : 0;
  a3=sin(a2);
  a4=(a0*a3);
  a4=(-a4);
  if (res[0]!=0) res[0][3]=a4;
  a4=(a1*a3);
  a4=(-a4);
  if (res[0]!=0) res[0][4]=a4;
  a2=cos(a2);
  if (res[0]!=0) res[0][5]=a2;
  a0=(a0*a2);
  if (res[0]!=0) res[0][6]=a0;
  a1=(a1*a2);
  if (res[0]!=0) res[0][7]=a1;
  if (res[0]!=0) res[0][8]=a3;
  return 0;
}

CASADI_SYMBOL_EXPORT int enu2ecef_rotation_standard(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int enu2ecef_rotation_standard_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void enu2ecef_rotation_standard_release(int mem) {
}

CASADI_SYMBOL_EXPORT void enu2ecef_rotation_standard_incref(void) {
}

CASADI_SYMBOL_EXPORT void enu2ecef_rotation_standard_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int enu2ecef_rotation_standard_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int enu2ecef_rotation_standard_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real enu2ecef_rotation_standard_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* enu2ecef_rotation_standard_name_in(casadi_int i) {
  switch (i) {
    case 0: return "lat";
    case 1: return "lon";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* enu2ecef_rotation_standard_name_out(casadi_int i) {
  switch (i) {
    case 0: return "R_ecef_enu";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* enu2ecef_rotation_standard_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* enu2ecef_rotation_standard_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int enu2ecef_rotation_standard_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int enu2ecef_rotation_standard_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


