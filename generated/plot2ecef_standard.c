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
  #define CASADI_PREFIX(ID) plot2ecef_standard_ ## ID
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
CASADI_SYMBOL_EXPORT void plot2ecef_standard_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int plot2ecef_standard_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int plot2ecef_standard_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {1, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};

/* plot2ecef_standard:(lat,lon,alt,heading,pitch,roll,r,q,e)->(p_ecef[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20;
  a00=arg[2]? arg[2][0] : 0;
  a01=6378137.;
  a02=1.;
  a03=-6.6943799901413173e-03;
  a04=arg[0]? arg[0][0] : 0;
  a05=sin(a04);
  a06=casadi_sq(a05);
  a03=(a03*a06);
  a02=(a02+a03);
  a02=sqrt(a02);
  a01=(a01/a02);
  a01=(a00+a01);
  a03=arg[1]? arg[1][0] : 0;
  a06=cos(a03);
  a04=cos(a04);
  a07=(a06*a04);
  a08=(a01*a07);
  a09=arg[6]? arg[6][0] : 0;
  a10=arg[8]? arg[8][0] : 0;
  a11=cos(a10);
  a11=(a09*a11);
  a12=arg[7]? arg[7][0] : 0;
  a13=cos(a12);
  a13=(a11*a13);
  a14=arg[4]? arg[4][0] : 0;
  a15=sin(a14);
  a16=(a13*a15);
  a14=cos(a14);
  a17=arg[5]? arg[5][0] : 0;
  a18=cos(a17);
  a19=(a14*a18);
  a10=sin(a10);
  a09=(a09*a10);
  a19=(a19*a09);
  a16=(a16+a19);
  a17=sin(a17);
  a12=sin(a12);
  a11=(a11*a12);
  a12=(a17*a11);
  a12=(a12*a14);
  a16=(a16-a12);
  a07=(a07*a16);
  a08=(a08+a07);
  a07=arg[3]? arg[3][0] : 0;
  a12=cos(a07);
  a19=(a12*a18);
  a07=sin(a07);
  a10=(a17*a07);
  a20=(a15*a10);
  a20=(a19+a20);
  a20=(a11*a20);
  a14=(a14*a13);
  a13=(a14*a07);
  a20=(a20+a13);
  a17=(a12*a17);
  a18=(a18*a07);
  a07=(a15*a18);
  a07=(a17-a07);
  a07=(a09*a07);
  a20=(a20+a07);
  a03=sin(a03);
  a07=(a20*a03);
  a08=(a08-a07);
  a12=(a12*a14);
  a17=(a17*a15);
  a17=(a17-a18);
  a11=(a11*a17);
  a12=(a12+a11);
  a15=(a15*a19);
  a10=(a10+a15);
  a09=(a09*a10);
  a12=(a12-a09);
  a09=(a05*a12);
  a10=(a06*a09);
  a08=(a08-a10);
  if (res[0]!=0) res[0][0]=a08;
  a20=(a20*a06);
  a06=(a03*a04);
  a01=(a01*a06);
  a20=(a20+a01);
  a06=(a16*a06);
  a20=(a20+a06);
  a03=(a03*a09);
  a20=(a20-a03);
  if (res[0]!=0) res[0][1]=a20;
  a16=(a05*a16);
  a20=6.3354393272928204e+06;
  a20=(a20/a02);
  a00=(a00+a20);
  a05=(a05*a00);
  a16=(a16+a05);
  a04=(a04*a12);
  a16=(a16+a04);
  if (res[0]!=0) res[0][2]=a16;
  return 0;
}

CASADI_SYMBOL_EXPORT int plot2ecef_standard(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int plot2ecef_standard_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void plot2ecef_standard_release(int mem) {
}

CASADI_SYMBOL_EXPORT void plot2ecef_standard_incref(void) {
}

CASADI_SYMBOL_EXPORT void plot2ecef_standard_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int plot2ecef_standard_n_in(void) { return 9;}

CASADI_SYMBOL_EXPORT casadi_int plot2ecef_standard_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real plot2ecef_standard_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* plot2ecef_standard_name_in(casadi_int i) {
  switch (i) {
    case 0: return "lat";
    case 1: return "lon";
    case 2: return "alt";
    case 3: return "heading";
    case 4: return "pitch";
    case 5: return "roll";
    case 6: return "r";
    case 7: return "q";
    case 8: return "e";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* plot2ecef_standard_name_out(casadi_int i) {
  switch (i) {
    case 0: return "p_ecef";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* plot2ecef_standard_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    case 3: return casadi_s0;
    case 4: return casadi_s0;
    case 5: return casadi_s0;
    case 6: return casadi_s0;
    case 7: return casadi_s0;
    case 8: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* plot2ecef_standard_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int plot2ecef_standard_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 9;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int plot2ecef_standard_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 9*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


