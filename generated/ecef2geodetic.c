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
  #define CASADI_PREFIX(ID) ecef2geodetic_ ## ID
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
#define casadi_sq CASADI_PREFIX(sq)

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

casadi_real casadi_sq(casadi_real x) { return x*x;}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void ecef2geodetic_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int ecef2geodetic_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int ecef2geodetic_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};

/* ecef2geodetic:(p_ecef[3])->(geodetic[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10;
  a00=arg[0]? arg[0][2] : 0;
  a01=4.2841311513313573e+04;
  a02=arg[0]? arg[0][0] : 0;
  a03=casadi_sq(a02);
  a04=arg[0]? arg[0][1] : 0;
  a05=casadi_sq(a04);
  a06=(a03+a05);
  a07=sqrt(a06);
  a08=-4.2269639397749110e+04;
  a09=casadi_sq(a00);
  a10=9.9330562000985867e-01;
  a03=(a10*a03);
  a03=(a09+a03);
  a10=(a10*a05);
  a03=(a03+a10);
  a10=sqrt(a03);
  a03=(a03*a10);
  a08=(a08/a03);
  a06=(a06*a07);
  a08=(a08*a06);
  a08=(a07+a08);
  a06=casadi_sq(a08);
  a10=9.9664718933525254e-01;
  a10=(a10*a00);
  a05=4.2697672707179969e+04;
  a05=(a05/a03);
  a09=(a00*a09);
  a05=(a05*a09);
  a10=(a10+a05);
  a05=casadi_sq(a10);
  a09=(a06+a05);
  a03=sqrt(a09);
  a09=(a09*a03);
  a01=(a01/a09);
  a10=(a10*a05);
  a01=(a01*a10);
  a01=(a00+a01);
  a10=-4.2697672707179969e+04;
  a10=(a10/a09);
  a08=(a08*a06);
  a10=(a10*a08);
  a10=(a07+a10);
  a08=atan2(a01,a10);
  if (res[0]!=0) res[0][0]=a08;
  a04=atan2(a04,a02);
  if (res[0]!=0) res[0][1]=a04;
  a04=-6378137.;
  a02=1.;
  a08=-6.6943799901413173e-03;
  a06=casadi_sq(a01);
  a08=(a08*a06);
  a09=casadi_sq(a10);
  a06=(a06+a09);
  a08=(a08/a06);
  a02=(a02+a08);
  a02=sqrt(a02);
  a04=(a04*a02);
  a06=sqrt(a06);
  a07=(a07/a06);
  a07=(a07*a10);
  a04=(a04+a07);
  a01=(a01/a06);
  a01=(a01*a00);
  a04=(a04+a01);
  if (res[0]!=0) res[0][2]=a04;
  return 0;
}

CASADI_SYMBOL_EXPORT int ecef2geodetic(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int ecef2geodetic_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void ecef2geodetic_release(int mem) {
}

CASADI_SYMBOL_EXPORT void ecef2geodetic_incref(void) {
}

CASADI_SYMBOL_EXPORT void ecef2geodetic_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int ecef2geodetic_n_in(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_int ecef2geodetic_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real ecef2geodetic_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* ecef2geodetic_name_in(casadi_int i) {
  switch (i) {
    case 0: return "p_ecef";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* ecef2geodetic_name_out(casadi_int i) {
  switch (i) {
    case 0: return "geodetic";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* ecef2geodetic_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* ecef2geodetic_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int ecef2geodetic_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 1;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int ecef2geodetic_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 1*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


