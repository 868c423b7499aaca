#pragma once
// The JSON encoding of LCM messages, as Foxglove's "json" message encoding and the MCAP export
// carry them: an object with one member per field in .lcm order, a nested array per array
// dimension, integers as integers, non-finite numbers as null. Its JSON Schema is generated from
// the same .lcm file (sdlqr/lcmtypes/generated/json_schemas.hpp), so the two cannot disagree.

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "sdlqr/lcmtypes/fields.hpp"
#include "sdlqr/lcmtypes/generated/json_schemas.hpp"

namespace sdlqr::foxglove {

using Json = nlohmann::ordered_json;

namespace lcm_json {

// Fills one JSON object field by field (the generated visit of sdlqr/lcmtypes/fields.hpp).
class FieldWriter {
 public:
  explicit FieldWriter(Json& object) : object_(object) {}

  template <class T>
  void operator()(const lcmtypes::FieldDescriptor& field, const T& member) {
    if constexpr (lcmtypes::kIsVector<T>) {
      object_[std::string(field.name)] = vector(field, 0, member);
    } else {
      object_[std::string(field.name)] = value(field, member);
      lengths_.note(field, member);
    }
  }

 private:
  template <class T>
  static Json value(const lcmtypes::FieldDescriptor& field, const T& v) {
    if constexpr (std::is_array_v<T>) {
      Json array = Json::array();
      for (const auto& element : v) array.push_back(value(field, element));
      return array;
    } else if constexpr (std::is_floating_point_v<T>) {
      return std::isfinite(v) ? Json(static_cast<double>(v)) : Json(nullptr);
    } else if constexpr (std::is_integral_v<T>) {
      if (field.type == "boolean") return Json(v != 0);
      return Json(static_cast<int64_t>(v));
    } else {
      return Json(v);  // std::string
    }
  }

  template <class T>
  Json vector(const lcmtypes::FieldDescriptor& field, int depth, const std::vector<T>& array) const {
    const int64_t length = lengths_.of(field, depth);
    const std::size_t n = length < 0 ? 0 : std::min(array.size(), static_cast<std::size_t>(length));
    Json out = Json::array();
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (lcmtypes::kIsVector<T>) out.push_back(vector(field, depth + 1, array[i]));
      else out.push_back(value(field, array[i]));
    }
    return out;
  }

  Json& object_;
  lcmtypes::ArrayLengths lengths_;
};

}  // namespace lcm_json

// The JSON of one lcm-gen message.
template <class LcmType>
Json toJson(const LcmType& message) {
  Json object = Json::object();
  lcm_json::FieldWriter writer(object);
  lcmtypes::visitLcmFields(writer, message);
  return object;
}

// JSON text of any document: compact, invalid UTF-8 (a hostile string field) replaced, never thrown.
std::string dumpJson(const Json& json);

// Decodes `size` bytes as the LCM type `lcm_type` (e.g. "imu_t"; the bus's size walk first, as
// every process reads the bus) and writes its JSON text to *out. False when the type is not one
// of lcmtypes/ or the bytes are not one whole message of it.
bool lcmBytesToJson(std::string_view lcm_type, const void* data, std::size_t size, std::string* out);

// The generated JSON Schema of an LCM type, nullptr when unknown.
const lcmtypes::JsonSchemaText* jsonSchemaOf(std::string_view lcm_type);

}  // namespace sdlqr::foxglove
