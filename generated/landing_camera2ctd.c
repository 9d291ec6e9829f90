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
  #define CASADI_PREFIX(ID) landing_camera2ctd_ ## ID
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
CASADI_SYMBOL_EXPORT void landing_camera2ctd_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int landing_camera2ctd_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int landing_camera2ctd_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {2, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};
static const casadi_int casadi_s2[3] = {1, 1, 1};
static const casadi_int casadi_s3[3] = {2, 2, 1};

/* landing_camera2ctd:(angles_cam[2],attitude[3],angled_deck)->(angles_ctd[2],J[2x2]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26;
  a00=arg[1]? arg[1][0] : 0;
  a01=cos(a00);
  a02=arg[1]? arg[1][2] : 0;
  a03=sin(a02);
  a04=(a01*a03);
  a05=arg[1]? arg[1][1] : 0;
  a06=sin(a05);
  a02=cos(a02);
  a00=sin(a00);
  a07=(a02*a00);
  a08=(a06*a07);
  a08=(a04-a08);
  a09=arg[2]? arg[2][0] : 0;
  a10=cos(a09);
  a11=(a08*a10);
  a12=(a03*a00);
  a13=(a01*a02);
  a14=(a06*a13);
  a14=(a12+a14);
  a09=sin(a09);
  a15=(a14*a09);
  a11=(a11-a15);
  a15=arg[0]? arg[0][1] : 0;
  a16=sin(a15);
  a17=(a11*a16);
  a05=cos(a05);
  a01=(a01*a05);
  a18=(a09*a01);
  a00=(a05*a00);
  a19=(a00*a10);
  a18=(a18+a19);
  a19=(a09*a18);
  a04=(a04*a06);
  a04=(a04-a07);
  a07=(a09*a04);
  a12=(a06*a12);
  a13=(a13+a12);
  a12=(a13*a10);
  a07=(a07+a12);
  a12=(a07*a10);
  a19=(a19+a12);
  a15=cos(a15);
  a12=arg[0]? arg[0][0] : 0;
  a20=sin(a12);
  a21=(a15*a20);
  a22=(a19*a21);
  a17=(a17+a22);
  a07=(a09*a07);
  a18=(a18*a10);
  a07=(a07-a18);
  a12=cos(a12);
  a18=(a15*a12);
  a22=(a07*a18);
  a17=(a17+a22);
  a08=(a09*a08);
  a14=(a14*a10);
  a08=(a08+a14);
  a14=(a16*a08);
  a00=(a09*a00);
  a01=(a01*a10);
  a00=(a00-a01);
  a01=(a09*a00);
  a13=(a09*a13);
  a04=(a04*a10);
  a13=(a13-a04);
  a04=(a13*a10);
  a01=(a01+a04);
  a04=(a21*a01);
  a14=(a14+a04);
  a13=(a09*a13);
  a00=(a00*a10);
  a13=(a13-a00);
  a00=(a18*a13);
  a14=(a14+a00);
  a00=atan2(a17,a14);
  if (res[0]!=0) res[0][0]=a00;
  a00=(a09*a06);
  a03=(a03*a05);
  a04=(a03*a10);
  a00=(a00-a04);
  a04=(a21*a00);
  a09=(a09*a03);
  a06=(a06*a10);
  a09=(a09+a06);
  a06=(a18*a09);
  a04=(a04-a06);
  a06=(a16*a05);
  a06=(a06*a02);
  a04=(a04+a06);
  a06=casadi_sq(a17);
  a10=casadi_sq(a14);
  a06=(a06+a10);
  a10=sqrt(a06);
  a03=atan2(a04,a10);
  if (res[0]!=0) res[0][1]=a03;
  a03=(a14/a06);
  a22=(a19*a03);
  a23=(a17/a06);
  a24=(a01*a23);
  a22=(a22-a24);
  a24=(a18*a22);
  a25=(a07*a03);
  a26=(a13*a23);
  a25=(a25-a26);
  a26=(a21*a25);
  a24=(a24-a26);
  if (res[1]!=0) res[1][0]=a24;
  a24=casadi_sq(a04);
  a06=(a06+a24);
  a04=(a04/a06);
  a04=(a04/a10);
  a17=(a17*a04);
  a07=(a07*a17);
  a14=(a14*a04);
  a13=(a13*a14);
  a07=(a07+a13);
  a09=(a09*a10);
  a09=(a09/a06);
  a07=(a07+a09);
  a21=(a21*a07);
  a00=(a00*a10);
  a00=(a00/a06);
  a19=(a19*a17);
  a01=(a01*a14);
  a19=(a19+a01);
  a00=(a00-a19);
  a18=(a18*a00);
  a21=(a21+a18);
  if (res[1]!=0) res[1][1]=a21;
  a03=(a11*a03);
  a23=(a08*a23);
  a03=(a03-a23);
  a03=(a15*a03);
  a12=(a16*a12);
  a25=(a25*a12);
  a03=(a03-a25);
  a16=(a16*a20);
  a22=(a22*a16);
  a03=(a03-a22);
  if (res[1]!=0) res[1][2]=a03;
  a05=(a05*a02);
  a05=(a05*a10);
  a05=(a05/a06);
  a11=(a11*a17);
  a08=(a08*a14);
  a11=(a11+a08);
  a05=(a05-a11);
  a15=(a15*a05);
  a16=(a16*a00);
  a15=(a15-a16);
  a12=(a12*a07);
  a15=(a15+a12);
  if (res[1]!=0) res[1][3]=a15;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_camera2ctd(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int landing_camera2ctd_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void landing_camera2ctd_release(int mem) {
}

CASADI_SYMBOL_EXPORT void landing_camera2ctd_incref(void) {
}

CASADI_SYMBOL_EXPORT void landing_camera2ctd_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int landing_camera2ctd_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int landing_camera2ctd_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real landing_camera2ctd_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_camera2ctd_name_in(casadi_int i) {
  switch (i) {
    case 0: return "angles_cam";
    case 1: return "attitude";
    case 2: return "angled_deck";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_camera2ctd_name_out(casadi_int i) {
  switch (i) {
    case 0: return "angles_ctd";
    case 1: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_camera2ctd_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_camera2ctd_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int landing_camera2ctd_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_camera2ctd_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


