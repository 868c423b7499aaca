// Build-time generator: reads the MAVLink XML definitions (mavlink/definitions/) and writes
// OUT.hpp (sdlqr/mavlink/messages.hpp), only when its content changed.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "sdlqr/mavlinkgen/emit.hpp"

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw sdlqr::mavlinkgen::DefinitionError("cannot read " + path);
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
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << content;
  if (!out) throw sdlqr::mavlinkgen::DefinitionError("cannot write " + path.string());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || std::string(argv[1]) == "--help") {
    std::cout << "usage: sdlqr_mavlink_gen OUT.hpp FILE.xml...\n\n"
                 "Writes the message structs, enums and message table of the MAVLink definitions in\n"
                 "FILE.xml (mavlink/definitions/; <include> is not followed: name every file) to OUT.hpp.\n"
                 "Exit code 2 with FILE:LINE on a definition it cannot read.\n";
    return argc < 3 ? 2 : 0;
  }
  try {
    sdlqr::mavlinkgen::Definitions all;
    std::string note;
    for (int i = 2; i < argc; ++i) {
      const std::string name = std::filesystem::path(argv[i]).filename().string();
      sdlqr::mavlinkgen::merge(all, sdlqr::mavlinkgen::parseDefinitions(readFile(argv[i]), name));
      note += (note.empty() ? "" : ", ") + name;
    }
    writeIfChanged(argv[1], sdlqr::mavlinkgen::emitMessagesHeader(all, "mavlink/definitions/{" + note + "}"));
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "sdlqr_mavlink_gen: " << e.what() << "\n";
    return 2;
  }
}
