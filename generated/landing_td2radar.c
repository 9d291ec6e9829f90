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
  #define CASADI_PREFIX(ID) landing_td2radar_ ## ID
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
CASADI_SYMBOL_EXPORT void landing_td2radar_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int landing_td2radar_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int landing_td2radar_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};

/* landing_td2radar:(p_td[3],attitude[3],angled_deck,d_radar_deck[3])->(polar_rdr[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18;
  a00=arg[0]? arg[0][0] : 0;
  a01=arg[2]? arg[2][0] : 0;
  a02=sin(a01);
  a03=arg[1]? arg[1][0] : 0;
  a04=cos(a03);
  a05=arg[1]? arg[1][2] : 0;
  a06=cos(a05);
  a07=(a04*a06);
  a03=sin(a03);
  a05=sin(a05);
  a08=(a03*a05);
  a09=arg[1]? arg[1][1] : 0;
  a10=sin(a09);
  a11=(a08*a10);
  a11=(a07+a11);
  a12=(a02*a11);
  a13=(a05*a10);
  a13=(a13*a04);
  a14=(a03*a06);
  a13=(a13-a14);
  a01=cos(a01);
  a15=(a13*a01);
  a12=(a12-a15);
  a12=(a00*a12);
  a15=arg[3]? arg[3][0] : 0;
  a12=(a12-a15);
  a15=arg[0]? arg[0][1] : 0;
  a13=(a02*a13);
  a11=(a11*a01);
  a13=(a13+a11);
  a13=(a15*a13);
  a12=(a12+a13);
  a09=cos(a09);
  a13=arg[0]? arg[0][2] : 0;
  a11=(a09*a13);
  a16=(a05*a11);
  a12=(a12-a16);
  a16=casadi_sq(a12);
  a13=(a10*a13);
  a17=arg[3]? arg[3][1] : 0;
  a13=(a13-a17);
  a03=(a03*a09);
  a17=(a02*a03);
  a09=(a09*a04);
  a18=(a09*a01);
  a17=(a17-a18);
  a17=(a00*a17);
  a13=(a13+a17);
  a09=(a02*a09);
  a03=(a03*a01);
  a09=(a09+a03);
  a09=(a15*a09);
  a13=(a13+a09);
  a09=casadi_sq(a13);
  a16=(a16+a09);
  a11=(a11*a06);
  a06=arg[3]? arg[3][2] : 0;
  a11=(a11-a06);
  a05=(a05*a04);
  a14=(a10*a14);
  a05=(a05-a14);
  a14=(a05*a02);
  a10=(a10*a07);
  a08=(a08+a10);
  a10=(a08*a01);
  a14=(a14+a10);
  a00=(a00*a14);
  a11=(a11+a00);
  a05=(a05*a01);
  a02=(a02*a08);
  a05=(a05-a02);
  a15=(a15*a05);
  a11=(a11+a15);
  a15=casadi_sq(a11);
  a15=(a16+a15);
  a15=sqrt(a15);
  if (res[0]!=0) res[0][0]=a15;
  a13=atan2(a13,a12);
  if (res[0]!=0) res[0][1]=a13;
  a16=sqrt(a16);
  a11=atan2(a11,a16);
  if (res[0]!=0) res[0][2]=a11;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_td2radar(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int landing_td2radar_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void landing_td2radar_release(int mem) {
}

CASADI_SYMBOL_EXPORT void landing_td2radar_incref(void) {
}

CASADI_SYMBOL_EXPORT void landing_td2radar_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int landing_td2radar_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int landing_td2radar_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real landing_td2radar_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_td2radar_name_in(casadi_int i) {
  switch (i) {
    case 0: return "p_td";
    case 1: return "attitude";
    case 2: return "angled_deck";
    case 3: return "d_radar_deck";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_td2radar_name_out(casadi_int i) {
  switch (i) {
    case 0: return "polar_rdr";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_td2radar_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_td2radar_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int landing_td2radar_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_td2radar_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


