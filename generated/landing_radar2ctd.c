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
  #define CASADI_PREFIX(ID) landing_radar2ctd_ ## ID
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
CASADI_SYMBOL_EXPORT void landing_radar2ctd_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int landing_radar2ctd_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int landing_radar2ctd_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {3, 3, 1};

/* landing_radar2ctd:(polar_rdr[3],attitude[3],angled_deck,d_radar_deck[3],d_camera_deck[3])->(polar_ctd[3],BMA[3x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32;
  a00=arg[0]? arg[0][2] : 0;
  a01=sin(a00);
  a02=arg[0]? arg[0][0] : 0;
  a03=(a01*a02);
  a04=arg[3]? arg[3][2] : 0;
  a04=(a03+a04);
  a05=arg[2]? arg[2][0] : 0;
  a06=cos(a05);
  a07=arg[1]? arg[1][0] : 0;
  a08=cos(a07);
  a09=arg[1]? arg[1][2] : 0;
  a10=sin(a09);
  a11=(a08*a10);
  a09=cos(a09);
  a07=sin(a07);
  a12=(a09*a07);
  a13=arg[1]? arg[1][1] : 0;
  a14=sin(a13);
  a15=(a12*a14);
  a11=(a11-a15);
  a15=(a06*a11);
  a05=sin(a05);
  a16=(a07*a10);
  a17=(a09*a08);
  a18=(a17*a14);
  a18=(a16+a18);
  a19=(a05*a18);
  a15=(a15-a19);
  a19=(a04*a15);
  a20=arg[3]? arg[3][0] : 0;
  a21=arg[0]? arg[0][1] : 0;
  a22=cos(a21);
  a00=cos(a00);
  a23=(a00*a02);
  a24=(a22*a23);
  a20=(a20+a24);
  a16=(a16*a14);
  a17=(a17+a16);
  a16=(a17*a06);
  a24=(a08*a14);
  a24=(a24*a10);
  a24=(a24-a12);
  a12=(a24*a05);
  a16=(a16+a12);
  a12=(a20*a16);
  a19=(a19+a12);
  a13=cos(a13);
  a07=(a07*a13);
  a12=(a06*a07);
  a08=(a08*a13);
  a25=(a05*a08);
  a12=(a12+a25);
  a21=sin(a21);
  a23=(a21*a23);
  a25=arg[3]? arg[3][1] : 0;
  a25=(a23+a25);
  a26=(a12*a25);
  a19=(a19+a26);
  a26=arg[4]? arg[4][0] : 0;
  a27=(a16*a26);
  a19=(a19-a27);
  a27=arg[4]? arg[4][1] : 0;
  a28=(a12*a27);
  a19=(a19-a28);
  a28=arg[4]? arg[4][2] : 0;
  a29=(a15*a28);
  a19=(a19-a29);
  a29=casadi_sq(a19);
  a11=(a05*a11);
  a18=(a06*a18);
  a11=(a11+a18);
  a18=(a04*a11);
  a17=(a17*a05);
  a24=(a06*a24);
  a17=(a17-a24);
  a24=(a20*a17);
  a18=(a18+a24);
  a05=(a05*a07);
  a06=(a06*a08);
  a05=(a05-a06);
  a06=(a05*a25);
  a18=(a18+a06);
  a06=(a17*a26);
  a18=(a18-a06);
  a06=(a05*a27);
  a18=(a18-a06);
  a06=(a11*a28);
  a18=(a18-a06);
  a06=casadi_sq(a18);
  a29=(a29+a06);
  a06=(a09*a13);
  a04=(a04*a06);
  a25=(a25*a14);
  a04=(a04+a25);
  a10=(a10*a13);
  a26=(a10*a26);
  a04=(a04+a26);
  a28=(a06*a28);
  a04=(a04-a28);
  a20=(a20*a10);
  a04=(a04-a20);
  a27=(a14*a27);
  a04=(a04-a27);
  a27=casadi_sq(a04);
  a27=(a29+a27);
  a20=sqrt(a27);
  if (res[0]!=0) res[0][0]=a20;
  a28=atan2(a19,a18);
  if (res[0]!=0) res[0][1]=a28;
  a28=sqrt(a29);
  a26=atan2(a04,a28);
  if (res[0]!=0) res[0][2]=a26;
  a26=(a04/a20);
  a06=(a06*a26);
  a25=(a19/a20);
  a08=(a15*a25);
  a06=(a06+a08);
  a20=(a18/a20);
  a08=(a11*a20);
  a06=(a06+a08);
  a08=(a06*a01);
  a07=(a16*a25);
  a24=(a17*a20);
  a07=(a07+a24);
  a24=(a26*a10);
  a07=(a07-a24);
  a24=(a00*a22);
  a30=(a07*a24);
  a08=(a08+a30);
  a25=(a12*a25);
  a20=(a05*a20);
  a25=(a25+a20);
  a26=(a26*a14);
  a25=(a25+a26);
  a26=(a21*a00);
  a20=(a25*a26);
  a08=(a08+a20);
  if (res[1]!=0) res[1][0]=a08;
  a08=(a18/a29);
  a20=(a16*a08);
  a30=(a19/a29);
  a31=(a17*a30);
  a20=(a20-a31);
  a31=(a24*a20);
  a32=(a12*a18);
  a32=(a32/a29);
  a29=(a05*a30);
  a32=(a32-a29);
  a29=(a26*a32);
  a31=(a31+a29);
  a08=(a15*a08);
  a30=(a11*a30);
  a08=(a08-a30);
  a30=(a08*a01);
  a31=(a31+a30);
  if (res[1]!=0) res[1][1]=a31;
  a14=(a28*a14);
  a14=(a14/a27);
  a04=(a04/a27);
  a04=(a04/a28);
  a19=(a19*a04);
  a12=(a12*a19);
  a18=(a18*a04);
  a05=(a05*a18);
  a12=(a12+a05);
  a14=(a14-a12);
  a26=(a26*a14);
  a16=(a16*a19);
  a17=(a17*a18);
  a16=(a16+a17);
  a17=(a28/a27);
  a17=(a17*a10);
  a16=(a16+a17);
  a17=(a24*a16);
  a26=(a26-a17);
  a09=(a09*a28);
  a09=(a09/a27);
  a09=(a09*a13);
  a15=(a15*a19);
  a11=(a11*a18);
  a15=(a15+a11);
  a09=(a09-a15);
  a01=(a09*a01);
  a26=(a26+a01);
  if (res[1]!=0) res[1][2]=a26;
  a26=(a24*a25);
  a26=(a26*a02);
  a01=(a23*a07);
  a26=(a26-a01);
  if (res[1]!=0) res[1][3]=a26;
  a26=(a24*a32);
  a26=(a26*a02);
  a01=(a23*a20);
  a26=(a26-a01);
  if (res[1]!=0) res[1][4]=a26;
  a23=(a23*a16);
  a24=(a24*a14);
  a24=(a24*a02);
  a23=(a23+a24);
  if (res[1]!=0) res[1][5]=a23;
  a06=(a00*a06);
  a06=(a06*a02);
  a22=(a03*a22);
  a07=(a07*a22);
  a21=(a21*a03);
  a25=(a25*a21);
  a07=(a07+a25);
  a06=(a06-a07);
  if (res[1]!=0) res[1][6]=a06;
  a08=(a00*a08);
  a08=(a08*a02);
  a20=(a22*a20);
  a32=(a21*a32);
  a20=(a20+a32);
  a08=(a08-a20);
  if (res[1]!=0) res[1][7]=a08;
  a22=(a22*a16);
  a21=(a21*a14);
  a22=(a22-a21);
  a00=(a00*a09);
  a00=(a00*a02);
  a22=(a22+a00);
  if (res[1]!=0) res[1][8]=a22;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_radar2ctd(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int landing_radar2ctd_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void landing_radar2ctd_release(int mem) {
}

CASADI_SYMBOL_EXPORT void landing_radar2ctd_incref(void) {
}

CASADI_SYMBOL_EXPORT void landing_radar2ctd_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int landing_radar2ctd_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int landing_radar2ctd_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real landing_radar2ctd_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_radar2ctd_name_in(casadi_int i) {
  switch (i) {
    case 0: return "polar_rdr";
    case 1: return "attitude";
    case 2: return "angled_deck";
    case 3: return "d_radar_deck";
    case 4: return "d_camera_deck";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* landing_radar2ctd_name_out(casadi_int i) {
  switch (i) {
    case 0: return "polar_ctd";
    case 1: return "BMA";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_radar2ctd_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s0;
    case 4: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* landing_radar2ctd_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int landing_radar2ctd_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int landing_radar2ctd_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


