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
  #define CASADI_PREFIX(ID) fleet_rows_4_ ## ID
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
CASADI_SYMBOL_EXPORT void fleet_rows_4_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int fleet_rows_4_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int fleet_rows_4_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {4, 1, 1};
static const casadi_int casadi_s3[3] = {19, 3, 1};

/* fleet_rows_4:(p_ecef[3],lat,lon,alt,heading,pitch,roll,att_err[3],bias[3],lever_deck[3],r,q,e,weight[3],basis[4])->(rows_t[19x3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85, a86, a87, a88, a89;
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
  a66=(a00*a65);
  a66=(-a66);
  if (res[0]!=0) res[0][0]=a66;
  a66=(a45/a44);
  a66=(a01*a66);
  a67=(a00*a66);
  a67=(-a67);
  if (res[0]!=0) res[0][1]=a67;
  a67=(a58/a44);
  a67=(a01*a67);
  a68=(a00*a67);
  a68=(-a68);
  if (res[0]!=0) res[0][2]=a68;
  a68=arg[14]? arg[14][1] : 0;
  a69=(a68*a65);
  a69=(-a69);
  if (res[0]!=0) res[0][3]=a69;
  a69=(a68*a66);
  a69=(-a69);
  if (res[0]!=0) res[0][4]=a69;
  a69=(a68*a67);
  a69=(-a69);
  if (res[0]!=0) res[0][5]=a69;
  a69=arg[14]? arg[14][2] : 0;
  a70=(a69*a65);
  a70=(-a70);
  if (res[0]!=0) res[0][6]=a70;
  a70=(a69*a66);
  a70=(-a70);
  if (res[0]!=0) res[0][7]=a70;
  a70=(a69*a67);
  a70=(-a70);
  if (res[0]!=0) res[0][8]=a70;
  a70=arg[14]? arg[14][3] : 0;
  a65=(a70*a65);
  a65=(-a65);
  if (res[0]!=0) res[0][9]=a65;
  a66=(a70*a66);
  a66=(-a66);
  if (res[0]!=0) res[0][10]=a66;
  a67=(a70*a67);
  a67=(-a67);
  if (res[0]!=0) res[0][11]=a67;
  a67=5.0000000000000000e-01;
  a66=(a67*a45);
  a65=-2.;
  a71=(a22*a05);
  a72=(a04*a26);
  a71=(a71-a72);
  a71=(a29*a71);
  a73=(a65*a71);
  a74=(a33*a18);
  a75=(a03*a74);
  a76=(a04*a60);
  a75=(a75-a76);
  a75=(a37*a75);
  a76=(a65*a75);
  a73=(a73+a76);
  a76=(a04*a40);
  a39=(a05*a39);
  a76=(a76+a39);
  a76=(a43*a76);
  a39=(a65*a76);
  a73=(a73+a39);
  a73=(a66*a73);
  a39=(a67*a02);
  a77=(a03*a26);
  a78=(a05*a48);
  a78=(a77+a78);
  a78=(a29*a78);
  a79=(a65*a78);
  a80=(a03*a60);
  a74=(a04*a74);
  a80=(a80+a74);
  a80=(a37*a80);
  a74=(a65*a80);
  a79=(a79+a74);
  a57=(a05*a57);
  a74=(a03*a40);
  a57=(a57-a74);
  a57=(a43*a57);
  a74=(a65*a57);
  a79=(a79+a74);
  a79=(a39*a79);
  a73=(a73+a79);
  a79=(a67*a58);
  a74=(2.*a12);
  a74=(a74*a06);
  a74=(a74*a18);
  a74=(a74*a37);
  a81=(a20*a06);
  a81=(a81*a29);
  a82=(a65*a81);
  a83=(a06*a38);
  a83=(a83*a43);
  a84=(a65*a83);
  a82=(a82+a84);
  a74=(a74-a82);
  a74=(a79*a74);
  a73=(a73+a74);
  a73=(a73/a44);
  a73=(a01*a73);
  a73=(-a73);
  if (res[0]!=0) res[0][12]=a73;
  a73=(a11*a18);
  a74=(a73*a04);
  a74=(a74-a09);
  a09=(a17*a03);
  a09=(a09*a62);
  a74=(a74+a09);
  a74=(a37*a74);
  a09=(a65*a74);
  a82=(a42*a19);
  a84=(a03*a33);
  a85=(a84*a25);
  a82=(a82+a85);
  a85=(a52*a15);
  a82=(a82+a85);
  a82=(a29*a82);
  a85=(a65*a82);
  a09=(a09-a85);
  a84=(a21*a84);
  a42=(a42*a24);
  a84=(a84+a42);
  a42=(a14*a52);
  a84=(a84+a42);
  a84=(a43*a84);
  a42=(a65*a84);
  a09=(a09-a42);
  a09=(a66*a09);
  a31=(a31*a15);
  a42=(a04*a33);
  a85=(a42*a25);
  a86=(a32*a15);
  a85=(a85+a86);
  a31=(a31-a85);
  a31=(a29*a31);
  a85=(a65*a31);
  a86=(a17*a04);
  a86=(a86*a05);
  a86=(a86*a11);
  a87=(a73*a03);
  a13=(a13+a87);
  a86=(a86-a13);
  a86=(a37*a86);
  a13=(a65*a86);
  a85=(a85+a13);
  a30=(a30*a14);
  a30=(a30*a18);
  a42=(a42*a21);
  a13=(a32*a14);
  a42=(a42+a13);
  a30=(a30-a42);
  a30=(a43*a30);
  a42=(a65*a30);
  a85=(a85+a42);
  a85=(a39*a85);
  a09=(a09+a85);
  a85=(a61*a14);
  a42=(a14*a62);
  a85=(a85-a42);
  a85=(a43*a85);
  a42=(a65*a85);
  a61=(a61*a15);
  a13=(a62*a15);
  a61=(a61-a13);
  a61=(a29*a61);
  a13=(a65*a61);
  a42=(a42+a13);
  a13=(a17*a11);
  a87=(a06*a13);
  a33=(a33+a87);
  a33=(a37*a33);
  a87=(a65*a33);
  a42=(a42-a87);
  a42=(a79*a42);
  a09=(a09+a42);
  a09=(a09/a44);
  a09=(a01*a09);
  a09=(-a09);
  if (res[0]!=0) res[0][13]=a09;
  a09=(a56*a29);
  a42=(a65*a09);
  a87=(a04*a20);
  a87=(a87-a47);
  a77=(a05*a77);
  a87=(a87+a77);
  a87=(a43*a87);
  a77=(a65*a87);
  a42=(a42+a77);
  a66=(a66*a42);
  a42=(a41*a29);
  a77=(a65*a42);
  a72=(a05*a72);
  a88=(a03*a20);
  a16=(a16+a88);
  a72=(a72-a16);
  a72=(a43*a72);
  a16=(a65*a72);
  a77=(a77+a16);
  a39=(a39*a77);
  a66=(a66+a39);
  a29=(a64*a29);
  a39=(a65*a29);
  a77=(a06*a26);
  a77=(a59+a77);
  a43=(a43*a77);
  a77=(a65*a43);
  a39=(a39-a77);
  a79=(a79*a39);
  a66=(a66+a79);
  a66=(a66/a44);
  a66=(a01*a66);
  a66=(-a66);
  if (res[0]!=0) res[0][14]=a66;
  a66=(-a01);
  if (res[0]!=0) res[0][15]=a66;
  a66=0.;
  if (res[0]!=0) res[0][16]=a66;
  if (res[0]!=0) res[0][17]=a66;
  a79=arg[10]? arg[10][0] : 0;
  a39=arg[8]? arg[8][0] : 0;
  a44=(a44+a39);
  a79=(a79-a44);
  a01=(a01*a79);
  if (res[0]!=0) res[0][18]=a01;
  a01=arg[13]? arg[13][1] : 0;
  a79=(a05*a58);
  a44=(a07*a02);
  a79=(a79+a44);
  a44=(a46*a45);
  a79=(a79+a44);
  a44=(a12*a79);
  a39=(a44*a15);
  a77=(a04*a45);
  a16=(a03*a02);
  a77=(a77-a16);
  a16=(a20*a77);
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
  a79=(a11*a79);
  a88=(a53*a77);
  a88=(a79+a88);
  a02=(a02-a88);
  a88=casadi_sq(a02);
  a45=(a45+a88);
  a88=(a16/a45);
  a36=(a88*a36);
  a89=(a02/a45);
  a23=(a89*a23);
  a36=(a36-a23);
  a36=(a01*a36);
  a23=(a00*a36);
  if (res[0]!=0) res[0][19]=a23;
  a55=(a88*a55);
  a49=(a89*a49);
  a55=(a55+a49);
  a55=(a01*a55);
  a49=(a00*a55);
  a49=(-a49);
  if (res[0]!=0) res[0][20]=a49;
  a63=(a88*a63);
  a10=(a89*a10);
  a63=(a63-a10);
  a63=(a01*a63);
  a10=(a00*a63);
  if (res[0]!=0) res[0][21]=a10;
  a10=(a68*a36);
  if (res[0]!=0) res[0][22]=a10;
  a10=(a68*a55);
  a10=(-a10);
  if (res[0]!=0) res[0][23]=a10;
  a10=(a68*a63);
  if (res[0]!=0) res[0][24]=a10;
  a10=(a69*a36);
  if (res[0]!=0) res[0][25]=a10;
  a10=(a69*a55);
  a10=(-a10);
  if (res[0]!=0) res[0][26]=a10;
  a10=(a69*a63);
  if (res[0]!=0) res[0][27]=a10;
  a36=(a70*a36);
  if (res[0]!=0) res[0][28]=a36;
  a55=(a70*a55);
  a55=(-a55);
  if (res[0]!=0) res[0][29]=a55;
  a63=(a70*a63);
  if (res[0]!=0) res[0][30]=a63;
  a81=(a81+a83);
  a83=(a12*a06);
  a83=(a83*a18);
  a83=(a83*a37);
  a81=(a81+a83);
  a83=(a81*a06);
  a71=(a71+a75);
  a71=(a71+a76);
  a76=(a71*a50);
  a83=(a83+a76);
  a78=(a78+a80);
  a78=(a78+a57);
  a57=(a78*a27);
  a83=(a83+a57);
  a57=(a17*a83);
  a57=(a57*a12);
  a81=(a81*a05);
  a80=(a71*a46);
  a81=(a81-a80);
  a80=(a78*a07);
  a81=(a81-a80);
  a80=(a81*a11);
  a78=(a03*a78);
  a71=(a71*a04);
  a78=(a78-a71);
  a71=(a78*a53);
  a76=(a80+a71);
  a60=(a77*a60);
  a76=(a76+a60);
  a75=(a53*a58);
  a76=(a76+a75);
  a57=(a57-a76);
  a57=(a88*a57);
  a76=(a83*a26);
  a37=(a20*a78);
  a63=(a77*a26);
  a55=(a37+a63);
  a36=(a20*a58);
  a55=(a55+a36);
  a55=(a76-a55);
  a10=(a12*a15);
  a49=(a81*a10);
  a55=(a55+a49);
  a55=(a89*a55);
  a57=(a57-a55);
  a57=(a01*a57);
  if (res[0]!=0) res[0][31]=a57;
  a85=(a85+a61);
  a33=(a33-a85);
  a85=(a33*a06);
  a31=(a31+a86);
  a31=(a31+a30);
  a30=(a31*a27);
  a85=(a85+a30);
  a82=(a82-a74);
  a82=(a82+a84);
  a84=(a82*a50);
  a85=(a85-a84);
  a84=(a17*a85);
  a84=(a84*a12);
  a33=(a33*a05);
  a74=(a31*a07);
  a33=(a33-a74);
  a74=(a82*a46);
  a33=(a33+a74);
  a74=(a33*a11);
  a82=(a82*a04);
  a31=(a03*a31);
  a82=(a82+a31);
  a31=(a82*a53);
  a30=(a74+a31);
  a13=(a58*a13);
  a30=(a30+a13);
  a30=(a30+a44);
  a84=(a84-a30);
  a73=(a73*a77);
  a84=(a84+a73);
  a84=(a88*a84);
  a73=(a85*a26);
  a30=(a20*a82);
  a86=(a73-a30);
  a61=(a10*a33);
  a86=(a86+a61);
  a57=(a12*a58);
  a25=(a25*a57);
  a86=(a86+a25);
  a55=(a79*a15);
  a86=(a86-a55);
  a23=(a12*a77);
  a19=(a23*a19);
  a86=(a86-a19);
  a86=(a89*a86);
  a84=(a84-a86);
  a84=(a01*a84);
  if (res[0]!=0) res[0][32]=a84;
  a43=(a43-a29);
  a29=(a43*a06);
  a09=(a09+a87);
  a50=(a09*a50);
  a29=(a29+a50);
  a42=(a42+a72);
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
  a88=(a88*a27);
  a27=(a26*a29);
  a09=(a20*a42);
  a46=(a27-a09);
  a10=(a10*a43);
  a46=(a46+a10);
  a05=(a14*a44);
  a72=(a38*a77);
  a50=(a40*a58);
  a87=(a72+a50);
  a87=(a05-a87);
  a46=(a46+a87);
  a89=(a89*a46);
  a88=(a88-a89);
  a88=(a01*a88);
  if (res[0]!=0) res[0][33]=a88;
  if (res[0]!=0) res[0][34]=a66;
  a88=(-a01);
  if (res[0]!=0) res[0][35]=a88;
  if (res[0]!=0) res[0][36]=a66;
  a88=arg[8]? arg[8][1] : 0;
  a89=atan2(a16,a02);
  a88=(a88+a89);
  a89=arg[11]? arg[11][0] : 0;
  a88=(a88-a89);
  a89=sin(a88);
  a89=(-a89);
  a88=cos(a88);
  a89=atan2(a89,a88);
  a01=(a01*a89);
  if (res[0]!=0) res[0][37]=a01;
  a01=arg[13]? arg[13][2] : 0;
  a89=casadi_sq(a87);
  a89=(a45+a89);
  a88=(a87/a89);
  a45=sqrt(a45);
  a88=(a88/a45);
  a16=(a67*a16);
  a28=(a65*a28);
  a22=(a65*a22);
  a28=(a28-a22);
  a04=(2.*a04);
  a04=(a04*a12);
  a04=(a04*a06);
  a04=(a04*a15);
  a28=(a28+a04);
  a28=(a16*a28);
  a67=(a67*a02);
  a32=(a65*a32);
  a35=(a65*a35);
  a32=(a32+a35);
  a03=(2.*a03);
  a03=(a03*a12);
  a03=(a03*a18);
  a32=(a32+a03);
  a32=(a67*a32);
  a28=(a28+a32);
  a28=(a88*a28);
  a89=(a45/a89);
  a41=(a89*a41);
  a28=(a28-a41);
  a28=(a01*a28);
  a41=(a00*a28);
  if (res[0]!=0) res[0][38]=a41;
  a51=(a65*a51);
  a48=(-a48);
  a48=(2.*a48);
  a51=(a51+a48);
  a47=(2.*a47);
  a51=(a51+a47);
  a51=(a16*a51);
  a52=(a65*a52);
  a54=(a65*a54);
  a52=(a52+a54);
  a34=(a65*a34);
  a52=(a52+a34);
  a52=(a67*a52);
  a51=(a51+a52);
  a51=(a88*a51);
  a56=(a89*a56);
  a51=(a51-a56);
  a51=(a01*a51);
  a56=(a00*a51);
  if (res[0]!=0) res[0][39]=a56;
  a08=(2.*a08);
  a59=(2.*a59);
  a08=(a08+a59);
  a08=(a16*a08);
  a62=(a65*a62);
  a17=(2.*a17);
  a59=(a17*a12);
  a59=(a59*a06);
  a62=(a62+a59);
  a62=(a67*a62);
  a08=(a08+a62);
  a08=(a88*a08);
  a64=(a89*a64);
  a08=(a08-a64);
  a08=(a01*a08);
  a00=(a00*a08);
  if (res[0]!=0) res[0][40]=a00;
  a00=(a68*a28);
  if (res[0]!=0) res[0][41]=a00;
  a00=(a68*a51);
  if (res[0]!=0) res[0][42]=a00;
  a68=(a68*a08);
  if (res[0]!=0) res[0][43]=a68;
  a68=(a69*a28);
  if (res[0]!=0) res[0][44]=a68;
  a68=(a69*a51);
  if (res[0]!=0) res[0][45]=a68;
  a69=(a69*a08);
  if (res[0]!=0) res[0][46]=a69;
  a28=(a70*a28);
  if (res[0]!=0) res[0][47]=a28;
  a51=(a70*a51);
  if (res[0]!=0) res[0][48]=a51;
  a70=(a70*a08);
  if (res[0]!=0) res[0][49]=a70;
  a37=(-a37);
  a37=(2.*a37);
  a63=(-a63);
  a63=(2.*a63);
  a37=(a37+a63);
  a36=(-a36);
  a36=(2.*a36);
  a37=(a37+a36);
  a76=(2.*a76);
  a37=(a37+a76);
  a49=(2.*a49);
  a37=(a37+a49);
  a37=(a16*a37);
  a80=(a65*a80);
  a71=(a65*a71);
  a80=(a80+a71);
  a60=(a65*a60);
  a80=(a80+a60);
  a75=(a65*a75);
  a80=(a80+a75);
  a75=(a17*a83);
  a75=(a75*a12);
  a80=(a80+a75);
  a80=(a67*a80);
  a37=(a37+a80);
  a37=(a88*a37);
  a80=(a12*a14);
  a81=(a81*a80);
  a78=(a78*a38);
  a81=(a81-a78);
  a83=(a83*a40);
  a81=(a81-a83);
  a83=(a38*a58);
  a81=(a81-a83);
  a83=(a40*a77);
  a81=(a81+a83);
  a81=(a89*a81);
  a37=(a37-a81);
  a37=(a01*a37);
  if (res[0]!=0) res[0][50]=a37;
  a55=(a65*a55);
  a19=(a65*a19);
  a55=(a55+a19);
  a30=(-a30);
  a30=(2.*a30);
  a55=(a55+a30);
  a73=(2.*a73);
  a55=(a55+a73);
  a61=(2.*a61);
  a55=(a55+a61);
  a25=(2.*a25);
  a55=(a55+a25);
  a55=(a16*a55);
  a74=(a65*a74);
  a31=(a65*a31);
  a74=(a74+a31);
  a13=(a65*a13);
  a74=(a74+a13);
  a44=(a65*a44);
  a74=(a74+a44);
  a44=(a17*a85);
  a44=(a44*a12);
  a74=(a74+a44);
  a11=(2.*a11);
  a11=(a11*a18);
  a11=(a11*a77);
  a74=(a74+a11);
  a74=(a67*a74);
  a55=(a55+a74);
  a55=(a88*a55);
  a21=(a21*a57);
  a33=(a33*a80);
  a21=(a21+a33);
  a82=(a82*a38);
  a21=(a21-a82);
  a85=(a85*a40);
  a21=(a21-a85);
  a24=(a24*a23);
  a21=(a21-a24);
  a14=(a14*a79);
  a21=(a21-a14);
  a21=(a89*a21);
  a55=(a55-a21);
  a55=(a01*a55);
  if (res[0]!=0) res[0][51]=a55;
  a09=(-a09);
  a09=(2.*a09);
  a27=(2.*a27);
  a09=(a09+a27);
  a10=(2.*a10);
  a09=(a09+a10);
  a72=(-a72);
  a72=(2.*a72);
  a09=(a09+a72);
  a50=(-a50);
  a50=(2.*a50);
  a09=(a09+a50);
  a05=(2.*a05);
  a09=(a09+a05);
  a16=(a16*a09);
  a07=(a65*a07);
  a65=(a65*a53);
  a07=(a07+a65);
  a17=(a17*a29);
  a17=(a17*a12);
  a07=(a07+a17);
  a67=(a67*a07);
  a16=(a16+a67);
  a88=(a88*a16);
  a43=(a43*a80);
  a43=(a43-a39);
  a42=(a42*a38);
  a43=(a43-a42);
  a29=(a29*a40);
  a43=(a43-a29);
  a77=(a77*a20);
  a43=(a43+a77);
  a58=(a58*a26);
  a43=(a43-a58);
  a89=(a89*a43);
  a88=(a88-a89);
  a88=(a01*a88);
  if (res[0]!=0) res[0][52]=a88;
  if (res[0]!=0) res[0][53]=a66;
  if (res[0]!=0) res[0][54]=a66;
  a66=(-a01);
  if (res[0]!=0) res[0][55]=a66;
  a66=arg[12]? arg[12][0] : 0;
  a88=arg[8]? arg[8][2] : 0;
  a87=atan2(a87,a45);
  a88=(a88+a87);
  a66=(a66-a88);
  a01=(a01*a66);
  if (res[0]!=0) res[0][56]=a01;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_rows_4(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int fleet_rows_4_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void fleet_rows_4_release(int mem) {
}

CASADI_SYMBOL_EXPORT void fleet_rows_4_incref(void) {
}

CASADI_SYMBOL_EXPORT void fleet_rows_4_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int fleet_rows_4_n_in(void) { return 15;}

CASADI_SYMBOL_EXPORT casadi_int fleet_rows_4_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real fleet_rows_4_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* fleet_rows_4_name_in(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const char* fleet_rows_4_name_out(casadi_int i) {
  switch (i) {
    case 0: return "rows_t";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_rows_4_sparsity_in(casadi_int i) {
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
    case 14: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* fleet_rows_4_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int fleet_rows_4_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 15;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int fleet_rows_4_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 15*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


