// Build-time generator: reads the .lcm files of one package and writes the headers of
// sdlqr/lcmgen/emit.hpp into OUT_DIR/<package>/lcmtypes/generated/. Writes a file only when its
// content changed, so an unchanged schema recompiles nothing.

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "sdlqr/lcmgen/emit.hpp"
#include "sdlqr/lcmgen/generated_file.hpp"

using sdlqr::lcmgen::readFile;
using sdlqr::lcmgen::writeIfChanged;

int main(int argc, char** argv) {
  if (argc < 3 || std::string(argv[1]) == "--help") {
    std::cout << "usage: sdlqr_lcmtypes_gen OUT_DIR FILE.lcm...\n\n"
                 "Writes OUT_DIR/<package>/lcmtypes/generated/{plain,plain_fields,descriptors,lcm_fields,\n"
                 "wire_fits,convert,channels,outbox,json_schemas}.hpp from the LCM definitions of one package (their @ annotations:\n"
                 "lcmtypes/gen/include/sdlqr/lcmgen/schema.hpp); exit code 2 with file:line on a\n"
                 "definition it cannot describe.\n";
    return argc < 3 ? 2 : 0;
  }
  try {
    const std::filesystem::path out_root = argv[1];
    std::vector<std::string> files(argv + 2, argv + argc);
    std::sort(files.begin(), files.end());
    std::vector<sdlqr::lcmgen::LcmStruct> types;
    for (const std::string& file : files) {
      types.push_back(sdlqr::lcmgen::parseLcmStruct(readFile(file), std::filesystem::path(file).filename().string()));
    }
    const std::string note = std::to_string(types.size()) + " .lcm files of package " + types.front().package;
    for (const sdlqr::lcmgen::GeneratedHeader& header : sdlqr::lcmgen::emitAll(types, note)) {
      const std::filesystem::path path = out_root / sdlqr::lcmgen::generatedInclude(types.front().package, header.name);
      std::filesystem::create_directories(path.parent_path());
      writeIfChanged(path, header.text);
    }
  } catch (const std::exception& e) {
    std::cerr << "sdlqr_lcmtypes_gen: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
