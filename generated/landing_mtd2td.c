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
  #define CASADI_PREFIX(ID) landing_mtd2td_ ## ID
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
CASADI_SYMBOL_EXPORT void landing_mtd2td_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int landing_mtd2td_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int landing_mtd2td_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};

/* landing_mtd2td:(p_mtd[3],attitude[3],angled_deck,l_td_deck[3])->(p_td[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19;
  a00=arg[0]? arg[0][0] : 0;
  a01=arg[3]? arg[3][0] : 0;
  a02=-1.;
  a03=arg[1]? arg[1][2] : 0;
  a04=cos(a03);
  a05=arg[1]? arg[1][0] : 0;
  a06=cos(a05);
  a07=(a04*a06);
  a08=(a02+a07);
  a09=arg[1]? arg[1][1] : 0;
  a10=sin(a09);
  a05=sin(a05);
  a03=sin(a03);
  a11=(a05*a03);
  a12=(a10*a11);
  a08=(a08+a12);
  a12=arg[2]? arg[2][0] : 0;
  a13=sin(a12);
  a14=(a08*a13);
  a15=(a06*a10);
  a15=(a15*a03);
  a16=(a04*a05);
  a15=(a15-a16);
  a12=cos(a12);
  a17=(a15*a12);
  a14=(a14-a17);
  a14=(a01*a14);
  a00=(a00-a14);
  a14=arg[3]? arg[3][1] : 0;
  a17=(a05*a13);
  a09=cos(a09);
  a17=(a17*a09);
  a18=(a09*a06);
  a18=(a02+a18);
  a19=(a18*a12);
  a17=(a17-a19);
  a17=(a14*a17);
  a00=(a00-a17);
  a17=arg[3]? arg[3][2] : 0;
  a06=(a06*a03);
  a16=(a16*a10);
  a06=(a06-a16);
  a16=(a13*a06);
  a07=(a10*a07);
  a11=(a11+a07);
  a07=(a11*a12);
  a16=(a16+a07);
  a16=(a17*a16);
  a00=(a00-a16);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[0]? arg[0][1] : 0;
  a08=(a08*a12);
  a15=(a13*a15);
  a08=(a08+a15);
  a08=(a01*a08);
  a00=(a00-a08);
  a18=(a13*a18);
  a05=(a05*a09);
  a05=(a05*a12);
  a18=(a18+a05);
  a18=(a14*a18);
  a00=(a00-a18);
  a06=(a06*a12);
  a13=(a13*a11);
  a06=(a06-a13);
  a06=(a17*a06);
  a00=(a00-a06);
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[0]? arg[0][2] : 0;
  a10=(a10*a14);
  a00=(a00-a10);
  a04=(a04*a09);
  a02=(a02+a04);
  a17=(a17*a02);
  a00=(a00-a17);
  a09=(a09*a03);
  a09=(a09*a01);
  a00=(a00+a09);
  if (res[0]!=0) res[0][2]=a00;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_mtd2td(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int landing_mtd2td_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void landing_mtd2td_release(int mem) {
}

CASADI_SYMBOL_EXPORT void landing_mtd2td_incref(void) {
}

CASADI_SYMBOL_EXPORT void landing_mtd2td_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int landing_mtd2td_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int landing_mtd2td_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real landing_mtd2td_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_mtd2td_name_in(casadi_int i) {
  switch (i) {
    case 0: return "p_mtd";
    case 1: return "attitude";
    case 2: return "angled_deck";
    case 3: return "l_td_deck";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_mtd2td_name_out(casadi_int i) {
  switch (i) {
    case 0: return "p_td";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_mtd2td_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_mtd2td_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int landing_mtd2td_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_mtd2td_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


