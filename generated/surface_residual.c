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
  #define CASADI_PREFIX(ID) surface_residual_ ## ID
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
CASADI_SYMBOL_EXPORT void surface_residual_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int surface_residual_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int surface_residual_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {1, 3, 1};

/* surface_residual:(p_ecef[3],alt_surface)->(residual,J[1x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55;
  a00=arg[1]? arg[1][0] : 0;
  a01=6378137.;
  a02=1.;
  a03=-6.6943799901413173e-03;
  a04=arg[0]? arg[0][2] : 0;
  a05=4.2841311513313573e+04;
  a06=9.9664718933525254e-01;
  a06=(a06*a04);
  a07=4.2697672707179969e+04;
  a08=casadi_sq(a04);
  a09=(a04*a08);
  a10=(a07*a09);
  a11=9.9330562000985867e-01;
  a12=arg[0]? arg[0][0] : 0;
  a13=casadi_sq(a12);
  a14=(a11*a13);
  a14=(a08+a14);
  a15=arg[0]? arg[0][1] : 0;
  a16=casadi_sq(a15);
  a11=(a11*a16);
  a14=(a14+a11);
  a11=sqrt(a14);
  a11=(a14*a11);
  a10=(a10/a11);
  a06=(a06+a10);
  a10=casadi_sq(a06);
  a17=(a06*a10);
  a18=(a05*a17);
  a13=(a13+a16);
  a16=sqrt(a13);
  a19=-4.2269639397749110e+04;
  a13=(a13*a16);
  a19=(a19*a13);
  a19=(a19/a11);
  a19=(a16+a19);
  a20=casadi_sq(a19);
  a21=(a10+a20);
  a22=sqrt(a21);
  a22=(a21*a22);
  a23=(a18/a22);
  a23=(a04+a23);
  a24=casadi_sq(a23);
  a03=(a03*a24);
  a25=(a19*a20);
  a07=(a07/a22);
  a26=(a25*a07);
  a26=(a16-a26);
  a27=casadi_sq(a26);
  a27=(a24+a27);
  a03=(a03/a27);
  a03=(a02+a03);
  a03=sqrt(a03);
  a28=(a01*a03);
  a00=(a00+a28);
  a28=sqrt(a27);
  a29=(a16/a28);
  a30=(a26*a29);
  a00=(a00-a30);
  a30=(a23/a28);
  a31=(a30*a04);
  a00=(a00-a31);
  if (res[0]!=0) res[0][0]=a00;
  a01=(a01/a03);
  a03=3.3471899950706587e-03;
  a24=(a03*a24);
  a00=casadi_sq(a27);
  a24=(a24/a00);
  a00=-3.2705617946547577e+10;
  a31=-2.5000000000000000e+00;
  a14=pow(a14,a31);
  a09=(a09*a14);
  a32=(a09*a12);
  a10=(a10/a22);
  a33=(a32*a10);
  a34=(a00*a33);
  a35=8.5682623026627145e+04;
  a17=(a35*a17);
  a21=pow(a21,a31);
  a31=(a17*a21);
  a36=3.8170654435245076e+05;
  a36=(a36*a06);
  a32=(a32*a36);
  a37=1.5000000000000000e+00;
  a37=(a37*a19);
  a38=(a12/a16);
  a39=(2.*a38);
  a40=-2.5361783638649466e+05;
  a41=(a16/a11);
  a42=(a41*a12);
  a43=(a40*a42);
  a39=(a39+a43);
  a43=2.5192002221744598e+05;
  a13=(a14*a13);
  a44=(a13*a12);
  a45=(a43*a44);
  a39=(a39+a45);
  a39=(a37*a39);
  a32=(a32-a39);
  a39=(a31*a32);
  a34=(a34+a39);
  a34=(a23*a34);
  a39=-8.5395345414359937e+04;
  a45=(a25*a21);
  a46=(a45*a32);
  a47=(a39*a46);
  a48=3.;
  a49=(a48*a38);
  a50=-3.8042675457974197e+05;
  a42=(a50*a42);
  a49=(a49+a42);
  a42=3.7788003332616895e+05;
  a44=(a42*a44);
  a49=(a49+a44);
  a49=(a20*a49);
  a44=8.5395345414359937e+04;
  a44=(a44/a22);
  a51=(a49*a44);
  a47=(a47-a51);
  a51=2.;
  a52=(a51/a16);
  a12=(a52*a12);
  a47=(a47+a12);
  a47=(a26*a47);
  a12=(a34+a47);
  a12=(a24*a12);
  a03=(a03/a27);
  a53=(a34*a03);
  a12=(a12-a53);
  a12=(a01*a12);
  a53=-4.2697672707179969e+04;
  a46=(a53*a46);
  a46=(a46+a38);
  a49=(a07*a49);
  a46=(a46-a49);
  a46=(a29*a46);
  a49=(a26/a28);
  a38=(a38*a49);
  a46=(a46+a38);
  a38=(a04/a28);
  a54=-1.6352808973273788e+10;
  a33=(a54*a33);
  a55=(a18*a21);
  a32=(a55*a32);
  a33=(a33+a32);
  a33=(a38*a33);
  a46=(a46+a33);
  a33=-5.0000000000000000e-01;
  a34=(a33*a34);
  a47=(a33*a47);
  a34=(a34+a47);
  a27=(a27*a28);
  a34=(a34/a27);
  a28=(a23*a04);
  a47=(a34*a28);
  a46=(a46+a47);
  a47=(a26*a16);
  a34=(a34*a47);
  a46=(a46+a34);
  a12=(a12-a46);
  if (res[1]!=0) res[1][0]=a12;
  a09=(a09*a15);
  a12=(a10*a09);
  a00=(a00*a12);
  a36=(a36*a09);
  a16=(a15/a16);
  a09=(2.*a16);
  a41=(a41*a15);
  a40=(a40*a41);
  a09=(a09+a40);
  a40=(a13*a15);
  a43=(a43*a40);
  a09=(a09+a43);
  a37=(a37*a09);
  a36=(a36-a37);
  a31=(a31*a36);
  a00=(a00+a31);
  a00=(a23*a00);
  a45=(a45*a36);
  a31=(a39*a45);
  a48=(a48*a16);
  a41=(a50*a41);
  a48=(a48+a41);
  a42=(a42*a40);
  a48=(a48+a42);
  a48=(a20*a48);
  a44=(a44*a48);
  a31=(a31-a44);
  a52=(a52*a15);
  a31=(a31+a52);
  a31=(a26*a31);
  a52=(a00+a31);
  a52=(a24*a52);
  a15=(a03*a00);
  a52=(a52-a15);
  a52=(a01*a52);
  a45=(a53*a45);
  a45=(a45+a16);
  a07=(a07*a48);
  a45=(a45-a07);
  a45=(a29*a45);
  a54=(a54*a12);
  a55=(a55*a36);
  a54=(a54+a55);
  a54=(a38*a54);
  a45=(a45+a54);
  a49=(a49*a16);
  a45=(a45+a49);
  a00=(a33*a00);
  a31=(a33*a31);
  a00=(a00+a31);
  a00=(a00/a27);
  a31=(a28*a00);
  a45=(a45+a31);
  a00=(a47*a00);
  a45=(a45+a00);
  a52=(a52-a45);
  if (res[1]!=0) res[1][1]=a52;
  a52=2.9899415680057575e+00;
  a45=-3.8427905436461972e+05;
  a00=casadi_sq(a08);
  a14=(a14*a00);
  a45=(a45*a14);
  a52=(a52+a45);
  a45=3.8427905436461972e+05;
  a08=(a08/a11);
  a45=(a45*a08);
  a52=(a52+a45);
  a10=(a10*a52);
  a35=(a35*a10);
  a51=(a51+a35);
  a13=(a13*a04);
  a50=(a50*a13);
  a50=(a50*a19);
  a19=-1.5000000000000000e+00;
  a19=(a19*a06);
  a06=1.9932943786705051e+00;
  a04=-2.5618603624307981e+05;
  a04=(a04*a14);
  a06=(a06+a04);
  a04=2.5618603624307981e+05;
  a04=(a04*a08);
  a06=(a06+a04);
  a19=(a19*a06);
  a50=(a50+a19);
  a21=(a21*a50);
  a17=(a17*a21);
  a51=(a51+a17);
  a23=(a23*a51);
  a51=-3.2486674112201004e+10;
  a13=(a13/a22);
  a13=(a13*a20);
  a51=(a51*a13);
  a25=(a25*a21);
  a39=(a39*a25);
  a51=(a51+a39);
  a26=(a26*a51);
  a51=(a23+a26);
  a24=(a24*a51);
  a03=(a03*a23);
  a24=(a24-a03);
  a01=(a01*a24);
  a24=-1.6243337056100502e+10;
  a24=(a24*a13);
  a53=(a53*a25);
  a24=(a24+a53);
  a29=(a29*a24);
  a30=(a30+a29);
  a05=(a05*a10);
  a02=(a02+a05);
  a18=(a18*a21);
  a02=(a02+a18);
  a38=(a38*a02);
  a30=(a30+a38);
  a23=(a33*a23);
  a33=(a33*a26);
  a23=(a23+a33);
  a23=(a23/a27);
  a28=(a28*a23);
  a30=(a30+a28);
  a47=(a47*a23);
  a30=(a30+a47);
  a01=(a01-a30);
  if (res[1]!=0) res[1][2]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int surface_residual(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int surface_residual_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void surface_residual_release(int mem) {
}

CASADI_SYMBOL_EXPORT void surface_residual_incref(void) {
}

CASADI_SYMBOL_EXPORT void surface_residual_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int surface_residual_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int surface_residual_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real surface_residual_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* surface_residual_name_in(casadi_int i) {
  switch (i) {
    case 0: return "p_ecef";
    case 1: return "alt_surface";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* surface_residual_name_out(casadi_int i) {
  switch (i) {
    case 0: return "residual";
    case 1: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* surface_residual_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* surface_residual_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    case 1: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int surface_residual_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int surface_residual_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


