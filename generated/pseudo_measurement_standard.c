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
  #define CASADI_PREFIX(ID) pseudo_measurement_standard_ ## ID
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
#define casadi_s4 CASADI_PREFIX(s4)
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
CASADI_SYMBOL_EXPORT void pseudo_measurement_standard_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int pseudo_measurement_standard_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int pseudo_measurement_standard_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {6, 1, 1};
static const casadi_int casadi_s2[3] = {3, 12, 1};
static const casadi_int casadi_s3[3] = {3, 6, 1};
static const casadi_int casadi_s4[3] = {3, 3, 1};

/* pseudo_measurement_standard:(nav_a[3],att_a[3],meas_a[3],nav_b[3],att_b[3],meas_b[3],sigma0[6])->(Z[3],H[3x12],M[3x6],R[3x3],p_a_ecef[3],p_b_ecef[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100;
  a000=arg[4]? arg[4][1] : 0;
  a001=cos(a000);
  a002=arg[5]? arg[5][2] : 0;
  a003=cos(a002);
  a004=arg[5]? arg[5][1] : 0;
  a005=cos(a004);
  a006=(a003*a005);
  a007=(a001*a006);
  a008=arg[5]? arg[5][0] : 0;
  a009=(a007*a008);
  a010=arg[4]? arg[4][0] : 0;
  a011=sin(a010);
  a012=(a009*a011);
  a010=cos(a010);
  a013=arg[4]? arg[4][2] : 0;
  a014=cos(a013);
  a015=(a010*a014);
  a013=sin(a013);
  a016=(a013*a011);
  a000=sin(a000);
  a017=(a016*a000);
  a017=(a015+a017);
  a004=sin(a004);
  a018=(a003*a004);
  a019=(a017*a018);
  a020=(a019*a008);
  a020=(a012+a020);
  a021=(a014*a011);
  a022=(a000*a021);
  a023=(a010*a013);
  a022=(a022-a023);
  a002=sin(a002);
  a024=(a022*a002);
  a025=(a024*a008);
  a020=(a020-a025);
  a025=arg[3]? arg[3][1] : 0;
  a026=sin(a025);
  a027=(a020*a026);
  a028=arg[3]? arg[3][0] : 0;
  a029=sin(a028);
  a030=(a010*a009);
  a031=(a015*a000);
  a016=(a016+a031);
  a031=(a016*a002);
  a032=(a031*a008);
  a030=(a030-a032);
  a032=(a023*a000);
  a032=(a032-a021);
  a033=(a018*a032);
  a034=(a033*a008);
  a030=(a030+a034);
  a025=cos(a025);
  a034=(a030*a025);
  a035=(a029*a034);
  a036=(a027+a035);
  a037=arg[0]? arg[0][2] : 0;
  a038=6378137.;
  a039=1.;
  a040=-6.6943799901413173e-03;
  a041=arg[0]? arg[0][0] : 0;
  a042=sin(a041);
  a043=casadi_sq(a042);
  a043=(a040*a043);
  a043=(a039+a043);
  a043=sqrt(a043);
  a044=(a038/a043);
  a044=(a037+a044);
  a045=arg[0]? arg[0][1] : 0;
  a046=cos(a045);
  a041=cos(a041);
  a047=(a046*a041);
  a048=(a044*a047);
  a049=arg[1]? arg[1][1] : 0;
  a050=sin(a049);
  a051=arg[2]? arg[2][2] : 0;
  a052=cos(a051);
  a053=arg[2]? arg[2][1] : 0;
  a054=cos(a053);
  a055=(a052*a054);
  a056=(a050*a055);
  a057=arg[2]? arg[2][0] : 0;
  a058=(a056*a057);
  a051=sin(a051);
  a059=(a051*a057);
  a060=arg[1]? arg[1][2] : 0;
  a061=cos(a060);
  a049=cos(a049);
  a062=(a061*a049);
  a063=(a059*a062);
  a063=(a058+a063);
  a053=sin(a053);
  a064=(a052*a053);
  a065=(a064*a057);
  a060=sin(a060);
  a066=(a060*a049);
  a067=(a065*a066);
  a063=(a063-a067);
  a047=(a047*a063);
  a048=(a048+a047);
  a047=arg[1]? arg[1][0] : 0;
  a067=sin(a047);
  a068=(a049*a055);
  a069=(a068*a057);
  a070=(a067*a069);
  a071=(a061*a067);
  a072=(a050*a071);
  a047=cos(a047);
  a073=(a047*a060);
  a072=(a072-a073);
  a074=(a072*a051);
  a075=(a074*a057);
  a075=(a070-a075);
  a076=(a047*a061);
  a077=(a060*a067);
  a078=(a050*a077);
  a078=(a076+a078);
  a079=(a078*a064);
  a080=(a079*a057);
  a075=(a075+a080);
  a045=sin(a045);
  a080=(a075*a045);
  a048=(a048-a080);
  a080=(a047*a069);
  a081=(a050*a076);
  a081=(a077+a081);
  a082=(a051*a081);
  a083=(a082*a057);
  a080=(a080-a083);
  a083=(a073*a050);
  a083=(a083-a071);
  a084=(a064*a083);
  a085=(a084*a057);
  a080=(a080+a085);
  a085=(a046*a080);
  a086=(a042*a085);
  a048=(a048-a086);
  a036=(a036+a048);
  a086=arg[3]? arg[3][2] : 0;
  a087=casadi_sq(a029);
  a040=(a040*a087);
  a039=(a039+a040);
  a039=sqrt(a039);
  a038=(a038/a039);
  a038=(a086+a038);
  a028=cos(a028);
  a040=(a025*a028);
  a087=(a038*a040);
  a036=(a036-a087);
  a088=(a006*a000);
  a089=(a088*a008);
  a090=(a002*a008);
  a091=(a001*a014);
  a092=(a090*a091);
  a092=(a089+a092);
  a093=(a018*a008);
  a094=(a013*a001);
  a095=(a093*a094);
  a092=(a092-a095);
  a095=(a040*a092);
  a036=(a036-a095);
  if (res[0]!=0) res[0][0]=a036;
  a036=(a045*a041);
  a044=(a036*a044);
  a096=(a036*a063);
  a044=(a044+a096);
  a075=(a075*a046);
  a044=(a044+a075);
  a075=(a045*a080);
  a096=(a075*a042);
  a044=(a044-a096);
  a096=(a026*a030);
  a097=(a029*a096);
  a098=(a044+a097);
  a099=(a026*a028);
  a100=(a092*a099);
  a098=(a098-a100);
  a020=(a020*a025);
  a098=(a098-a020);
  a038=(a038*a099);
  a098=(a098-a038);
  if (res[0]!=0) res[0][1]=a098;
  a063=(a042*a063);
  a098=6.3354393272928204e+06;
  a043=(a098/a043);
  a037=(a037+a043);
  a037=(a042*a037);
  a063=(a063+a037);
  a080=(a041*a080);
  a063=(a063+a080);
  a098=(a098/a039);
  a086=(a086+a098);
  a086=(a029*a086);
  a098=(a063-a086);
  a030=(a030*a028);
  a098=(a098-a030);
  a092=(a029*a092);
  a098=(a098-a092);
  if (res[0]!=0) res[0][2]=a098;
  a098=(a072*a059);
  a098=(a098-a070);
  a070=(a078*a065);
  a098=(a098-a070);
  a070=(a042*a046);
  a039=(a098*a070);
  a075=(a075+a039);
  a075=(-a075);
  if (res[1]!=0) res[1][0]=a075;
  a075=(a045*a042);
  a039=(a098*a075);
  a085=(a085-a039);
  if (res[1]!=0) res[1][1]=a085;
  a098=(a098*a041);
  if (res[1]!=0) res[1][2]=a098;
  a098=(a050*a065);
  a085=(a098*a060);
  a085=(a069+a085);
  a050=(a050*a059);
  a061=(a050*a061);
  a085=(a085-a061);
  a061=(a085*a046);
  a061=(a061*a041);
  a073=(a073*a052);
  a073=(a073*a053);
  a073=(a073*a049);
  a073=(a073*a057);
  a039=(a049*a059);
  a076=(a039*a076);
  a080=(a047*a058);
  a076=(a076+a080);
  a073=(a073-a076);
  a076=(a070*a073);
  a077=(a077*a052);
  a077=(a077*a053);
  a077=(a077*a049);
  a077=(a077*a057);
  a071=(a039*a071);
  a058=(a067*a058);
  a071=(a071+a058);
  a077=(a077-a071);
  a071=(a077*a045);
  a076=(a076+a071);
  a061=(a061-a076);
  if (res[1]!=0) res[1][3]=a061;
  a061=(a036*a085);
  a077=(a077*a046);
  a061=(a061+a077);
  a077=(a073*a075);
  a061=(a061-a077);
  if (res[1]!=0) res[1][4]=a061;
  a073=(a073*a041);
  a085=(a085*a042);
  a073=(a073+a085);
  if (res[1]!=0) res[1][5]=a073;
  a073=(a059*a083);
  a085=(a065*a081);
  a085=(a073+a085);
  a061=(a070*a085);
  a077=(a078*a059);
  a076=(a072*a065);
  a076=(a077+a076);
  a071=(a076*a045);
  a061=(a061+a071);
  a059=(a059*a066);
  a071=(a062*a065);
  a071=(a059+a071);
  a058=(a071*a046);
  a058=(a058*a041);
  a061=(a061+a058);
  a061=(-a061);
  if (res[1]!=0) res[1][6]=a061;
  a076=(a076*a046);
  a061=(a036*a071);
  a076=(a076-a061);
  a061=(a085*a075);
  a076=(a076-a061);
  if (res[1]!=0) res[1][7]=a076;
  a085=(a085*a041);
  a071=(a071*a042);
  a085=(a085-a071);
  if (res[1]!=0) res[1][8]=a085;
  a051=(a051*a062);
  a056=(a056+a051);
  a064=(a064*a066);
  a056=(a056-a064);
  a064=(a056*a046);
  a064=(a064*a041);
  a084=(a084-a082);
  a082=(a047*a068);
  a084=(a084+a082);
  a082=(a070*a084);
  a079=(a079-a074);
  a068=(a067*a068);
  a079=(a079+a068);
  a068=(a079*a045);
  a082=(a082+a068);
  a064=(a064-a082);
  if (res[1]!=0) res[1][9]=a064;
  a082=(a036*a056);
  a079=(a079*a046);
  a082=(a082+a079);
  a079=(a084*a075);
  a082=(a082-a079);
  if (res[1]!=0) res[1][10]=a082;
  a084=(a084*a041);
  a056=(a056*a042);
  a084=(a084+a056);
  if (res[1]!=0) res[1][11]=a084;
  a055=(a055*a057);
  a083=(a055*a083);
  a049=(a049*a065);
  a065=(a049*a047);
  a083=(a083-a065);
  a065=(a070*a083);
  a055=(a055*a078);
  a049=(a049*a067);
  a055=(a055-a049);
  a049=(a055*a045);
  a065=(a065+a049);
  a060=(a060*a069);
  a098=(a098+a060);
  a060=(a098*a046);
  a060=(a060*a041);
  a065=(a065+a060);
  a060=(-a065);
  if (res[1]!=0) res[1][12]=a060;
  a055=(a055*a046);
  a069=(a036*a098);
  a055=(a055-a069);
  a069=(a083*a075);
  a055=(a055-a069);
  if (res[1]!=0) res[1][13]=a055;
  a083=(a083*a041);
  a098=(a098*a042);
  a083=(a083-a098);
  if (res[1]!=0) res[1][14]=a083;
  a073=(a073*a053);
  a039=(a039*a054);
  a047=(a039*a047);
  a073=(a073+a047);
  a081=(a052*a081);
  a081=(a081*a057);
  a073=(a073+a081);
  a070=(a070*a073);
  a077=(a077*a053);
  a039=(a039*a067);
  a077=(a077+a039);
  a072=(a072*a052);
  a072=(a072*a057);
  a077=(a077+a072);
  a045=(a077*a045);
  a070=(a070+a045);
  a059=(a059*a053);
  a050=(a050*a054);
  a059=(a059-a050);
  a052=(a052*a062);
  a052=(a052*a057);
  a059=(a059+a052);
  a052=(a059*a046);
  a052=(a052*a041);
  a070=(a070+a052);
  if (res[1]!=0) res[1][15]=a070;
  a036=(a036*a059);
  a077=(a077*a046);
  a036=(a036-a077);
  a075=(a073*a075);
  a036=(a036+a075);
  if (res[1]!=0) res[1][16]=a036;
  a059=(a059*a042);
  a073=(a073*a041);
  a059=(a059-a073);
  if (res[1]!=0) res[1][17]=a059;
  a073=(a090*a022);
  a073=(a073-a012);
  a012=(a017*a093);
  a073=(a073-a012);
  a012=(a029*a025);
  a041=(a073*a012);
  a096=(a096+a041);
  if (res[1]!=0) res[1][18]=a096;
  a096=(a073*a026);
  a096=(a096*a029);
  a096=(a096-a034);
  if (res[1]!=0) res[1][19]=a096;
  a073=(a073*a028);
  a073=(-a073);
  if (res[1]!=0) res[1][20]=a073;
  a023=(a023*a003);
  a023=(a023*a004);
  a023=(a023*a001);
  a023=(a023*a008);
  a073=(a010*a089);
  a096=(a001*a090);
  a015=(a015*a096);
  a073=(a073+a015);
  a023=(a023-a073);
  a073=(a012*a023);
  a015=(a013*a003);
  a015=(a015*a004);
  a015=(a015*a001);
  a015=(a015*a011);
  a015=(a015*a008);
  a021=(a096*a021);
  a089=(a011*a089);
  a021=(a021+a089);
  a015=(a015-a021);
  a021=(a015*a026);
  a073=(a073+a021);
  a021=(a000*a093);
  a089=(a013*a021);
  a089=(a009+a089);
  a000=(a000*a090);
  a014=(a000*a014);
  a089=(a089-a014);
  a014=(a089*a040);
  a073=(a073-a014);
  if (res[1]!=0) res[1][21]=a073;
  a073=(a023*a026);
  a073=(a073*a029);
  a015=(a015*a025);
  a014=(a089*a099);
  a015=(a015+a014);
  a073=(a073-a015);
  if (res[1]!=0) res[1][22]=a073;
  a023=(a023*a028);
  a089=(a089*a029);
  a023=(a023+a089);
  a023=(-a023);
  if (res[1]!=0) res[1][23]=a023;
  a023=(a032*a090);
  a089=(a016*a093);
  a089=(a023+a089);
  a073=(a012*a089);
  a015=(a017*a090);
  a014=(a093*a022);
  a014=(a015+a014);
  a034=(a014*a026);
  a073=(a073+a034);
  a090=(a090*a094);
  a034=(a091*a093);
  a034=(a090+a034);
  a041=(a034*a040);
  a073=(a073+a041);
  if (res[1]!=0) res[1][24]=a073;
  a073=(a034*a099);
  a014=(a014*a025);
  a073=(a073-a014);
  a014=(a089*a026);
  a014=(a014*a029);
  a073=(a073+a014);
  if (res[1]!=0) res[1][25]=a073;
  a034=(a034*a029);
  a089=(a089*a028);
  a034=(a034-a089);
  if (res[1]!=0) res[1][26]=a034;
  a033=(a033-a031);
  a031=(a010*a007);
  a033=(a033+a031);
  a031=(a012*a033);
  a019=(a019-a024);
  a007=(a007*a011);
  a019=(a019+a007);
  a007=(a019*a026);
  a031=(a031+a007);
  a002=(a091*a002);
  a088=(a088+a002);
  a018=(a018*a094);
  a088=(a088-a018);
  a018=(a088*a040);
  a031=(a031-a018);
  if (res[1]!=0) res[1][27]=a031;
  a018=(a033*a026);
  a018=(a018*a029);
  a019=(a019*a025);
  a094=(a088*a099);
  a019=(a019+a094);
  a018=(a018-a019);
  if (res[1]!=0) res[1][28]=a018;
  a033=(a033*a028);
  a088=(a088*a029);
  a033=(a033+a088);
  a088=(-a033);
  if (res[1]!=0) res[1][29]=a088;
  a006=(a006*a008);
  a032=(a006*a032);
  a001=(a001*a093);
  a093=(a010*a001);
  a032=(a032-a093);
  a093=(a012*a032);
  a017=(a017*a006);
  a001=(a001*a011);
  a017=(a017-a001);
  a001=(a017*a026);
  a093=(a093+a001);
  a013=(a013*a009);
  a021=(a021+a013);
  a013=(a021*a040);
  a093=(a093+a013);
  if (res[1]!=0) res[1][30]=a093;
  a013=(a021*a099);
  a017=(a017*a025);
  a013=(a013-a017);
  a017=(a032*a026);
  a017=(a017*a029);
  a013=(a013+a017);
  if (res[1]!=0) res[1][31]=a013;
  a021=(a021*a029);
  a032=(a032*a028);
  a021=(a021-a032);
  if (res[1]!=0) res[1][32]=a021;
  a096=(a096*a005);
  a010=(a010*a096);
  a023=(a004*a023);
  a010=(a010+a023);
  a016=(a003*a016);
  a016=(a016*a008);
  a010=(a010+a016);
  a012=(a012*a010);
  a015=(a004*a015);
  a096=(a096*a011);
  a015=(a015+a096);
  a022=(a003*a022);
  a022=(a022*a008);
  a015=(a015+a022);
  a022=(a015*a026);
  a012=(a012+a022);
  a004=(a004*a090);
  a000=(a000*a005);
  a004=(a004-a000);
  a003=(a003*a091);
  a003=(a003*a008);
  a004=(a004+a003);
  a040=(a004*a040);
  a012=(a012+a040);
  a040=(-a012);
  if (res[1]!=0) res[1][33]=a040;
  a015=(a015*a025);
  a099=(a004*a099);
  a015=(a015-a099);
  a026=(a010*a026);
  a026=(a026*a029);
  a015=(a015-a026);
  if (res[1]!=0) res[1][34]=a015;
  a010=(a010*a028);
  a004=(a004*a029);
  a010=(a010-a004);
  if (res[1]!=0) res[1][35]=a010;
  if (res[2]!=0) res[2][0]=a064;
  if (res[2]!=0) res[2][1]=a082;
  if (res[2]!=0) res[2][2]=a084;
  if (res[2]!=0) res[2][3]=a060;
  if (res[2]!=0) res[2][4]=a055;
  if (res[2]!=0) res[2][5]=a083;
  if (res[2]!=0) res[2][6]=a070;
  if (res[2]!=0) res[2][7]=a036;
  if (res[2]!=0) res[2][8]=a059;
  if (res[2]!=0) res[2][9]=a031;
  if (res[2]!=0) res[2][10]=a018;
  if (res[2]!=0) res[2][11]=a088;
  if (res[2]!=0) res[2][12]=a093;
  if (res[2]!=0) res[2][13]=a013;
  if (res[2]!=0) res[2][14]=a021;
  if (res[2]!=0) res[2][15]=a040;
  if (res[2]!=0) res[2][16]=a015;
  if (res[2]!=0) res[2][17]=a010;
  a040=arg[6]? arg[6][2] : 0;
  a040=casadi_sq(a040);
  a088=casadi_sq(a070);
  a088=(a040*a088);
  a060=arg[6]? arg[6][5] : 0;
  a060=casadi_sq(a060);
  a004=casadi_sq(a012);
  a004=(a060*a004);
  a088=(a088+a004);
  a004=arg[6]? arg[6][1] : 0;
  a004=casadi_sq(a004);
  a029=casadi_sq(a065);
  a029=(a004*a029);
  a088=(a088+a029);
  a029=arg[6]? arg[6][4] : 0;
  a029=casadi_sq(a029);
  a028=casadi_sq(a093);
  a028=(a029*a028);
  a088=(a088+a028);
  a028=arg[6]? arg[6][0] : 0;
  a028=casadi_sq(a028);
  a026=casadi_sq(a064);
  a026=(a028*a026);
  a088=(a088+a026);
  a026=arg[6]? arg[6][3] : 0;
  a026=casadi_sq(a026);
  a099=casadi_sq(a031);
  a099=(a026*a099);
  a088=(a088+a099);
  if (res[3]!=0) res[3][0]=a088;
  a064=(a064*a028);
  a088=(a082*a064);
  a065=(a065*a004);
  a099=(a055*a065);
  a088=(a088-a099);
  a070=(a070*a040);
  a099=(a036*a070);
  a088=(a088+a099);
  a031=(a031*a026);
  a099=(a018*a031);
  a088=(a088+a099);
  a093=(a093*a029);
  a099=(a013*a093);
  a088=(a088+a099);
  a012=(a012*a060);
  a099=(a015*a012);
  a088=(a088-a099);
  if (res[3]!=0) res[3][1]=a088;
  a064=(a084*a064);
  a065=(a083*a065);
  a064=(a064-a065);
  a070=(a059*a070);
  a064=(a064+a070);
  a031=(a033*a031);
  a064=(a064-a031);
  a093=(a021*a093);
  a064=(a064+a093);
  a012=(a010*a012);
  a064=(a064-a012);
  if (res[3]!=0) res[3][2]=a064;
  if (res[3]!=0) res[3][3]=a088;
  a088=casadi_sq(a036);
  a088=(a040*a088);
  a012=casadi_sq(a015);
  a012=(a060*a012);
  a088=(a088+a012);
  a012=casadi_sq(a055);
  a012=(a004*a012);
  a088=(a088+a012);
  a012=casadi_sq(a013);
  a012=(a029*a012);
  a088=(a088+a012);
  a012=casadi_sq(a082);
  a012=(a028*a012);
  a088=(a088+a012);
  a012=casadi_sq(a018);
  a012=(a026*a012);
  a088=(a088+a012);
  if (res[3]!=0) res[3][4]=a088;
  a082=(a082*a084);
  a082=(a082*a028);
  a055=(a055*a083);
  a055=(a055*a004);
  a082=(a082+a055);
  a036=(a036*a059);
  a036=(a036*a040);
  a082=(a082+a036);
  a018=(a018*a033);
  a018=(a018*a026);
  a082=(a082-a018);
  a013=(a013*a021);
  a013=(a013*a029);
  a082=(a082+a013);
  a015=(a015*a010);
  a015=(a015*a060);
  a082=(a082+a015);
  if (res[3]!=0) res[3][5]=a082;
  if (res[3]!=0) res[3][6]=a064;
  if (res[3]!=0) res[3][7]=a082;
  a059=casadi_sq(a059);
  a040=(a040*a059);
  a010=casadi_sq(a010);
  a060=(a060*a010);
  a040=(a040+a060);
  a083=casadi_sq(a083);
  a004=(a004*a083);
  a040=(a040+a004);
  a021=casadi_sq(a021);
  a029=(a029*a021);
  a040=(a040+a029);
  a084=casadi_sq(a084);
  a028=(a028*a084);
  a040=(a040+a028);
  a033=casadi_sq(a033);
  a026=(a026*a033);
  a040=(a040+a026);
  if (res[3]!=0) res[3][8]=a040;
  if (res[4]!=0) res[4][0]=a048;
  if (res[4]!=0) res[4][1]=a044;
  if (res[4]!=0) res[4][2]=a063;
  a087=(a087+a095);
  a087=(a087-a027);
  a087=(a087-a035);
  if (res[5]!=0) res[5][0]=a087;
  a100=(a100+a020);
  a100=(a100+a038);
  a100=(a100-a097);
  if (res[5]!=0) res[5][1]=a100;
  a086=(a086+a030);
  a086=(a086+a092);
  if (res[5]!=0) res[5][2]=a086;
  return 0;
}

CASADI_SYMBOL_EXPORT int pseudo_measurement_standard(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int pseudo_measurement_standard_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void pseudo_measurement_standard_release(int mem) {
}

CASADI_SYMBOL_EXPORT void pseudo_measurement_standard_incref(void) {
}

CASADI_SYMBOL_EXPORT void pseudo_measurement_standard_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int pseudo_measurement_standard_n_in(void) { return 7;}

CASADI_SYMBOL_EXPORT casadi_int pseudo_measurement_standard_n_out(void) { return 6;}

CASADI_SYMBOL_EXPORT casadi_real pseudo_measurement_standard_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* pseudo_measurement_standard_name_in(casadi_int i) {
  switch (i) {
    case 0: return "nav_a";
    case 1: return "att_a";
    case 2: return "meas_a";
    case 3: return "nav_b";
    case 4: return "att_b";
    case 5: return "meas_b";
    case 6: return "sigma0";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* pseudo_measurement_standard_name_out(casadi_int i) {
  switch (i) {
    case 0: return "Z";
    case 1: return "H";
    case 2: return "M";
    case 3: return "R";
    case 4: return "p_a_ecef";
    case 5: return "p_b_ecef";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* pseudo_measurement_standard_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    case 3: return casadi_s0;
    case 4: return casadi_s0;
    case 5: return casadi_s0;
    case 6: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* pseudo_measurement_standard_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s2;
    case 2: return casadi_s3;
    case 3: return casadi_s4;
    case 4: return casadi_s0;
    case 5: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int pseudo_measurement_standard_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7;
  if (sz_res) *sz_res = 6;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int pseudo_measurement_standard_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 6*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


