// Build-time generator: reads the .lcm files of one package and writes the headers of
// sdlqr/lcmgen/emit.hpp into OUT_DIR/<package>/lcmtypes/generated/. Writes a file only when its
// content changed, so an unchanged schema recompiles nothing.

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "sdlqr/lcmgen/emit.hpp"
#include "sdlqr/lcmgen/generated_file.hpp"
#include "sdlqr/lcmgen/generator_main.hpp"

using sdlqr::lcmgen::readFile;
using sdlqr::lcmgen::writeIfChanged;

int main(int argc, char** argv) {
  std::string out_dir;
  std::vector<std::string> files;
  CLI::App app("Writes OUT_DIR/<package>/lcmtypes/generated/{plain,plain_fields,descriptors,lcm_fields,\n"
               "wire_fits,convert,channels,outbox,json_schemas}.hpp from the LCM definitions of one package (their\n"
               "@ annotations: lcmtypes/gen/include/sdlqr/lcmgen/schema.hpp); exit code 2 with file:line on a\n"
               "definition it cannot describe.",
               "sdlqr_lcmtypes_gen");
  app.add_option("OUT_DIR", out_dir, "folder of the generated headers")->required();
  app.add_option("FILE.lcm", files, "the package's definitions")->required();
  return sdlqr::lcmgen::runGenerator(app, argc, argv, [&] {
    const std::filesystem::path out_root = out_dir;
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
  });
}
