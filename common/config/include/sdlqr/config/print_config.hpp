#pragma once
// Prints whole sections of a vehicle file as commented YAML (each a "# help" line, "name:" and its
// keys): the printed defaults of tools/setup/params (config/quad255.yaml) and the --print-config of
// every process, which shows the sections it reads with the values it would run with.

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "sdlqr/config/param_table.hpp"

namespace sdlqr {

struct PrintedSection {
  std::string name;
  std::string help;
  std::function<void(YamlWriter&)> print_keys;
};

// A loaded section: `value` must outlive the PrintedSection.
template <class T>
PrintedSection printedSection(const std::string& name, const T& value) {
  return {name, T::declaration().help(), [&value](YamlWriter& out) { T::declaration().print(value, out); }};
}

// `header` lines are printed as comments first; sections follow in the given order.
void printSections(std::ostream& out, const std::vector<std::string>& header, const std::vector<PrintedSection>& sections);

// --print-config: "# <program> reads these sections of <file>, and runs with these values:".
void printProcessConfig(std::ostream& out, const std::string& program, const std::string& config_path,
                        const std::vector<PrintedSection>& sections);

}  // namespace sdlqr
