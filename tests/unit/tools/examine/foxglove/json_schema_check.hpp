#pragma once
// Checks a JSON value against the subset of JSON Schema (draft-07) the generator writes: type
// (one or a list), properties, required, additionalProperties false, items, minItems, maxItems,
// minimum, maximum. Returns the first violation's path, "" when the value conforms.

#include <string>

#include "sdlqr/foxglove/lcm_json.hpp"

namespace sdlqr::foxglove::testing {

inline bool hasType(const Json& value, const std::string& type) {
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  if (type == "string") return value.is_string();
  if (type == "boolean") return value.is_boolean();
  if (type == "null") return value.is_null();
  if (type == "integer") return value.is_number_integer();
  if (type == "number") return value.is_number();
  return false;
}

inline std::string violation(const Json& value, const Json& schema, const std::string& path = "$") {
  if (schema.contains("type")) {
    bool ok = false;
    for (const Json& t : schema["type"].is_array() ? schema["type"] : Json::array({schema["type"]})) ok = ok || hasType(value, t);
    if (!ok) return path + ": not " + schema["type"].dump();
  }
  if (value.is_number() && schema.contains("minimum") && value.get<double>() < schema["minimum"].get<double>()) return path + ": < minimum";
  if (value.is_number() && schema.contains("maximum") && value.get<double>() > schema["maximum"].get<double>()) return path + ": > maximum";
  if (value.is_array()) {
    if (schema.contains("minItems") && value.size() < schema["minItems"].get<std::size_t>()) return path + ": too few items";
    if (schema.contains("maxItems") && value.size() > schema["maxItems"].get<std::size_t>()) return path + ": too many items";
    for (std::size_t i = 0; i < value.size() && schema.contains("items"); ++i) {
      const std::string v = violation(value[i], schema["items"], path + "[" + std::to_string(i) + "]");
      if (!v.empty()) return v;
    }
  }
  if (value.is_object()) {
    for (const Json& key : schema.value("required", Json::array())) {
      if (!value.contains(key.get<std::string>())) return path + "." + key.get<std::string>() + ": missing";
    }
    for (const auto& [key, member] : value.items()) {
      const auto properties = schema.find("properties");
      if (properties == schema.end() || !properties->contains(key)) {
        if (schema.value("additionalProperties", true) == false) return path + "." + key + ": not in the schema";
        continue;
      }
      const std::string v = violation(member, (*properties)[key], path + "." + key);
      if (!v.empty()) return v;
    }
  }
  return "";
}

}  // namespace sdlqr::foxglove::testing
