#pragma once
// Invalid vehicle files derived from the parameter declarations: for every declared key a wrong
// type, a word for a number, NaN, Inf, a value just outside each bound of its range, a fraction for
// an integer, a short list, a NaN or out-of-range element, a wrong word for a choice or a flag;
// for every section and subsection an unknown key. A parameter added to a declaration gets its
// cases without an edit here.

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "sdlqr/config/param_table.hpp"

namespace sdlqr::testing {

struct DeclaredCase {
  std::string name;     // gtest-safe: section_key_kind
  std::string section;  // top-level section the case breaks
  std::string key;      // the full key the error must name ("lqr.r_diag[0]")
  YAML::Node value;     // what the key is set to
  std::vector<std::string> path;  // where, from the top of the file
};

// The value just outside the low (below = true) or high end of `range`; false when that end is open-ended.
bool outsideValue(const Range& range, bool below, double* value);

std::vector<DeclaredCase> declaredCases(const std::string& section, const ParamSection& declaration);

// `root` (a whole vehicle file) with the case applied.
YAML::Node withCase(const YAML::Node& root, const DeclaredCase& c);

std::string gtestSafe(std::string text);

}  // namespace sdlqr::testing
