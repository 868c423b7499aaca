// Build-time generator: reads parameter declaration files (sdlqr/paramgen/declaration.hpp) and
// writes OUT_DIR/<name>_rows.hpp for each <name>.yaml, only when its text changed. A file it
// cannot describe stops the build with one line naming the file and the key (exit code 2).

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "sdlqr/lcmgen/generated_file.hpp"
#include "sdlqr/paramgen/declaration.hpp"

int main(int argc, char** argv) {
  // CLI11 directly: the generator is built before the libraries whose ArgParser the others use.
  std::string out_dir;
  std::vector<std::string> files;
  CLI::App app("Writes OUT_DIR/<name>_rows.hpp, the ParamTable rows of each parameter declaration file\n"
               "<name>.yaml (format: common/config/gen/include/sdlqr/paramgen/declaration.hpp).",
               "sdlqr_paramgen");
  app.add_option("OUT_DIR", out_dir, "folder of the generated headers")->required();
  app.add_option("FILE.yaml", files, "declaration files")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "sdlqr_paramgen: " << e.what() << " (see --help)\n";
    return 2;
  }
  try {
    for (const std::string& file : files) {
      const auto declaration = sdlqr::paramgen::parseDeclaration(sdlqr::lcmgen::readFile(file), file);
      const std::filesystem::path out = std::filesystem::path(out_dir) / (std::filesystem::path(file).stem().string() + "_rows.hpp");
      sdlqr::lcmgen::writeIfChanged(out, sdlqr::paramgen::emitRows(declaration));
    }
  } catch (const std::exception& e) {
    std::cerr << "sdlqr_paramgen: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
