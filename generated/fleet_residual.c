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
  #define CASADI_PREFIX(ID) fleet_residual_ ## ID
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
CASADI_SYMBOL_EXPORT void fleet_residual_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int fleet_residual_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int fleet_residual_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {3, 9, 1};

/* fleet_residual:(p_ecef[3],lat,lon,alt,heading,pitch,roll,att_err[3],bias[3],lever_deck[3],r,q,e)->(residual[3],J[3x9],plot[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82;
  a00=arg[10]? arg[10][0] : 0;
  a01=arg[0]? arg[0][0] : 0;
  a02=arg[2]? arg[2][0] : 0;
  a03=cos(a02);
  a04=arg[1]? arg[1][0] : 0;
  a05=cos(a04);
  a06=(a03*a05);
  a07=arg[3]? arg[3][0] : 0;
  a08=6378137.;
  a09=1.;
  a10=-6.6943799901413173e-03;
  a04=sin(a04);
  a11=casadi_sq(a04);
  a10=(a10*a11);
  a09=(a09+a10);
  a09=sqrt(a09);
  a08=(a08/a09);
  a08=(a07+a08);
  a10=(a06*a08);
  a01=(a01-a10);
  a10=arg[7]? arg[7][1] : 0;
  a11=arg[5]? arg[5][0] : 0;
  a10=(a10-a11);
  a11=cos(a10);
  a12=(a11*a06);
  a13=arg[7]? arg[7][2] : 0;
  a14=arg[6]? arg[6][0] : 0;
  a13=(a13-a14);
  a14=sin(a13);
  a15=(a12*a14);
  a10=sin(a10);
  a16=arg[7]? arg[7][0] : 0;
  a17=arg[4]? arg[4][0] : 0;
  a16=(a16-a17);
  a17=sin(a16);
  a18=(a17*a14);
  a19=(a10*a18);
  a16=cos(a16);
  a13=cos(a13);
  a20=(a16*a13);
  a19=(a19-a20);
  a02=sin(a02);
  a21=(a19*a02);
  a22=(a15+a21);
  a23=(a13*a17);
  a24=(a16*a14);
  a25=(a24*a10);
  a25=(a23+a25);
  a26=(a03*a04);
  a27=(a25*a26);
  a22=(a22-a27);
  a28=arg[9]? arg[9][0] : 0;
  a29=(a22*a28);
  a01=(a01-a29);
  a29=(a02*a11);
  a30=(a29*a17);
  a31=(a06*a10);
  a32=(a04*a11);
  a33=(a16*a32);
  a34=(a03*a33);
  a35=(a31+a34);
  a35=(a30-a35);
  a36=arg[9]? arg[9][1] : 0;
  a37=(a35*a36);
  a01=(a01-a37);
  a37=(a23*a10);
  a37=(a24+a37);
  a38=(a02*a37);
  a39=(a20*a10);
  a39=(a18-a39);
  a40=(a26*a39);
  a40=(a38+a40);
  a41=(a03*a11);
  a42=(a41*a05);
  a42=(a42*a13);
  a40=(a40+a42);
  a42=arg[9]? arg[9][2] : 0;
  a43=(a40*a42);
  a01=(a01-a43);
  a43=casadi_sq(a01);
  a44=arg[0]? arg[0][1] : 0;
  a45=(a02*a05);
  a08=(a08*a45);
  a44=(a44-a08);
  a08=(a11*a45);
  a46=(a08*a14);
  a47=(a19*a03);
  a48=(a46-a47);
  a49=(a02*a04);
  a50=(a25*a49);
  a48=(a48-a50);
  a51=(a48*a28);
  a44=(a44-a51);
  a51=(a45*a10);
  a52=(a11*a17);
  a53=(a03*a52);
  a54=(a51+a53);
  a33=(a02*a33);
  a54=(a54+a33);
  a55=(a54*a36);
  a44=(a44+a55);
  a55=(a13*a08);
  a56=(a03*a37);
  a55=(a55-a56);
  a57=(a39*a49);
  a55=(a55+a57);
  a57=(a55*a42);
  a44=(a44-a57);
  a57=casadi_sq(a44);
  a43=(a43+a57);
  a57=arg[0]? arg[0][2] : 0;
  a58=6.3354393272928204e+06;
  a58=(a58/a09);
  a07=(a07+a58);
  a07=(a04*a07);
  a57=(a57-a07);
  a07=(a25*a05);
  a58=(a32*a14);
  a09=(a07+a58);
  a59=(a09*a28);
  a57=(a57-a59);
  a59=(a16*a11);
  a60=(a59*a05);
  a61=(a04*a10);
  a62=(a60-a61);
  a63=(a62*a36);
  a57=(a57-a63);
  a63=(a32*a13);
  a64=(a05*a39);
  a63=(a63-a64);
  a64=(a63*a42);
  a57=(a57-a64);
  a64=casadi_sq(a57);
  a43=(a43+a64);
  a43=sqrt(a43);
  a64=arg[8]? arg[8][0] : 0;
  a64=(a43+a64);
  a00=(a00-a64);
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[8]? arg[8][1] : 0;
  a65=(a04*a57);
  a66=(a06*a01);
  a65=(a65+a66);
  a66=(a45*a44);
  a65=(a65+a66);
  a66=(a11*a65);
  a67=(a66*a14);
  a68=(a03*a44);
  a69=(a02*a01);
  a68=(a68-a69);
  a69=(a19*a68);
  a69=(a67-a69);
  a70=(a05*a57);
  a71=(a26*a01);
  a70=(a70-a71);
  a71=(a49*a44);
  a70=(a70-a71);
  a71=(a25*a70);
  a69=(a69+a71);
  a71=(a59*a70);
  a65=(a10*a65);
  a72=(a52*a68);
  a72=(a65+a72);
  a71=(a71-a72);
  a72=atan2(a69,a71);
  a00=(a00+a72);
  a72=arg[11]? arg[11][0] : 0;
  a72=(a00-a72);
  a73=sin(a72);
  a73=(-a73);
  a72=cos(a72);
  a73=atan2(a73,a72);
  if (res[0]!=0) res[0][1]=a73;
  a73=arg[12]? arg[12][0] : 0;
  a72=arg[8]? arg[8][2] : 0;
  a74=(a13*a66);
  a75=(a37*a68);
  a76=(a39*a70);
  a77=(a75+a76);
  a77=(a74-a77);
  a78=casadi_sq(a69);
  a79=casadi_sq(a71);
  a78=(a78+a79);
  a79=sqrt(a78);
  a80=atan2(a77,a79);
  a72=(a72+a80);
  a73=(a73-a72);
  if (res[0]!=0) res[0][2]=a73;
  a73=(a01/a43);
  a73=(-a73);
  if (res[1]!=0) res[1][0]=a73;
  a73=(a69/a78);
  a35=(a73*a35);
  a80=(a71/a78);
  a22=(a80*a22);
  a35=(a35-a22);
  if (res[1]!=0) res[1][1]=a35;
  a35=casadi_sq(a77);
  a78=(a78+a35);
  a35=(a77/a78);
  a35=(a35/a79);
  a22=5.0000000000000000e-01;
  a69=(a22*a69);
  a81=-2.;
  a27=(a81*a27);
  a82=(a81*a21);
  a27=(a27-a82);
  a82=(2.*a03);
  a82=(a82*a11);
  a82=(a82*a05);
  a82=(a82*a14);
  a27=(a27+a82);
  a27=(a69*a27);
  a71=(a22*a71);
  a82=(a81*a31);
  a34=(a81*a34);
  a82=(a82+a34);
  a34=(2.*a02);
  a34=(a34*a11);
  a34=(a34*a17);
  a82=(a82+a34);
  a82=(a71*a82);
  a27=(a27+a82);
  a27=(a35*a27);
  a79=(a79/a78);
  a78=(a79*a40);
  a27=(a27-a78);
  if (res[1]!=0) res[1][2]=a27;
  a27=(a44/a43);
  a27=(-a27);
  if (res[1]!=0) res[1][3]=a27;
  a54=(a73*a54);
  a48=(a80*a48);
  a54=(a54+a48);
  a54=(-a54);
  if (res[1]!=0) res[1][4]=a54;
  a50=(a81*a50);
  a54=(-a47);
  a54=(2.*a54);
  a50=(a50+a54);
  a54=(2.*a46);
  a50=(a50+a54);
  a50=(a69*a50);
  a54=(a81*a51);
  a53=(a81*a53);
  a54=(a54+a53);
  a33=(a81*a33);
  a54=(a54+a33);
  a54=(a71*a54);
  a50=(a50+a54);
  a50=(a35*a50);
  a54=(a79*a55);
  a50=(a50-a54);
  if (res[1]!=0) res[1][5]=a50;
  a50=(a57/a43);
  a50=(-a50);
  if (res[1]!=0) res[1][6]=a50;
  a62=(a73*a62);
  a09=(a80*a09);
  a62=(a62-a09);
  if (res[1]!=0) res[1][7]=a62;
  a07=(2.*a07);
  a62=(2.*a58);
  a07=(a07+a62);
  a07=(a69*a07);
  a62=(a81*a61);
  a09=(2.*a16);
  a50=(a09*a11);
  a50=(a50*a05);
  a62=(a62+a50);
  a62=(a71*a62);
  a07=(a07+a62);
  a07=(a35*a07);
  a62=(a79*a63);
  a07=(a07-a62);
  if (res[1]!=0) res[1][8]=a07;
  a44=(a22*a44);
  a21=(a21*a04);
  a07=(a03*a25);
  a21=(a21-a07);
  a21=(a28*a21);
  a62=(a81*a21);
  a50=(a32*a17);
  a54=(a02*a50);
  a33=(a03*a59);
  a54=(a54-a33);
  a54=(a36*a54);
  a33=(a81*a54);
  a62=(a62+a33);
  a33=(a03*a39);
  a38=(a04*a38);
  a33=(a33+a38);
  a33=(a42*a33);
  a38=(a81*a33);
  a62=(a62+a38);
  a62=(a44*a62);
  a01=(a22*a01);
  a38=(a02*a25);
  a47=(a04*a47);
  a47=(a38+a47);
  a47=(a28*a47);
  a53=(a81*a47);
  a48=(a02*a59);
  a50=(a03*a50);
  a48=(a48+a50);
  a48=(a36*a48);
  a50=(a81*a48);
  a53=(a53+a50);
  a56=(a04*a56);
  a50=(a02*a39);
  a56=(a56-a50);
  a56=(a42*a56);
  a50=(a81*a56);
  a53=(a53+a50);
  a53=(a01*a53);
  a62=(a62+a53);
  a22=(a22*a57);
  a57=(2.*a11);
  a57=(a57*a05);
  a57=(a57*a17);
  a57=(a57*a36);
  a53=(a19*a05);
  a53=(a53*a28);
  a50=(a81*a53);
  a27=(a05*a37);
  a27=(a27*a42);
  a78=(a81*a27);
  a50=(a50+a78);
  a57=(a57-a50);
  a57=(a22*a57);
  a62=(a62+a57);
  a62=(a62/a43);
  a62=(-a62);
  if (res[1]!=0) res[1][9]=a62;
  a53=(a53+a27);
  a27=(a11*a05);
  a27=(a27*a17);
  a27=(a27*a36);
  a53=(a53+a27);
  a27=(a53*a05);
  a21=(a21+a54);
  a21=(a21+a33);
  a33=(a21*a49);
  a27=(a27+a33);
  a47=(a47+a48);
  a47=(a47+a56);
  a56=(a47*a26);
  a27=(a27+a56);
  a56=(a16*a27);
  a56=(a56*a11);
  a53=(a53*a04);
  a48=(a21*a45);
  a53=(a53-a48);
  a48=(a47*a06);
  a53=(a53-a48);
  a48=(a53*a10);
  a47=(a02*a47);
  a21=(a21*a03);
  a47=(a47-a21);
  a21=(a47*a52);
  a33=(a48+a21);
  a59=(a68*a59);
  a33=(a33+a59);
  a54=(a52*a70);
  a33=(a33+a54);
  a56=(a56-a33);
  a56=(a73*a56);
  a33=(a27*a25);
  a62=(a19*a47);
  a57=(a68*a25);
  a50=(a62+a57);
  a78=(a19*a70);
  a50=(a50+a78);
  a50=(a33-a50);
  a82=(a11*a14);
  a34=(a53*a82);
  a50=(a50+a34);
  a50=(a80*a50);
  a56=(a56-a50);
  if (res[1]!=0) res[1][10]=a56;
  a62=(-a62);
  a62=(2.*a62);
  a57=(-a57);
  a57=(2.*a57);
  a62=(a62+a57);
  a78=(-a78);
  a78=(2.*a78);
  a62=(a62+a78);
  a33=(2.*a33);
  a62=(a62+a33);
  a34=(2.*a34);
  a62=(a62+a34);
  a62=(a69*a62);
  a48=(a81*a48);
  a21=(a81*a21);
  a48=(a48+a21);
  a59=(a81*a59);
  a48=(a48+a59);
  a54=(a81*a54);
  a48=(a48+a54);
  a54=(a09*a27);
  a54=(a54*a11);
  a48=(a48+a54);
  a48=(a71*a48);
  a62=(a62+a48);
  a62=(a35*a62);
  a48=(a11*a13);
  a53=(a53*a48);
  a47=(a47*a37);
  a53=(a53-a47);
  a27=(a27*a39);
  a53=(a53-a27);
  a27=(a37*a70);
  a53=(a53-a27);
  a27=(a39*a68);
  a53=(a53+a27);
  a53=(a79*a53);
  a62=(a62-a53);
  if (res[1]!=0) res[1][11]=a62;
  a62=(a10*a17);
  a53=(a62*a03);
  a53=(a53-a08);
  a08=(a16*a02);
  a08=(a08*a61);
  a53=(a53+a08);
  a53=(a36*a53);
  a08=(a81*a53);
  a27=(a41*a18);
  a47=(a02*a32);
  a54=(a47*a24);
  a27=(a27+a54);
  a54=(a51*a14);
  a27=(a27+a54);
  a27=(a28*a27);
  a54=(a81*a27);
  a08=(a08-a54);
  a47=(a20*a47);
  a41=(a41*a23);
  a47=(a47+a41);
  a51=(a13*a51);
  a47=(a47+a51);
  a47=(a42*a47);
  a51=(a81*a47);
  a08=(a08-a51);
  a08=(a44*a08);
  a30=(a30*a14);
  a51=(a03*a32);
  a41=(a51*a24);
  a54=(a31*a14);
  a41=(a41+a54);
  a30=(a30-a41);
  a30=(a28*a30);
  a41=(a81*a30);
  a54=(a16*a03);
  a54=(a54*a04);
  a54=(a54*a10);
  a59=(a62*a02);
  a12=(a12+a59);
  a54=(a54-a12);
  a54=(a36*a54);
  a12=(a81*a54);
  a41=(a41+a12);
  a29=(a29*a13);
  a29=(a29*a17);
  a51=(a51*a20);
  a31=(a31*a13);
  a51=(a51+a31);
  a29=(a29-a51);
  a29=(a42*a29);
  a51=(a81*a29);
  a41=(a41+a51);
  a41=(a01*a41);
  a08=(a08+a41);
  a41=(a60*a13);
  a51=(a13*a61);
  a41=(a41-a51);
  a41=(a42*a41);
  a51=(a81*a41);
  a60=(a60*a14);
  a61=(a61*a14);
  a60=(a60-a61);
  a60=(a28*a60);
  a61=(a81*a60);
  a51=(a51+a61);
  a61=(a16*a10);
  a31=(a05*a61);
  a32=(a32+a31);
  a36=(a36*a32);
  a32=(a81*a36);
  a51=(a51-a32);
  a51=(a22*a51);
  a08=(a08+a51);
  a08=(a08/a43);
  a08=(-a08);
  if (res[1]!=0) res[1][12]=a08;
  a41=(a41+a60);
  a36=(a36-a41);
  a41=(a36*a05);
  a30=(a30+a54);
  a30=(a30+a29);
  a29=(a30*a26);
  a41=(a41+a29);
  a27=(a27-a53);
  a27=(a27+a47);
  a47=(a27*a49);
  a41=(a41-a47);
  a47=(a16*a41);
  a47=(a47*a11);
  a36=(a36*a04);
  a53=(a30*a06);
  a36=(a36-a53);
  a53=(a27*a45);
  a36=(a36+a53);
  a53=(a36*a10);
  a27=(a27*a03);
  a30=(a02*a30);
  a27=(a27+a30);
  a30=(a27*a52);
  a29=(a53+a30);
  a61=(a70*a61);
  a29=(a29+a61);
  a29=(a29+a66);
  a47=(a47-a29);
  a62=(a62*a68);
  a47=(a47+a62);
  a47=(a73*a47);
  a62=(a41*a25);
  a29=(a19*a27);
  a54=(a62-a29);
  a60=(a82*a36);
  a54=(a54+a60);
  a08=(a11*a70);
  a24=(a24*a08);
  a54=(a54+a24);
  a14=(a65*a14);
  a54=(a54-a14);
  a51=(a11*a68);
  a18=(a51*a18);
  a54=(a54-a18);
  a54=(a80*a54);
  a47=(a47-a54);
  if (res[1]!=0) res[1][13]=a47;
  a14=(a81*a14);
  a18=(a81*a18);
  a14=(a14+a18);
  a29=(-a29);
  a29=(2.*a29);
  a14=(a14+a29);
  a62=(2.*a62);
  a14=(a14+a62);
  a60=(2.*a60);
  a14=(a14+a60);
  a24=(2.*a24);
  a14=(a14+a24);
  a14=(a69*a14);
  a53=(a81*a53);
  a30=(a81*a30);
  a53=(a53+a30);
  a61=(a81*a61);
  a53=(a53+a61);
  a66=(a81*a66);
  a53=(a53+a66);
  a66=(a09*a41);
  a66=(a66*a11);
  a53=(a53+a66);
  a66=(2.*a10);
  a66=(a66*a17);
  a66=(a66*a68);
  a53=(a53+a66);
  a53=(a71*a53);
  a14=(a14+a53);
  a14=(a35*a14);
  a20=(a20*a08);
  a36=(a36*a48);
  a20=(a20+a36);
  a27=(a27*a37);
  a20=(a20-a27);
  a41=(a41*a39);
  a20=(a20-a41);
  a23=(a23*a51);
  a20=(a20-a23);
  a13=(a13*a65);
  a20=(a20-a13);
  a20=(a79*a20);
  a14=(a14-a20);
  if (res[1]!=0) res[1][14]=a14;
  a55=(a55*a28);
  a14=(a81*a55);
  a20=(a03*a19);
  a20=(a20-a46);
  a38=(a04*a38);
  a20=(a20+a38);
  a20=(a42*a20);
  a38=(a81*a20);
  a14=(a14+a38);
  a44=(a44*a14);
  a40=(a40*a28);
  a14=(a81*a40);
  a07=(a04*a07);
  a38=(a02*a19);
  a15=(a15+a38);
  a07=(a07-a15);
  a07=(a42*a07);
  a15=(a81*a07);
  a14=(a14+a15);
  a01=(a01*a14);
  a44=(a44+a01);
  a63=(a63*a28);
  a28=(a81*a63);
  a01=(a05*a25);
  a58=(a58+a01);
  a42=(a42*a58);
  a58=(a81*a42);
  a28=(a28-a58);
  a22=(a22*a28);
  a44=(a44+a22);
  a44=(a44/a43);
  a44=(-a44);
  if (res[1]!=0) res[1][15]=a44;
  a42=(a42-a63);
  a05=(a42*a05);
  a55=(a55+a20);
  a49=(a55*a49);
  a05=(a05+a49);
  a40=(a40+a07);
  a26=(a40*a26);
  a05=(a05+a26);
  a16=(a16*a05);
  a16=(a16*a11);
  a42=(a42*a04);
  a45=(a55*a45);
  a42=(a42-a45);
  a06=(a40*a06);
  a42=(a42-a06);
  a10=(a42*a10);
  a02=(a02*a40);
  a55=(a55*a03);
  a02=(a02-a55);
  a52=(a02*a52);
  a55=(a10+a52);
  a16=(a16-a55);
  a73=(a73*a16);
  a16=(a25*a05);
  a55=(a19*a02);
  a03=(a16-a55);
  a82=(a82*a42);
  a03=(a03+a82);
  a03=(a03+a77);
  a80=(a80*a03);
  a73=(a73-a80);
  if (res[1]!=0) res[1][16]=a73;
  a55=(-a55);
  a55=(2.*a55);
  a16=(2.*a16);
  a55=(a55+a16);
  a82=(2.*a82);
  a55=(a55+a82);
  a75=(-a75);
  a75=(2.*a75);
  a55=(a55+a75);
  a76=(-a76);
  a76=(2.*a76);
  a55=(a55+a76);
  a74=(2.*a74);
  a55=(a55+a74);
  a69=(a69*a55);
  a10=(a81*a10);
  a81=(a81*a52);
  a10=(a10+a81);
  a09=(a09*a05);
  a09=(a09*a11);
  a10=(a10+a09);
  a71=(a71*a10);
  a69=(a69+a71);
  a35=(a35*a69);
  a42=(a42*a48);
  a42=(a42-a67);
  a02=(a02*a37);
  a42=(a42-a02);
  a05=(a05*a39);
  a42=(a42-a05);
  a68=(a68*a19);
  a42=(a42+a68);
  a70=(a70*a25);
  a42=(a42-a70);
  a79=(a79*a42);
  a35=(a35-a79);
  if (res[1]!=0) res[1][17]=a35;
  a35=-1.;
  if (res[1]!=0) res[1][18]=a35;
  a79=0.;
  if (res[1]!=0) res[1][19]=a79;
  if (res[1]!=0) res[1][20]=a79;
  if (res[1]!=0) res[1][21]=a79;
  if (res[1]!=0) res[1][22]=a35;
  if (res[1]!=0) res[1][23]=a79;
  if (res[1]!=0) res[1][24]=a79;
  if (res[1]!=0) res[1][25]=a79;
  if (res[1]!=0) res[1][26]=a35;
  if (res[2]!=0) res[2][0]=a64;
  a64=sin(a00);
  a00=cos(a00);
  a64=atan2(a64,a00);
  if (res[2]!=0) res[2][1]=a64;
  if (res[2]!=0) res[2][2]=a72;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_residual(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int fleet_residual_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void fleet_residual_release(int mem) {
}

CASADI_SYMBOL_EXPORT void fleet_residual_incref(void) {
}

CASADI_SYMBOL_EXPORT void fleet_residual_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int fleet_residual_n_in(void) { return 13;}

CASADI_SYMBOL_EXPORT casadi_int fleet_residual_n_out(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_real fleet_residual_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_residual_name_in(casadi_int i) {
  switch (i) {
    case 0: return "p_ecef";
    case 1: return "lat";
    case 2: return "lon";
    case 3: return "alt";
    case 4: return "heading";
    case 5: return "pitch";
    case 6: return "roll";
    case 7: return "att_err";
    case 8: return "bias";
    case 9: return "lever_deck";
    case 10: return "r";
    case 11: return "q";
    case 12: return "e";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_residual_name_out(casadi_int i) {
  switch (i) {
    case 0: return "residual";
    case 1: return "J";
    case 2: return "plot";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_residual_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s1;
    case 3: return casadi_s1;
    case 4: return casadi_s1;
    case 5: return casadi_s1;
    case 6: return casadi_s1;
    case 7: return casadi_s0;
    case 8: return casadi_s0;
    case 9: return casadi_s0;
    case 10: return casadi_s1;
    case 11: return casadi_s1;
    case 12: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_residual_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s2;
    case 2: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int fleet_residual_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13;
  if (sz_res) *sz_res = 3;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_residual_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


