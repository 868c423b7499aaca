// Reads a parameter declaration file into its rows and refuses, with one line naming the file and
// the key, what the C++ table would refuse later or never see: an unknown type or field, a missing
// unit, doc or default, a range it cannot read, a duplicate key, a default outside its range.

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sdlqr/paramgen/declaration.hpp"

namespace sdlqr::paramgen {

namespace {

// The fields each type accepts beyond `key`; those before the '|' are required.
const std::map<std::string, std::pair<std::set<std::string>, std::set<std::string>>>& fieldsOfType() {
  static const std::map<std::string, std::pair<std::set<std::string>, std::set<std::string>>> fields = {
      {"number", {{"default", "unit", "range", "doc"}, {"field", "in_flight"}}},
      {"integer", {{"default", "unit", "range", "doc"}, {"field"}}},
      {"list", {{"default", "size", "unit", "range", "doc"}, {"field", "in_flight"}}},
      {"flag", {{"default", "doc"}, {"field"}}},
      {"choice", {{"default", "choices", "doc"}, {"field", "in_flight"}}},
      {"derived_list", {{"size", "unit", "range", "doc", "placeholder", "derive", "get", "set"}, {}}},
      {"section", {{}, {"field"}}},
  };
  return fields;
}

bool isConstantName(const std::string& text) {
  return text.size() > 1 && text[0] == 'k' && std::isupper(static_cast<unsigned char>(text[1]));
}

class RowReader {
 public:
  RowReader(const YAML::Node& node, std::string where) : node_(node), where_(std::move(where)) {}

  [[noreturn]] void fail(const std::string& reason) const { throw DeclarationError(where_ + ": " + reason); }

  std::string text(const char* name) const {
    const YAML::Node value = node_[name];
    if (!value) fail(std::string("missing ") + name);
    if (!value.IsScalar()) fail(std::string(name) + " must be a scalar");
    return value.Scalar();
  }
  std::string optionalText(const char* name) const { return node_[name] ? text(name) : std::string(); }

  Row read(const std::string& key) const {
    Row row;
    row.key = key;
    row.type = text("type");
    const auto known = fieldsOfType().find(row.type);
    if (known == fieldsOfType().end()) fail("unknown type '" + row.type + "'");
    checkFields(known->second.first, known->second.second);
    row.field = optionalText("field");
    row.in_flight = optionalText("in_flight");
    if (row.type == "section") return row;
    row.doc = text("doc");
    if (row.type == "choice") return readChoice(std::move(row));
    if (row.type == "flag") return readFlag(std::move(row));
    row.unit = text("unit");
    row.range = range();
    if (row.type == "list" || row.type == "derived_list") row.size = size();
    if (row.type == "derived_list") return readDerived(std::move(row));
    row.defaults = defaults(row);
    for (const std::string& value : row.defaults) checkInRange(row, value);
    return row;
  }

 private:
  void checkFields(const std::set<std::string>& required, const std::set<std::string>& optional) const {
    for (const std::string& name : required) {
      if (!node_[name]) fail("missing " + name);
    }
    for (const auto& entry : node_) {
      const std::string name = entry.first.Scalar();
      if (name != "key" && name != "type" && !required.count(name) && !optional.count(name)) {
        fail("unknown field '" + name + "'");
      }
    }
  }

  RangeSpec range() const {
    try {
      return parseRange(text("range"));
    } catch (const std::invalid_argument& e) {
      fail(e.what());
    }
  }

  int size() const {
    const std::string written = text("size");
    char* end = nullptr;
    const long value = std::strtol(written.c_str(), &end, 10);
    if (*end != '\0' || value < 1 || value > 16) fail("size '" + written + "' must be a whole number from 1 to 16");
    return static_cast<int>(value);
  }

  std::vector<std::string> defaults(const Row& row) const {
    if (row.type != "list") return {text("default")};
    const YAML::Node list = node_["default"];
    if (!list.IsSequence() || static_cast<int>(list.size()) != row.size) {
      fail("default must be a list of " + std::to_string(row.size) + " numbers");
    }
    std::vector<std::string> out;
    for (const YAML::Node& element : list) out.push_back(element.Scalar());
    return out;
  }

  void checkInRange(const Row& row, const std::string& value) const {
    if (isConstantName(value) && row.type != "list") return;  // checked by the generated static_assert
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0') fail("default '" + value + "' is not a number");
    if (row.type == "integer" && value.find_first_of(".eE") != std::string::npos) {
      fail("default '" + value + "' is not a whole number");
    }
    if (!row.range.contains(number)) fail("default " + value + " outside " + text("range"));
  }

  Row readChoice(Row row) const {
    const YAML::Node choices = node_["choices"];
    if (!choices.IsMap() || choices.size() == 0) fail("choices must map each word to its enumerator");
    for (const auto& entry : choices) row.choices.emplace_back(entry.first.Scalar(), entry.second.Scalar());
    const std::string word = text("default");
    for (const auto& choice : row.choices) {
      if (choice.first == word) row.defaults = {choice.second};
    }
    if (row.defaults.empty()) fail("default '" + word + "' is not one of the choices");
    return row;
  }

  Row readFlag(Row row) const {
    const std::string value = text("default");
    if (value != "true" && value != "false") fail("default '" + value + "' must be true or false");
    row.defaults = {value};
    return row;
  }

  Row readDerived(Row row) const {
    row.placeholder = text("placeholder");
    row.derive = text("derive");
    row.get = text("get");
    row.set = text("set");
    return row;
  }

  YAML::Node node_;
  std::string where_;
};

Section readSection(const YAML::Node& node, const std::string& file) {
  Section section;
  section.name = node["struct"] ? node["struct"].Scalar() : "";
  if (section.name.empty()) throw DeclarationError(file + ": a section without its struct");
  const std::string where = file + ": " + section.name;
  if (!node["help"]) throw DeclarationError(where + ": missing help");
  section.help = node["help"].Scalar();
  std::set<std::string> keys;
  for (const YAML::Node& entry : node["rows"]) {
    if (entry["code"]) {
      Row row;
      row.type = "code";
      row.code = entry["code"].Scalar();
      if (entry.size() != 1) throw DeclarationError(where + "." + row.code + ": a code row names only its function");
      section.rows.push_back(row);
      continue;
    }
    const std::string key = entry["key"] ? entry["key"].Scalar() : "";
    if (key.empty()) throw DeclarationError(where + ": a row without its key");
    if (!keys.insert(key).second) throw DeclarationError(where + "." + key + ": duplicate key");
    section.rows.push_back(RowReader(entry, where + "." + key).read(key));
  }
  return section;
}

}  // namespace

Declaration parseDeclaration(const std::string& yaml_text, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw DeclarationError(file + ": " + e.what());
  }
  if (!root.IsMap() || !root["namespace"] || !root["sections"]) {
    throw DeclarationError(file + ": expected a mapping with namespace and sections");
  }
  for (const auto& entry : root) {
    const std::string name = entry.first.Scalar();
    if (name != "header" && name != "namespace" && name != "sections") {
      throw DeclarationError(file + ": unknown field '" + name + "'");
    }
  }
  Declaration declaration;
  declaration.file = file;
  declaration.header = root["header"] ? root["header"].Scalar() : "";
  declaration.name_space = root["namespace"].Scalar();
  for (const YAML::Node& section : root["sections"]) declaration.sections.push_back(readSection(section, file));
  return declaration;
}

}  // namespace sdlqr::paramgen
