// The JSON encoding of LCM messages and the JSON Schemas generated from lcmtypes/*.lcm: every
// field, in .lcm order, arrays by their lengths, non-finite numbers as null, and each encoding
// valid under its type's schema.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "json_schema_check.hpp"
#include "sdlqr/foxglove/lcm_json.hpp"
#include "sdlqr/heartbeat_t.hpp"
#include "sdlqr/lcmtypes/generated/descriptors.hpp"
#include "sdlqr/lcmtypes/generated/lcm_fields.hpp"
#include "sdlqr/sim_truth_t.hpp"
#include "sdlqr/trajectory_t.hpp"

namespace sdlqr::foxglove {
namespace {

template <class T>
std::string encoded(const T& message) {
  std::string bytes(static_cast<std::size_t>(message.getEncodedSize()), '\0');
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

Json schemaOf(std::string_view type) { return Json::parse(jsonSchemaOf(type)->text); }

sim_truth_t truthMessage() {
  sim_truth_t m{};
  m.utime = 12'345'678;
  m.seq = 42;
  for (int i = 0; i < 3; ++i) m.position[i] = 0.1 * (i + 1);
  m.orientation[0] = 1.0;
  m.battery_voltage = std::numeric_limits<double>::quiet_NaN();
  m.thrust_scale = std::numeric_limits<double>::infinity();
  m.on_ground = 1;
  return m;
}

TEST(LcmJson, EveryFieldInLcmOrderWithItsValue) {
  const sim_truth_t m = truthMessage();
  const Json j = toJson(m);
  const lcmtypes::TypeDescriptor& type = lcmtypes::LcmFields<sim_truth_t>::type;
  ASSERT_EQ(j.size(), type.num_fields);
  std::size_t i = 0;
  for (const auto& [key, value] : j.items()) EXPECT_EQ(key, type.fields[i++].name);
  EXPECT_EQ(j["utime"], 12'345'678);
  EXPECT_EQ(j["seq"], 42);
  EXPECT_EQ(j["position"], Json::array({0.1, 0.2, 0.30000000000000004}));
  EXPECT_EQ(j["orientation"][0], 1.0);
  EXPECT_EQ(j["on_ground"], 1);
}

TEST(LcmJson, NonFiniteNumbersAreNullAndTheSchemaAllowsIt) {
  const Json j = toJson(truthMessage());
  EXPECT_TRUE(j["battery_voltage"].is_null());
  EXPECT_TRUE(j["thrust_scale"].is_null());
  EXPECT_EQ(testing::violation(j, schemaOf("sim_truth_t")), "");
}

TEST(LcmJson, DoublesRoundTripExactly) {
  sim_truth_t m = truthMessage();
  m.position[0] = 0.1 + 0.2;
  m.position[1] = -1.2345678901234567e-300;
  const Json back = Json::parse(dumpJson(toJson(m)));
  EXPECT_EQ(back["position"][0].get<double>(), m.position[0]);
  EXPECT_EQ(back["position"][1].get<double>(), m.position[1]);
}

TEST(LcmJson, VariableArraysFollowTheirLengthFieldAndNest) {
  trajectory_t m{};
  m.num_samples = 2;
  m.t = {0.0, 0.5, 9.9};  // a reused message may hold more than num_samples: the length field wins
  m.x = {std::vector<double>(10, 1.0), std::vector<double>(10, 2.0), std::vector<double>(10, 3.0)};
  m.u = {std::vector<double>(4, 0.0), std::vector<double>(4, 0.0), std::vector<double>(4, 0.0)};
  const Json j = toJson(m);
  ASSERT_EQ(j["t"].size(), 2u);
  ASSERT_EQ(j["x"].size(), 2u);
  EXPECT_EQ(j["x"][1].size(), 10u);
  EXPECT_EQ(j["x"][1][9], 2.0);
  EXPECT_EQ(testing::violation(j, schemaOf("trajectory_t")), "");
}

TEST(LcmJson, StringsThatAreNotUtf8AreReplacedNotThrown) {
  heartbeat_t m{};
  m.process = "sdlqr-\xff\xfe";
  m.num_counters = 1;
  m.counter_names = {"reject.nan"};
  m.counter_values = {3};
  std::string text;
  const std::string bytes = encoded(m);
  ASSERT_TRUE(lcmBytesToJson("heartbeat_t", bytes.data(), bytes.size(), &text));
  const Json j = Json::parse(text);
  EXPECT_EQ(j["counter_names"], Json::array({"reject.nan"}));
  EXPECT_EQ(j["counter_values"], Json::array({3}));
  EXPECT_EQ(testing::violation(j, schemaOf("heartbeat_t")), "");
}

TEST(LcmJson, BytesThatAreNotOneMessageOrAnUnknownTypeGiveNothing) {
  const std::string bytes = encoded(truthMessage());
  std::string text = "untouched";
  EXPECT_FALSE(lcmBytesToJson("sim_truth_t", bytes.data(), bytes.size() - 1, &text));
  EXPECT_FALSE(lcmBytesToJson("imu_t", bytes.data(), bytes.size(), &text));  // another type's fingerprint
  EXPECT_FALSE(lcmBytesToJson("no_such_t", bytes.data(), bytes.size(), &text));
  EXPECT_EQ(text, "untouched");
  EXPECT_TRUE(lcmBytesToJson("sim_truth_t", bytes.data(), bytes.size(), &text));
}

TEST(LcmJsonSchema, EveryTypeHasOneWithEveryFieldRequiredInOrder) {
  for (const lcmtypes::TypeDescriptor* type : lcmtypes::kAllTypes) {
    SCOPED_TRACE(std::string(type->name));
    const lcmtypes::JsonSchemaText* text = jsonSchemaOf(type->name);
    ASSERT_NE(text, nullptr);
    EXPECT_EQ(text->name, "sdlqr." + std::string(type->name));
    const Json schema = Json::parse(text->text);
    EXPECT_EQ(schema["additionalProperties"], false);
    ASSERT_EQ(schema["required"].size(), type->num_fields);
    std::size_t i = 0;
    for (const auto& [key, property] : schema["properties"].items()) {
      const lcmtypes::FieldDescriptor& f = type->fields[i];
      EXPECT_EQ(key, f.name);
      EXPECT_EQ(schema["required"][i++], f.name);
      EXPECT_NE(property["description"].get<std::string>().find("[" + std::string(f.unit) + "]"), std::string::npos);
      if (f.num_dimensions > 0 && f.dimensions[0].size > 0) {
        EXPECT_EQ(property["maxItems"], f.dimensions[0].size);
      }
    }
  }
}

TEST(LcmJsonSchema, ASchemaRefusesAMessageOfAnotherShape) {
  Json j = toJson(truthMessage());
  j["position"].push_back(0.4);
  EXPECT_EQ(testing::violation(j, schemaOf("sim_truth_t")), "$.position: too many items");
  j = toJson(truthMessage());
  j["utime"] = 1.5;
  EXPECT_EQ(testing::violation(j, schemaOf("sim_truth_t")), "$.utime: not \"integer\"");
  j = toJson(truthMessage());
  j["extra"] = 1;
  EXPECT_EQ(testing::violation(j, schemaOf("sim_truth_t")), "$.extra: not in the schema");
}

}  // namespace
}  // namespace sdlqr::foxglove
