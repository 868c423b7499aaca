#pragma once
// One judged line of sdlqr-faultcheck: what was measured and whether it passed.

#include <algorithm>
#include <string>
#include <vector>

namespace sdlqr::faults {

struct Finding {
  bool ok = false;
  std::string text;  // what was measured, with its limit
};

inline bool allOk(const std::vector<Finding>& findings) {
  return std::all_of(findings.begin(), findings.end(), [](const Finding& f) { return f.ok; });
}

}  // namespace sdlqr::faults
