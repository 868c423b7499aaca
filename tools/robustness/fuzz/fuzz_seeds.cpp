// Writes the seed corpora: of fuzz_messages, for every bus type, the selector byte and the encoding
// of a default message (and of a short trajectory), so the fuzzer starts past the fingerprints; of
// fuzz_mavlink (with MAVLINK_DIR), one frame of every MAVLink message, to the parser and through the
// bridge, so it starts past the checksums.
//   fuzz_seeds DIR [MAVLINK_DIR]

#include <cstdio>
#include <fstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "message_types.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/mavlink/frame.hpp"
#include "sdlqr/mavlink/messages.hpp"

namespace {

using namespace sdlqr;

template <class Lcm>
void write(const std::string& dir, int selector, const Lcm& message, const std::string& suffix = "") {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()) + 1);
  bytes[0] = static_cast<uint8_t>(selector);
  message.encode(bytes.data(), 1, static_cast<int>(bytes.size() - 1));
  std::ofstream(dir + "/seed_" + std::to_string(selector) + suffix, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// The default plain struct (identity quaternion, zeros) as its LCM message.
template <class Lcm>
Lcm defaultMessage() {
  using Plain = decltype(bus::fromLcm(std::declval<const Lcm&>()));
  return bus::toLcm(Plain{});
}

template <size_t... I>
void writeAll(const std::string& dir, std::index_sequence<I...>) {
  (write(dir, static_cast<int>(I), defaultMessage<std::tuple_element_t<I, fuzz::BusTypes>>()), ...);
}

void writeMavlink(const std::string& dir) {
  mavlink::FrameWriter writer(mavlink::Address{1, 1});
  std::apply([&](auto... messages) {
    auto one = [&](auto message) {
      uint8_t frame[mavlink::kMaxFrameSize + 1];
      const size_t size = writer.write(message, 0, frame + 1);
      for (uint8_t selector : {0, 4}) {  // the parser alone, through the bridge (fuzz_mavlink.cpp)
        frame[0] = selector;
        std::ofstream(dir + "/seed_" + std::to_string(selector) + "_" + std::string(decltype(message)::kName),
                      std::ios::binary)
            .write(reinterpret_cast<const char*>(frame), static_cast<std::streamsize>(size + 1));
      }
    };
    (one(messages), ...);
  }, mavlink::AllMessages{});
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> folders;
  ArgParser parser("fuzz_seeds",
                   "Write the seed corpus of fuzz_messages into DIR and, given MAVLINK_DIR, fuzz_mavlink's\n"
                   "(one frame of every MAVLink message) into it (existing folders).");
  parser.allowPositional(&folders, "DIR [MAVLINK_DIR]");
  parser.parseOrExit(argc, argv);
  if (folders.size() != 1 && folders.size() != 2) {
    std::fprintf(stderr, "fuzz_seeds: expected a folder DIR and an optional MAVLINK_DIR (see --help)\n");
    return 2;
  }
  if (folders.size() == 2) writeMavlink(folders[1]);
  const std::string dir = folders.front();
  writeAll(dir, std::make_index_sequence<fuzz::kBusTypeCount>{});
  Trajectory trajectory;
  trajectory.samples.resize(3);
  constexpr int kTrajectorySelector = 7;
  static_assert(std::is_same_v<std::tuple_element_t<kTrajectorySelector, fuzz::BusTypes>, trajectory_t>);
  write(dir, kTrajectorySelector, bus::toLcm(trajectory), "_samples");
  return 0;
}
