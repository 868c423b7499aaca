// Writes the seed corpus of fuzz_messages: for every bus type, the selector byte and the encoding
// of a default message (and of a short trajectory), so the fuzzer starts past the fingerprints.
//   fuzz_seeds DIR

#include <cstdio>
#include <fstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "message_types.hpp"
#include "sdlqr/config/cli.hpp"

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

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> folder;
  ArgParser parser("fuzz_seeds", "Write the seed corpus of fuzz_messages into DIR (an existing folder).");
  parser.allowPositional(&folder, "DIR");
  parser.parseOrExit(argc, argv);
  if (folder.size() != 1) {
    std::fprintf(stderr, "fuzz_seeds: expected one folder DIR (see --help)\n");
    return 2;
  }
  const std::string dir = folder.front();
  writeAll(dir, std::make_index_sequence<fuzz::kBusTypeCount>{});
  Trajectory trajectory;
  trajectory.samples.resize(3);
  constexpr int kTrajectorySelector = 7;
  static_assert(std::is_same_v<std::tuple_element_t<kTrajectorySelector, fuzz::BusTypes>, trajectory_t>);
  write(dir, kTrajectorySelector, bus::toLcm(trajectory), "_samples");
  return 0;
}
