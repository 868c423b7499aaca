// Build-time generator: reads parameter declaration files (sdlqr/paramgen/declaration.hpp) and
// writes OUT_DIR/<name>_rows.hpp for each <name>.yaml, only when its text changed. A file it
// cannot describe stops the build with one line naming the file and the key (exit code 2).

#include <filesystem>
#include <string>
#include <vector>

#include "sdlqr/lcmgen/generated_file.hpp"
#include "sdlqr/lcmgen/generator_main.hpp"
#include "sdlqr/paramgen/declaration.hpp"

int main(int argc, char** argv) {
  std::string out_dir;
  std::vector<std::string> files;
  CLI::App app("Writes OUT_DIR/<name>_rows.hpp, the ParamTable rows of each parameter declaration file\n"
               "<name>.yaml (format: common/config/gen/include/sdlqr/paramgen/declaration.hpp).",
               "sdlqr_paramgen");
  app.add_option("OUT_DIR", out_dir, "folder of the generated headers")->required();
  app.add_option("FILE.yaml", files, "declaration files")->required();
  return sdlqr::lcmgen::runGenerator(app, argc, argv, [&] {
    for (const std::string& file : files) {
      const auto declaration = sdlqr::paramgen::parseDeclaration(sdlqr::lcmgen::readFile(file), file);
      const auto stem = std::filesystem::path(file).stem().string();
      sdlqr::lcmgen::writeIfChanged(std::filesystem::path(out_dir) / (stem + "_rows.hpp"),
                                    sdlqr::paramgen::emitRows(declaration));
    }
  });
}
