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
  #define CASADI_PREFIX(ID) deck2enu_ ## ID
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
CASADI_SYMBOL_EXPORT void deck2enu_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int deck2enu_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int deck2enu_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {1, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};

/* deck2enu:(r,q,e,heading,pitch,roll)->(u_enu[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14;
  a00=arg[0]? arg[0][0] : 0;
  a01=arg[2]? arg[2][0] : 0;
  a02=cos(a01);
  a02=(a00*a02);
  a03=arg[1]? arg[1][0] : 0;
  a04=sin(a03);
  a04=(a02*a04);
  a05=arg[3]? arg[3][0] : 0;
  a06=cos(a05);
  a07=arg[5]? arg[5][0] : 0;
  a08=cos(a07);
  a09=(a06*a08);
  a10=arg[4]? arg[4][0] : 0;
  a11=sin(a10);
  a07=sin(a07);
  a05=sin(a05);
  a12=(a07*a05);
  a13=(a11*a12);
  a13=(a09+a13);
  a13=(a04*a13);
  a10=cos(a10);
  a03=cos(a03);
  a02=(a02*a03);
  a03=(a10*a02);
  a14=(a03*a05);
  a13=(a13+a14);
  a01=sin(a01);
  a00=(a00*a01);
  a01=(a06*a07);
  a05=(a08*a05);
  a14=(a11*a05);
  a14=(a01-a14);
  a14=(a00*a14);
  a13=(a13+a14);
  if (res[0]!=0) res[0][0]=a13;
  a06=(a06*a03);
  a01=(a01*a11);
  a01=(a01-a05);
  a01=(a04*a01);
  a06=(a06+a01);
  a09=(a11*a09);
  a12=(a12+a09);
  a12=(a00*a12);
  a06=(a06-a12);
  if (res[0]!=0) res[0][1]=a06;
  a02=(a02*a11);
  a08=(a10*a08);
  a08=(a08*a00);
  a02=(a02+a08);
  a07=(a07*a04);
  a07=(a07*a10);
  a02=(a02-a07);
  if (res[0]!=0) res[0][2]=a02;
  return 0;
}

CASADI_SYMBOL_EXPORT int deck2enu(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int deck2enu_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void deck2enu_release(int mem) {
}

CASADI_SYMBOL_EXPORT void deck2enu_incref(void) {
}

CASADI_SYMBOL_EXPORT void deck2enu_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int deck2enu_n_in(void) { return 6;}

CASADI_SYMBOL_EXPORT casadi_int deck2enu_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real deck2enu_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* deck2enu_name_in(casadi_int i) {
  switch (i) {
    case 0: return "r";
    case 1: return "q";
    case 2: return "e";
    case 3: return "heading";
    case 4: return "pitch";
    case 5: return "roll";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* deck2enu_name_out(casadi_int i) {
  switch (i) {
    case 0: return "u_enu";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* deck2enu_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    case 3: return casadi_s0;
    case 4: return casadi_s0;
    case 5: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* deck2enu_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int deck2enu_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 6;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int deck2enu_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 6*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


