#include "declared_cases.hpp"

#include <cctype>
#include <sstream>

namespace sdlqr::testing {

namespace {

std::vector<std::string> split(const std::string& dotted) {
  std::vector<std::string> parts;
  std::string part;
  std::stringstream in(dotted);
  while (std::getline(in, part, '.')) parts.push_back(part);
  return parts;
}

std::string joined(const std::vector<std::string>& path) {
  std::string out;
  for (const std::string& part : path) out += (out.empty() ? "" : ".") + part;
  return out;
}

}  // namespace

bool outsideValue(const Range& range, bool below, double* value) {
  if (below) {
    if (!range.hasLow()) return false;
    *value = range.low_open ? range.low : range.low - 1.0;
  } else {
    if (!range.hasHigh()) return false;
    *value = range.high_open ? range.high : range.high + 1.0;
  }
  return true;
}

std::string gtestSafe(std::string text) {
  for (char& c : text) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return text;
}

std::vector<DeclaredCase> declaredCases(const std::string& section, const ParamSection& declaration) {
  std::vector<DeclaredCase> cases;
  auto add = [&](const std::vector<std::string>& path, const std::string& kind, const std::string& key,
                 const YAML::Node& value) {
    cases.push_back({gtestSafe(joined(path) + "_" + kind), section, key, value, path});
  };
  for (const ParamInfo& info : declaration.params()) {
    std::vector<std::string> path{section};
    for (const std::string& part : split(info.key)) path.push_back(part);
    const std::string key = joined(path);
    add(path, "wrong_type", key, YAML::Load("{not: a value}"));
    double outside = 0.0;
    switch (info.kind) {
      case ParamKind::kNumber:
      case ParamKind::kInteger:
        add(path, "word", key, YAML::Node("not-a-number"));
        add(path, "nan", key, YAML::Load(".nan"));
        add(path, "inf", key, YAML::Load(".inf"));
        if (outsideValue(info.range, true, &outside)) add(path, "below_range", key, YAML::Node(outside));
        if (outsideValue(info.range, false, &outside)) add(path, "above_range", key, YAML::Node(outside));
        if (info.kind == ParamKind::kInteger) add(path, "fraction", key, YAML::Node(1.5));
        break;
      case ParamKind::kList: {
        const YAML::Node defaults = YAML::Load(info.default_text);
        add(path, "word", key, YAML::Node("not-a-list"));
        YAML::Node shorter(YAML::NodeType::Sequence);
        for (size_t i = 0; i + 1 < defaults.size(); ++i) shorter.push_back(defaults[i]);
        add(path, "short_list", key, shorter);
        auto withFirst = [&](const YAML::Node& first) {
          YAML::Node list = YAML::Clone(defaults);
          list[0] = first;
          return list;
        };
        add(path, "nan_element", key + "[0]", withFirst(YAML::Load(".nan")));
        if (outsideValue(info.range, true, &outside)) add(path, "element_below_range", key + "[0]", withFirst(YAML::Node(outside)));
        if (outsideValue(info.range, false, &outside)) add(path, "element_above_range", key + "[0]", withFirst(YAML::Node(outside)));
        break;
      }
      case ParamKind::kChoice:
      case ParamKind::kFlag:
        add(path, "bad_word", key, YAML::Node("not-a-choice"));
        break;
    }
  }
  std::vector<std::vector<std::string>> maps{{section}};
  for (const std::string& sub : declaration.subsections()) {
    std::vector<std::string> path{section};
    for (const std::string& part : split(sub)) path.push_back(part);
    maps.push_back(path);
  }
  for (std::vector<std::string> path : maps) {
    path.push_back("no_such_key");
    add(path, "unknown_key", joined(path), YAML::Node(1));
  }
  return cases;
}

YAML::Node withCase(const YAML::Node& root, const DeclaredCase& c) {
  YAML::Node copy = YAML::Clone(root);
  YAML::Node node;
  node.reset(copy);
  for (size_t i = 0; i + 1 < c.path.size(); ++i) {
    if (!node[c.path[i]] || !node[c.path[i]].IsMap()) node[c.path[i]] = YAML::Node(YAML::NodeType::Map);
    YAML::Node next = node[c.path[i]];
    node.reset(next);
  }
  node[c.path.back()] = c.value;
  return copy;
}

}  // namespace sdlqr::testing
