#include "sdlqr/config/print_config.hpp"

namespace sdlqr {

void printSections(std::ostream& out, const std::vector<std::string>& header, const std::vector<PrintedSection>& sections) {
  YamlWriter writer(out);
  for (const std::string& line : header) writer.comment(line);
  for (const PrintedSection& section : sections) {
    writer.blank();
    writer.comment(section.help);
    writer.open(section.name);
    section.print_keys(writer);
    writer.close();
  }
}

void printProcessConfig(std::ostream& out, const std::string& program, const std::string& config_path,
                        const std::vector<PrintedSection>& sections) {
  const std::string source = config_path.empty() ? "the built-in defaults" : config_path;
  printSections(out, {program + " reads these sections of " + source + " and runs with these values:"}, sections);
}

}  // namespace sdlqr
