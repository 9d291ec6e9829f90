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
  #define CASADI_PREFIX(ID) cv_predict_ ## ID
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
CASADI_SYMBOL_EXPORT void cv_predict_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int cv_predict_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int cv_predict_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {6, 1, 1};
static const casadi_int casadi_s1[3] = {6, 6, 1};
static const casadi_int casadi_s2[3] = {1, 1, 1};

/* cv_predict:(x[6],P[6x6],dt,accel_sigma)->(x_pred[6],P_pred[6x6]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20;
  a00=arg[0]? arg[0][0] : 0;
  a01=arg[2]? arg[2][0] : 0;
  a02=arg[0]? arg[0][3] : 0;
  a03=(a01*a02);
  a00=(a00+a03);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[0]? arg[0][1] : 0;
  a03=arg[0]? arg[0][4] : 0;
  a04=(a01*a03);
  a00=(a00+a04);
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[0]? arg[0][2] : 0;
  a04=arg[0]? arg[0][5] : 0;
  a05=(a01*a04);
  a00=(a00+a05);
  if (res[0]!=0) res[0][2]=a00;
  if (res[0]!=0) res[0][3]=a02;
  if (res[0]!=0) res[0][4]=a03;
  if (res[0]!=0) res[0][5]=a04;
  a04=arg[1]? arg[1][0] : 0;
  a03=arg[1]? arg[1][18] : 0;
  a02=(a01*a03);
  a04=(a04+a02);
  a02=arg[1]? arg[1][21] : 0;
  a00=(a01*a02);
  a03=(a03+a00);
  a00=(a03*a01);
  a04=(a04+a00);
  a00=arg[3]? arg[3][0] : 0;
  a00=casadi_sq(a00);
  a05=casadi_sq(a01);
  a05=(a01*a05);
  a05=(a00*a05);
  a06=3.;
  a05=(a05/a06);
  a04=(a04+a05);
  if (res[1]!=0) res[1][0]=a04;
  a04=arg[1]? arg[1][6] : 0;
  a06=arg[1]? arg[1][19] : 0;
  a07=(a01*a06);
  a04=(a04+a07);
  a07=arg[1]? arg[1][24] : 0;
  a08=arg[1]? arg[1][27] : 0;
  a09=(a01*a08);
  a07=(a07+a09);
  a09=(a07*a01);
  a04=(a04+a09);
  if (res[1]!=0) res[1][1]=a04;
  a09=arg[1]? arg[1][12] : 0;
  a10=arg[1]? arg[1][20] : 0;
  a11=(a01*a10);
  a09=(a09+a11);
  a11=arg[1]? arg[1][30] : 0;
  a12=arg[1]? arg[1][33] : 0;
  a13=(a01*a12);
  a11=(a11+a13);
  a13=(a11*a01);
  a09=(a09+a13);
  if (res[1]!=0) res[1][2]=a09;
  a13=casadi_sq(a01);
  a13=(a00*a13);
  a14=2.;
  a13=(a13/a14);
  a03=(a03+a13);
  if (res[1]!=0) res[1][3]=a03;
  if (res[1]!=0) res[1][4]=a07;
  if (res[1]!=0) res[1][5]=a11;
  if (res[1]!=0) res[1][6]=a04;
  a04=arg[1]? arg[1][7] : 0;
  a14=arg[1]? arg[1][25] : 0;
  a15=(a01*a14);
  a04=(a04+a15);
  a15=arg[1]? arg[1][28] : 0;
  a16=(a01*a15);
  a14=(a14+a16);
  a16=(a14*a01);
  a04=(a04+a16);
  a04=(a04+a05);
  if (res[1]!=0) res[1][7]=a04;
  a04=arg[1]? arg[1][13] : 0;
  a16=arg[1]? arg[1][26] : 0;
  a17=(a01*a16);
  a04=(a04+a17);
  a17=arg[1]? arg[1][31] : 0;
  a18=arg[1]? arg[1][34] : 0;
  a19=(a01*a18);
  a17=(a17+a19);
  a19=(a17*a01);
  a04=(a04+a19);
  if (res[1]!=0) res[1][8]=a04;
  a19=(a01*a08);
  a06=(a06+a19);
  if (res[1]!=0) res[1][9]=a06;
  a14=(a14+a13);
  if (res[1]!=0) res[1][10]=a14;
  if (res[1]!=0) res[1][11]=a17;
  if (res[1]!=0) res[1][12]=a09;
  if (res[1]!=0) res[1][13]=a04;
  a04=arg[1]? arg[1][14] : 0;
  a09=arg[1]? arg[1][32] : 0;
  a19=(a01*a09);
  a04=(a04+a19);
  a19=arg[1]? arg[1][35] : 0;
  a20=(a01*a19);
  a09=(a09+a20);
  a20=(a09*a01);
  a04=(a04+a20);
  a04=(a04+a05);
  if (res[1]!=0) res[1][14]=a04;
  a04=(a01*a12);
  a10=(a10+a04);
  if (res[1]!=0) res[1][15]=a10;
  a04=(a01*a18);
  a16=(a16+a04);
  if (res[1]!=0) res[1][16]=a16;
  a09=(a09+a13);
  if (res[1]!=0) res[1][17]=a09;
  if (res[1]!=0) res[1][18]=a03;
  if (res[1]!=0) res[1][19]=a06;
  if (res[1]!=0) res[1][20]=a10;
  a00=(a00*a01);
  a02=(a02+a00);
  if (res[1]!=0) res[1][21]=a02;
  if (res[1]!=0) res[1][22]=a08;
  if (res[1]!=0) res[1][23]=a12;
  if (res[1]!=0) res[1][24]=a07;
  if (res[1]!=0) res[1][25]=a14;
  if (res[1]!=0) res[1][26]=a16;
  if (res[1]!=0) res[1][27]=a08;
  a15=(a15+a00);
  if (res[1]!=0) res[1][28]=a15;
  if (res[1]!=0) res[1][29]=a18;
  if (res[1]!=0) res[1][30]=a11;
  if (res[1]!=0) res[1][31]=a17;
  if (res[1]!=0) res[1][32]=a09;
  if (res[1]!=0) res[1][33]=a12;
  if (res[1]!=0) res[1][34]=a18;
  a19=(a19+a00);
  if (res[1]!=0) res[1][35]=a19;
  return 0;
}

CASADI_SYMBOL_EXPORT int cv_predict(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int cv_predict_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void cv_predict_release(int mem) {
}

CASADI_SYMBOL_EXPORT void cv_predict_incref(void) {
}

CASADI_SYMBOL_EXPORT void cv_predict_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int cv_predict_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int cv_predict_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real cv_predict_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* cv_predict_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "P";
    case 2: return "dt";
    case 3: return "accel_sigma";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* cv_predict_name_out(casadi_int i) {
  switch (i) {
    case 0: return "x_pred";
    case 1: return "P_pred";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* cv_predict_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* cv_predict_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int cv_predict_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int cv_predict_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


