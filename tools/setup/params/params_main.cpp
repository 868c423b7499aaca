// sdlqr-params: the vehicle file from the parameter declarations. Prints the defaults (the text of
// config/quad255.yaml), checks a file as every process would read it, prints a file's values.

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/params/vehicle_file.hpp"

using namespace sdlqr;

namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path, "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-params", [&] {
    bool defaults = false;
    std::string check_path, print_path, compare_path;
    ArgParser parser("sdlqr-params",
                     "The vehicle file from the parameter declarations (key, unit, default, range, help of\n"
                     "every parameter, each declared once by the struct that holds it).");
    parser.addFlag("--defaults", &defaults, "print the vehicle file of defaults (config/quad255.yaml is this output)");
    parser.addOption("--check", &check_path, "FILE",
                     "load every section of FILE as the processes do: prints 'FILE: ok' or the one-line error");
    parser.addOption("--print", &print_path, "FILE", "print every section of FILE with the values it gives (defaults filled in)");
    parser.addOption("--compare-defaults", &compare_path, "FILE",
                     "exit 0 if FILE is the printed defaults, else 1 naming the first differing line");
    parser.setEpilog(
        "examples: sdlqr-params --defaults > config/quad255.yaml\n"
        "          sdlqr-params --check my_quad.yaml\n"
        "exit codes: 0 done, 1 --compare-defaults found a difference, 2 bad option or an invalid FILE");
    parser.parseOrExit(argc, argv);
    const int actions = (defaults ? 1 : 0) + !check_path.empty() + !print_path.empty() + !compare_path.empty();
    if (actions != 1) throw std::invalid_argument("give exactly one of --defaults, --check, --print, --compare-defaults");

    if (defaults) {
      std::cout << params::defaultVehicleFileText();
    } else if (!check_path.empty()) {
      params::VehicleFile::load(check_path);
      std::cout << check_path << ": ok\n";
    } else if (!print_path.empty()) {
      printSections(std::cout, {"every section of " + print_path + " with the values the processes run with"},
                    params::VehicleFile::load(print_path).sections());
    } else {
      const std::string difference = params::firstDifference(params::defaultVehicleFileText(), readText(compare_path));
      if (!difference.empty()) {
        std::cout << compare_path << " differs from the printed defaults at " << difference << "\n";
        return 1;
      }
      std::cout << compare_path << ": the printed defaults\n";
    }
    return 0;
  });
}
