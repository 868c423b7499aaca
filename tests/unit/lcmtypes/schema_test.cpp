// The generator's view of lcmtypes/*.lcm must match the files: checked against the .lcm text
// with an independent reading (regular expressions), and on hand-made definitions.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "sdlqr/lcmgen/schema.hpp"
#include "schema_error.hpp"
#include "sdlqr/lcmtypes/generated/descriptors.hpp"

namespace sdlqr::lcmgen {
namespace {

namespace fs = std::filesystem;
using lcmtypes::FieldDescriptor;
using lcmtypes::findType;
using lcmtypes::kAllTypes;
using lcmtypes::TypeDescriptor;

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path lcmDir() { return fs::path(SDLQR_SOURCE_DIR) / "lcmtypes"; }

std::vector<std::string> columnsOf(const TypeDescriptor& t) { return {t.columns, t.columns + t.num_columns}; }

TEST(LcmSchema, ImuDescriptorMatchesItsLcmFile) {
  const TypeDescriptor* imu = findType("imu_t");
  ASSERT_NE(imu, nullptr);
  ASSERT_EQ(imu->num_fields, 4u);
  EXPECT_EQ(imu->fields[0].name, "utime");
  EXPECT_EQ(imu->fields[0].unit, "us");
  EXPECT_EQ(imu->fields[2].name, "gyro");
  EXPECT_EQ(imu->fields[2].unit, "rad/s");
  EXPECT_EQ(imu->fields[2].dimensions[0].size, 3);
  EXPECT_EQ(imu->fields[3].name, "accel");
  EXPECT_EQ(imu->fields[3].unit, "m/s^2");
  const std::vector<std::string> expected = {"utime [us]",         "seq [-]",           "gyro[0] [rad/s]",
                                             "gyro[1] [rad/s]",    "gyro[2] [rad/s]",   "accel[0] [m/s^2]",
                                             "accel[1] [m/s^2]",   "accel[2] [m/s^2]"};
  EXPECT_EQ(columnsOf(*imu), expected);
}

TEST(LcmSchema, StateAndInputUnitListsAreSpreadOverTheLayout) {
  const std::vector<std::string> gains = columnsOf(*findType("gains_t"));
  auto has = [&](const std::string& column) { return std::find(gains.begin(), gains.end(), column) != gains.end(); };
  EXPECT_TRUE(has("x_lin[2] [m]"));
  EXPECT_TRUE(has("x_lin[3] [-]"));
  EXPECT_TRUE(has("x_lin[6] [-]"));
  EXPECT_TRUE(has("x_lin[7] [m/s]"));
  EXPECT_TRUE(has("u_lin[2] [rad/s]"));
  EXPECT_TRUE(has("u_lin[3] [m/s^2]"));
  EXPECT_TRUE(has("K[39] [-]"));
  const std::vector<std::string> trajectory = columnsOf(*findType("trajectory_t"));
  EXPECT_EQ(trajectory.back(), "u[num_samples][4] [rad/s, m/s^2]");
}

// An independent reading of every .lcm file: field lines are "<type> <name>[dims]; // [unit]".
TEST(LcmSchema, EveryLcmFileIsDescribedFieldForField) {
  const std::regex field_line(
      R"(^\s*(int8_t|int16_t|int32_t|int64_t|float|double|string|boolean|byte)\s+(\w+)((\[\w+\])*)\s*;\s*//\s*\[([^\]]*)\])");
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(lcmDir())) {
    if (entry.path().extension() != ".lcm") continue;
    ++files;
    const std::string type_name = entry.path().stem().string();
    const TypeDescriptor* type = findType(type_name);
    ASSERT_NE(type, nullptr) << type_name << " has no generated descriptor";
    std::istringstream text(readText(entry.path()));
    std::string line;
    size_t index = 0;
    size_t scalar_columns = 0;
    while (std::getline(text, line)) {
      std::smatch m;
      if (!std::regex_search(line, m, field_line)) continue;
      ASSERT_LT(index, type->num_fields) << type_name;
      const FieldDescriptor& f = type->fields[index++];
      EXPECT_EQ(f.type, m[1].str()) << type_name << "." << m[2];
      EXPECT_EQ(f.name, m[2].str()) << type_name;
      std::string unit = m[5].str();
      unit.erase(0, unit.find_first_not_of(' '));
      unit.erase(unit.find_last_not_of(' ') + 1);
      EXPECT_EQ(f.unit, unit) << type_name << "." << f.name;
      const std::string dims = m[3].str();
      EXPECT_EQ(f.num_dimensions, static_cast<int>(std::count(dims.begin(), dims.end(), '['))) << f.name;
      scalar_columns += f.num_dimensions == 0 ? 1 : 0;
    }
    EXPECT_EQ(index, type->num_fields) << type_name << ": field count differs from the .lcm file";
    EXPECT_GE(type->num_columns, type->num_fields) << type_name;
    EXPECT_GE(type->num_columns, scalar_columns) << type_name;
  }
  EXPECT_EQ(files, std::size(kAllTypes));
  std::cout << "[ figures  ] " << files << " .lcm files, " << std::size(kAllTypes) << " descriptors\n";
}

TEST(LcmSchema, ParsesConstantsMultiNamesAndTwoDimensions) {
  const LcmStruct s = parseLcmStruct(
      "package demo;\n"
      "/* block\n comment */\n"
      "struct pair_t {\n"
      "  int64_t utime; // [us] time\n"
      "  int64_t seq;   // [-]\n"
      "  const int8_t A = 1, B = 2;\n"
      "  int32_t n;     // [-] count\n"
      "  float a, b;    // [m] two at once\n"
      "  double grid[2][3]; // [N]\n"
      "  string names[n];   // [-]\n"
      "  double rows[n][2]; // [m, m/s]\n"
      "}\n",
      "pair_t.lcm");
  EXPECT_EQ(s.package, "demo");
  EXPECT_EQ(s.name, "pair_t");
  ASSERT_EQ(s.fields.size(), 8u);
  EXPECT_TRUE(s.hasUtimeAndSeq());
  EXPECT_EQ(s.fields[3].name, "a");
  EXPECT_EQ(s.fields[4].name, "b");
  EXPECT_EQ(s.fields[4].unit, "m");
  EXPECT_EQ(s.fields[5].fixedElementCount(), 6);
  EXPECT_TRUE(s.fields[7].hasVariableDimension());
  const std::vector<std::string> columns = csvColumns(s);
  const std::vector<std::string> expected = {"utime [us]",      "seq [-]",         "n [-]",           "a [m]",
                                             "b [m]",           "grid[0][0] [N]",  "grid[0][1] [N]",  "grid[0][2] [N]",
                                             "grid[1][0] [N]",  "grid[1][1] [N]",  "grid[1][2] [N]",  "names[n] [-]",
                                             "rows[n][2] [m, m/s]"};
  EXPECT_EQ(columns, expected);
}

TEST(LcmSchema, ReadsAnnotationsAndConstantsFromComments) {
  const LcmStruct s = parseLcmStruct(
      "package demo;\n"
      "// A demo message.\n"
      "// @plain Demo @method int twice() const\n"
      "struct demo_t {\n"
      "  int64_t utime; // [us] time @default -1\n"
      "  int8_t mode;   // [-] one of MODE_* @enum DemoMode MODE_ @default MODE_B\n"
      "  const int8_t MODE_A = 0, MODE_B = 1; // the modes\n"
      "}\n",
      "demo_t.lcm");
  EXPECT_EQ(s.comment, "A demo message.");
  EXPECT_EQ(s.annotations.find("plain")->second, "Demo");
  EXPECT_EQ(s.annotations.find("method")->second, "int twice() const");
  ASSERT_EQ(s.fields.size(), 2u);
  EXPECT_EQ(s.fields[0].comment, "[us] time");  // the unit comment without the annotations
  EXPECT_EQ(s.fields[0].annotation("default"), "-1");
  EXPECT_EQ(s.fields[1].annotation("enum"), "DemoMode MODE_");
  EXPECT_EQ(s.fields[1].annotation("default"), "MODE_B");
  EXPECT_FALSE(s.fields[1].has("as"));
  ASSERT_EQ(s.constants.size(), 2u);
  EXPECT_EQ(s.constants[1].name, "MODE_B");
  EXPECT_EQ(s.constants[1].value, "1");
  EXPECT_EQ(s.constants[1].comment, "the modes");
}

void expectSchemaError(const std::string& text, const std::string& fragment) {
  test::expectSchemaError([&] { parseLcmStruct(text, "bad.lcm"); }, fragment, text);
}

TEST(LcmSchema, RejectsWhatTheExportCannotDescribe) {
  expectSchemaError("struct a_t {\n double x; // no unit\n}\n", "[unit]");
  expectSchemaError("struct a_t {\n double x;\n}\n", "[unit]");
  expectSchemaError("struct a_t {\n double x; // []\n}\n", "empty [unit]");
  expectSchemaError("struct a_t {\n other_t x; // [-]\n}\n", "not an LCM primitive");
  expectSchemaError("struct a_t {\n double x[n]; // [-]\n}\n", "not a field declared before");
  expectSchemaError("struct a_t {\n double n; // [-]\n double x[n]; // [-]\n}\n", "integer scalar");
  expectSchemaError("struct a_t {\n double x[2][2][2]; // [-]\n}\n", "more than 2 dimensions");
  expectSchemaError("struct a_t {\n double x; // [-]\n", "missing '}'");
  expectSchemaError("package p;\n", "no struct");
}

}  // namespace
}  // namespace sdlqr::lcmgen
