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
  #define CASADI_PREFIX(ID) fleet_plot2ecef_ecc_ ## ID
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
CASADI_SYMBOL_EXPORT void fleet_plot2ecef_ecc_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int fleet_plot2ecef_ecc_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int fleet_plot2ecef_ecc_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {1, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};
static const casadi_int casadi_s2[3] = {2, 1, 1};

/* fleet_plot2ecef_ecc:(lat,lon,alt,heading,pitch,roll,att_err[3],bias[3],gain,pos_err[3],ecc[2],lever_deck[3],r,q,e)->(p_ecef[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38;
  a00=arg[1]? arg[1][0] : 0;
  a01=sin(a00);
  a02=arg[9]? arg[9][0] : 0;
  a03=(a01*a02);
  a00=cos(a00);
  a04=arg[0]? arg[0][0] : 0;
  a05=sin(a04);
  a06=(a00*a05);
  a07=arg[9]? arg[9][1] : 0;
  a08=(a06*a07);
  a03=(a03+a08);
  a04=cos(a04);
  a08=(a00*a04);
  a09=arg[2]? arg[2][0] : 0;
  a10=6378137.;
  a11=1.;
  a12=-6.6943799901413173e-03;
  a13=casadi_sq(a05);
  a12=(a12*a13);
  a12=(a11+a12);
  a12=sqrt(a12);
  a10=(a10/a12);
  a10=(a09+a10);
  a13=(a08*a10);
  a03=(a03+a13);
  a13=arg[12]? arg[12][0] : 0;
  a14=arg[7]? arg[7][0] : 0;
  a13=(a13-a14);
  a14=arg[8]? arg[8][0] : 0;
  a11=(a11+a14);
  a14=(a13/a11);
  a15=arg[7]? arg[7][2] : 0;
  a16=arg[14]? arg[14][0] : 0;
  a15=(a15-a16);
  a16=cos(a15);
  a17=(a14*a16);
  a18=arg[7]? arg[7][1] : 0;
  a19=arg[13]? arg[13][0] : 0;
  a18=(a18-a19);
  a20=arg[10]? arg[10][1] : 0;
  a21=cos(a19);
  a20=(a20*a21);
  a18=(a18+a20);
  a20=arg[10]? arg[10][0] : 0;
  a19=sin(a19);
  a20=(a20*a19);
  a18=(a18+a20);
  a20=cos(a18);
  a19=(a17*a20);
  a21=arg[6]? arg[6][1] : 0;
  a22=arg[4]? arg[4][0] : 0;
  a21=(a21-a22);
  a22=sin(a21);
  a23=(a19*a22);
  a21=cos(a21);
  a15=sin(a15);
  a14=(a14*a15);
  a15=(a21*a14);
  a24=arg[6]? arg[6][2] : 0;
  a25=arg[5]? arg[5][0] : 0;
  a24=(a24-a25);
  a25=cos(a24);
  a15=(a15*a25);
  a23=(a23+a15);
  a18=sin(a18);
  a17=(a17*a18);
  a18=(a21*a17);
  a24=sin(a24);
  a18=(a18*a24);
  a23=(a23+a18);
  a18=(a08*a23);
  a03=(a03-a18);
  a18=arg[11]? arg[11][0] : 0;
  a15=(a08*a21);
  a26=(a15*a24);
  a27=arg[6]? arg[6][0] : 0;
  a28=arg[3]? arg[3][0] : 0;
  a27=(a27-a28);
  a28=cos(a27);
  a29=(a28*a25);
  a27=sin(a27);
  a30=(a27*a24);
  a31=(a22*a30);
  a31=(a29-a31);
  a32=(a01*a31);
  a33=(a25*a27);
  a34=(a28*a24);
  a35=(a34*a22);
  a35=(a33+a35);
  a36=(a35*a06);
  a32=(a32+a36);
  a26=(a26-a32);
  a26=(a18*a26);
  a03=(a03+a26);
  a26=arg[11]? arg[11][1] : 0;
  a32=(a01*a21);
  a32=(a32*a27);
  a36=(a28*a21);
  a37=(a06*a36);
  a38=(a08*a22);
  a37=(a37+a38);
  a32=(a32-a37);
  a32=(a26*a32);
  a03=(a03+a32);
  a32=arg[11]? arg[11][2] : 0;
  a33=(a33*a22);
  a34=(a34+a33);
  a33=(a01*a34);
  a29=(a29*a22);
  a29=(a29-a30);
  a30=(a06*a29);
  a33=(a33-a30);
  a15=(a15*a25);
  a33=(a33+a15);
  a33=(a32*a33);
  a03=(a03+a33);
  a33=(a34*a14);
  a15=(a17*a31);
  a33=(a33-a15);
  a27=(a21*a27);
  a19=(a27*a19);
  a33=(a33-a19);
  a19=(a01*a33);
  a03=(a03-a19);
  a11=(a36/a11);
  a11=(a11*a13);
  a11=(a11*a16);
  a11=(a11*a20);
  a17=(a35*a17);
  a14=(a29*a14);
  a17=(a17+a14);
  a11=(a11-a17);
  a06=(a06*a11);
  a03=(a03-a06);
  a06=arg[9]? arg[9][2] : 0;
  a08=(a08*a06);
  a03=(a03-a08);
  if (res[0]!=0) res[0][0]=a03;
  a33=(a00*a33);
  a03=(a01*a04);
  a10=(a10*a03);
  a33=(a33+a10);
  a10=(a23*a03);
  a33=(a33-a10);
  a01=(a01*a05);
  a10=(a01*a07);
  a33=(a33+a10);
  a31=(a00*a31);
  a10=(a21*a03);
  a08=(a10*a24);
  a31=(a31+a08);
  a08=(a35*a01);
  a31=(a31-a08);
  a31=(a18*a31);
  a33=(a33+a31);
  a27=(a00*a27);
  a36=(a36*a01);
  a27=(a27+a36);
  a36=(a03*a22);
  a27=(a27+a36);
  a27=(a26*a27);
  a33=(a33-a27);
  a10=(a25*a10);
  a34=(a00*a34);
  a10=(a10-a34);
  a34=(a29*a01);
  a10=(a10-a34);
  a10=(a32*a10);
  a33=(a33+a10);
  a00=(a00*a02);
  a33=(a33-a00);
  a01=(a11*a01);
  a33=(a33-a01);
  a03=(a03*a06);
  a33=(a33-a03);
  if (res[0]!=0) res[0][1]=a33;
  a33=6.3354393272928204e+06;
  a33=(a33/a12);
  a09=(a09+a33);
  a09=(a05*a09);
  a23=(a05*a23);
  a09=(a09-a23);
  a11=(a04*a11);
  a09=(a09+a11);
  a35=(a35*a04);
  a11=(a05*a21);
  a24=(a11*a24);
  a35=(a35+a24);
  a18=(a18*a35);
  a09=(a09+a18);
  a28=(a28*a04);
  a28=(a28*a21);
  a22=(a05*a22);
  a28=(a28-a22);
  a26=(a26*a28);
  a09=(a09+a26);
  a29=(a04*a29);
  a25=(a25*a11);
  a29=(a29+a25);
  a32=(a32*a29);
  a09=(a09+a32);
  a05=(a05*a06);
  a09=(a09-a05);
  a04=(a04*a07);
  a09=(a09-a04);
  if (res[0]!=0) res[0][2]=a09;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_plot2ecef_ecc(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int fleet_plot2ecef_ecc_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void fleet_plot2ecef_ecc_release(int mem) {
}

CASADI_SYMBOL_EXPORT void fleet_plot2ecef_ecc_incref(void) {
}

CASADI_SYMBOL_EXPORT void fleet_plot2ecef_ecc_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int fleet_plot2ecef_ecc_n_in(void) { return 15;}

CASADI_SYMBOL_EXPORT casadi_int fleet_plot2ecef_ecc_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real fleet_plot2ecef_ecc_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_plot2ecef_ecc_name_in(casadi_int i) {
  switch (i) {
    case 0: return "lat";
    case 1: return "lon";
    case 2: return "alt";
    case 3: return "heading";
    case 4: return "pitch";
    case 5: return "roll";
    case 6: return "att_err";
    case 7: return "bias";
    case 8: return "gain";
    case 9: return "pos_err";
    case 10: return "ecc";
    case 11: return "lever_deck";
    case 12: return "r";
    case 13: return "q";
    case 14: return "e";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_plot2ecef_ecc_name_out(casadi_int i) {
  switch (i) {
    case 0: return "p_ecef";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_plot2ecef_ecc_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    case 3: return casadi_s0;
    case 4: return casadi_s0;
    case 5: return casadi_s0;
    case 6: return casadi_s1;
    case 7: return casadi_s1;
    case 8: return casadi_s0;
    case 9: return casadi_s1;
    case 10: return casadi_s2;
    case 11: return casadi_s1;
    case 12: return casadi_s0;
    case 13: return casadi_s0;
    case 14: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_plot2ecef_ecc_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int fleet_plot2ecef_ecc_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 15;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_plot2ecef_ecc_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 15*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


