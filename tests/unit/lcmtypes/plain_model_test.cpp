// The plain structs and conversions the generator writes for annotated .lcm text: member
// types, initial values, enums, row groups, and a one-line error naming file and line for every
// annotation it cannot honour.

#include <gtest/gtest.h>

#include "schema_error.hpp"
#include "sdlqr/lcmgen/emit.hpp"

namespace sdlqr::lcmgen {
namespace {

const char* const kDemo =
    "package demo;\n"
    "// A demo message.\n"
    "// @plain Demo\n"
    "struct demo_t {\n"
    "  int64_t utime;       // [us] time\n"
    "  int64_t seq;         // [-] sequence @default -1\n"
    "  double  p[3];        // [m] position\n"
    "  double  q[4];        // [-] attitude @as Quat\n"
    "  double  k[40];       // [-] gain @as GainMatrix\n"
    "  int32_t grid[2][3];  // [-] a table\n"
    "  int8_t  on;          // [-] 1 when on @as bool @default true\n"
    "  int8_t  mode;        // [-] MODE_* @enum DemoMode MODE_ @default MODE_B\n"
    "  int32_t n;           // [-] rows @rows rows DemoRow\n"
    "  double  t[n];        // [s] time of each row\n"
    "  double  x[n][10];    // [m, -, m/s] state of each row\n"
    "  string  names[n];    // [-] name of each row @row name\n"
    "  int32_t m;           // [-] count of values\n"
    "  float   values[m];   // [V] values\n"
    "  const int8_t MODE_A = 0;\n"
    "  const int8_t MODE_B = 1;  // the second\n"
    "}\n";

std::string plainOf(const std::string& lcm) {
  const std::vector<LcmStruct> types = {parseLcmStruct(lcm, "demo_t.lcm")};
  return emitPlainHeader(buildPlainModel(types), "test");
}

void expectHas(const std::string& text, const std::string& fragment) {
  EXPECT_NE(text.find(fragment), std::string::npos) << "missing: " << fragment << "\nin:\n" << text;
}

TEST(PlainModel, MembersTakeTheTypesAndInitialValuesTheAnnotationsName) {
  const std::string plain = plainOf(kDemo);
  expectHas(plain, "namespace demo {");
  expectHas(plain, "using ::sdlqr::Vec3;");  // another package names the math aliases
  expectHas(plain, "enum class DemoMode : int8_t {\n  kA = 0,\n  kB = 1,  // the second\n};");
  expectHas(plain, "struct DemoRow {\n  double t = 0.0;  // [s] time of each row\n"
                   "  State x = State::Zero();  // [m, -, m/s] state of each row\n"
                   "  std::string name;  // [-] name of each row\n};");
  expectHas(plain, "// demo_t: A demo message.\nstruct Demo {");
  expectHas(plain, "  int64_t seq = -1;  // [-] sequence\n");
  expectHas(plain, "  Vec3 p = Vec3::Zero();  // [m] position\n");
  expectHas(plain, "  Quat q = identityQuat();");
  expectHas(plain, "  GainMatrix k = GainMatrix::Zero();");
  expectHas(plain, "  std::array<std::array<int32_t, 3>, 2> grid = {};");
  expectHas(plain, "  bool on = true;");
  expectHas(plain, "  DemoMode mode = DemoMode::kB;");
  expectHas(plain, "  std::vector<DemoRow> rows;  // n rows of t, x, names; [-] rows\n");
  expectHas(plain, "  std::vector<float> values;  // [V] values\n");
  EXPECT_EQ(plain.find(" n = "), std::string::npos) << "a length field is no plain member";
  EXPECT_EQ(plain.find(" m = "), std::string::npos) << "a length field is no plain member";
}

TEST(PlainModel, ConversionsCopyEveryMemberBothWays) {
  const std::vector<LcmStruct> types = {parseLcmStruct(kDemo, "demo_t.lcm")};
  const std::string convert = emitConvertHeader(buildPlainModel(types), "test");
  expectHas(convert, "inline Demo fromLcm(const ::demo::demo_t& m) {");
  expectHas(convert, "inline ::demo::demo_t toLcm(const Demo& s) {");
  expectHas(convert, "for (int i0 = 0; i0 < 40; ++i0) s.k(i0 / 10, i0 % 10) = m.k[i0];");  // row-major
  expectHas(convert, "for (int i0 = 0; i0 < 40; ++i0) m.k[i0] = s.k(i0 / 10, i0 % 10);");
  expectHas(convert, "s.grid[i0][i1] = m.grid[i0][i1];");
  expectHas(convert, "s.on = m.on != 0;");
  expectHas(convert, "m.on = s.on ? 1 : 0;");
  expectHas(convert, "s.mode = static_cast<DemoMode>(m.mode);");
  expectHas(convert, "s.rows.resize(::sdlqr::lcmtypes::rowCount(m.n, m.t.size(), m.x.size(), m.names.size()));");
  expectHas(convert, "row.name = m.names[i0];");
  expectHas(convert, "m.n = static_cast<int32_t>(s.rows.size());");
  expectHas(convert, "m.x[i0].resize(10);");
  expectHas(convert, "m.m = static_cast<int32_t>(s.values.size());");
  expectHas(convert, "s.values.resize(::sdlqr::lcmtypes::rowCount(m.m, m.values.size()));");
}

void expectModelError(const std::string& text, const std::string& fragment) {
  test::expectSchemaError(
      [&] {
        const std::vector<LcmStruct> types = {parseLcmStruct(text, "bad.lcm")};
        buildPlainModel(types);
      },
      fragment, text);
}

void expectFieldsError(const std::string& fields, const std::string& fragment) {
  expectModelError("package p;\n// @plain P\nstruct p_t {\n" + fields + "}\n", fragment);
}

TEST(PlainModel, RefusesAnnotationsItCannotHonour) {
  expectFieldsError(" double a[3]; // [-] @as Quat\n", "holds 4 numbers");
  expectFieldsError(" double a[4]; // [-] @as Matrix7\n", "not one of");
  expectFieldsError(" int32_t a[3]; // [-] @as Vec3\n", "only double arrays");
  expectFieldsError(" double a; // [-] @as Vec3\n", "only @as bool");
  expectFieldsError(" int32_t a; // [-] @as bool\n", "@as bool needs an int8_t");
  expectFieldsError(" int8_t a; // [-] @enum Nowhere\n", "declared by no field");
  expectFieldsError(" int8_t a; // [-] @enum E X_\n", "no constant starts with X_");
  expectFieldsError(" int8_t a; // [-] @enum E A_ @default B_ONE\n const int8_t A_ONE = 1;\n", "not a constant of enum E");
  expectFieldsError(" int32_t a; // [-] @flags F_\n", "no constant starts with F_");
  expectFieldsError(" int32_t n; // [-]\n double a[n]; // [-]\n double b[n]; // [-]\n", "add @rows");
  expectFieldsError(" int32_t n; // [-] @rows r\n double a[n]; // [-]\n", "@rows needs");
  expectFieldsError(" int32_t n; // [-]\n double a[2][n]; // [-]\n", "only the first dimension may be variable");
  expectModelError("package p;\nstruct p_t {\n double a; // [-]\n}\n", "needs @plain");
}

TEST(PlainModel, ConstantNamesAreCamelCase) {
  EXPECT_EQ(constantName("VIO_TIMEOUT"), "kVioTimeout");
  EXPECT_EQ(constantName("OK"), "kOk");
}

}  // namespace
}  // namespace sdlqr::lcmgen
