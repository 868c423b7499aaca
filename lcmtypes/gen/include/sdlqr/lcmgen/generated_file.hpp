#pragma once
// The file handling of the build-time generators (lcmtypes/gen, mavlink/gen): read an input
// whole, write an output only when its text changed, so an unchanged schema recompiles nothing.
// Header-only: each generator includes it without linking the other. Errors are std::runtime_error
// naming the file (the generators print them and exit 2).

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sdlqr::lcmgen {

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void writeIfChanged(const std::filesystem::path& path, const std::string& content) {
  std::ifstream existing(path, std::ios::binary);
  if (existing) {
    std::ostringstream old;
    old << existing.rdbuf();
    if (old.str() == content) return;
  }
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << content;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace sdlqr::lcmgen
