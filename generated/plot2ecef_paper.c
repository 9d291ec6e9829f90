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
  #define CASADI_PREFIX(ID) plot2ecef_paper_ ## ID
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
CASADI_SYMBOL_EXPORT void plot2ecef_paper_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int plot2ecef_paper_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int plot2ecef_paper_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {1, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};

/* plot2ecef_paper:(lat,lon,alt,heading,pitch,roll,r,q,e)->(p_ecef[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  a00=arg[1]? arg[1][0] : 0;
  a01=cos(a00);
  a02=arg[0]? arg[0][0] : 0;
  a03=cos(a02);
  a04=arg[2]? arg[2][0] : 0;
  a05=6378137.;
  a06=1.;
  a07=-6.6943799901413173e-03;
  a02=sin(a02);
  a08=casadi_sq(a02);
  a07=(a07*a08);
  a07=(a06+a07);
  a07=sqrt(a07);
  a05=(a05/a07);
  a05=(a04+a05);
  a05=(a03*a05);
  a09=(a01*a05);
  a10=arg[6]? arg[6][0] : 0;
  a11=arg[8]? arg[8][0] : 0;
  a12=cos(a11);
  a12=(a10*a12);
  a13=arg[7]? arg[7][0] : 0;
  a14=cos(a13);
  a14=(a12*a14);
  a15=arg[4]? arg[4][0] : 0;
  a16=sin(a15);
  a17=(a14*a16);
  a15=cos(a15);
  a18=arg[5]? arg[5][0] : 0;
  a19=cos(a18);
  a20=(a15*a19);
  a11=sin(a11);
  a10=(a10*a11);
  a20=(a20*a10);
  a17=(a17+a20);
  a18=sin(a18);
  a13=sin(a13);
  a12=(a12*a13);
  a13=(a18*a12);
  a13=(a13*a15);
  a17=(a17-a13);
  a13=1.3524414300892025e-02;
  a13=(a13*a08);
  a13=(a06+a13);
  a13=sqrt(a13);
  a13=(a03/a13);
  a08=(a17*a13);
  a20=(a01*a08);
  a09=(a09+a20);
  a20=arg[3]? arg[3][0] : 0;
  a11=cos(a20);
  a21=(a11*a19);
  a20=sin(a20);
  a22=(a18*a20);
  a23=(a16*a22);
  a23=(a21+a23);
  a23=(a12*a23);
  a15=(a15*a14);
  a14=(a15*a20);
  a23=(a23+a14);
  a18=(a11*a18);
  a19=(a19*a20);
  a20=(a16*a19);
  a20=(a18-a20);
  a20=(a10*a20);
  a23=(a23+a20);
  a00=sin(a00);
  a20=(a23*a00);
  a09=(a09-a20);
  a11=(a11*a15);
  a18=(a18*a16);
  a18=(a18-a19);
  a12=(a12*a18);
  a11=(a11+a12);
  a16=(a16*a21);
  a22=(a22+a16);
  a10=(a10*a22);
  a11=(a11-a10);
  a10=-1.3343945256830230e-02;
  a03=casadi_sq(a03);
  a10=(a10*a03);
  a06=(a06+a10);
  a06=sqrt(a06);
  a06=(a02/a06);
  a10=(a11*a06);
  a03=(a01*a10);
  a09=(a09-a03);
  if (res[0]!=0) res[0][0]=a09;
  a23=(a23*a01);
  a05=(a00*a05);
  a23=(a23+a05);
  a08=(a00*a08);
  a23=(a23+a08);
  a00=(a00*a10);
  a23=(a23-a00);
  if (res[0]!=0) res[0][1]=a23;
  a23=6.3354393272928204e+06;
  a23=(a23/a07);
  a04=(a04+a23);
  a02=(a02*a04);
  a17=(a17*a06);
  a02=(a02+a17);
  a13=(a13*a11);
  a02=(a02+a13);
  if (res[0]!=0) res[0][2]=a02;
  return 0;
}

CASADI_SYMBOL_EXPORT int plot2ecef_paper(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int plot2ecef_paper_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void plot2ecef_paper_release(int mem) {
}

CASADI_SYMBOL_EXPORT void plot2ecef_paper_incref(void) {
}

CASADI_SYMBOL_EXPORT void plot2ecef_paper_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int plot2ecef_paper_n_in(void) { return 9;}

CASADI_SYMBOL_EXPORT casadi_int plot2ecef_paper_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real plot2ecef_paper_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* plot2ecef_paper_name_in(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const char* plot2ecef_paper_name_out(casadi_int i) {
  switch (i) {
    case 0: return "p_ecef";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* plot2ecef_paper_sparsity_in(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const casadi_int* plot2ecef_paper_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int plot2ecef_paper_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 9;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int plot2ecef_paper_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 9*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


