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
  #define CASADI_PREFIX(ID) pseudo_measurement_paper_ ## ID
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
CASADI_SYMBOL_EXPORT void pseudo_measurement_paper_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int pseudo_measurement_paper_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int pseudo_measurement_paper_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {6, 1, 1};
static const casadi_int casadi_s2[3] = {3, 12, 1};
static const casadi_int casadi_s3[3] = {3, 6, 1};
static const casadi_int casadi_s4[3] = {3, 3, 1};

/* pseudo_measurement_paper:(nav_a[3],att_a[3],meas_a[3],nav_b[3],att_b[3],meas_b[3],sigma0[6])->(Z[3],H[3x12],M[3x6],R[3x3],p_a_ecef[3],p_b_ecef[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a000, a001, a002, a003, a004, a005, a006, a007, a008, a009, a010, a011;
  casadi_real a012, a013, a014, a015, a016, a017, a018, a019, a020, a021, a022, a023;
  casadi_real a024, a025, a026, a027, a028, a029, a030, a031, a032, a033, a034, a035;
  casadi_real a036, a037, a038, a039, a040, a041, a042, a043, a044, a045, a046, a047;
  casadi_real a048, a049, a050, a051, a052, a053, a054, a055, a056, a057, a058, a059;
  casadi_real a060, a061, a062, a063, a064, a065, a066, a067, a068, a069, a070, a071;
  casadi_real a072, a073, a074, a075, a076, a077, a078, a079, a080, a081, a082, a083;
  casadi_real a084, a085, a086, a087, a088, a089, a090, a091, a092, a093, a094, a095;
  casadi_real a096, a097, a098, a099, a100, a101, a102, a103;
  a000=arg[0]? arg[0][1] : 0;
  a001=cos(a000);
  a002=arg[0]? arg[0][0] : 0;
  a003=cos(a002);
  a004=arg[0]? arg[0][2] : 0;
  a005=6378137.;
  a006=1.;
  a007=-6.6943799901413173e-03;
  a002=sin(a002);
  a008=casadi_sq(a002);
  a009=(a007*a008);
  a009=(a006+a009);
  a009=sqrt(a009);
  a010=(a005/a009);
  a010=(a004+a010);
  a010=(a003*a010);
  a011=(a001*a010);
  a012=arg[1]? arg[1][1] : 0;
  a013=sin(a012);
  a014=arg[2]? arg[2][2] : 0;
  a015=cos(a014);
  a016=arg[2]? arg[2][1] : 0;
  a017=cos(a016);
  a018=(a015*a017);
  a019=(a013*a018);
  a020=arg[2]? arg[2][0] : 0;
  a021=(a019*a020);
  a014=sin(a014);
  a022=(a014*a020);
  a023=arg[1]? arg[1][2] : 0;
  a024=cos(a023);
  a012=cos(a012);
  a025=(a024*a012);
  a026=(a022*a025);
  a026=(a021+a026);
  a016=sin(a016);
  a027=(a015*a016);
  a028=(a027*a020);
  a023=sin(a023);
  a029=(a023*a012);
  a030=(a028*a029);
  a026=(a026-a030);
  a030=1.3524414300892025e-02;
  a008=(a030*a008);
  a008=(a006+a008);
  a008=sqrt(a008);
  a031=(a003/a008);
  a032=(a026*a031);
  a033=(a001*a032);
  a011=(a011+a033);
  a033=arg[1]? arg[1][0] : 0;
  a034=cos(a033);
  a035=(a012*a018);
  a036=(a035*a020);
  a037=(a034*a036);
  a033=sin(a033);
  a038=(a023*a033);
  a039=(a034*a024);
  a040=(a013*a039);
  a040=(a038+a040);
  a041=(a014*a040);
  a042=(a041*a020);
  a037=(a037-a042);
  a042=(a034*a023);
  a043=(a042*a013);
  a044=(a024*a033);
  a043=(a043-a044);
  a045=(a027*a043);
  a046=(a045*a020);
  a037=(a037+a046);
  a046=(a001*a037);
  a047=-1.3343945256830230e-02;
  a048=casadi_sq(a003);
  a048=(a047*a048);
  a048=(a006+a048);
  a048=sqrt(a048);
  a048=(a002/a048);
  a049=(a046*a048);
  a011=(a011-a049);
  a049=(a033*a036);
  a050=(a013*a044);
  a050=(a050-a042);
  a051=(a050*a014);
  a052=(a051*a020);
  a052=(a049-a052);
  a053=(a013*a038);
  a053=(a039+a053);
  a054=(a053*a027);
  a055=(a054*a020);
  a052=(a052+a055);
  a000=sin(a000);
  a055=(a052*a000);
  a011=(a011-a055);
  a055=arg[4]? arg[4][1] : 0;
  a056=cos(a055);
  a057=arg[5]? arg[5][2] : 0;
  a058=cos(a057);
  a059=arg[5]? arg[5][1] : 0;
  a060=cos(a059);
  a061=(a058*a060);
  a062=(a056*a061);
  a063=arg[5]? arg[5][0] : 0;
  a064=(a062*a063);
  a065=arg[4]? arg[4][0] : 0;
  a066=sin(a065);
  a067=(a064*a066);
  a065=cos(a065);
  a068=arg[4]? arg[4][2] : 0;
  a069=cos(a068);
  a070=(a065*a069);
  a068=sin(a068);
  a071=(a068*a066);
  a055=sin(a055);
  a072=(a071*a055);
  a072=(a070+a072);
  a059=sin(a059);
  a073=(a058*a059);
  a074=(a072*a073);
  a075=(a074*a063);
  a075=(a067+a075);
  a076=(a069*a066);
  a077=(a055*a076);
  a078=(a065*a068);
  a077=(a077-a078);
  a057=sin(a057);
  a079=(a077*a057);
  a080=(a079*a063);
  a075=(a075-a080);
  a080=arg[3]? arg[3][1] : 0;
  a081=sin(a080);
  a082=(a075*a081);
  a083=(a011+a082);
  a080=cos(a080);
  a084=(a065*a064);
  a085=(a070*a055);
  a071=(a071+a085);
  a085=(a071*a057);
  a086=(a085*a063);
  a084=(a084-a086);
  a086=(a078*a055);
  a086=(a086-a076);
  a087=(a073*a086);
  a088=(a087*a063);
  a084=(a084+a088);
  a088=(a080*a084);
  a089=arg[3]? arg[3][0] : 0;
  a090=sin(a089);
  a089=cos(a089);
  a091=casadi_sq(a089);
  a047=(a047*a091);
  a047=(a006+a047);
  a047=sqrt(a047);
  a091=(a090/a047);
  a092=(a088*a091);
  a083=(a083+a092);
  a093=arg[3]? arg[3][2] : 0;
  a094=casadi_sq(a090);
  a007=(a007*a094);
  a007=(a006+a007);
  a007=sqrt(a007);
  a005=(a005/a007);
  a005=(a093+a005);
  a005=(a089*a005);
  a095=(a080*a005);
  a083=(a083-a095);
  a096=(a061*a055);
  a097=(a096*a063);
  a098=(a057*a063);
  a099=(a056*a069);
  a100=(a098*a099);
  a100=(a097+a100);
  a101=(a073*a063);
  a102=(a068*a056);
  a103=(a101*a102);
  a100=(a100-a103);
  a030=(a030*a094);
  a006=(a006+a030);
  a006=sqrt(a006);
  a089=(a089/a006);
  a006=(a100*a089);
  a030=(a080*a006);
  a083=(a083-a030);
  if (res[0]!=0) res[0][0]=a083;
  a083=(a081*a084);
  a094=(a083*a091);
  a052=(a052*a001);
  a010=(a000*a010);
  a052=(a052+a010);
  a032=(a000*a032);
  a052=(a052+a032);
  a032=(a000*a037);
  a010=(a048*a032);
  a052=(a052-a010);
  a010=(a094+a052);
  a075=(a075*a080);
  a010=(a010-a075);
  a005=(a081*a005);
  a010=(a010-a005);
  a006=(a081*a006);
  a010=(a010-a006);
  if (res[0]!=0) res[0][1]=a010;
  a026=(a048*a026);
  a010=6.3354393272928204e+06;
  a009=(a010/a009);
  a004=(a004+a009);
  a002=(a002*a004);
  a026=(a026+a002);
  a037=(a031*a037);
  a026=(a026+a037);
  a010=(a010/a007);
  a093=(a093+a010);
  a093=(a090*a093);
  a010=(a026-a093);
  a100=(a091*a100);
  a010=(a010-a100);
  a084=(a084*a089);
  a010=(a010-a084);
  if (res[0]!=0) res[0][2]=a010;
  a010=(a050*a022);
  a010=(a010-a049);
  a049=(a053*a028);
  a010=(a010-a049);
  a049=(a048*a001);
  a007=(a010*a049);
  a032=(a032+a007);
  a032=(-a032);
  if (res[1]!=0) res[1][0]=a032;
  a032=(a048*a000);
  a007=(a010*a032);
  a046=(a046-a007);
  if (res[1]!=0) res[1][1]=a046;
  a010=(a010*a031);
  if (res[1]!=0) res[1][2]=a010;
  a010=(a013*a028);
  a046=(a010*a023);
  a046=(a036+a046);
  a013=(a013*a022);
  a024=(a013*a024);
  a046=(a046-a024);
  a024=(a046*a001);
  a024=(a024*a003);
  a024=(a024/a008);
  a042=(a042*a015);
  a042=(a042*a016);
  a042=(a042*a012);
  a042=(a042*a020);
  a007=(a012*a022);
  a039=(a007*a039);
  a037=(a034*a021);
  a039=(a039+a037);
  a042=(a042-a039);
  a039=(a049*a042);
  a038=(a038*a015);
  a038=(a038*a016);
  a038=(a038*a012);
  a038=(a038*a020);
  a044=(a007*a044);
  a021=(a033*a021);
  a044=(a044+a021);
  a038=(a038-a044);
  a044=(a038*a000);
  a039=(a039+a044);
  a024=(a024-a039);
  if (res[1]!=0) res[1][3]=a024;
  a038=(a038*a001);
  a024=(a000*a031);
  a039=(a046*a024);
  a038=(a038+a039);
  a039=(a042*a032);
  a038=(a038-a039);
  if (res[1]!=0) res[1][4]=a038;
  a046=(a048*a046);
  a042=(a042*a031);
  a046=(a046+a042);
  if (res[1]!=0) res[1][5]=a046;
  a046=(a022*a043);
  a042=(a028*a040);
  a042=(a046+a042);
  a038=(a049*a042);
  a039=(a053*a022);
  a044=(a050*a028);
  a044=(a039+a044);
  a021=(a044*a000);
  a038=(a038+a021);
  a022=(a022*a029);
  a021=(a025*a028);
  a021=(a022+a021);
  a037=(a021*a001);
  a037=(a037*a003);
  a037=(a037/a008);
  a038=(a038+a037);
  a038=(-a038);
  if (res[1]!=0) res[1][6]=a038;
  a044=(a044*a001);
  a038=(a021*a024);
  a044=(a044-a038);
  a038=(a042*a032);
  a044=(a044-a038);
  if (res[1]!=0) res[1][7]=a044;
  a042=(a042*a031);
  a021=(a048*a021);
  a042=(a042-a021);
  if (res[1]!=0) res[1][8]=a042;
  a014=(a014*a025);
  a019=(a019+a014);
  a027=(a027*a029);
  a019=(a019-a027);
  a027=(a019*a001);
  a027=(a027*a003);
  a027=(a027/a008);
  a045=(a045-a041);
  a041=(a034*a035);
  a045=(a045+a041);
  a041=(a049*a045);
  a054=(a054-a051);
  a035=(a033*a035);
  a054=(a054+a035);
  a035=(a054*a000);
  a041=(a041+a035);
  a027=(a027-a041);
  if (res[1]!=0) res[1][9]=a027;
  a054=(a054*a001);
  a041=(a019*a024);
  a054=(a054+a041);
  a041=(a045*a032);
  a054=(a054-a041);
  if (res[1]!=0) res[1][10]=a054;
  a019=(a048*a019);
  a045=(a045*a031);
  a019=(a019+a045);
  if (res[1]!=0) res[1][11]=a019;
  a018=(a018*a020);
  a043=(a018*a043);
  a012=(a012*a028);
  a028=(a012*a034);
  a043=(a043-a028);
  a028=(a049*a043);
  a018=(a018*a053);
  a012=(a012*a033);
  a018=(a018-a012);
  a012=(a018*a000);
  a028=(a028+a012);
  a023=(a023*a036);
  a010=(a010+a023);
  a023=(a010*a001);
  a023=(a023*a003);
  a023=(a023/a008);
  a028=(a028+a023);
  a023=(-a028);
  if (res[1]!=0) res[1][12]=a023;
  a018=(a018*a001);
  a036=(a010*a024);
  a018=(a018-a036);
  a036=(a043*a032);
  a018=(a018-a036);
  if (res[1]!=0) res[1][13]=a018;
  a043=(a043*a031);
  a010=(a048*a010);
  a043=(a043-a010);
  if (res[1]!=0) res[1][14]=a043;
  a046=(a046*a016);
  a007=(a007*a017);
  a034=(a007*a034);
  a046=(a046+a034);
  a040=(a015*a040);
  a040=(a040*a020);
  a046=(a046+a040);
  a049=(a049*a046);
  a039=(a039*a016);
  a007=(a007*a033);
  a039=(a039+a007);
  a050=(a050*a015);
  a050=(a050*a020);
  a039=(a039+a050);
  a000=(a039*a000);
  a049=(a049+a000);
  a022=(a022*a016);
  a013=(a013*a017);
  a022=(a022-a013);
  a015=(a015*a025);
  a015=(a015*a020);
  a022=(a022+a015);
  a015=(a022*a001);
  a015=(a015*a003);
  a015=(a015/a008);
  a049=(a049+a015);
  if (res[1]!=0) res[1][15]=a049;
  a024=(a022*a024);
  a039=(a039*a001);
  a024=(a024-a039);
  a032=(a046*a032);
  a024=(a024+a032);
  if (res[1]!=0) res[1][16]=a024;
  a048=(a048*a022);
  a046=(a046*a031);
  a048=(a048-a046);
  if (res[1]!=0) res[1][17]=a048;
  a046=(a098*a077);
  a046=(a046-a067);
  a067=(a072*a101);
  a046=(a046-a067);
  a067=(a080*a091);
  a031=(a046*a067);
  a083=(a083+a031);
  if (res[1]!=0) res[1][18]=a083;
  a083=(a046*a081);
  a083=(a083*a090);
  a083=(a083/a047);
  a083=(a083-a088);
  if (res[1]!=0) res[1][19]=a083;
  a046=(a046*a089);
  a046=(-a046);
  if (res[1]!=0) res[1][20]=a046;
  a078=(a078*a058);
  a078=(a078*a059);
  a078=(a078*a056);
  a078=(a078*a063);
  a046=(a065*a097);
  a083=(a056*a098);
  a070=(a070*a083);
  a046=(a046+a070);
  a078=(a078-a046);
  a046=(a067*a078);
  a070=(a068*a058);
  a070=(a070*a059);
  a070=(a070*a056);
  a070=(a070*a066);
  a070=(a070*a063);
  a076=(a083*a076);
  a097=(a066*a097);
  a076=(a076+a097);
  a070=(a070-a076);
  a076=(a070*a081);
  a046=(a046+a076);
  a076=(a055*a101);
  a097=(a068*a076);
  a097=(a064+a097);
  a055=(a055*a098);
  a069=(a055*a069);
  a097=(a097-a069);
  a069=(a080*a089);
  a088=(a097*a069);
  a046=(a046-a088);
  if (res[1]!=0) res[1][21]=a046;
  a046=(a078*a081);
  a046=(a046*a090);
  a046=(a046/a047);
  a070=(a070*a080);
  a088=(a081*a089);
  a031=(a097*a088);
  a070=(a070+a031);
  a046=(a046-a070);
  if (res[1]!=0) res[1][22]=a046;
  a078=(a078*a089);
  a097=(a097*a091);
  a078=(a078+a097);
  a078=(-a078);
  if (res[1]!=0) res[1][23]=a078;
  a078=(a086*a098);
  a097=(a071*a101);
  a097=(a078+a097);
  a046=(a067*a097);
  a070=(a072*a098);
  a031=(a101*a077);
  a031=(a070+a031);
  a022=(a031*a081);
  a046=(a046+a022);
  a098=(a098*a102);
  a022=(a099*a101);
  a022=(a098+a022);
  a032=(a069*a022);
  a046=(a046+a032);
  if (res[1]!=0) res[1][24]=a046;
  a046=(a022*a088);
  a031=(a031*a080);
  a046=(a046-a031);
  a031=(a097*a081);
  a031=(a031*a090);
  a031=(a031/a047);
  a046=(a046+a031);
  if (res[1]!=0) res[1][25]=a046;
  a022=(a022*a091);
  a097=(a097*a089);
  a022=(a022-a097);
  if (res[1]!=0) res[1][26]=a022;
  a087=(a087-a085);
  a085=(a065*a062);
  a087=(a087+a085);
  a085=(a067*a087);
  a074=(a074-a079);
  a062=(a062*a066);
  a074=(a074+a062);
  a062=(a074*a081);
  a085=(a085+a062);
  a057=(a099*a057);
  a096=(a096+a057);
  a073=(a073*a102);
  a096=(a096-a073);
  a073=(a069*a096);
  a085=(a085-a073);
  if (res[1]!=0) res[1][27]=a085;
  a073=(a087*a081);
  a073=(a073*a090);
  a073=(a073/a047);
  a074=(a074*a080);
  a102=(a096*a088);
  a074=(a074+a102);
  a073=(a073-a074);
  if (res[1]!=0) res[1][28]=a073;
  a087=(a087*a089);
  a096=(a096*a091);
  a087=(a087+a096);
  a096=(-a087);
  if (res[1]!=0) res[1][29]=a096;
  a061=(a061*a063);
  a086=(a061*a086);
  a056=(a056*a101);
  a101=(a065*a056);
  a086=(a086-a101);
  a101=(a067*a086);
  a072=(a072*a061);
  a056=(a056*a066);
  a072=(a072-a056);
  a056=(a072*a081);
  a101=(a101+a056);
  a068=(a068*a064);
  a076=(a076+a068);
  a068=(a069*a076);
  a101=(a101+a068);
  if (res[1]!=0) res[1][30]=a101;
  a068=(a076*a088);
  a072=(a072*a080);
  a068=(a068-a072);
  a072=(a086*a081);
  a072=(a072*a090);
  a072=(a072/a047);
  a068=(a068+a072);
  if (res[1]!=0) res[1][31]=a068;
  a076=(a076*a091);
  a086=(a086*a089);
  a076=(a076-a086);
  if (res[1]!=0) res[1][32]=a076;
  a083=(a083*a060);
  a065=(a065*a083);
  a078=(a059*a078);
  a065=(a065+a078);
  a071=(a058*a071);
  a071=(a071*a063);
  a065=(a065+a071);
  a067=(a067*a065);
  a070=(a059*a070);
  a083=(a083*a066);
  a070=(a070+a083);
  a077=(a058*a077);
  a077=(a077*a063);
  a070=(a070+a077);
  a077=(a070*a081);
  a067=(a067+a077);
  a059=(a059*a098);
  a055=(a055*a060);
  a059=(a059-a055);
  a058=(a058*a099);
  a058=(a058*a063);
  a059=(a059+a058);
  a069=(a069*a059);
  a067=(a067+a069);
  a069=(-a067);
  if (res[1]!=0) res[1][33]=a069;
  a070=(a070*a080);
  a088=(a059*a088);
  a070=(a070-a088);
  a081=(a065*a081);
  a081=(a081*a090);
  a081=(a081/a047);
  a070=(a070-a081);
  if (res[1]!=0) res[1][34]=a070;
  a065=(a065*a089);
  a059=(a059*a091);
  a065=(a065-a059);
  if (res[1]!=0) res[1][35]=a065;
  if (res[2]!=0) res[2][0]=a027;
  if (res[2]!=0) res[2][1]=a054;
  if (res[2]!=0) res[2][2]=a019;
  if (res[2]!=0) res[2][3]=a023;
  if (res[2]!=0) res[2][4]=a018;
  if (res[2]!=0) res[2][5]=a043;
  if (res[2]!=0) res[2][6]=a049;
  if (res[2]!=0) res[2][7]=a024;
  if (res[2]!=0) res[2][8]=a048;
  if (res[2]!=0) res[2][9]=a085;
  if (res[2]!=0) res[2][10]=a073;
  if (res[2]!=0) res[2][11]=a096;
  if (res[2]!=0) res[2][12]=a101;
  if (res[2]!=0) res[2][13]=a068;
  if (res[2]!=0) res[2][14]=a076;
  if (res[2]!=0) res[2][15]=a069;
  if (res[2]!=0) res[2][16]=a070;
  if (res[2]!=0) res[2][17]=a065;
  a069=arg[6]? arg[6][2] : 0;
  a069=casadi_sq(a069);
  a096=casadi_sq(a049);
  a096=(a069*a096);
  a023=arg[6]? arg[6][5] : 0;
  a023=casadi_sq(a023);
  a059=casadi_sq(a067);
  a059=(a023*a059);
  a096=(a096+a059);
  a059=arg[6]? arg[6][1] : 0;
  a059=casadi_sq(a059);
  a091=casadi_sq(a028);
  a091=(a059*a091);
  a096=(a096+a091);
  a091=arg[6]? arg[6][4] : 0;
  a091=casadi_sq(a091);
  a089=casadi_sq(a101);
  a089=(a091*a089);
  a096=(a096+a089);
  a089=arg[6]? arg[6][0] : 0;
  a089=casadi_sq(a089);
  a081=casadi_sq(a027);
  a081=(a089*a081);
  a096=(a096+a081);
  a081=arg[6]? arg[6][3] : 0;
  a081=casadi_sq(a081);
  a047=casadi_sq(a085);
  a047=(a081*a047);
  a096=(a096+a047);
  if (res[3]!=0) res[3][0]=a096;
  a027=(a027*a089);
  a096=(a054*a027);
  a028=(a028*a059);
  a047=(a018*a028);
  a096=(a096-a047);
  a049=(a049*a069);
  a047=(a024*a049);
  a096=(a096+a047);
  a085=(a085*a081);
  a047=(a073*a085);
  a096=(a096+a047);
  a101=(a101*a091);
  a047=(a068*a101);
  a096=(a096+a047);
  a067=(a067*a023);
  a047=(a070*a067);
  a096=(a096-a047);
  if (res[3]!=0) res[3][1]=a096;
  a027=(a019*a027);
  a028=(a043*a028);
  a027=(a027-a028);
  a049=(a048*a049);
  a027=(a027+a049);
  a085=(a087*a085);
  a027=(a027-a085);
  a101=(a076*a101);
  a027=(a027+a101);
  a067=(a065*a067);
  a027=(a027-a067);
  if (res[3]!=0) res[3][2]=a027;
  if (res[3]!=0) res[3][3]=a096;
  a096=casadi_sq(a024);
  a096=(a069*a096);
  a067=casadi_sq(a070);
  a067=(a023*a067);
  a096=(a096+a067);
  a067=casadi_sq(a018);
  a067=(a059*a067);
  a096=(a096+a067);
  a067=casadi_sq(a068);
  a067=(a091*a067);
  a096=(a096+a067);
  a067=casadi_sq(a054);
  a067=(a089*a067);
  a096=(a096+a067);
  a067=casadi_sq(a073);
  a067=(a081*a067);
  a096=(a096+a067);
  if (res[3]!=0) res[3][4]=a096;
  a054=(a054*a019);
  a054=(a054*a089);
  a018=(a018*a043);
  a018=(a018*a059);
  a054=(a054+a018);
  a024=(a024*a048);
  a024=(a024*a069);
  a054=(a054+a024);
  a073=(a073*a087);
  a073=(a073*a081);
  a054=(a054-a073);
  a068=(a068*a076);
  a068=(a068*a091);
  a054=(a054+a068);
  a070=(a070*a065);
  a070=(a070*a023);
  a054=(a054+a070);
  if (res[3]!=0) res[3][5]=a054;
  if (res[3]!=0) res[3][6]=a027;
  if (res[3]!=0) res[3][7]=a054;
  a048=casadi_sq(a048);
  a069=(a069*a048);
  a065=casadi_sq(a065);
  a023=(a023*a065);
  a069=(a069+a023);
  a043=casadi_sq(a043);
  a059=(a059*a043);
  a069=(a069+a059);
  a076=casadi_sq(a076);
  a091=(a091*a076);
  a069=(a069+a091);
  a019=casadi_sq(a019);
  a089=(a089*a019);
  a069=(a069+a089);
  a087=casadi_sq(a087);
  a081=(a081*a087);
  a069=(a069+a081);
  if (res[3]!=0) res[3][8]=a069;
  if (res[4]!=0) res[4][0]=a011;
  if (res[4]!=0) res[4][1]=a052;
  if (res[4]!=0) res[4][2]=a026;
  a095=(a095+a030);
  a095=(a095-a082);
  a095=(a095-a092);
  if (res[5]!=0) res[5][0]=a095;
  a075=(a075+a005);
  a075=(a075+a006);
  a075=(a075-a094);
  if (res[5]!=0) res[5][1]=a075;
  a093=(a093+a100);
  a093=(a093+a084);
  if (res[5]!=0) res[5][2]=a093;
  return 0;
}

CASADI_SYMBOL_EXPORT int pseudo_measurement_paper(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int pseudo_measurement_paper_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void pseudo_measurement_paper_release(int mem) {
}

CASADI_SYMBOL_EXPORT void pseudo_measurement_paper_incref(void) {
}

CASADI_SYMBOL_EXPORT void pseudo_measurement_paper_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int pseudo_measurement_paper_n_in(void) { return 7;}

CASADI_SYMBOL_EXPORT casadi_int pseudo_measurement_paper_n_out(void) { return 6;}

CASADI_SYMBOL_EXPORT casadi_real pseudo_measurement_paper_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* pseudo_measurement_paper_name_in(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const char* pseudo_measurement_paper_name_out(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const casadi_int* pseudo_measurement_paper_sparsity_in(casadi_int i) {
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

CASADI_SYMBOL_EXPORT const casadi_int* pseudo_measurement_paper_sparsity_out(casadi_int i) {
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

CASADI_SYMBOL_EXPORT int pseudo_measurement_paper_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7;
  if (sz_res) *sz_res = 6;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int pseudo_measurement_paper_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 6*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}


