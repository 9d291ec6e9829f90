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
  #define CASADI_PREFIX(ID) landing_ctd2td_ ## ID
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
CASADI_SYMBOL_EXPORT void landing_ctd2td_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int landing_ctd2td_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int landing_ctd2td_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {3, 3, 1};

/* landing_ctd2td:(polar_ctd[3],attitude[3],angled_deck,d_camera_deck[3])->(p_td[3],J[3x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25;
  a00=arg[0]? arg[0][1] : 0;
  a01=cos(a00);
  a02=arg[0]? arg[0][2] : 0;
  a03=cos(a02);
  a04=(a01*a03);
  a05=arg[0]? arg[0][0] : 0;
  a06=(a04*a05);
  a07=arg[3]? arg[3][0] : 0;
  a08=arg[1]? arg[1][2] : 0;
  a09=cos(a08);
  a10=arg[1]? arg[1][0] : 0;
  a11=cos(a10);
  a12=(a09*a11);
  a13=arg[1]? arg[1][1] : 0;
  a14=sin(a13);
  a10=sin(a10);
  a08=sin(a08);
  a15=(a10*a08);
  a16=(a14*a15);
  a16=(a12+a16);
  a17=arg[2]? arg[2][0] : 0;
  a18=sin(a17);
  a19=(a16*a18);
  a20=(a11*a14);
  a20=(a20*a08);
  a21=(a09*a10);
  a20=(a20-a21);
  a17=cos(a17);
  a22=(a20*a17);
  a19=(a19-a22);
  a19=(a07*a19);
  a19=(a06+a19);
  a22=arg[3]? arg[3][1] : 0;
  a13=cos(a13);
  a10=(a10*a13);
  a23=(a18*a10);
  a24=(a13*a11);
  a25=(a24*a17);
  a23=(a23-a25);
  a23=(a22*a23);
  a19=(a19+a23);
  a23=arg[3]? arg[3][2] : 0;
  a11=(a11*a08);
  a21=(a21*a14);
  a11=(a11-a21);
  a21=(a18*a11);
  a12=(a14*a12);
  a15=(a15+a12);
  a12=(a15*a17);
  a21=(a21+a12);
  a21=(a23*a21);
  a19=(a19+a21);
  if (res[0]!=0) res[0][0]=a19;
  a00=sin(a00);
  a19=(a03*a00);
  a21=(a19*a05);
  a16=(a16*a17);
  a20=(a18*a20);
  a16=(a16+a20);
  a16=(a07*a16);
  a16=(a21+a16);
  a24=(a18*a24);
  a10=(a10*a17);
  a24=(a24+a10);
  a24=(a22*a24);
  a16=(a16+a24);
  a11=(a11*a17);
  a18=(a18*a15);
  a11=(a11-a18);
  a11=(a23*a11);
  a16=(a16+a11);
  if (res[0]!=0) res[0][1]=a16;
  a02=sin(a02);
  a16=(a02*a05);
  a14=(a14*a22);
  a14=(a16+a14);
  a09=(a09*a13);
  a09=(a09*a23);
  a14=(a14+a09);
  a13=(a13*a08);
  a13=(a13*a07);
  a14=(a14-a13);
  if (res[0]!=0) res[0][2]=a14;
  if (res[1]!=0) res[1][0]=a04;
  if (res[1]!=0) res[1][1]=a19;
  if (res[1]!=0) res[1][2]=a02;
  a21=(-a21);
  if (res[1]!=0) res[1][3]=a21;
  if (res[1]!=0) res[1][4]=a06;
  a06=0.;
  if (res[1]!=0) res[1][5]=a06;
  a01=(a01*a16);
  a01=(-a01);
  if (res[1]!=0) res[1][6]=a01;
  a00=(a00*a16);
  a00=(-a00);
  if (res[1]!=0) res[1][7]=a00;
  a03=(a03*a05);
  if (res[1]!=0) res[1][8]=a03;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_ctd2td(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int landing_ctd2td_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void landing_ctd2td_release(int mem) {
}

CASADI_SYMBOL_EXPORT void landing_ctd2td_incref(void) {
}

CASADI_SYMBOL_EXPORT void landing_ctd2td_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int landing_ctd2td_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int landing_ctd2td_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real landing_ctd2td_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_ctd2td_name_in(casadi_int i) {
  switch (i) {
    case 0: return "polar_ctd";
    case 1: return "attitude";
    case 2: return "angled_deck";
    case 3: return "d_camera_deck";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_ctd2td_name_out(casadi_int i) {
  switch (i) {
    case 0: return "p_td";
    case 1: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_ctd2td_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_ctd2td_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int landing_ctd2td_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_ctd2td_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


