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
  #define CASADI_PREFIX(ID) fleet_rows_1_ ## ID
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
CASADI_SYMBOL_EXPORT void fleet_rows_1_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int fleet_rows_1_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int fleet_rows_1_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {10, 3, 1};

/* fleet_rows_1:(p_ecef[3],lat,lon,alt,heading,pitch,roll,att_err[3],bias[3],lever_deck[3],r,q,e,weight[3],basis)->(rows_t[10x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85, a86;
  a00=arg[14]? arg[14][0] : 0;
  a01=arg[13]? arg[13][0] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a03=arg[2]? arg[2][0] : 0;
  a04=cos(a03);
  a05=arg[1]? arg[1][0] : 0;
  a06=cos(a05);
  a07=(a04*a06);
  a08=arg[3]? arg[3][0] : 0;
  a09=6378137.;
  a10=1.;
  a11=-6.6943799901413173e-03;
  a05=sin(a05);
  a12=casadi_sq(a05);
  a11=(a11*a12);
  a10=(a10+a11);
  a10=sqrt(a10);
  a09=(a09/a10);
  a09=(a08+a09);
  a11=(a07*a09);
  a02=(a02-a11);
  a11=arg[7]? arg[7][1] : 0;
  a12=arg[5]? arg[5][0] : 0;
  a11=(a11-a12);
  a12=cos(a11);
  a13=(a12*a07);
  a14=arg[7]? arg[7][2] : 0;
  a15=arg[6]? arg[6][0] : 0;
  a14=(a14-a15);
  a15=sin(a14);
  a16=(a13*a15);
  a11=sin(a11);
  a17=arg[7]? arg[7][0] : 0;
  a18=arg[4]? arg[4][0] : 0;
  a17=(a17-a18);
  a18=sin(a17);
  a19=(a18*a15);
  a20=(a11*a19);
  a17=cos(a17);
  a14=cos(a14);
  a21=(a17*a14);
  a20=(a20-a21);
  a03=sin(a03);
  a22=(a20*a03);
  a23=(a16+a22);
  a24=(a14*a18);
  a25=(a17*a15);
  a26=(a25*a11);
  a26=(a24+a26);
  a27=(a04*a05);
  a28=(a26*a27);
  a23=(a23-a28);
  a29=arg[9]? arg[9][0] : 0;
  a30=(a23*a29);
  a02=(a02-a30);
  a30=(a03*a12);
  a31=(a30*a18);
  a32=(a07*a11);
  a33=(a05*a12);
  a34=(a17*a33);
  a35=(a04*a34);
  a36=(a32+a35);
  a36=(a31-a36);
  a37=arg[9]? arg[9][1] : 0;
  a38=(a36*a37);
  a02=(a02-a38);
  a38=(a24*a11);
  a38=(a25+a38);
  a39=(a03*a38);
  a40=(a21*a11);
  a40=(a19-a40);
  a41=(a27*a40);
  a41=(a39+a41);
  a42=(a04*a12);
  a43=(a42*a06);
  a43=(a43*a14);
  a41=(a41+a43);
  a43=arg[9]? arg[9][2] : 0;
  a44=(a41*a43);
  a02=(a02-a44);
  a44=casadi_sq(a02);
  a45=arg[0]? arg[0][1] : 0;
  a46=(a03*a06);
  a09=(a09*a46);
  a45=(a45-a09);
  a09=(a12*a46);
  a47=(a09*a15);
  a48=(a20*a04);
  a49=(a47-a48);
  a50=(a03*a05);
  a51=(a26*a50);
  a49=(a49-a51);
  a52=(a49*a29);
  a45=(a45-a52);
  a52=(a46*a11);
  a53=(a12*a18);
  a54=(a04*a53);
  a55=(a52+a54);
  a34=(a03*a34);
  a55=(a55+a34);
  a56=(a55*a37);
  a45=(a45+a56);
  a56=(a14*a09);
  a57=(a04*a38);
  a56=(a56-a57);
  a58=(a40*a50);
  a56=(a56+a58);
  a58=(a56*a43);
  a45=(a45-a58);
  a58=casadi_sq(a45);
  a44=(a44+a58);
  a58=arg[0]? arg[0][2] : 0;
  a59=6.3354393272928204e+06;
  a59=(a59/a10);
  a08=(a08+a59);
  a08=(a05*a08);
  a58=(a58-a08);
  a08=(a26*a06);
  a59=(a33*a15);
  a10=(a08+a59);
  a60=(a10*a29);
  a58=(a58-a60);
  a60=(a17*a12);
  a61=(a60*a06);
  a62=(a05*a11);
  a63=(a61-a62);
  a64=(a63*a37);
  a58=(a58-a64);
  a64=(a33*a14);
  a65=(a06*a40);
  a64=(a64-a65);
  a65=(a64*a43);
  a58=(a58-a65);
  a65=casadi_sq(a58);
  a44=(a44+a65);
  a44=sqrt(a44);
  a65=(a02/a44);
  a65=(a01*a65);
  a65=(a00*a65);
  a65=(-a65);
  if (res[0]!=0) res[0][0]=a65;
  a65=(a45/a44);
  a65=(a01*a65);
  a65=(a00*a65);
  a65=(-a65);
  if (res[0]!=0) res[0][1]=a65;
  a65=(a58/a44);
  a65=(a01*a65);
  a65=(a00*a65);
  a65=(-a65);
  if (res[0]!=0) res[0][2]=a65;
  a65=5.0000000000000000e-01;
  a66=(a65*a45);
  a67=-2.;
  a68=(a22*a05);
  a69=(a04*a26);
  a68=(a68-a69);
  a68=(a29*a68);
  a70=(a67*a68);
  a71=(a33*a18);
  a72=(a03*a71);
  a73=(a04*a60);
  a72=(a72-a73);
  a72=(a37*a72);
  a73=(a67*a72);
  a70=(a70+a73);
  a73=(a04*a40);
  a39=(a05*a39);
  a73=(a73+a39);
  a73=(a43*a73);
  a39=(a67*a73);
  a70=(a70+a39);
  a70=(a66*a70);
  a39=(a65*a02);
  a74=(a03*a26);
  a75=(a05*a48);
  a75=(a74+a75);
  a75=(a29*a75);
  a76=(a67*a75);
  a77=(a03*a60);
  a71=(a04*a71);
  a77=(a77+a71);
  a77=(a37*a77);
  a71=(a67*a77);
  a76=(a76+a71);
  a57=(a05*a57);
  a71=(a03*a40);
  a57=(a57-a71);
  a57=(a43*a57);
  a71=(a67*a57);
  a76=(a76+a71);
  a76=(a39*a76);
  a70=(a70+a76);
  a76=(a65*a58);
  a71=(2.*a12);
  a71=(a71*a06);
  a71=(a71*a18);
  a71=(a71*a37);
  a78=(a20*a06);
  a78=(a78*a29);
  a79=(a67*a78);
  a80=(a06*a38);
  a80=(a80*a43);
  a81=(a67*a80);
  a79=(a79+a81);
  a71=(a71-a79);
  a71=(a76*a71);
  a70=(a70+a71);
  a70=(a70/a44);
  a70=(a01*a70);
  a70=(-a70);
  if (res[0]!=0) res[0][3]=a70;
  a70=(a11*a18);
  a71=(a70*a04);
  a71=(a71-a09);
  a09=(a17*a03);
  a09=(a09*a62);
  a71=(a71+a09);
  a71=(a37*a71);
  a09=(a67*a71);
  a79=(a42*a19);
  a81=(a03*a33);
  a82=(a81*a25);
  a79=(a79+a82);
  a82=(a52*a15);
  a79=(a79+a82);
  a79=(a29*a79);
  a82=(a67*a79);
  a09=(a09-a82);
  a81=(a21*a81);
  a42=(a42*a24);
  a81=(a81+a42);
  a42=(a14*a52);
  a81=(a81+a42);
  a81=(a43*a81);
  a42=(a67*a81);
  a09=(a09-a42);
  a09=(a66*a09);
  a31=(a31*a15);
  a42=(a04*a33);
  a82=(a42*a25);
  a83=(a32*a15);
  a82=(a82+a83);
  a31=(a31-a82);
  a31=(a29*a31);
  a82=(a67*a31);
  a83=(a17*a04);
  a83=(a83*a05);
  a83=(a83*a11);
  a84=(a70*a03);
  a13=(a13+a84);
  a83=(a83-a13);
  a83=(a37*a83);
  a13=(a67*a83);
  a82=(a82+a13);
  a30=(a30*a14);
  a30=(a30*a18);
  a42=(a42*a21);
  a13=(a32*a14);
  a42=(a42+a13);
  a30=(a30-a42);
  a30=(a43*a30);
  a42=(a67*a30);
  a82=(a82+a42);
  a82=(a39*a82);
  a09=(a09+a82);
  a82=(a61*a14);
  a42=(a14*a62);
  a82=(a82-a42);
  a82=(a43*a82);
  a42=(a67*a82);
  a61=(a61*a15);
  a13=(a62*a15);
  a61=(a61-a13);
  a61=(a29*a61);
  a13=(a67*a61);
  a42=(a42+a13);
  a13=(a17*a11);
  a84=(a06*a13);
  a33=(a33+a84);
  a33=(a37*a33);
  a84=(a67*a33);
  a42=(a42-a84);
  a42=(a76*a42);
  a09=(a09+a42);
  a09=(a09/a44);
  a09=(a01*a09);
  a09=(-a09);
  if (res[0]!=0) res[0][4]=a09;
  a09=(a56*a29);
  a42=(a67*a09);
  a84=(a04*a20);
  a84=(a84-a47);
  a74=(a05*a74);
  a84=(a84+a74);
  a84=(a43*a84);
  a74=(a67*a84);
  a42=(a42+a74);
  a66=(a66*a42);
  a42=(a41*a29);
  a74=(a67*a42);
  a69=(a05*a69);
  a85=(a03*a20);
  a16=(a16+a85);
  a69=(a69-a16);
  a69=(a43*a69);
  a16=(a67*a69);
  a74=(a74+a16);
  a39=(a39*a74);
  a66=(a66+a39);
  a29=(a64*a29);
  a39=(a67*a29);
  a74=(a06*a26);
  a74=(a59+a74);
  a43=(a43*a74);
  a74=(a67*a43);
  a39=(a39-a74);
  a76=(a76*a39);
  a66=(a66+a76);
  a66=(a66/a44);
  a66=(a01*a66);
  a66=(-a66);
  if (res[0]!=0) res[0][5]=a66;
  a66=(-a01);
  if (res[0]!=0) res[0][6]=a66;
  a66=0.;
  if (res[0]!=0) res[0][7]=a66;
  if (res[0]!=0) res[0][8]=a66;
  a76=arg[10]? arg[10][0] : 0;
  a39=arg[8]? arg[8][0] : 0;
  a44=(a44+a39);
  a76=(a76-a44);
  a01=(a01*a76);
  if (res[0]!=0) res[0][9]=a01;
  a01=arg[13]? arg[13][1] : 0;
  a76=(a05*a58);
  a44=(a07*a02);
  a76=(a76+a44);
  a44=(a46*a45);
  a76=(a76+a44);
  a44=(a12*a76);
  a39=(a44*a15);
  a74=(a04*a45);
  a16=(a03*a02);
  a74=(a74-a16);
  a16=(a20*a74);
  a16=(a39-a16);
  a58=(a06*a58);
  a02=(a27*a02);
  a58=(a58-a02);
  a45=(a50*a45);
  a58=(a58-a45);
  a45=(a26*a58);
  a16=(a16+a45);
  a45=casadi_sq(a16);
  a02=(a60*a58);
  a76=(a11*a76);
  a85=(a53*a74);
  a85=(a76+a85);
  a02=(a02-a85);
  a85=casadi_sq(a02);
  a45=(a45+a85);
  a85=(a16/a45);
  a36=(a85*a36);
  a86=(a02/a45);
  a23=(a86*a23);
  a36=(a36-a23);
  a36=(a01*a36);
  a36=(a00*a36);
  if (res[0]!=0) res[0][10]=a36;
  a55=(a85*a55);
  a49=(a86*a49);
  a55=(a55+a49);
  a55=(a01*a55);
  a55=(a00*a55);
  a55=(-a55);
  if (res[0]!=0) res[0][11]=a55;
  a63=(a85*a63);
  a10=(a86*a10);
  a63=(a63-a10);
  a63=(a01*a63);
  a63=(a00*a63);
  if (res[0]!=0) res[0][12]=a63;
  a78=(a78+a80);
  a80=(a12*a06);
  a80=(a80*a18);
  a80=(a80*a37);
  a78=(a78+a80);
  a80=(a78*a06);
  a68=(a68+a72);
  a68=(a68+a73);
  a73=(a68*a50);
  a80=(a80+a73);
  a75=(a75+a77);
  a75=(a75+a57);
  a57=(a75*a27);
  a80=(a80+a57);
  a57=(a17*a80);
  a57=(a57*a12);
  a78=(a78*a05);
  a77=(a68*a46);
  a78=(a78-a77);
  a77=(a75*a07);
  a78=(a78-a77);
  a77=(a78*a11);
  a75=(a03*a75);
  a68=(a68*a04);
  a75=(a75-a68);
  a68=(a75*a53);
  a73=(a77+a68);
  a60=(a74*a60);
  a73=(a73+a60);
  a72=(a53*a58);
  a73=(a73+a72);
  a57=(a57-a73);
  a57=(a85*a57);
  a73=(a80*a26);
  a37=(a20*a75);
  a63=(a74*a26);
  a10=(a37+a63);
  a55=(a20*a58);
  a10=(a10+a55);
  a10=(a73-a10);
  a49=(a12*a15);
  a36=(a78*a49);
  a10=(a10+a36);
  a10=(a86*a10);
  a57=(a57-a10);
  a57=(a01*a57);
  if (res[0]!=0) res[0][13]=a57;
  a82=(a82+a61);
  a33=(a33-a82);
  a82=(a33*a06);
  a31=(a31+a83);
  a31=(a31+a30);
  a30=(a31*a27);
  a82=(a82+a30);
  a79=(a79-a71);
  a79=(a79+a81);
  a81=(a79*a50);
  a82=(a82-a81);
  a81=(a17*a82);
  a81=(a81*a12);
  a33=(a33*a05);
  a71=(a31*a07);
  a33=(a33-a71);
  a71=(a79*a46);
  a33=(a33+a71);
  a71=(a33*a11);
  a79=(a79*a04);
  a31=(a03*a31);
  a79=(a79+a31);
  a31=(a79*a53);
  a30=(a71+a31);
  a13=(a58*a13);
  a30=(a30+a13);
  a30=(a30+a44);
  a81=(a81-a30);
  a70=(a70*a74);
  a81=(a81+a70);
  a81=(a85*a81);
  a70=(a82*a26);
  a30=(a20*a79);
  a83=(a70-a30);
  a61=(a49*a33);
  a83=(a83+a61);
  a57=(a12*a58);
  a25=(a25*a57);
  a83=(a83+a25);
  a10=(a76*a15);
  a83=(a83-a10);
  a23=(a12*a74);
  a19=(a23*a19);
  a83=(a83-a19);
  a83=(a86*a83);
  a81=(a81-a83);
  a81=(a01*a81);
  if (res[0]!=0) res[0][14]=a81;
  a43=(a43-a29);
  a29=(a43*a06);
  a09=(a09+a84);
  a50=(a09*a50);
  a29=(a29+a50);
  a42=(a42+a69);
  a27=(a42*a27);
  a29=(a29+a27);
  a27=(a17*a29);
  a27=(a27*a12);
  a43=(a43*a05);
  a46=(a09*a46);
  a43=(a43-a46);
  a07=(a42*a07);
  a43=(a43-a07);
  a07=(a43*a11);
  a42=(a03*a42);
  a09=(a09*a04);
  a42=(a42-a09);
  a53=(a42*a53);
  a09=(a07+a53);
  a27=(a27-a09);
  a85=(a85*a27);
  a27=(a26*a29);
  a09=(a20*a42);
  a46=(a27-a09);
  a49=(a49*a43);
  a46=(a46+a49);
  a05=(a14*a44);
  a69=(a38*a74);
  a50=(a40*a58);
  a84=(a69+a50);
  a84=(a05-a84);
  a46=(a46+a84);
  a86=(a86*a46);
  a85=(a85-a86);
  a85=(a01*a85);
  if (res[0]!=0) res[0][15]=a85;
  if (res[0]!=0) res[0][16]=a66;
  a85=(-a01);
  if (res[0]!=0) res[0][17]=a85;
  if (res[0]!=0) res[0][18]=a66;
  a85=arg[8]? arg[8][1] : 0;
  a86=atan2(a16,a02);
  a85=(a85+a86);
  a86=arg[11]? arg[11][0] : 0;
  a85=(a85-a86);
  a86=sin(a85);
  a86=(-a86);
  a85=cos(a85);
  a86=atan2(a86,a85);
  a01=(a01*a86);
  if (res[0]!=0) res[0][19]=a01;
  a01=arg[13]? arg[13][2] : 0;
  a86=casadi_sq(a84);
  a86=(a45+a86);
  a85=(a84/a86);
  a45=sqrt(a45);
  a85=(a85/a45);
  a16=(a65*a16);
  a28=(a67*a28);
  a22=(a67*a22);
  a28=(a28-a22);
  a04=(2.*a04);
  a04=(a04*a12);
  a04=(a04*a06);
  a04=(a04*a15);
  a28=(a28+a04);
  a28=(a16*a28);
  a65=(a65*a02);
  a32=(a67*a32);
  a35=(a67*a35);
  a32=(a32+a35);
  a03=(2.*a03);
  a03=(a03*a12);
  a03=(a03*a18);
  a32=(a32+a03);
  a32=(a65*a32);
  a28=(a28+a32);
  a28=(a85*a28);
  a86=(a45/a86);
  a41=(a86*a41);
  a28=(a28-a41);
  a28=(a01*a28);
  a28=(a00*a28);
  if (res[0]!=0) res[0][20]=a28;
  a51=(a67*a51);
  a48=(-a48);
  a48=(2.*a48);
  a51=(a51+a48);
  a47=(2.*a47);
  a51=(a51+a47);
  a51=(a16*a51);
  a52=(a67*a52);
  a54=(a67*a54);
  a52=(a52+a54);
  a34=(a67*a34);
  a52=(a52+a34);
  a52=(a65*a52);
  a51=(a51+a52);
  a51=(a85*a51);
  a56=(a86*a56);
  a51=(a51-a56);
  a51=(a01*a51);
  a51=(a00*a51);
  if (res[0]!=0) res[0][21]=a51;
  a08=(2.*a08);
  a59=(2.*a59);
  a08=(a08+a59);
  a08=(a16*a08);
  a62=(a67*a62);
  a17=(2.*a17);
  a59=(a17*a12);
  a59=(a59*a06);
  a62=(a62+a59);
  a62=(a65*a62);
  a08=(a08+a62);
  a08=(a85*a08);
  a64=(a86*a64);
  a08=(a08-a64);
  a08=(a01*a08);
  a00=(a00*a08);
  if (res[0]!=0) res[0][22]=a00;
  a37=(-a37);
  a37=(2.*a37);
  a63=(-a63);
  a63=(2.*a63);
  a37=(a37+a63);
  a55=(-a55);
  a55=(2.*a55);
  a37=(a37+a55);
  a73=(2.*a73);
  a37=(a37+a73);
  a36=(2.*a36);
  a37=(a37+a36);
  a37=(a16*a37);
  a77=(a67*a77);
  a68=(a67*a68);
  a77=(a77+a68);
  a60=(a67*a60);
  a77=(a77+a60);
  a72=(a67*a72);
  a77=(a77+a72);
  a72=(a17*a80);
  a72=(a72*a12);
  a77=(a77+a72);
  a77=(a65*a77);
  a37=(a37+a77);
  a37=(a85*a37);
  a77=(a12*a14);
  a78=(a78*a77);
  a75=(a75*a38);
  a78=(a78-a75);
  a80=(a80*a40);
  a78=(a78-a80);
  a80=(a38*a58);
  a78=(a78-a80);
  a80=(a40*a74);
  a78=(a78+a80);
  a78=(a86*a78);
  a37=(a37-a78);
  a37=(a01*a37);
  if (res[0]!=0) res[0][23]=a37;
  a10=(a67*a10);
  a19=(a67*a19);
  a10=(a10+a19);
  a30=(-a30);
  a30=(2.*a30);
  a10=(a10+a30);
  a70=(2.*a70);
  a10=(a10+a70);
  a61=(2.*a61);
  a10=(a10+a61);
  a25=(2.*a25);
  a10=(a10+a25);
  a10=(a16*a10);
  a71=(a67*a71);
  a31=(a67*a31);
  a71=(a71+a31);
  a13=(a67*a13);
  a71=(a71+a13);
  a44=(a67*a44);
  a71=(a71+a44);
  a44=(a17*a82);
  a44=(a44*a12);
  a71=(a71+a44);
  a11=(2.*a11);
  a11=(a11*a18);
  a11=(a11*a74);
  a71=(a71+a11);
  a71=(a65*a71);
  a10=(a10+a71);
  a10=(a85*a10);
  a21=(a21*a57);
  a33=(a33*a77);
  a21=(a21+a33);
  a79=(a79*a38);
  a21=(a21-a79);
  a82=(a82*a40);
  a21=(a21-a82);
  a24=(a24*a23);
  a21=(a21-a24);
  a14=(a14*a76);
  a21=(a21-a14);
  a21=(a86*a21);
  a10=(a10-a21);
  a10=(a01*a10);
  if (res[0]!=0) res[0][24]=a10;
  a09=(-a09);
  a09=(2.*a09);
  a27=(2.*a27);
  a09=(a09+a27);
  a49=(2.*a49);
  a09=(a09+a49);
  a69=(-a69);
  a69=(2.*a69);
  a09=(a09+a69);
  a50=(-a50);
  a50=(2.*a50);
  a09=(a09+a50);
  a05=(2.*a05);
  a09=(a09+a05);
  a16=(a16*a09);
  a07=(a67*a07);
  a67=(a67*a53);
  a07=(a07+a67);
  a17=(a17*a29);
  a17=(a17*a12);
  a07=(a07+a17);
  a65=(a65*a07);
  a16=(a16+a65);
  a85=(a85*a16);
  a43=(a43*a77);
  a43=(a43-a39);
  a42=(a42*a38);
  a43=(a43-a42);
  a29=(a29*a40);
  a43=(a43-a29);
  a74=(a74*a20);
  a43=(a43+a74);
  a58=(a58*a26);
  a43=(a43-a58);
  a86=(a86*a43);
  a85=(a85-a86);
  a85=(a01*a85);
  if (res[0]!=0) res[0][25]=a85;
  if (res[0]!=0) res[0][26]=a66;
  if (res[0]!=0) res[0][27]=a66;
  a66=(-a01);
  if (res[0]!=0) res[0][28]=a66;
  a66=arg[12]? arg[12][0] : 0;
  a85=arg[8]? arg[8][2] : 0;
  a84=atan2(a84,a45);
  a85=(a85+a84);
  a66=(a66-a85);
  a01=(a01*a66);
  if (res[0]!=0) res[0][29]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_rows_1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int fleet_rows_1_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void fleet_rows_1_release(int mem) {
}

CASADI_SYMBOL_EXPORT void fleet_rows_1_incref(void) {
}

CASADI_SYMBOL_EXPORT void fleet_rows_1_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int fleet_rows_1_n_in(void) { return 15;}

CASADI_SYMBOL_EXPORT casadi_int fleet_rows_1_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real fleet_rows_1_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_rows_1_name_in(casadi_int i) {
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
    case 13: return "weight";
    case 14: return "basis";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_rows_1_name_out(casadi_int i) {
  switch (i) {
    case 0: return "rows_t";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_rows_1_sparsity_in(casadi_int i) {
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
    case 13: return casadi_s0;
    case 14: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_rows_1_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int fleet_rows_1_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 15;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_rows_1_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 15*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


