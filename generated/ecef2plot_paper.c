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
  #define CASADI_PREFIX(ID) ecef2plot_paper_ ## ID
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
CASADI_SYMBOL_EXPORT void ecef2plot_paper_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int ecef2plot_paper_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int ecef2plot_paper_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};

/* ecef2plot_paper:(p_ecef[3],lat,lon,alt,heading,pitch,roll)->(plot[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19;
  a00=arg[0]? arg[0][2] : 0;
  a01=arg[1]? arg[1][0] : 0;
  a02=sin(a01);
  a03=arg[3]? arg[3][0] : 0;
  a04=6.3354393272928204e+06;
  a05=1.;
  a06=-6.6943799901413173e-03;
  a07=casadi_sq(a02);
  a06=(a06*a07);
  a06=(a05+a06);
  a06=sqrt(a06);
  a04=(a04/a06);
  a04=(a03+a04);
  a04=(a02*a04);
  a00=(a00-a04);
  a04=1.3524414300892025e-02;
  a04=(a04*a07);
  a04=(a05+a04);
  a04=sqrt(a04);
  a07=(a00/a04);
  a01=cos(a01);
  a07=(a07*a01);
  a08=-1.3343945256830230e-02;
  a09=casadi_sq(a01);
  a08=(a08*a09);
  a05=(a05+a08);
  a05=sqrt(a05);
  a02=(a02/a05);
  a05=arg[2]? arg[2][0] : 0;
  a08=cos(a05);
  a09=arg[0]? arg[0][0] : 0;
  a10=6378137.;
  a10=(a10/a06);
  a03=(a03+a10);
  a03=(a01*a03);
  a10=(a08*a03);
  a09=(a09-a10);
  a10=(a08*a09);
  a06=(a02*a10);
  a05=sin(a05);
  a11=arg[0]? arg[0][1] : 0;
  a03=(a03*a05);
  a11=(a11-a03);
  a03=(a05*a11);
  a12=(a02*a03);
  a06=(a06+a12);
  a07=(a07-a06);
  a06=arg[4]? arg[4][0] : 0;
  a12=cos(a06);
  a13=arg[6]? arg[6][0] : 0;
  a14=sin(a13);
  a15=(a12*a14);
  a16=arg[5]? arg[5][0] : 0;
  a17=sin(a16);
  a18=(a15*a17);
  a13=cos(a13);
  a06=sin(a06);
  a19=(a13*a06);
  a18=(a18-a19);
  a18=(a07*a18);
  a08=(a08*a11);
  a09=(a09*a05);
  a08=(a08-a09);
  a09=(a12*a13);
  a05=(a14*a06);
  a11=(a17*a05);
  a11=(a09+a11);
  a11=(a08*a11);
  a18=(a18+a11);
  a00=(a00*a02);
  a01=(a01/a04);
  a10=(a10*a01);
  a00=(a00+a10);
  a03=(a03*a01);
  a00=(a00+a03);
  a16=cos(a16);
  a03=(a00*a16);
  a14=(a14*a03);
  a18=(a18-a14);
  a14=casadi_sq(a18);
  a00=(a17*a00);
  a12=(a12*a07);
  a12=(a12*a16);
  a00=(a00+a12);
  a06=(a06*a16);
  a06=(a06*a08);
  a00=(a00+a06);
  a06=casadi_sq(a00);
  a14=(a14+a06);
  a13=(a13*a03);
  a09=(a17*a09);
  a05=(a05+a09);
  a07=(a07*a05);
  a13=(a13-a07);
  a17=(a17*a19);
  a15=(a15-a17);
  a08=(a08*a15);
  a13=(a13+a08);
  a08=casadi_sq(a13);
  a08=(a14+a08);
  a08=sqrt(a08);
  if (res[0]!=0) res[0][0]=a08;
  a18=atan2(a18,a00);
  if (res[0]!=0) res[0][1]=a18;
  a14=sqrt(a14);
  a13=atan2(a13,a14);
  if (res[0]!=0) res[0][2]=a13;
  return 0;
}

CASADI_SYMBOL_EXPORT int ecef2plot_paper(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int ecef2plot_paper_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void ecef2plot_paper_release(int mem) {
}

CASADI_SYMBOL_EXPORT void ecef2plot_paper_incref(void) {
}

CASADI_SYMBOL_EXPORT void ecef2plot_paper_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int ecef2plot_paper_n_in(void) { return 7;}

CASADI_SYMBOL_EXPORT casadi_int ecef2plot_paper_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real ecef2plot_paper_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* ecef2plot_paper_name_in(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const char* ecef2plot_paper_name_out(casadi_int i) {
  switch (i) {
    case 0: return "plot";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* ecef2plot_paper_sparsity_in(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const casadi_int* ecef2plot_paper_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int ecef2plot_paper_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int ecef2plot_paper_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


