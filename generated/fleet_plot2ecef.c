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
  #define CASADI_PREFIX(ID) fleet_plot2ecef_ ## ID
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
CASADI_SYMBOL_EXPORT void fleet_plot2ecef_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int fleet_plot2ecef_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int fleet_plot2ecef_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {1, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};

/* fleet_plot2ecef:(lat,lon,alt,heading,pitch,roll,att_err[3],bias[3],lever_deck[3],r,q,e)->(p_ecef[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36;
  a00=arg[1]? arg[1][0] : 0;
  a01=cos(a00);
  a02=arg[0]? arg[0][0] : 0;
  a03=cos(a02);
  a04=(a01*a03);
  a05=arg[2]? arg[2][0] : 0;
  a06=6378137.;
  a07=1.;
  a08=-6.6943799901413173e-03;
  a02=sin(a02);
  a09=casadi_sq(a02);
  a08=(a08*a09);
  a07=(a07+a08);
  a07=sqrt(a07);
  a06=(a06/a07);
  a06=(a05+a06);
  a08=(a04*a06);
  a09=arg[9]? arg[9][0] : 0;
  a10=arg[7]? arg[7][0] : 0;
  a09=(a09-a10);
  a10=arg[7]? arg[7][2] : 0;
  a11=arg[11]? arg[11][0] : 0;
  a10=(a10-a11);
  a11=sin(a10);
  a11=(a09*a11);
  a12=arg[6]? arg[6][1] : 0;
  a13=arg[4]? arg[4][0] : 0;
  a12=(a12-a13);
  a13=cos(a12);
  a14=arg[6]? arg[6][2] : 0;
  a15=arg[5]? arg[5][0] : 0;
  a14=(a14-a15);
  a15=cos(a14);
  a16=(a13*a15);
  a17=(a11*a16);
  a10=cos(a10);
  a18=(a09*a10);
  a19=arg[7]? arg[7][1] : 0;
  a20=arg[10]? arg[10][0] : 0;
  a19=(a19-a20);
  a20=sin(a19);
  a20=(a18*a20);
  a14=sin(a14);
  a21=(a13*a14);
  a22=(a20*a21);
  a17=(a17+a22);
  a19=cos(a19);
  a18=(a18*a19);
  a12=sin(a12);
  a22=(a18*a12);
  a17=(a17+a22);
  a22=(a04*a17);
  a08=(a08-a22);
  a22=arg[8]? arg[8][0] : 0;
  a23=(a04*a13);
  a24=(a23*a14);
  a00=sin(a00);
  a25=arg[6]? arg[6][0] : 0;
  a26=arg[3]? arg[3][0] : 0;
  a25=(a25-a26);
  a26=cos(a25);
  a27=(a26*a15);
  a25=sin(a25);
  a28=(a25*a14);
  a29=(a12*a28);
  a29=(a27-a29);
  a30=(a00*a29);
  a31=(a15*a25);
  a32=(a26*a14);
  a33=(a32*a12);
  a33=(a31+a33);
  a34=(a01*a02);
  a35=(a33*a34);
  a30=(a30+a35);
  a24=(a24-a30);
  a24=(a22*a24);
  a08=(a08+a24);
  a24=arg[8]? arg[8][1] : 0;
  a30=(a00*a13);
  a30=(a30*a25);
  a35=(a26*a13);
  a36=(a34*a35);
  a04=(a04*a12);
  a36=(a36+a04);
  a30=(a30-a36);
  a30=(a24*a30);
  a08=(a08+a30);
  a30=arg[8]? arg[8][2] : 0;
  a31=(a31*a12);
  a32=(a32+a31);
  a31=(a00*a32);
  a27=(a27*a12);
  a27=(a27-a28);
  a28=(a34*a27);
  a31=(a31-a28);
  a23=(a23*a15);
  a31=(a31+a23);
  a31=(a30*a31);
  a08=(a08+a31);
  a31=(a32*a11);
  a23=(a20*a29);
  a31=(a31-a23);
  a25=(a13*a25);
  a18=(a25*a18);
  a31=(a31-a18);
  a18=(a00*a31);
  a08=(a08-a18);
  a09=(a35*a09);
  a09=(a09*a10);
  a09=(a09*a19);
  a20=(a33*a20);
  a11=(a27*a11);
  a20=(a20+a11);
  a09=(a09-a20);
  a34=(a34*a09);
  a08=(a08-a34);
  if (res[0]!=0) res[0][0]=a08;
  a31=(a01*a31);
  a08=(a00*a03);
  a06=(a06*a08);
  a31=(a31+a06);
  a06=(a17*a08);
  a31=(a31-a06);
  a29=(a01*a29);
  a21=(a21*a08);
  a29=(a29+a21);
  a00=(a00*a02);
  a21=(a33*a00);
  a29=(a29-a21);
  a29=(a22*a29);
  a31=(a31+a29);
  a25=(a01*a25);
  a35=(a35*a00);
  a25=(a25+a35);
  a35=(a08*a12);
  a25=(a25+a35);
  a25=(a24*a25);
  a31=(a31-a25);
  a16=(a16*a08);
  a01=(a01*a32);
  a16=(a16-a01);
  a01=(a27*a00);
  a16=(a16-a01);
  a16=(a30*a16);
  a31=(a31+a16);
  a00=(a09*a00);
  a31=(a31-a00);
  if (res[0]!=0) res[0][1]=a31;
  a31=6.3354393272928204e+06;
  a31=(a31/a07);
  a05=(a05+a31);
  a05=(a02*a05);
  a17=(a02*a17);
  a05=(a05-a17);
  a09=(a03*a09);
  a05=(a05+a09);
  a33=(a33*a03);
  a09=(a02*a13);
  a14=(a09*a14);
  a33=(a33+a14);
  a22=(a22*a33);
  a05=(a05+a22);
  a26=(a26*a03);
  a26=(a26*a13);
  a02=(a02*a12);
  a26=(a26-a02);
  a24=(a24*a26);
  a05=(a05+a24);
  a03=(a03*a27);
  a15=(a15*a09);
  a03=(a03+a15);
  a30=(a30*a03);
  a05=(a05+a30);
  if (res[0]!=0) res[0][2]=a05;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_plot2ecef(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int fleet_plot2ecef_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void fleet_plot2ecef_release(int mem) {
}

CASADI_SYMBOL_EXPORT void fleet_plot2ecef_incref(void) {
}

CASADI_SYMBOL_EXPORT void fleet_plot2ecef_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int fleet_plot2ecef_n_in(void) { return 12;}

CASADI_SYMBOL_EXPORT casadi_int fleet_plot2ecef_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real fleet_plot2ecef_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_plot2ecef_name_in(casadi_int i) {
  switch (i) {
    case 0: return "lat";
    case 1: return "lon";
    case 2: return "alt";
    case 3: return "heading";
    case 4: return "pitch";
    case 5: return "roll";
    case 6: return "att_err";
    case 7: return "bias";
    case 8: return "lever_deck";
    case 9: return "r";
    case 10: return "q";
    case 11: return "e";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_plot2ecef_name_out(casadi_int i) {
  switch (i) {
    case 0: return "p_ecef";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_plot2ecef_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    case 3: return casadi_s0;
    case 4: return casadi_s0;
    case 5: return casadi_s0;
    case 6: return casadi_s1;
    case 7: return casadi_s1;
    case 8: return casadi_s1;
    case 9: return casadi_s0;
    case 10: return casadi_s0;
    case 11: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_plot2ecef_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int fleet_plot2ecef_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 12;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_plot2ecef_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 12*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


