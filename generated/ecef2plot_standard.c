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
  #define CASADI_PREFIX(ID) ecef2plot_standard_ ## ID
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
CASADI_SYMBOL_EXPORT void ecef2plot_standard_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int ecef2plot_standard_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int ecef2plot_standard_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};

/* ecef2plot_standard:(p_ecef[3],lat,lon,alt,heading,pitch,roll)->(plot[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17;
  a00=arg[1]? arg[1][0] : 0;
  a01=cos(a00);
  a02=arg[0]? arg[0][2] : 0;
  a00=sin(a00);
  a03=arg[3]? arg[3][0] : 0;
  a04=6.3354393272928204e+06;
  a05=1.;
  a06=-6.6943799901413173e-03;
  a07=casadi_sq(a00);
  a06=(a06*a07);
  a05=(a05+a06);
  a05=sqrt(a05);
  a04=(a04/a05);
  a04=(a03+a04);
  a04=(a00*a04);
  a02=(a02-a04);
  a04=(a01*a02);
  a06=arg[2]? arg[2][0] : 0;
  a07=cos(a06);
  a08=arg[0]? arg[0][0] : 0;
  a09=6378137.;
  a09=(a09/a05);
  a03=(a03+a09);
  a03=(a01*a03);
  a09=(a07*a03);
  a08=(a08-a09);
  a09=(a07*a08);
  a05=(a09*a00);
  a04=(a04-a05);
  a06=sin(a06);
  a05=arg[0]? arg[0][1] : 0;
  a03=(a03*a06);
  a05=(a05-a03);
  a03=(a06*a05);
  a10=(a03*a00);
  a04=(a04-a10);
  a10=arg[6]? arg[6][0] : 0;
  a11=sin(a10);
  a12=arg[5]? arg[5][0] : 0;
  a13=sin(a12);
  a14=(a11*a13);
  a15=arg[4]? arg[4][0] : 0;
  a16=cos(a15);
  a14=(a14*a16);
  a10=cos(a10);
  a15=sin(a15);
  a17=(a10*a15);
  a14=(a14-a17);
  a14=(a04*a14);
  a07=(a07*a05);
  a08=(a08*a06);
  a07=(a07-a08);
  a08=(a10*a16);
  a06=(a11*a15);
  a05=(a13*a06);
  a05=(a08+a05);
  a05=(a07*a05);
  a14=(a14+a05);
  a09=(a01*a09);
  a01=(a01*a03);
  a09=(a09+a01);
  a02=(a02*a00);
  a09=(a09+a02);
  a12=cos(a12);
  a02=(a09*a12);
  a00=(a11*a02);
  a14=(a14-a00);
  a00=casadi_sq(a14);
  a09=(a13*a09);
  a15=(a15*a12);
  a15=(a15*a07);
  a09=(a09+a15);
  a12=(a04*a12);
  a12=(a12*a16);
  a09=(a09+a12);
  a12=casadi_sq(a09);
  a00=(a00+a12);
  a10=(a10*a02);
  a08=(a13*a08);
  a06=(a06+a08);
  a04=(a04*a06);
  a10=(a10-a04);
  a11=(a11*a16);
  a13=(a13*a17);
  a11=(a11-a13);
  a07=(a07*a11);
  a10=(a10+a07);
  a07=casadi_sq(a10);
  a07=(a00+a07);
  a07=sqrt(a07);
  if (res[0]!=0) res[0][0]=a07;
  a14=atan2(a14,a09);
  if (res[0]!=0) res[0][1]=a14;
  a00=sqrt(a00);
  a10=atan2(a10,a00);
  if (res[0]!=0) res[0][2]=a10;
  return 0;
}

CASADI_SYMBOL_EXPORT int ecef2plot_standard(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int ecef2plot_standard_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void ecef2plot_standard_release(int mem) {
}

CASADI_SYMBOL_EXPORT void ecef2plot_standard_incref(void) {
}

CASADI_SYMBOL_EXPORT void ecef2plot_standard_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int ecef2plot_standard_n_in(void) { return 7;}

CASADI_SYMBOL_EXPORT casadi_int ecef2plot_standard_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real ecef2plot_standard_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* ecef2plot_standard_name_in(casadi_int i) {
  switch (i) {
    case 0: return "p_ecef";
    case 1: return "lat";
    case 2: return "lon";
    case 3: return "alt";
    case 4: return "heading";
    case 5: return "pitch";
    case 6: return "roll";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* ecef2plot_standard_name_out(casadi_int i) {
  switch (i) {
    case 0: return "plot";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* ecef2plot_standard_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s1;
    case 3: return casadi_s1;
    case 4: return casadi_s1;
    case 5: return casadi_s1;
    case 6: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* ecef2plot_standard_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int ecef2plot_standard_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int ecef2plot_standard_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


