// Build-time generator: reads lcmtypes/*.lcm and writes the descriptor and CSV row headers of
// the logger (see sdlqr/logger/lcm_schema.hpp). Writes a file only when its content changed.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "sdlqr/logger/lcm_schema.hpp"

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw sdlqr::logger::LcmSchemaError("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeIfChanged(const std::filesystem::path& path, const std::string& content) {
  std::ifstream existing(path, std::ios::binary);
  if (existing) {
    std::ostringstream old;
    old << existing.rdbuf();
    if (old.str() == content) return;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << content;
  if (!out) throw sdlqr::logger::LcmSchemaError("cannot write " + path.string());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || std::string(argv[1]) == "--help") {
    std::cout << "usage: sdlqr_lcm_fields_gen OUT_DIR FILE.lcm...\n\n"
                 "Writes OUT_DIR/lcm_type_descriptors.hpp and OUT_DIR/lcm_csv_rows.hpp from the LCM\n"
                 "definitions; exit code 2 with file:line on a definition it cannot describe.\n";
    return argc < 3 ? 2 : 0;
  }
  try {
    const std::filesystem::path out_dir = argv[1];
    std::vector<std::string> files(argv + 2, argv + argc);
    std::sort(files.begin(), files.end());
    std::vector<sdlqr::logger::LcmStruct> types;
    for (const std::string& file : files) {
      types.push_back(sdlqr::logger::parseLcmStruct(readFile(file), std::filesystem::path(file).filename().string()));
    }
    std::filesystem::create_directories(out_dir);
    const std::string note = "lcmtypes/*.lcm (" + std::to_string(types.size()) + " types)";
    writeIfChanged(out_dir / "lcm_type_descriptors.hpp", sdlqr::logger::emitDescriptorsHeader(types, note));
    writeIfChanged(out_dir / "lcm_csv_rows.hpp", sdlqr::logger::emitCsvRowsHeader(types, note));
  } catch (const std::exception& e) {
    std::cerr << "sdlqr_lcm_fields_gen: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
