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
  #define CASADI_PREFIX(ID) cv_gate_ ## ID
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
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
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
CASADI_SYMBOL_EXPORT void cv_gate_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int cv_gate_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int cv_gate_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {6, 1, 1};
static const casadi_int casadi_s1[3] = {6, 6, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {3, 3, 1};
static const casadi_int casadi_s4[3] = {1, 1, 1};

/* cv_gate:(x_pred[6],P_pred[6x6],z[3],R[3x3])->(d2,logdet) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  a00=arg[2]? arg[2][0] : 0;
  a01=arg[0]? arg[0][0] : 0;
  a00=(a00-a01);
  a01=arg[1]? arg[1][0] : 0;
  a02=arg[3]? arg[3][0] : 0;
  a01=(a01+a02);
  a02=(1./a01);
  a02=sqrt(a02);
  a00=(a00*a02);
  a03=casadi_sq(a00);
  a04=arg[2]? arg[2][1] : 0;
  a05=arg[0]? arg[0][1] : 0;
  a04=(a04-a05);
  a05=arg[1]? arg[1][6] : 0;
  a06=arg[3]? arg[3][3] : 0;
  a05=(a05+a06);
  a05=(a05*a02);
  a06=(a05*a00);
  a04=(a04-a06);
  a06=arg[1]? arg[1][7] : 0;
  a07=arg[3]? arg[3][4] : 0;
  a06=(a06+a07);
  a07=casadi_sq(a05);
  a06=(a06-a07);
  a07=(1./a06);
  a07=sqrt(a07);
  a04=(a04*a07);
  a08=casadi_sq(a04);
  a03=(a03+a08);
  a08=arg[2]? arg[2][2] : 0;
  a09=arg[0]? arg[0][2] : 0;
  a08=(a08-a09);
  a09=arg[1]? arg[1][12] : 0;
  a10=arg[3]? arg[3][6] : 0;
  a09=(a09+a10);
  a09=(a09*a02);
  a00=(a09*a00);
  a10=arg[1]? arg[1][13] : 0;
  a11=arg[3]? arg[3][7] : 0;
  a10=(a10+a11);
  a05=(a09*a05);
  a10=(a10-a05);
  a10=(a10*a07);
  a04=(a10*a04);
  a00=(a00+a04);
  a08=(a08-a00);
  a00=arg[1]? arg[1][14] : 0;
  a04=arg[3]? arg[3][8] : 0;
  a00=(a00+a04);
  a10=casadi_sq(a10);
  a09=casadi_sq(a09);
  a10=(a10+a09);
  a00=(a00-a10);
  a10=(1./a00);
  a10=sqrt(a10);
  a08=(a08*a10);
  a08=casadi_sq(a08);
  a03=(a03+a08);
  if (res[0]!=0) res[0][0]=a03;
  a01=(a01*a02);
  a01=log(a01);
  a06=(a06*a07);
  a06=log(a06);
  a01=(a01+a06);
  a00=(a00*a10);
  a00=log(a00);
  a01=(a01+a00);
  a01=(2.*a01);
  if (res[1]!=0) res[1][0]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int cv_gate(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int cv_gate_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void cv_gate_release(int mem) {
}

CASADI_SYMBOL_EXPORT void cv_gate_incref(void) {
}

CASADI_SYMBOL_EXPORT void cv_gate_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int cv_gate_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int cv_gate_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real cv_gate_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* cv_gate_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x_pred";
    case 1: return "P_pred";
    case 2: return "z";
    case 3: return "R";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* cv_gate_name_out(casadi_int i) {
  switch (i) {
    case 0: return "d2";
    case 1: return "logdet";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* cv_gate_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* cv_gate_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int cv_gate_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int cv_gate_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


