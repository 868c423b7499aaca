#pragma once
// The command line of a build-time generator (lcmtypes/gen, common/config/gen), written once:
// CLI11 directly (Debian libcli11-dev), since the generators are built before the libraries whose
// ArgParser every other executable uses. --help prints and exits 0; a bad option, or an input
// the generator cannot describe, is one line "<name>: reason" and exit code 2.

#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

namespace sdlqr::lcmgen {

// Parses the command line into `app`'s options, then runs generate().
template <class Generate>
int runGenerator(CLI::App& app, int argc, char** argv, Generate&& generate) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << app.get_name() << ": " << e.what() << " (see --help)\n";
    return 2;
  }
  try {
    generate();
  } catch (const std::exception& e) {
    std::cerr << app.get_name() << ": " << e.what() << "\n";
    return 2;
  }
  return 0;
}

}  // namespace sdlqr::lcmgen
