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
  #define CASADI_PREFIX(ID) deck2enu_jacobians_ ## ID
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
CASADI_SYMBOL_EXPORT void deck2enu_jacobians_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int deck2enu_jacobians_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int deck2enu_jacobians_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {1, 1, 1};
static const casadi_int casadi_s1[3] = {3, 1, 1};
static const casadi_int casadi_s2[3] = {3, 6, 1};
static const casadi_int casadi_s3[3] = {3, 3, 1};

/* deck2enu_jacobians:(r,q,e,heading,pitch,roll)->(u_enu[3],Psi[3x6],Gamma[3x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  a00=arg[2]? arg[2][0] : 0;
  a01=cos(a00);
  a02=arg[0]? arg[0][0] : 0;
  a03=(a01*a02);
  a04=arg[1]? arg[1][0] : 0;
  a05=cos(a04);
  a06=arg[4]? arg[4][0] : 0;
  a07=cos(a06);
  a08=(a05*a07);
  a09=(a03*a08);
  a10=arg[3]? arg[3][0] : 0;
  a11=sin(a10);
  a12=(a09*a11);
  a10=cos(a10);
  a13=arg[5]? arg[5][0] : 0;
  a14=cos(a13);
  a15=(a10*a14);
  a13=sin(a13);
  a16=(a13*a11);
  a06=sin(a06);
  a17=(a16*a06);
  a17=(a15+a17);
  a04=sin(a04);
  a18=(a01*a04);
  a19=(a17*a18);
  a20=(a19*a02);
  a20=(a12+a20);
  a21=(a14*a11);
  a22=(a06*a21);
  a23=(a10*a13);
  a22=(a22-a23);
  a00=sin(a00);
  a24=(a22*a00);
  a25=(a24*a02);
  a20=(a20-a25);
  if (res[0]!=0) res[0][0]=a20;
  a20=(a10*a09);
  a25=(a15*a06);
  a16=(a16+a25);
  a25=(a16*a00);
  a26=(a25*a02);
  a20=(a20-a26);
  a26=(a23*a06);
  a26=(a26-a21);
  a27=(a18*a26);
  a28=(a27*a02);
  a20=(a20+a28);
  if (res[0]!=0) res[0][1]=a20;
  a28=(a05*a06);
  a29=(a03*a28);
  a30=(a00*a02);
  a31=(a07*a14);
  a32=(a30*a31);
  a32=(a29+a32);
  a33=(a18*a02);
  a34=(a13*a07);
  a35=(a33*a34);
  a32=(a32-a35);
  if (res[0]!=0) res[0][2]=a32;
  if (res[1]!=0) res[1][0]=a20;
  a20=(a30*a22);
  a20=(a20-a12);
  a12=(a17*a33);
  a20=(a20-a12);
  if (res[1]!=0) res[1][1]=a20;
  a20=0.;
  if (res[1]!=0) res[1][2]=a20;
  a20=(a13*a01);
  a20=(a20*a04);
  a20=(a20*a07);
  a20=(a20*a11);
  a20=(a20*a02);
  a12=(a29*a11);
  a32=(a07*a30);
  a21=(a32*a21);
  a12=(a12+a21);
  a20=(a20-a12);
  if (res[1]!=0) res[1][3]=a20;
  a23=(a23*a01);
  a23=(a23*a04);
  a23=(a23*a07);
  a23=(a23*a02);
  a29=(a10*a29);
  a15=(a15*a32);
  a29=(a29+a15);
  a23=(a23-a29);
  if (res[1]!=0) res[1][4]=a23;
  a23=(a06*a33);
  a29=(a13*a23);
  a29=(a09+a29);
  a06=(a06*a14);
  a06=(a06*a30);
  a29=(a29-a06);
  if (res[1]!=0) res[1][5]=a29;
  a29=(a17*a30);
  a06=(a33*a22);
  a06=(a29+a06);
  if (res[1]!=0) res[1][6]=a06;
  a06=(a26*a30);
  a14=(a16*a33);
  a14=(a06+a14);
  if (res[1]!=0) res[1][7]=a14;
  a14=(a30*a34);
  a15=(a31*a33);
  a15=(a14+a15);
  a15=(-a15);
  if (res[1]!=0) res[1][8]=a15;
  a19=(a19-a24);
  a24=(a01*a08);
  a15=(a24*a11);
  a19=(a19+a15);
  if (res[1]!=0) res[1][9]=a19;
  a27=(a27-a25);
  a24=(a10*a24);
  a27=(a27+a24);
  if (res[1]!=0) res[1][10]=a27;
  a24=(a01*a28);
  a00=(a31*a00);
  a24=(a24+a00);
  a18=(a18*a34);
  a24=(a24-a18);
  if (res[1]!=0) res[1][11]=a24;
  a05=(a03*a05);
  a17=(a17*a05);
  a07=(a07*a33);
  a33=(a11*a07);
  a17=(a17-a33);
  if (res[1]!=0) res[1][12]=a17;
  a26=(a26*a05);
  a07=(a10*a07);
  a26=(a26-a07);
  if (res[1]!=0) res[1][13]=a26;
  a13=(a13*a09);
  a23=(a23+a13);
  a23=(-a23);
  if (res[1]!=0) res[1][14]=a23;
  a29=(a04*a29);
  a08=(a08*a30);
  a11=(a11*a08);
  a29=(a29+a11);
  a22=(a01*a22);
  a22=(a22*a02);
  a29=(a29+a22);
  a29=(-a29);
  if (res[1]!=0) res[1][15]=a29;
  a10=(a10*a08);
  a06=(a04*a06);
  a10=(a10+a06);
  a01=(a01*a16);
  a01=(a01*a02);
  a10=(a10+a01);
  a10=(-a10);
  if (res[1]!=0) res[1][16]=a10;
  a04=(a04*a14);
  a03=(a03*a31);
  a04=(a04+a03);
  a28=(a28*a30);
  a04=(a04-a28);
  if (res[1]!=0) res[1][17]=a04;
  if (res[2]!=0) res[2][0]=a19;
  if (res[2]!=0) res[2][1]=a27;
  if (res[2]!=0) res[2][2]=a24;
  if (res[2]!=0) res[2][3]=a17;
  if (res[2]!=0) res[2][4]=a26;
  if (res[2]!=0) res[2][5]=a23;
  if (res[2]!=0) res[2][6]=a29;
  if (res[2]!=0) res[2][7]=a10;
  if (res[2]!=0) res[2][8]=a04;
  return 0;
}

CASADI_SYMBOL_EXPORT int deck2enu_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int deck2enu_jacobians_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void deck2enu_jacobians_release(int mem) {
}

CASADI_SYMBOL_EXPORT void deck2enu_jacobians_incref(void) {
}

CASADI_SYMBOL_EXPORT void deck2enu_jacobians_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int deck2enu_jacobians_n_in(void) { return 6;}

CASADI_SYMBOL_EXPORT casadi_int deck2enu_jacobians_n_out(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_real deck2enu_jacobians_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* deck2enu_jacobians_name_in(casadi_int i) {
  switch (i) {
    case 0: return "r";
    case 1: return "q";
    case 2: return "e";
    case 3: return "heading";
    case 4: return "pitch";
    case 5: return "roll";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* deck2enu_jacobians_name_out(casadi_int i) {
  switch (i) {
    case 0: return "u_enu";
    case 1: return "Psi";
    case 2: return "Gamma";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* deck2enu_jacobians_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    case 3: return casadi_s0;
    case 4: return casadi_s0;
    case 5: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* deck2enu_jacobians_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s2;
    case 2: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int deck2enu_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 6;
  if (sz_res) *sz_res = 3;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int deck2enu_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 6*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


