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
  #define CASADI_PREFIX(ID) fleet_rows_ecc3_1_ ## ID
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
CASADI_SYMBOL_EXPORT void fleet_rows_ecc3_1_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int fleet_rows_ecc3_1_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int fleet_rows_ecc3_1_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {2, 1, 1};
static const casadi_int casadi_s3[3] = {12, 3, 1};

/* fleet_rows_ecc3_1:(p_ecef[3],lat,lon,alt,heading,pitch,roll,att_err[3],bias[3],ecc[2],lever_deck[3],r,q,e,weight[3],basis)->(rows_t[12x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85, a86, a87;
  a00=arg[15]? arg[15][0] : 0;
  a01=arg[14]? arg[14][0] : 0;
  a02=arg[0]? arg[0][0] : 0;
  a03=arg[1]? arg[1][0] : 0;
  a04=cos(a03);
  a05=arg[2]? arg[2][0] : 0;
  a06=cos(a05);
  a07=(a04*a06);
  a08=arg[3]? arg[3][0] : 0;
  a09=6378137.;
  a10=1.;
  a11=-6.6943799901413173e-03;
  a03=(-a03);
  a03=sin(a03);
  a12=casadi_sq(a03);
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
  a12=sin(a11);
  a13=arg[7]? arg[7][0] : 0;
  a14=arg[4]? arg[4][0] : 0;
  a13=(a13-a14);
  a14=cos(a13);
  a15=arg[7]? arg[7][2] : 0;
  a16=arg[6]? arg[6][0] : 0;
  a15=(a15-a16);
  a16=sin(a15);
  a17=(a14*a16);
  a18=(a12*a17);
  a15=cos(a15);
  a13=sin(a13);
  a19=(a15*a13);
  a18=(a18+a19);
  a20=(a03*a06);
  a21=(a18*a20);
  a22=(a13*a16);
  a23=(a22*a12);
  a24=(a15*a14);
  a23=(a23-a24);
  a05=(-a05);
  a05=sin(a05);
  a25=(a23*a05);
  a26=(a21-a25);
  a11=cos(a11);
  a27=(a11*a07);
  a28=(a27*a16);
  a26=(a26+a28);
  a29=arg[10]? arg[10][0] : 0;
  a30=(a26*a29);
  a02=(a02-a30);
  a30=(a11*a03);
  a31=(a30*a06);
  a31=(a31*a14);
  a32=(a07*a12);
  a33=(a11*a13);
  a34=(a05*a33);
  a35=(a32+a34);
  a35=(a31-a35);
  a36=arg[10]? arg[10][1] : 0;
  a37=(a35*a36);
  a02=(a02-a37);
  a37=(a15*a27);
  a38=(a19*a12);
  a38=(a38+a17);
  a39=(a05*a38);
  a40=(a15*a12);
  a40=(a40*a14);
  a40=(a22-a40);
  a41=(a40*a20);
  a41=(a39+a41);
  a37=(a37-a41);
  a41=arg[10]? arg[10][2] : 0;
  a42=(a37*a41);
  a02=(a02-a42);
  a42=arg[0]? arg[0][2] : 0;
  a43=6.3354393272928204e+06;
  a43=(a43/a10);
  a08=(a08+a43);
  a08=(a03*a08);
  a42=(a42+a08);
  a08=(a18*a04);
  a43=(a30*a16);
  a10=(a08-a43);
  a44=(a10*a29);
  a42=(a42-a44);
  a44=(a03*a12);
  a45=(a11*a14);
  a46=(a04*a45);
  a47=(a44+a46);
  a48=(a47*a36);
  a42=(a42-a48);
  a48=(a04*a40);
  a49=(a15*a30);
  a48=(a48+a49);
  a49=(a48*a41);
  a42=(a42+a49);
  a49=casadi_sq(a42);
  a50=casadi_sq(a02);
  a49=(a49+a50);
  a50=arg[0]? arg[0][1] : 0;
  a51=(a03*a05);
  a52=(a18*a51);
  a53=(a04*a05);
  a54=(a11*a53);
  a55=(a54*a16);
  a56=(a52+a55);
  a57=(a23*a06);
  a56=(a56+a57);
  a58=(a56*a29);
  a50=(a50+a58);
  a58=(a53*a12);
  a59=(a06*a33);
  a60=(a30*a14);
  a60=(a05*a60);
  a61=(a59+a60);
  a61=(a58-a61);
  a62=(a61*a36);
  a50=(a50-a62);
  a62=(a40*a51);
  a63=(a15*a54);
  a62=(a62-a63);
  a63=(a06*a38);
  a62=(a62-a63);
  a63=(a62*a41);
  a50=(a50-a63);
  a09=(a53*a09);
  a50=(a50+a09);
  a09=casadi_sq(a50);
  a49=(a49+a09);
  a49=sqrt(a49);
  a09=(a02/a49);
  a09=(a01*a09);
  a09=(a00*a09);
  a09=(-a09);
  if (res[0]!=0) res[0][0]=a09;
  a09=(a50/a49);
  a09=(a01*a09);
  a09=(a00*a09);
  a09=(-a09);
  if (res[0]!=0) res[0][1]=a09;
  a09=(a42/a49);
  a09=(a01*a09);
  a09=(a00*a09);
  a09=(-a09);
  if (res[0]!=0) res[0][2]=a09;
  a09=5.0000000000000000e-01;
  a63=(a09*a50);
  a64=-2.;
  a65=(a03*a25);
  a66=(a18*a06);
  a65=(a65-a66);
  a65=(a29*a65);
  a67=(a64*a65);
  a68=(a30*a13);
  a69=(a68*a05);
  a70=(a45*a06);
  a69=(a69-a70);
  a69=(a36*a69);
  a70=(a64*a69);
  a67=(a67+a70);
  a70=(a40*a06);
  a39=(a03*a39);
  a70=(a70+a39);
  a70=(a41*a70);
  a39=(a64*a70);
  a67=(a67+a39);
  a67=(a63*a67);
  a39=(a09*a02);
  a71=(a40*a05);
  a72=(a20*a38);
  a71=(a71-a72);
  a71=(a41*a71);
  a72=(a64*a71);
  a73=(a18*a05);
  a74=(a57*a03);
  a74=(a73+a74);
  a74=(a29*a74);
  a75=(a64*a74);
  a76=(a45*a05);
  a68=(a68*a06);
  a76=(a76+a68);
  a76=(a36*a76);
  a68=(a64*a76);
  a75=(a75+a68);
  a72=(a72-a75);
  a72=(a39*a72);
  a67=(a67+a72);
  a72=(a09*a42);
  a75=(2.*a04);
  a68=(a75*a11);
  a68=(a68*a13);
  a68=(a68*a36);
  a77=(a04*a23);
  a77=(a77*a29);
  a78=(a64*a77);
  a79=(a04*a38);
  a79=(a79*a41);
  a80=(a64*a79);
  a78=(a78+a80);
  a68=(a68-a78);
  a68=(a72*a68);
  a67=(a67+a68);
  a67=(a67/a49);
  a67=(a01*a67);
  a67=(-a67);
  if (res[0]!=0) res[0][3]=a67;
  a58=(a58*a16);
  a67=(a11*a06);
  a68=(a67*a22);
  a78=(a30*a05);
  a80=(a78*a17);
  a68=(a68+a80);
  a58=(a58-a68);
  a58=(a29*a58);
  a68=(a64*a58);
  a80=(a13*a06);
  a80=(a80*a12);
  a81=(a44*a14);
  a82=(a81*a05);
  a80=(a80+a82);
  a80=(a80+a54);
  a80=(a36*a80);
  a54=(a64*a80);
  a68=(a68+a54);
  a54=(a15*a04);
  a54=(a54*a05);
  a54=(a54*a12);
  a78=(a24*a78);
  a67=(a67*a19);
  a78=(a78+a67);
  a54=(a54-a78);
  a54=(a41*a54);
  a78=(a64*a54);
  a68=(a68+a78);
  a68=(a63*a68);
  a31=(a31*a16);
  a78=(a32*a16);
  a67=(a11*a05);
  a82=(a67*a22);
  a78=(a78+a82);
  a31=(a31-a78);
  a31=(a29*a31);
  a78=(a64*a31);
  a82=(a13*a05);
  a82=(a82*a12);
  a81=(a81*a06);
  a81=(a81+a27);
  a82=(a82-a81);
  a82=(a36*a82);
  a81=(a64*a82);
  a78=(a78+a81);
  a81=(a15*a11);
  a27=(a81*a03);
  a27=(a27*a06);
  a27=(a27*a14);
  a83=(a15*a32);
  a67=(a67*a19);
  a83=(a83+a67);
  a27=(a27-a83);
  a27=(a41*a27);
  a83=(a64*a27);
  a78=(a78+a83);
  a78=(a39*a78);
  a68=(a68+a78);
  a78=(a04*a11);
  a83=(a78*a17);
  a67=(a44*a16);
  a83=(a83+a67);
  a83=(a29*a83);
  a67=(a64*a83);
  a84=(a04*a12);
  a84=(a84*a14);
  a30=(a30-a84);
  a30=(a36*a30);
  a84=(a64*a30);
  a67=(a67+a84);
  a84=(a15*a44);
  a85=(a78*a24);
  a84=(a84+a85);
  a84=(a41*a84);
  a85=(a64*a84);
  a67=(a67+a85);
  a67=(a72*a67);
  a68=(a68+a67);
  a68=(a68/a49);
  a68=(a01*a68);
  a68=(-a68);
  if (res[0]!=0) res[0][4]=a68;
  a68=(a62*a29);
  a67=(a64*a68);
  a57=(a55+a57);
  a73=(a73*a03);
  a57=(a57+a73);
  a57=(a41*a57);
  a73=(a64*a57);
  a67=(a67+a73);
  a63=(a63*a67);
  a67=(a37*a29);
  a73=(a64*a67);
  a66=(a66*a03);
  a66=(a28+a66);
  a66=(a25-a66);
  a66=(a41*a66);
  a85=(a64*a66);
  a73=(a73+a85);
  a39=(a39*a73);
  a63=(a63+a39);
  a39=(a43-a08);
  a41=(a41*a39);
  a39=(a64*a41);
  a29=(a48*a29);
  a73=(a64*a29);
  a39=(a39-a73);
  a72=(a72*a39);
  a63=(a63+a72);
  a63=(a63/a49);
  a63=(a01*a63);
  a63=(-a63);
  if (res[0]!=0) res[0][5]=a63;
  a63=(-a01);
  if (res[0]!=0) res[0][6]=a63;
  a63=0.;
  if (res[0]!=0) res[0][7]=a63;
  if (res[0]!=0) res[0][8]=a63;
  if (res[0]!=0) res[0][9]=a63;
  if (res[0]!=0) res[0][10]=a63;
  a72=arg[11]? arg[11][0] : 0;
  a39=arg[8]? arg[8][0] : 0;
  a39=(a39+a49);
  a72=(a72-a39);
  a01=(a01*a72);
  if (res[0]!=0) res[0][11]=a01;
  a01=arg[14]? arg[14][1] : 0;
  a07=(a07*a02);
  a72=(a03*a42);
  a39=(a53*a50);
  a72=(a72+a39);
  a07=(a07-a72);
  a72=(a11*a07);
  a39=(a16*a72);
  a42=(a04*a42);
  a49=(a20*a02);
  a42=(a42+a49);
  a49=(a51*a50);
  a42=(a42-a49);
  a49=(a18*a42);
  a39=(a39+a49);
  a02=(a05*a02);
  a50=(a06*a50);
  a02=(a02+a50);
  a50=(a23*a02);
  a49=(a39-a50);
  a73=casadi_sq(a49);
  a85=(a45*a42);
  a07=(a12*a07);
  a86=(a33*a02);
  a86=(a07+a86);
  a85=(a85-a86);
  a86=casadi_sq(a85);
  a73=(a73+a86);
  a86=(a49/a73);
  a35=(a86*a35);
  a87=(a85/a73);
  a26=(a87*a26);
  a35=(a35-a26);
  a35=(a01*a35);
  a35=(a00*a35);
  if (res[0]!=0) res[0][12]=a35;
  a56=(a87*a56);
  a61=(a86*a61);
  a56=(a56+a61);
  a56=(a01*a56);
  a56=(a00*a56);
  if (res[0]!=0) res[0][13]=a56;
  a47=(a86*a47);
  a10=(a10*a87);
  a47=(a47-a10);
  a47=(a01*a47);
  a47=(a00*a47);
  if (res[0]!=0) res[0][14]=a47;
  a77=(a77+a79);
  a78=(a78*a13);
  a78=(a78*a36);
  a77=(a77+a78);
  a78=(a04*a77);
  a74=(a74+a76);
  a74=(a74-a71);
  a71=(a74*a20);
  a78=(a78+a71);
  a65=(a65+a69);
  a65=(a65+a70);
  a70=(a65*a51);
  a78=(a78+a70);
  a70=(a11*a78);
  a70=(a70*a14);
  a69=(a65*a53);
  a77=(a03*a77);
  a69=(a69-a77);
  a77=(a04*a74);
  a77=(a77*a06);
  a69=(a69+a77);
  a77=(a69*a12);
  a74=(a74*a05);
  a65=(a65*a06);
  a74=(a74-a65);
  a65=(a74*a33);
  a71=(a77+a65);
  a45=(a45*a02);
  a71=(a71+a45);
  a76=(a33*a42);
  a71=(a71+a76);
  a70=(a70-a71);
  a70=(a86*a70);
  a71=(a18*a78);
  a36=(a74*a23);
  a79=(a18*a02);
  a47=(a36+a79);
  a10=(a23*a42);
  a47=(a47+a10);
  a47=(a71-a47);
  a56=(a11*a16);
  a61=(a56*a69);
  a47=(a47+a61);
  a47=(a87*a47);
  a70=(a70-a47);
  a70=(a01*a70);
  if (res[0]!=0) res[0][15]=a70;
  a58=(a58+a80);
  a58=(a58+a54);
  a54=(a58*a06);
  a31=(a31+a82);
  a31=(a31+a27);
  a27=(a31*a05);
  a54=(a54+a27);
  a27=(a54*a33);
  a83=(a83+a30);
  a83=(a83+a84);
  a84=(a03*a83);
  a30=(a58*a53);
  a84=(a84+a30);
  a30=(a04*a31);
  a30=(a30*a06);
  a84=(a84-a30);
  a30=(a84*a12);
  a82=(a27-a30);
  a80=(a12*a14);
  a80=(a80*a42);
  a82=(a82-a80);
  a82=(a82-a72);
  a58=(a58*a51);
  a83=(a04*a83);
  a31=(a31*a20);
  a83=(a83+a31);
  a58=(a58-a83);
  a83=(a11*a58);
  a83=(a83*a14);
  a82=(a82+a83);
  a83=(a13*a12);
  a83=(a83*a02);
  a82=(a82+a83);
  a82=(a86*a82);
  a83=(a54*a23);
  a31=(a18*a58);
  a70=(a83+a31);
  a47=(a56*a84);
  a70=(a70+a47);
  a35=(a11*a42);
  a17=(a35*a17);
  a70=(a70+a17);
  a16=(a16*a07);
  a70=(a70-a16);
  a26=(a11*a02);
  a22=(a26*a22);
  a70=(a70-a22);
  a70=(a87*a70);
  a82=(a82-a70);
  a82=(a01*a82);
  if (res[0]!=0) res[0][16]=a82;
  a68=(a68+a57);
  a57=(a68*a06);
  a67=(a67+a66);
  a66=(a67*a05);
  a57=(a57+a66);
  a33=(a57*a33);
  a53=(a68*a53);
  a29=(a29-a41);
  a41=(a03*a29);
  a53=(a53-a41);
  a41=(a04*a67);
  a41=(a41*a06);
  a53=(a53-a41);
  a41=(a53*a12);
  a66=(a33-a41);
  a04=(a04*a29);
  a67=(a67*a20);
  a04=(a04-a67);
  a68=(a68*a51);
  a04=(a04+a68);
  a68=(a11*a04);
  a68=(a68*a14);
  a66=(a66+a68);
  a86=(a86*a66);
  a66=(a15*a72);
  a68=(a40*a42);
  a51=(a66-a68);
  a67=(a38*a02);
  a51=(a51-a67);
  a20=(a57*a23);
  a29=(a51+a20);
  a18=(a18*a04);
  a29=(a29+a18);
  a56=(a56*a53);
  a29=(a29+a56);
  a87=(a87*a29);
  a86=(a86-a87);
  a86=(a01*a86);
  if (res[0]!=0) res[0][17]=a86;
  if (res[0]!=0) res[0][18]=a63;
  a86=(-a01);
  if (res[0]!=0) res[0][19]=a86;
  if (res[0]!=0) res[0][20]=a63;
  a86=arg[12]? arg[12][0] : 0;
  a87=sin(a86);
  a29=(a01*a87);
  a29=(-a29);
  if (res[0]!=0) res[0][21]=a29;
  a29=cos(a86);
  a82=(a01*a29);
  a82=(-a82);
  if (res[0]!=0) res[0][22]=a82;
  a82=arg[8]? arg[8][1] : 0;
  a70=arg[9]? arg[9][1] : 0;
  a29=(a29*a70);
  a82=(a82+a29);
  a29=arg[9]? arg[9][0] : 0;
  a87=(a87*a29);
  a82=(a82+a87);
  a87=atan2(a49,a85);
  a82=(a82+a87);
  a82=(a82-a86);
  a86=sin(a82);
  a86=(-a86);
  a82=cos(a82);
  a86=atan2(a86,a82);
  a01=(a01*a86);
  if (res[0]!=0) res[0][23]=a01;
  a01=arg[14]? arg[14][2] : 0;
  a86=casadi_sq(a51);
  a86=(a73+a86);
  a82=(a51/a86);
  a73=sqrt(a73);
  a82=(a82/a73);
  a49=(a09*a49);
  a25=(-a25);
  a25=(2.*a25);
  a21=(2.*a21);
  a25=(a25+a21);
  a28=(2.*a28);
  a25=(a25+a28);
  a25=(a49*a25);
  a09=(a09*a85);
  a32=(a64*a32);
  a34=(a64*a34);
  a32=(a32+a34);
  a11=(2.*a11);
  a03=(a11*a03);
  a03=(a03*a06);
  a03=(a03*a14);
  a32=(a32+a03);
  a32=(a09*a32);
  a25=(a25+a32);
  a25=(a82*a25);
  a86=(a73/a86);
  a37=(a86*a37);
  a25=(a25-a37);
  a25=(a01*a25);
  a25=(a00*a25);
  if (res[0]!=0) res[0][24]=a25;
  a52=(a64*a52);
  a55=(a64*a55);
  a52=(a52+a55);
  a23=(-a23);
  a23=(2.*a23);
  a23=(a23*a06);
  a52=(a52+a23);
  a52=(a49*a52);
  a59=(a64*a59);
  a60=(a64*a60);
  a59=(a59+a60);
  a75=(a75*a05);
  a75=(a75*a12);
  a59=(a59+a75);
  a59=(a09*a59);
  a52=(a52+a59);
  a52=(a82*a52);
  a62=(a86*a62);
  a52=(a52-a62);
  a52=(a01*a52);
  a52=(a00*a52);
  if (res[0]!=0) res[0][25]=a52;
  a48=(a86*a48);
  a43=(a64*a43);
  a08=(2.*a08);
  a43=(a43+a08);
  a43=(a49*a43);
  a44=(2.*a44);
  a46=(2.*a46);
  a44=(a44+a46);
  a44=(a09*a44);
  a43=(a43+a44);
  a43=(a82*a43);
  a48=(a48+a43);
  a48=(a01*a48);
  a00=(a00*a48);
  if (res[0]!=0) res[0][26]=a00;
  a36=(-a36);
  a36=(2.*a36);
  a79=(-a79);
  a79=(2.*a79);
  a36=(a36+a79);
  a10=(-a10);
  a10=(2.*a10);
  a36=(a36+a10);
  a71=(2.*a71);
  a36=(a36+a71);
  a61=(2.*a61);
  a36=(a36+a61);
  a36=(a49*a36);
  a77=(a64*a77);
  a65=(a64*a65);
  a77=(a77+a65);
  a45=(a64*a45);
  a77=(a77+a45);
  a76=(a64*a76);
  a77=(a77+a76);
  a76=(a11*a78);
  a76=(a76*a14);
  a77=(a77+a76);
  a77=(a09*a77);
  a36=(a36+a77);
  a36=(a82*a36);
  a69=(a81*a69);
  a74=(a74*a38);
  a69=(a69-a74);
  a78=(a78*a40);
  a69=(a69-a78);
  a78=(a40*a02);
  a69=(a69+a78);
  a42=(a38*a42);
  a69=(a69-a42);
  a69=(a86*a69);
  a36=(a36-a69);
  a36=(a01*a36);
  if (res[0]!=0) res[0][27]=a36;
  a16=(a64*a16);
  a22=(a64*a22);
  a16=(a16+a22);
  a83=(2.*a83);
  a16=(a16+a83);
  a31=(2.*a31);
  a16=(a16+a31);
  a47=(2.*a47);
  a16=(a16+a47);
  a17=(2.*a17);
  a16=(a16+a17);
  a16=(a49*a16);
  a30=(a64*a30);
  a27=(a64*a27);
  a30=(a30-a27);
  a80=(a64*a80);
  a30=(a30+a80);
  a72=(a64*a72);
  a30=(a30+a72);
  a72=(a11*a58);
  a72=(a72*a14);
  a30=(a30+a72);
  a13=(2.*a13);
  a13=(a13*a12);
  a13=(a13*a02);
  a30=(a30+a13);
  a30=(a09*a30);
  a16=(a16+a30);
  a16=(a82*a16);
  a24=(a24*a35);
  a15=(a15*a07);
  a24=(a24-a15);
  a84=(a81*a84);
  a24=(a24+a84);
  a54=(a54*a38);
  a24=(a24+a54);
  a58=(a58*a40);
  a24=(a24-a58);
  a26=(a26*a19);
  a24=(a24-a26);
  a24=(a86*a24);
  a16=(a16-a24);
  a16=(a01*a16);
  if (res[0]!=0) res[0][28]=a16;
  a68=(-a68);
  a68=(2.*a68);
  a66=(2.*a66);
  a68=(a68+a66);
  a20=(2.*a20);
  a68=(a68+a20);
  a18=(2.*a18);
  a68=(a68+a18);
  a56=(2.*a56);
  a68=(a68+a56);
  a67=(-a67);
  a67=(2.*a67);
  a68=(a68+a67);
  a49=(a49*a68);
  a41=(a64*a41);
  a64=(a64*a33);
  a41=(a41-a64);
  a11=(a11*a04);
  a11=(a11*a14);
  a41=(a41+a11);
  a09=(a09*a41);
  a49=(a49+a09);
  a82=(a82*a49);
  a81=(a81*a53);
  a81=(a81-a39);
  a57=(a57*a38);
  a81=(a81+a57);
  a04=(a04*a40);
  a81=(a81-a04);
  a81=(a81+a50);
  a86=(a86*a81);
  a82=(a82-a86);
  a82=(a01*a82);
  if (res[0]!=0) res[0][29]=a82;
  if (res[0]!=0) res[0][30]=a63;
  if (res[0]!=0) res[0][31]=a63;
  a82=(-a01);
  if (res[0]!=0) res[0][32]=a82;
  if (res[0]!=0) res[0][33]=a63;
  if (res[0]!=0) res[0][34]=a63;
  a63=arg[13]? arg[13][0] : 0;
  a82=arg[8]? arg[8][2] : 0;
  a51=atan2(a51,a73);
  a82=(a82+a51);
  a63=(a63-a82);
  a01=(a01*a63);
  if (res[0]!=0) res[0][35]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_rows_ecc3_1(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int fleet_rows_ecc3_1_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void fleet_rows_ecc3_1_release(int mem) {
}

CASADI_SYMBOL_EXPORT void fleet_rows_ecc3_1_incref(void) {
}

CASADI_SYMBOL_EXPORT void fleet_rows_ecc3_1_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int fleet_rows_ecc3_1_n_in(void) { return 16;}

CASADI_SYMBOL_EXPORT casadi_int fleet_rows_ecc3_1_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real fleet_rows_ecc3_1_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_rows_ecc3_1_name_in(casadi_int i) {
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
    case 9: return "ecc";
    case 10: return "lever_deck";
    case 11: return "r";
    case 12: return "q";
    case 13: return "e";
    case 14: return "weight";
    case 15: return "basis";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_rows_ecc3_1_name_out(casadi_int i) {
  switch (i) {
    case 0: return "rows_t";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_rows_ecc3_1_sparsity_in(casadi_int i) {
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
    case 9: return casadi_s2;
    case 10: return casadi_s0;
    case 11: return casadi_s1;
    case 12: return casadi_s1;
    case 13: return casadi_s1;
    case 14: return casadi_s0;
    case 15: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_rows_ecc3_1_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int fleet_rows_ecc3_1_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 16;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_rows_ecc3_1_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 16*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


