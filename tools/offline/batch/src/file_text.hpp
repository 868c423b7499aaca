#pragma once
// Internal to tools/offline/batch/src (spec.cpp, results.cpp, slurm_submit.cpp): a whole file as text.

#include <sys/stat.h>

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

inline bool exists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}

}  // namespace sdlqr::batch::detail
