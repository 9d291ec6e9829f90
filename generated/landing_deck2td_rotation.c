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
  #define CASADI_PREFIX(ID) landing_deck2td_rotation_ ## ID
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
#define casadi_s2 CASADI_PREFIX(s2)

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
CASADI_SYMBOL_EXPORT void landing_deck2td_rotation_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int landing_deck2td_rotation_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int landing_deck2td_rotation_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {3, 3, 1};

/* landing_deck2td_rotation:(attitude[3],angled_deck)->(R_td_deck[3x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14;
  a00=arg[0]? arg[0][2] : 0;
  a01=cos(a00);
  a02=arg[0]? arg[0][0] : 0;
  a03=cos(a02);
  a04=(a01*a03);
  a05=arg[0]? arg[0][1] : 0;
  a06=sin(a05);
  a02=sin(a02);
  a00=sin(a00);
  a07=(a02*a00);
  a08=(a06*a07);
  a08=(a04+a08);
  a09=arg[1]? arg[1][0] : 0;
  a10=sin(a09);
  a11=(a08*a10);
  a12=(a03*a06);
  a12=(a12*a00);
  a13=(a01*a02);
  a12=(a12-a13);
  a09=cos(a09);
  a14=(a12*a09);
  a11=(a11-a14);
  if (res[0]!=0) res[0][0]=a11;
  a08=(a08*a09);
  a12=(a10*a12);
  a08=(a08+a12);
  if (res[0]!=0) res[0][1]=a08;
  a05=cos(a05);
  a08=(a05*a00);
  a08=(-a08);
  if (res[0]!=0) res[0][2]=a08;
  a02=(a02*a05);
  a08=(a10*a02);
  a12=(a05*a03);
  a11=(a12*a09);
  a08=(a08-a11);
  if (res[0]!=0) res[0][3]=a08;
  a12=(a10*a12);
  a02=(a02*a09);
  a12=(a12+a02);
  if (res[0]!=0) res[0][4]=a12;
  if (res[0]!=0) res[0][5]=a06;
  a03=(a03*a00);
  a13=(a13*a06);
  a03=(a03-a13);
  a13=(a10*a03);
  a06=(a06*a04);
  a07=(a07+a06);
  a06=(a07*a09);
  a13=(a13+a06);
  if (res[0]!=0) res[0][6]=a13;
  a03=(a03*a09);
  a10=(a10*a07);
  a03=(a03-a10);
  if (res[0]!=0) res[0][7]=a03;
  a01=(a01*a05);
  if (res[0]!=0) res[0][8]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_deck2td_rotation(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int landing_deck2td_rotation_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void landing_deck2td_rotation_release(int mem) {
}

CASADI_SYMBOL_EXPORT void landing_deck2td_rotation_incref(void) {
}

CASADI_SYMBOL_EXPORT void landing_deck2td_rotation_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int landing_deck2td_rotation_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int landing_deck2td_rotation_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real landing_deck2td_rotation_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_deck2td_rotation_name_in(casadi_int i) {
  switch (i) {
    case 0: return "attitude";
    case 1: return "angled_deck";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_deck2td_rotation_name_out(casadi_int i) {
  switch (i) {
    case 0: return "R_td_deck";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_deck2td_rotation_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_deck2td_rotation_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int landing_deck2td_rotation_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_deck2td_rotation_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


