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
  #define CASADI_PREFIX(ID) cv_update_ ## ID
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
CASADI_SYMBOL_EXPORT void cv_update_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int cv_update_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int cv_update_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {6, 1, 1};
static const casadi_int casadi_s1[3] = {6, 6, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {3, 3, 1};

/* cv_update:(x_pred[6],P_pred[6x6],z[3],R[3x3])->(x[6],P[6x6]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44;
  a00=arg[0]? arg[0][0] : 0;
  a01=arg[1]? arg[1][0] : 0;
  a02=arg[3]? arg[3][0] : 0;
  a02=(a01+a02);
  a02=(1./a02);
  a02=sqrt(a02);
  a03=(a01*a02);
  a04=arg[1]? arg[1][6] : 0;
  a05=arg[3]? arg[3][3] : 0;
  a05=(a04+a05);
  a05=(a05*a02);
  a06=(a05*a03);
  a06=(a04-a06);
  a07=arg[1]? arg[1][7] : 0;
  a08=arg[3]? arg[3][4] : 0;
  a08=(a07+a08);
  a09=casadi_sq(a05);
  a08=(a08-a09);
  a08=(1./a08);
  a08=sqrt(a08);
  a06=(a06*a08);
  a09=arg[1]? arg[1][13] : 0;
  a10=arg[3]? arg[3][7] : 0;
  a10=(a09+a10);
  a11=arg[1]? arg[1][12] : 0;
  a12=arg[3]? arg[3][6] : 0;
  a12=(a11+a12);
  a12=(a12*a02);
  a13=(a12*a05);
  a10=(a10-a13);
  a10=(a10*a08);
  a13=(a12*a03);
  a14=(a10*a06);
  a13=(a13+a14);
  a13=(a11-a13);
  a14=arg[1]? arg[1][14] : 0;
  a15=arg[3]? arg[3][8] : 0;
  a15=(a14+a15);
  a16=casadi_sq(a10);
  a17=casadi_sq(a12);
  a16=(a16+a17);
  a15=(a15-a16);
  a15=(1./a15);
  a15=sqrt(a15);
  a13=(a13*a15);
  a13=(a13*a15);
  a16=(a10*a13);
  a06=(a06-a16);
  a06=(a06*a08);
  a16=(a05*a06);
  a17=(a12*a13);
  a16=(a16+a17);
  a03=(a03-a16);
  a03=(a03*a02);
  a16=arg[2]? arg[2][0] : 0;
  a16=(a16-a00);
  a17=(a03*a16);
  a18=arg[2]? arg[2][1] : 0;
  a19=arg[0]? arg[0][1] : 0;
  a18=(a18-a19);
  a20=(a06*a18);
  a17=(a17+a20);
  a20=arg[2]? arg[2][2] : 0;
  a21=arg[0]? arg[0][2] : 0;
  a20=(a20-a21);
  a22=(a13*a20);
  a17=(a17+a22);
  a00=(a00+a17);
  if (res[0]!=0) res[0][0]=a00;
  a00=(a04*a02);
  a17=(a05*a00);
  a17=(a07-a17);
  a17=(a17*a08);
  a22=(a12*a00);
  a23=(a10*a17);
  a22=(a22+a23);
  a22=(a09-a22);
  a22=(a22*a15);
  a22=(a22*a15);
  a23=(a10*a22);
  a17=(a17-a23);
  a17=(a17*a08);
  a23=(a05*a17);
  a24=(a12*a22);
  a23=(a23+a24);
  a00=(a00-a23);
  a00=(a00*a02);
  a23=(a00*a16);
  a24=(a17*a18);
  a23=(a23+a24);
  a24=(a22*a20);
  a23=(a23+a24);
  a19=(a19+a23);
  if (res[0]!=0) res[0][1]=a19;
  a19=(a11*a02);
  a23=(a05*a19);
  a23=(a09-a23);
  a23=(a23*a08);
  a24=(a12*a19);
  a25=(a10*a23);
  a24=(a24+a25);
  a24=(a14-a24);
  a24=(a24*a15);
  a24=(a24*a15);
  a25=(a10*a24);
  a23=(a23-a25);
  a23=(a23*a08);
  a25=(a05*a23);
  a26=(a12*a24);
  a25=(a25+a26);
  a19=(a19-a25);
  a19=(a19*a02);
  a25=(a19*a16);
  a26=(a23*a18);
  a25=(a25+a26);
  a26=(a24*a20);
  a25=(a25+a26);
  a21=(a21+a25);
  if (res[0]!=0) res[0][2]=a21;
  a21=arg[0]? arg[0][3] : 0;
  a25=arg[1]? arg[1][18] : 0;
  a26=(a25*a02);
  a27=arg[1]? arg[1][19] : 0;
  a28=(a05*a26);
  a28=(a27-a28);
  a28=(a28*a08);
  a29=arg[1]? arg[1][20] : 0;
  a30=(a12*a26);
  a31=(a10*a28);
  a30=(a30+a31);
  a30=(a29-a30);
  a30=(a30*a15);
  a30=(a30*a15);
  a31=(a10*a30);
  a28=(a28-a31);
  a28=(a28*a08);
  a31=(a05*a28);
  a32=(a12*a30);
  a31=(a31+a32);
  a26=(a26-a31);
  a26=(a26*a02);
  a31=(a26*a16);
  a32=(a28*a18);
  a31=(a31+a32);
  a32=(a30*a20);
  a31=(a31+a32);
  a21=(a21+a31);
  if (res[0]!=0) res[0][3]=a21;
  a21=arg[0]? arg[0][4] : 0;
  a31=arg[1]? arg[1][24] : 0;
  a32=(a31*a02);
  a33=arg[1]? arg[1][25] : 0;
  a34=(a05*a32);
  a34=(a33-a34);
  a34=(a34*a08);
  a35=arg[1]? arg[1][26] : 0;
  a36=(a12*a32);
  a37=(a10*a34);
  a36=(a36+a37);
  a36=(a35-a36);
  a36=(a36*a15);
  a36=(a36*a15);
  a37=(a10*a36);
  a34=(a34-a37);
  a34=(a34*a08);
  a37=(a05*a34);
  a38=(a12*a36);
  a37=(a37+a38);
  a32=(a32-a37);
  a32=(a32*a02);
  a37=(a32*a16);
  a38=(a34*a18);
  a37=(a37+a38);
  a38=(a36*a20);
  a37=(a37+a38);
  a21=(a21+a37);
  if (res[0]!=0) res[0][4]=a21;
  a21=arg[0]? arg[0][5] : 0;
  a37=arg[1]? arg[1][30] : 0;
  a38=(a37*a02);
  a39=arg[1]? arg[1][31] : 0;
  a40=(a05*a38);
  a40=(a39-a40);
  a40=(a40*a08);
  a41=arg[1]? arg[1][32] : 0;
  a42=(a12*a38);
  a43=(a10*a40);
  a42=(a42+a43);
  a42=(a41-a42);
  a42=(a42*a15);
  a42=(a42*a15);
  a10=(a10*a42);
  a40=(a40-a10);
  a40=(a40*a08);
  a05=(a05*a40);
  a12=(a12*a42);
  a05=(a05+a12);
  a38=(a38-a05);
  a38=(a38*a02);
  a16=(a38*a16);
  a18=(a40*a18);
  a16=(a16+a18);
  a20=(a42*a20);
  a16=(a16+a20);
  a21=(a21+a16);
  if (res[0]!=0) res[0][5]=a21;
  a21=(a03*a01);
  a16=(a06*a04);
  a21=(a21+a16);
  a16=(a13*a11);
  a21=(a21+a16);
  a21=(a01-a21);
  if (res[1]!=0) res[1][0]=a21;
  a21=5.0000000000000000e-01;
  a16=(a00*a01);
  a20=(a17*a04);
  a16=(a16+a20);
  a20=(a22*a11);
  a16=(a16+a20);
  a16=(a04-a16);
  a20=(a03*a04);
  a18=(a06*a07);
  a20=(a20+a18);
  a18=(a13*a09);
  a20=(a20+a18);
  a20=(a04-a20);
  a18=(a16+a20);
  a18=(a21*a18);
  if (res[1]!=0) res[1][1]=a18;
  a18=(a19*a01);
  a02=(a23*a04);
  a18=(a18+a02);
  a02=(a24*a11);
  a18=(a18+a02);
  a18=(a11-a18);
  a02=(a03*a11);
  a05=(a06*a09);
  a02=(a02+a05);
  a05=(a13*a14);
  a02=(a02+a05);
  a02=(a11-a02);
  a05=(a18+a02);
  a05=(a21*a05);
  if (res[1]!=0) res[1][2]=a05;
  a05=(a26*a01);
  a12=(a28*a04);
  a05=(a05+a12);
  a12=(a30*a11);
  a05=(a05+a12);
  a05=(a25-a05);
  a12=(a03*a25);
  a08=(a06*a27);
  a12=(a12+a08);
  a08=(a13*a29);
  a12=(a12+a08);
  a12=(a25-a12);
  a08=(a05+a12);
  a08=(a21*a08);
  if (res[1]!=0) res[1][3]=a08;
  a08=(a32*a01);
  a10=(a34*a04);
  a08=(a08+a10);
  a10=(a36*a11);
  a08=(a08+a10);
  a08=(a31-a08);
  a10=(a03*a31);
  a15=(a06*a33);
  a10=(a10+a15);
  a15=(a13*a35);
  a10=(a10+a15);
  a10=(a31-a10);
  a15=(a08+a10);
  a15=(a21*a15);
  if (res[1]!=0) res[1][4]=a15;
  a01=(a38*a01);
  a15=(a40*a04);
  a01=(a01+a15);
  a15=(a42*a11);
  a01=(a01+a15);
  a01=(a37-a01);
  a03=(a03*a37);
  a06=(a06*a39);
  a03=(a03+a06);
  a13=(a13*a41);
  a03=(a03+a13);
  a03=(a37-a03);
  a13=(a01+a03);
  a13=(a21*a13);
  if (res[1]!=0) res[1][5]=a13;
  a20=(a20+a16);
  a20=(a21*a20);
  if (res[1]!=0) res[1][6]=a20;
  a20=(a00*a04);
  a16=(a17*a07);
  a20=(a20+a16);
  a16=(a22*a09);
  a20=(a20+a16);
  a20=(a07-a20);
  if (res[1]!=0) res[1][7]=a20;
  a20=(a19*a04);
  a16=(a23*a07);
  a20=(a20+a16);
  a16=(a24*a09);
  a20=(a20+a16);
  a20=(a09-a20);
  a16=(a00*a11);
  a13=(a17*a09);
  a16=(a16+a13);
  a13=(a22*a14);
  a16=(a16+a13);
  a16=(a09-a16);
  a13=(a20+a16);
  a13=(a21*a13);
  if (res[1]!=0) res[1][8]=a13;
  a13=(a26*a04);
  a06=(a28*a07);
  a13=(a13+a06);
  a06=(a30*a09);
  a13=(a13+a06);
  a13=(a27-a13);
  a06=(a00*a25);
  a15=(a17*a27);
  a06=(a06+a15);
  a15=(a22*a29);
  a06=(a06+a15);
  a06=(a27-a06);
  a15=(a13+a06);
  a15=(a21*a15);
  if (res[1]!=0) res[1][9]=a15;
  a15=(a32*a04);
  a43=(a34*a07);
  a15=(a15+a43);
  a43=(a36*a09);
  a15=(a15+a43);
  a15=(a33-a15);
  a43=(a00*a31);
  a44=(a17*a33);
  a43=(a43+a44);
  a44=(a22*a35);
  a43=(a43+a44);
  a43=(a33-a43);
  a44=(a15+a43);
  a44=(a21*a44);
  if (res[1]!=0) res[1][10]=a44;
  a04=(a38*a04);
  a07=(a40*a07);
  a04=(a04+a07);
  a07=(a42*a09);
  a04=(a04+a07);
  a04=(a39-a04);
  a00=(a00*a37);
  a17=(a17*a39);
  a00=(a00+a17);
  a22=(a22*a41);
  a00=(a00+a22);
  a00=(a39-a00);
  a22=(a04+a00);
  a22=(a21*a22);
  if (res[1]!=0) res[1][11]=a22;
  a02=(a02+a18);
  a02=(a21*a02);
  if (res[1]!=0) res[1][12]=a02;
  a16=(a16+a20);
  a16=(a21*a16);
  if (res[1]!=0) res[1][13]=a16;
  a16=(a19*a11);
  a20=(a23*a09);
  a16=(a16+a20);
  a20=(a24*a14);
  a16=(a16+a20);
  a16=(a14-a16);
  if (res[1]!=0) res[1][14]=a16;
  a16=(a26*a11);
  a20=(a28*a09);
  a16=(a16+a20);
  a20=(a30*a14);
  a16=(a16+a20);
  a16=(a29-a16);
  a20=(a19*a25);
  a02=(a23*a27);
  a20=(a20+a02);
  a02=(a24*a29);
  a20=(a20+a02);
  a20=(a29-a20);
  a02=(a16+a20);
  a02=(a21*a02);
  if (res[1]!=0) res[1][15]=a02;
  a02=(a32*a11);
  a18=(a34*a09);
  a02=(a02+a18);
  a18=(a36*a14);
  a02=(a02+a18);
  a02=(a35-a02);
  a18=(a19*a31);
  a22=(a23*a33);
  a18=(a18+a22);
  a22=(a24*a35);
  a18=(a18+a22);
  a18=(a35-a18);
  a22=(a02+a18);
  a22=(a21*a22);
  if (res[1]!=0) res[1][16]=a22;
  a11=(a38*a11);
  a09=(a40*a09);
  a11=(a11+a09);
  a14=(a42*a14);
  a11=(a11+a14);
  a11=(a41-a11);
  a19=(a19*a37);
  a23=(a23*a39);
  a19=(a19+a23);
  a24=(a24*a41);
  a19=(a19+a24);
  a19=(a41-a19);
  a24=(a11+a19);
  a24=(a21*a24);
  if (res[1]!=0) res[1][17]=a24;
  a12=(a12+a05);
  a12=(a21*a12);
  if (res[1]!=0) res[1][18]=a12;
  a06=(a06+a13);
  a06=(a21*a06);
  if (res[1]!=0) res[1][19]=a06;
  a20=(a20+a16);
  a20=(a21*a20);
  if (res[1]!=0) res[1][20]=a20;
  a20=arg[1]? arg[1][21] : 0;
  a16=(a26*a25);
  a06=(a28*a27);
  a16=(a16+a06);
  a06=(a30*a29);
  a16=(a16+a06);
  a20=(a20-a16);
  if (res[1]!=0) res[1][21]=a20;
  a20=arg[1]? arg[1][27] : 0;
  a16=(a32*a25);
  a06=(a34*a27);
  a16=(a16+a06);
  a06=(a36*a29);
  a16=(a16+a06);
  a16=(a20-a16);
  a06=(a26*a31);
  a13=(a28*a33);
  a06=(a06+a13);
  a13=(a30*a35);
  a06=(a06+a13);
  a20=(a20-a06);
  a06=(a16+a20);
  a06=(a21*a06);
  if (res[1]!=0) res[1][22]=a06;
  a06=arg[1]? arg[1][33] : 0;
  a25=(a38*a25);
  a27=(a40*a27);
  a25=(a25+a27);
  a29=(a42*a29);
  a25=(a25+a29);
  a25=(a06-a25);
  a26=(a26*a37);
  a28=(a28*a39);
  a26=(a26+a28);
  a30=(a30*a41);
  a26=(a26+a30);
  a06=(a06-a26);
  a26=(a25+a06);
  a26=(a21*a26);
  if (res[1]!=0) res[1][23]=a26;
  a10=(a10+a08);
  a10=(a21*a10);
  if (res[1]!=0) res[1][24]=a10;
  a43=(a43+a15);
  a43=(a21*a43);
  if (res[1]!=0) res[1][25]=a43;
  a18=(a18+a02);
  a18=(a21*a18);
  if (res[1]!=0) res[1][26]=a18;
  a20=(a20+a16);
  a20=(a21*a20);
  if (res[1]!=0) res[1][27]=a20;
  a20=arg[1]? arg[1][28] : 0;
  a16=(a32*a31);
  a18=(a34*a33);
  a16=(a16+a18);
  a18=(a36*a35);
  a16=(a16+a18);
  a20=(a20-a16);
  if (res[1]!=0) res[1][28]=a20;
  a20=arg[1]? arg[1][34] : 0;
  a31=(a38*a31);
  a33=(a40*a33);
  a31=(a31+a33);
  a35=(a42*a35);
  a31=(a31+a35);
  a31=(a20-a31);
  a32=(a32*a37);
  a34=(a34*a39);
  a32=(a32+a34);
  a36=(a36*a41);
  a32=(a32+a36);
  a20=(a20-a32);
  a32=(a31+a20);
  a32=(a21*a32);
  if (res[1]!=0) res[1][29]=a32;
  a03=(a03+a01);
  a03=(a21*a03);
  if (res[1]!=0) res[1][30]=a03;
  a00=(a00+a04);
  a00=(a21*a00);
  if (res[1]!=0) res[1][31]=a00;
  a19=(a19+a11);
  a19=(a21*a19);
  if (res[1]!=0) res[1][32]=a19;
  a06=(a06+a25);
  a06=(a21*a06);
  if (res[1]!=0) res[1][33]=a06;
  a20=(a20+a31);
  a21=(a21*a20);
  if (res[1]!=0) res[1][34]=a21;
  a21=arg[1]? arg[1][35] : 0;
  a38=(a38*a37);
  a40=(a40*a39);
  a38=(a38+a40);
  a42=(a42*a41);
  a38=(a38+a42);
  a21=(a21-a38);
  if (res[1]!=0) res[1][35]=a21;
  return 0;
}

CASADI_SYMBOL_EXPORT int cv_update(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int cv_update_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void cv_update_release(int mem) {
}

CASADI_SYMBOL_EXPORT void cv_update_incref(void) {
}

CASADI_SYMBOL_EXPORT void cv_update_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int cv_update_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int cv_update_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real cv_update_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* cv_update_name_in(casadi_int i) {
  switch (i) {
    case 0: return "x_pred";
    case 1: return "P_pred";
    case 2: return "z";
    case 3: return "R";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* cv_update_name_out(casadi_int i) {
  switch (i) {
    case 0: return "x";
    case 1: return "P";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* cv_update_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* cv_update_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int cv_update_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int cv_update_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


