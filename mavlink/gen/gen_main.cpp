// Build-time generator: reads the MAVLink XML definitions (mavlink/definitions/) and writes
// OUT.hpp (sdlqr/mavlink/messages.hpp), only when its content changed.

#include <filesystem>
#include <iostream>

#include "sdlqr/lcmgen/generated_file.hpp"
#include "sdlqr/mavlinkgen/emit.hpp"

using sdlqr::lcmgen::readFile;
using sdlqr::lcmgen::writeIfChanged;

int main(int argc, char** argv) {
  const bool help = argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h");
  if (argc < 3 || help) {
    (help ? std::cout : std::cerr) << "usage: sdlqr_mavlink_gen OUT.hpp FILE.xml...\n\n"
                 "Writes the message structs, enums and message table of the MAVLink definitions in\n"
                 "FILE.xml (mavlink/definitions/; <include> is not followed: name every file) to OUT.hpp.\n"
                 "Exit code 2 with FILE:LINE on a definition it cannot read.\n";
    return help ? 0 : 2;
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
