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
  #define CASADI_PREFIX(ID) landing_radar2td_ ## ID
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
CASADI_SYMBOL_EXPORT void landing_radar2td_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int landing_radar2td_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int landing_radar2td_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {3, 3, 1};

/* landing_radar2td:(polar_rdr[3],attitude[3],angled_deck,d_radar_deck[3])->(p_td[3],u_deck[3],A[3x3],M[3x3],J[3x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29;
  a00=arg[1]? arg[1][2] : 0;
  a01=cos(a00);
  a02=arg[1]? arg[1][0] : 0;
  a03=cos(a02);
  a04=(a01*a03);
  a00=sin(a00);
  a02=sin(a02);
  a05=(a00*a02);
  a06=arg[1]? arg[1][1] : 0;
  a07=sin(a06);
  a08=(a05*a07);
  a08=(a04+a08);
  a09=arg[2]? arg[2][0] : 0;
  a10=sin(a09);
  a11=(a08*a10);
  a12=(a00*a03);
  a13=(a12*a07);
  a14=(a01*a02);
  a13=(a13-a14);
  a09=cos(a09);
  a15=(a13*a09);
  a11=(a11-a15);
  a15=arg[0]? arg[0][1] : 0;
  a16=cos(a15);
  a17=arg[0]? arg[0][2] : 0;
  a18=cos(a17);
  a19=(a16*a18);
  a20=arg[0]? arg[0][0] : 0;
  a21=(a19*a20);
  a22=arg[3]? arg[3][0] : 0;
  a22=(a21+a22);
  a23=(a11*a22);
  a15=sin(a15);
  a24=(a18*a15);
  a25=(a24*a20);
  a26=arg[3]? arg[3][1] : 0;
  a26=(a25+a26);
  a06=cos(a06);
  a02=(a06*a02);
  a27=(a10*a02);
  a03=(a06*a03);
  a28=(a09*a03);
  a27=(a27-a28);
  a28=(a26*a27);
  a23=(a23+a28);
  a17=sin(a17);
  a28=(a17*a20);
  a29=arg[3]? arg[3][2] : 0;
  a29=(a28+a29);
  a14=(a14*a07);
  a12=(a12-a14);
  a14=(a10*a12);
  a04=(a04*a07);
  a05=(a05+a04);
  a04=(a09*a05);
  a14=(a14+a04);
  a04=(a29*a14);
  a23=(a23+a04);
  if (res[0]!=0) res[0][0]=a23;
  a02=(a09*a02);
  a03=(a10*a03);
  a02=(a02+a03);
  a03=(a26*a02);
  a12=(a09*a12);
  a05=(a10*a05);
  a12=(a12-a05);
  a05=(a29*a12);
  a03=(a03+a05);
  a13=(a13*a10);
  a09=(a09*a08);
  a13=(a13+a09);
  a09=(a13*a22);
  a03=(a03+a09);
  if (res[0]!=0) res[0][1]=a03;
  a26=(a26*a07);
  a01=(a06*a01);
  a29=(a29*a01);
  a26=(a26+a29);
  a00=(a00*a06);
  a22=(a00*a22);
  a26=(a26-a22);
  if (res[0]!=0) res[0][2]=a26;
  if (res[1]!=0) res[1][0]=a21;
  if (res[1]!=0) res[1][1]=a25;
  if (res[1]!=0) res[1][2]=a28;
  if (res[2]!=0) res[2][0]=a19;
  if (res[2]!=0) res[2][1]=a24;
  if (res[2]!=0) res[2][2]=a17;
  a26=(-a25);
  if (res[2]!=0) res[2][3]=a26;
  if (res[2]!=0) res[2][4]=a21;
  a26=0.;
  if (res[2]!=0) res[2][5]=a26;
  a16=(a16*a28);
  a26=(-a16);
  if (res[2]!=0) res[2][6]=a26;
  a15=(a15*a28);
  a28=(-a15);
  if (res[2]!=0) res[2][7]=a28;
  a28=(a18*a20);
  if (res[2]!=0) res[2][8]=a28;
  if (res[3]!=0) res[3][0]=a11;
  if (res[3]!=0) res[3][1]=a13;
  a26=(-a00);
  if (res[3]!=0) res[3][2]=a26;
  if (res[3]!=0) res[3][3]=a27;
  if (res[3]!=0) res[3][4]=a02;
  if (res[3]!=0) res[3][5]=a07;
  if (res[3]!=0) res[3][6]=a14;
  if (res[3]!=0) res[3][7]=a12;
  if (res[3]!=0) res[3][8]=a01;
  a26=(a11*a19);
  a22=(a24*a27);
  a26=(a26+a22);
  a22=(a17*a14);
  a26=(a26+a22);
  if (res[4]!=0) res[4][0]=a26;
  a26=(a24*a02);
  a22=(a19*a13);
  a26=(a26+a22);
  a22=(a17*a12);
  a26=(a26+a22);
  if (res[4]!=0) res[4][1]=a26;
  a24=(a24*a07);
  a17=(a17*a01);
  a24=(a24+a17);
  a17=(a19*a00);
  a24=(a24-a17);
  if (res[4]!=0) res[4][2]=a24;
  a24=(a19*a27);
  a24=(a24*a20);
  a17=(a11*a25);
  a24=(a24-a17);
  if (res[4]!=0) res[4][3]=a24;
  a19=(a19*a02);
  a19=(a19*a20);
  a24=(a25*a13);
  a19=(a19-a24);
  if (res[4]!=0) res[4][4]=a19;
  a25=(a25*a00);
  a21=(a21*a07);
  a25=(a25+a21);
  if (res[4]!=0) res[4][5]=a25;
  a14=(a18*a14);
  a14=(a14*a20);
  a11=(a11*a16);
  a27=(a27*a15);
  a11=(a11+a27);
  a14=(a14-a11);
  if (res[4]!=0) res[4][6]=a14;
  a18=(a18*a12);
  a18=(a18*a20);
  a13=(a13*a16);
  a02=(a02*a15);
  a13=(a13+a02);
  a18=(a18-a13);
  if (res[4]!=0) res[4][7]=a18;
  a01=(a01*a28);
  a00=(a00*a16);
  a01=(a01+a00);
  a15=(a15*a07);
  a01=(a01-a15);
  if (res[4]!=0) res[4][8]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_radar2td(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int landing_radar2td_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void landing_radar2td_release(int mem) {
}

CASADI_SYMBOL_EXPORT void landing_radar2td_incref(void) {
}

CASADI_SYMBOL_EXPORT void landing_radar2td_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int landing_radar2td_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int landing_radar2td_n_out(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_real landing_radar2td_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_radar2td_name_in(casadi_int i) {
  switch (i) {
    case 0: return "polar_rdr";
    case 1: return "attitude";
    case 2: return "angled_deck";
    case 3: return "d_radar_deck";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_radar2td_name_out(casadi_int i) {
  switch (i) {
    case 0: return "p_td";
    case 1: return "u_deck";
    case 2: return "A";
    case 3: return "M";
    case 4: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_radar2td_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_radar2td_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s2;
    case 3: return casadi_s2;
    case 4: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int landing_radar2td_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 5;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_radar2td_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 5*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


