// The proof that a new message field is written once: tests/unit/lcmtypes/CMakeLists.txt copies
// state_estimate_t.lcm and trajectory_t.lcm into package sdlqr_probe with one added line each
// (`double wind[3]`, `double yaw_rate[num_samples]`), and the build generates everything else.
// This file is the "code that uses the field": the plain member exists with the right type, the
// conversions carry it both ways, the replay's comparison reports it, the CSV export has its
// columns and reads them back, and the size walk counts its bytes.

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <type_traits>

#include "leaf_support.hpp"
#include "sdlqr/foxglove/lcm_json.hpp"
#include "sdlqr/logger/csv_row.hpp"
#include "sdlqr/replay/series_comparison.hpp"
#include "sdlqr_probe/lcmtypes/generated/convert.hpp"
#include "sdlqr_probe/lcmtypes/generated/json_schemas.hpp"
#include "sdlqr_probe/lcmtypes/generated/lcm_fields.hpp"
#include "sdlqr_probe/lcmtypes/generated/plain_fields.hpp"
#include "sdlqr_probe/lcmtypes/generated/wire_fits.hpp"

namespace sdlqr_probe {
namespace {

using sdlqr::lcmtypes::test::decode;
using sdlqr::lcmtypes::test::differences;
using sdlqr::lcmtypes::test::encode;

static_assert(std::is_same_v<decltype(StateEstimate::wind), sdlqr::Vec3>, "a double[3] is a Vec3");
static_assert(std::is_same_v<decltype(TrajectorySample::yaw_rate), double>, "a row column is a row member");

StateEstimate estimateWithWind() {
  StateEstimate s;
  s.seq = 7;
  s.position = sdlqr::Vec3(1.0, 2.0, 3.0);
  s.wind = sdlqr::Vec3(0.5, -1.25, 2.0);
  return s;
}

TEST(NewField, TheJsonSchemaAndTheJsonEncodingCarryIt) {
  const sdlqr::foxglove::Json schema = sdlqr::foxglove::Json::parse(lcmtypes::findJsonSchema("state_estimate_t")->text);
  EXPECT_EQ(schema["title"], "sdlqr_probe.state_estimate_t");
  EXPECT_EQ(schema["properties"]["wind"]["maxItems"], 3);
  EXPECT_EQ(schema["properties"]["wind"]["description"], "[m/s] added by the probe: only this line and its use name it (null: not finite)");
  const sdlqr::foxglove::Json trajectory = sdlqr::foxglove::Json::parse(lcmtypes::findJsonSchema("trajectory_t")->text);
  EXPECT_EQ(trajectory["properties"]["yaw_rate"]["description"].get<std::string>().rfind("[rad/s]", 0), 0u);
  const sdlqr::foxglove::Json json = sdlqr::foxglove::toJson(toLcm(estimateWithWind()));
  EXPECT_EQ(json["wind"], sdlqr::foxglove::Json::array({0.5, -1.25, 2.0}));
}

TEST(NewField, TheConversionsCarryItBothWays) {
  const StateEstimate s = estimateWithWind();
  const state_estimate_t m = toLcm(s);
  EXPECT_EQ(m.wind[1], -1.25);
  const StateEstimate back = fromLcm(decode<state_estimate_t>(encode(m)));
  EXPECT_EQ(back.wind, s.wind);
  EXPECT_TRUE(differences(s, back).names.empty());

  Trajectory t;
  t.samples.resize(2);
  t.samples[1].yaw_rate = 0.75;
  const trajectory_t mt = toLcm(t);
  ASSERT_EQ(mt.yaw_rate.size(), 2u);
  EXPECT_EQ(mt.yaw_rate[1], 0.75);
  EXPECT_EQ(fromLcm(decode<trajectory_t>(encode(mt))).samples[1].yaw_rate, 0.75);
}

TEST(NewField, TheReplayComparisonReportsIt) {
  const std::vector<StateEstimate> recorded = {estimateWithWind()};
  std::vector<StateEstimate> replayed = recorded;
  EXPECT_TRUE(sdlqr::replay::compareSeries("PROBE", recorded, replayed, 0.0).bitForBit());
  replayed[0].wind[1] += 1e-9;
  const sdlqr::replay::ChannelComparison c = sdlqr::replay::compareSeries("PROBE", recorded, replayed, 0.0);
  EXPECT_FALSE(c.bitForBit());
  ASSERT_EQ(c.fields.size(), 1u);
  EXPECT_EQ(c.fields[0].field, "wind[1]");
  EXPECT_NEAR(c.fields[0].max_abs, 1e-9, 1e-15);
  EXPECT_EQ(c.first_difference.rfind("PROBE seq 7 wind[1]: recorded -1.25", 0), 0u) << c.first_difference;

  std::vector<Trajectory> trajectories(1);
  trajectories[0].samples.resize(3);
  std::vector<Trajectory> changed = trajectories;
  changed[0].samples[2].yaw_rate = 0.5;
  const sdlqr::replay::ChannelComparison rows = sdlqr::replay::compareSeries("PROBE", trajectories, changed, 0.0);
  ASSERT_FALSE(rows.fields.empty());
  EXPECT_EQ(rows.fields[0].field, "samples[2].yaw_rate");
}

TEST(NewField, TheCsvExportHasItsColumnsAndReadsThemBack) {
  const sdlqr::lcmtypes::TypeDescriptor& type = sdlqr::lcmtypes::LcmFields<state_estimate_t>::type;
  const std::vector<std::string_view> columns(type.columns, type.columns + type.num_columns);
  const auto at = std::find(columns.begin(), columns.end(), "wind[1] [m/s]");
  ASSERT_NE(at, columns.end());
  std::ostringstream text;
  sdlqr::logger::CsvWriter writer(text);
  const state_estimate_t m = toLcm(estimateWithWind());
  sdlqr::logger::writeCsvRow(writer, m);
  std::istringstream in(text.str());
  std::vector<std::string> cells;
  std::string error;
  ASSERT_TRUE(sdlqr::logger::readCsvRecord(in, &cells, &error)) << error;
  ASSERT_EQ(cells.size(), columns.size());
  EXPECT_EQ(cells[static_cast<std::size_t>(at - columns.begin())], "-1.25");
  state_estimate_t back{};
  ASSERT_TRUE(sdlqr::logger::readCsvRow(cells, back, &error)) << error;
  EXPECT_EQ(encode(back), encode(m));

  const sdlqr::lcmtypes::TypeDescriptor& rows = sdlqr::lcmtypes::LcmFields<trajectory_t>::type;
  const std::vector<std::string_view> row_columns(rows.columns, rows.columns + rows.num_columns);
  EXPECT_NE(std::find(row_columns.begin(), row_columns.end(), "yaw_rate[num_samples] [rad/s]"), row_columns.end());
}

TEST(NewField, TheSizeWalkCountsItsBytes) {
  const std::vector<uint8_t> bytes = encode(toLcm(estimateWithWind()));
  EXPECT_TRUE(lcmtypes::encodingFits(static_cast<const state_estimate_t*>(nullptr), bytes.data(),
                                     static_cast<int64_t>(bytes.size())));
  // Without the 24 bytes of wind the message is the real state_estimate_t's size, and too short.
  EXPECT_FALSE(lcmtypes::encodingFits(static_cast<const state_estimate_t*>(nullptr), bytes.data(),
                                      static_cast<int64_t>(bytes.size()) - 24));
}

}  // namespace
}  // namespace sdlqr_probe
