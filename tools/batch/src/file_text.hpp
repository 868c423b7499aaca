#pragma once
// Internal to tools/batch/src (spec.cpp, results.cpp): a whole file as text.

#include <fstream>
#include <sstream>
#include <string>

namespace sdlqr::batch::detail {

// The bytes of PATH; empty when it cannot be read (callers tell a missing file apart first).
inline std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace sdlqr::batch::detail
