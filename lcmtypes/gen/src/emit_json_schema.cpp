// JSON Schemas of the LCM types, for the JSON encoding of a message (tools/examine/foxglove
// lcm_json.hpp): one object member per field in .lcm order, one nested array per array dimension, integers as
// integers, float and double as numbers or null (JSON has no NaN or infinity), strings as strings.
// Foxglove advertises a channel's schema this way ("jsonschema" schema encoding), and the MCAP
// export writes it beside each channel.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <sstream>

#include "emit_text.hpp"
#include "sdlqr/lcmgen/emit.hpp"

namespace sdlqr::lcmgen {

namespace {

using Json = nlohmann::ordered_json;

// The raw string delimiter of the generated literals; a schema holding it is refused.
constexpr const char* kDelimiter = "sdlqr_json";

Json integerSchema(const std::string& type) {
  Json s = {{"type", "integer"}};
  if (type == "int8_t") s.update({{"minimum", -128}, {"maximum", 127}});
  if (type == "byte") s.update({{"minimum", 0}, {"maximum", 255}});
  if (type == "int16_t") s.update({{"minimum", -32768}, {"maximum", 32767}});
  if (type == "int32_t") s.update({{"minimum", INT32_MIN}, {"maximum", INT32_MAX}});
  return s;
}

Json leafSchema(const std::string& type) {
  if (type == "double" || type == "float") return {{"type", Json::array({"number", "null"})}};
  if (type == "string") return {{"type", "string"}};
  if (type == "boolean") return {{"type", "boolean"}};
  return integerSchema(type);
}

// Arrays nest from the outermost dimension in; a fixed dimension fixes the length, a variable one
// is the value of its length field.
Json dimensionSchema(const LcmField& field, size_t depth) {
  if (depth == field.dimensions.size()) return leafSchema(field.type);
  const LcmDimension& d = field.dimensions[depth];
  Json s = {{"type", "array"}, {"items", dimensionSchema(field, depth + 1)}};
  if (d.variable()) {
    s["description"] = "length: the value of " + d.length_field;
  } else {
    s["minItems"] = d.size;
    s["maxItems"] = d.size;
  }
  return s;
}

Json fieldSchema(const LcmField& field) {
  Json s = dimensionSchema(field, 0);
  std::string description = field.comment;
  if (field.type == "double" || field.type == "float") description += " (null: not finite)";
  s["description"] = description;
  return s;
}

std::string typeDescription(const LcmStruct& type) {
  std::string text = type.comment;
  if (!type.constants.empty()) text += "\nConstants:";
  for (const LcmConst& c : type.constants) {
    text += "\n  " + c.name + " = " + c.value + (c.comment.empty() ? "" : "  (" + c.comment + ")");
  }
  return text;
}

}  // namespace

std::string jsonSchemaName(const LcmStruct& type) { return type.package + "." + type.name; }

std::string jsonSchemaText(const LcmStruct& type) {
  Json properties = Json::object();
  Json required = Json::array();
  for (const LcmField& f : type.fields) {
    properties[f.name] = fieldSchema(f);
    required.push_back(f.name);
  }
  const Json schema = {
      {"$schema", "http://json-schema.org/draft-07/schema#"},
      {"title", jsonSchemaName(type)},
      {"description", typeDescription(type)},
      {"type", "object"},
      {"properties", properties},
      {"required", required},
      {"additionalProperties", false},
  };
  return schema.dump();
}

std::string emitJsonSchemasHeader(const std::vector<LcmStruct>& types, const std::string& source_note) {
  std::ostringstream out;
  out << text::headerOpening(source_note,
                             "// The JSON Schema (draft-07) of each LCM type's JSON encoding: an object member per field in\n"
                             "// .lcm order, a nested array per dimension, numbers or null (not finite) for float and double.\n\n");
  out << "#include <string_view>\n\n";
  const std::string ns = text::packageNamespace(types.empty() ? std::string() : types.front().package) + "::lcmtypes";
  out << "namespace " << ns << " {\n\n";
  out << "struct JsonSchemaText {\n"
         "  std::string_view lcm_type;  // \"imu_t\"\n"
         "  std::string_view name;      // \"<package>.imu_t\"\n"
         "  std::string_view text;      // the schema document\n"
         "};\n\n";
  out << "inline constexpr JsonSchemaText kJsonSchemas[] = {\n";
  for (const LcmStruct& t : types) {
    const std::string schema = jsonSchemaText(t);
    if (schema.find(std::string(")") + kDelimiter) != std::string::npos) {
      throw LcmSchemaError(t.file + ": the JSON Schema text holds the literal's delimiter )" + kDelimiter);
    }
    out << "    {" << text::quoted(t.name) << ", " << text::quoted(jsonSchemaName(t)) << ",\n     R\"" << kDelimiter
        << "(" << schema << ")" << kDelimiter << "\"},\n";
  }
  out << "};\n\n";
  out << "// nullptr when no type has that name.\n";
  out << "inline const JsonSchemaText* findJsonSchema(std::string_view lcm_type) {\n"
         "  for (const JsonSchemaText& s : kJsonSchemas) {\n    if (s.lcm_type == lcm_type) return &s;\n  }\n"
         "  return nullptr;\n}\n\n";
  out << "}  // namespace " << ns << "\n";
  return out.str();
}

}  // namespace sdlqr::lcmgen
