// CSV and JSON cells as the export writes them must read back to the very same values.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

#include "sdlqr/tables/csv.hpp"
#include "sdlqr/tables/json_document.hpp"

namespace sdlqr::tables {
namespace {

uint64_t bitsOf(double v) {
  uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof v);
  return bits;
}

// The cells of the first record of a CSV text; a failure naming the reader's error when it has none.
std::vector<std::string> firstRecordOf(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> cells;
  std::string error;
  EXPECT_TRUE(readCsvRecord(in, &cells, &error)) << error;
  return cells;
}

TEST(Csv, DoublesRoundTripBitForBit) {
  std::mt19937_64 rng(7);
  std::vector<double> values = {0.1, -0.0, 1e-320, std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::infinity(), 9.81, 1.0 / 3.0};
  while (values.size() < 20000) {
    const uint64_t bits = rng();
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isnan(v)) values.push_back(v);
  }
  std::ostringstream out;
  CsvWriter writer(out);
  for (double v : values) {
    writer.real(v);
    writer.endRow();
  }
  std::istringstream in(out.str());
  std::vector<std::string> cells;
  std::string error;
  for (double v : values) {
    ASSERT_TRUE(readCsvRecord(in, &cells, &error)) << error;
    ASSERT_EQ(cells.size(), 1u);
    double back = 0.0;
    ASSERT_TRUE(parseValue(cells[0], back)) << cells[0];
    ASSERT_EQ(bitsOf(back), bitsOf(v)) << cells[0];
  }
  EXPECT_FALSE(readCsvRecord(in, &cells, &error));
  EXPECT_EQ(writer.rows(), static_cast<int64_t>(values.size()));
}

TEST(Csv, NanAndIntegersRoundTrip) {
  std::ostringstream out;
  CsvWriter writer(out);
  writer.real(std::numeric_limits<double>::quiet_NaN());
  writer.integer(std::numeric_limits<int64_t>::min());
  writer.integer(std::numeric_limits<int64_t>::max());
  writer.real32(0.1f);
  writer.endRow();
  const std::vector<std::string> cells = firstRecordOf(out.str());
  ASSERT_EQ(cells.size(), 4u);
  double nan = 0.0;
  ASSERT_TRUE(parseValue(cells[0], nan));
  EXPECT_TRUE(std::isnan(nan));
  int64_t low = 0;
  int64_t high = 0;
  ASSERT_TRUE(parseValue(cells[1], low));
  ASSERT_TRUE(parseValue(cells[2], high));
  EXPECT_EQ(low, std::numeric_limits<int64_t>::min());
  EXPECT_EQ(high, std::numeric_limits<int64_t>::max());
  float f = 0.0f;
  ASSERT_TRUE(parseValue(cells[3], f));
  EXPECT_EQ(f, 0.1f);
  int8_t small = 0;
  EXPECT_FALSE(parseValue("128", small));
  EXPECT_FALSE(parseValue("12x", small));
  EXPECT_FALSE(parseValue("", small));
}

TEST(Csv, StringsAreQuotedAndEscaped) {
  const std::vector<std::string> texts = {"", "plain", "a,b", "say \"hi\"", "two\nlines", "cr\r", "\r\n", " lead"};
  std::ostringstream out;
  CsvWriter writer(out);
  writer.name("name [unit]");
  writer.name("x[num][10] [m, -, m/s]");
  writer.endRow();
  for (const std::string& t : texts) writer.text(t);
  writer.endRow();
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')), "name [unit],\"x[num][10] [m, -, m/s]\"");
  std::istringstream in(out.str());
  std::vector<std::string> cells;
  std::string error;
  ASSERT_TRUE(readCsvRecord(in, &cells, &error));
  EXPECT_EQ(columnName(cells[1]), "x[num][10]");
  EXPECT_EQ(columnUnit(cells[1]), "m, -, m/s");
  EXPECT_EQ(columnUnit(cells[0]), "unit");
  ASSERT_TRUE(readCsvRecord(in, &cells, &error)) << error;
  EXPECT_EQ(cells, texts);
}

TEST(Csv, VariableArraysBecomeOneJsonCell) {
  std::ostringstream out;
  CsvWriter writer(out);
  writer.integer(2);
  writer.beginArray();
  writer.beginArray();
  writer.real(0.5);
  writer.real(std::numeric_limits<double>::infinity());
  writer.endArray();
  writer.beginArray();
  writer.real(std::numeric_limits<double>::quiet_NaN());
  writer.real(-2.0);
  writer.endArray();
  writer.endArray();
  writer.beginArray();
  writer.text("reject.nan");
  writer.text("quote\" comma, newline\n");
  writer.endArray();
  writer.beginArray();
  writer.endArray();
  writer.endRow();

  const std::vector<std::string> cells = firstRecordOf(out.str());
  ASSERT_EQ(cells.size(), 4u);
  EXPECT_EQ(cells[1], "[[0.5,Infinity],[NaN,-2]]");
  std::string error;
  JsonDocument grid;
  ASSERT_TRUE(parseJson(cells[1], &grid, &error)) << error;
  ASSERT_TRUE(checkArray(grid, 2, "grid", &error));
  EXPECT_EQ(grid[0][0].get<double>(), 0.5);
  EXPECT_TRUE(std::isinf(grid[0][1].get<double>()));
  EXPECT_GT(grid[0][1].get<double>(), 0.0);
  EXPECT_TRUE(std::isnan(grid[1][0].get<double>()));
  EXPECT_EQ(numberText(grid[1][1]), "-2");
  JsonDocument names;
  ASSERT_TRUE(parseJson(cells[2], &names, &error)) << error;
  ASSERT_EQ(names.size(), 2u);
  EXPECT_EQ(names[1].get<std::string>(), "quote\" comma, newline\n");
  JsonDocument empty;
  ASSERT_TRUE(parseJson(cells[3], &empty, &error));
  EXPECT_TRUE(empty.is_array());
  EXPECT_TRUE(empty.empty());
}

TEST(Json, ReadsObjectsAndReportsErrors) {
  JsonDocument v;
  std::string error;
  ASSERT_TRUE(parseJson(R"({"a": {"b": [1, 2.5e3, -0]}, "s": "\u00e9\n NaN", "t": true, "n": null})", &v, &error)) << error;
  ASSERT_TRUE(v.contains("a"));
  EXPECT_EQ(v["a"]["b"][1].get<double>(), 2500.0);
  EXPECT_EQ(v["s"].get<std::string>(), "\xC3\xA9\n NaN");  // NaN inside a string stays text
  EXPECT_FALSE(v.contains("missing"));
  EXPECT_FALSE(parseJson("[1, 2", &v, &error));
  EXPECT_FALSE(parseJson("[1] x", &v, &error));
  EXPECT_FALSE(parseJson("\"open", &v, &error));
  EXPECT_FALSE(parseJson("{\"a\" 1}", &v, &error));
  EXPECT_NE(error.find("byte"), std::string::npos);
}

}  // namespace
}  // namespace sdlqr::tables
