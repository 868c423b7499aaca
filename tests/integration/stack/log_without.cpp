// A recorded flight with some of its messages taken out, as if the recorder had never heard them:
// every event of one channel, or only those of one seq (a COMMAND and its re-sends). The negative
// tests of the analysis judge such a log: an event of the scenario missing from it must fail.
//
//   log_without LOG OUT CHANNEL [SEQ]
//
// Every message of ours begins (after LCM's 8-byte fingerprint) with int64 utime and int64 seq,
// big-endian. Exit 1 when nothing matched (a negative test must never judge the whole log), 2 on
// bad arguments or files.

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include "recorded_events.hpp"

namespace {

using namespace sdlqr;

constexpr std::size_t kSeqOffset = 16;  // fingerprint, utime

int64_t seqOf(const uint8_t* data, std::size_t size) {
  if (size < kSeqOffset + 8) return std::numeric_limits<int64_t>::min();
  uint64_t value = 0;
  for (std::size_t i = 0; i < 8; ++i) value = (value << 8) | data[kSeqOffset + i];
  return static_cast<int64_t>(value);
}

int run(const std::string& in, const std::string& out, const std::string& channel, bool by_seq, int64_t seq) {
  std::vector<test::RecordedEvent> kept;
  int64_t removed = 0;
  for (test::RecordedEvent& e : test::readEvents(in)) {
    if (e.channel == channel && (!by_seq || seqOf(e.bytes.data(), e.bytes.size()) == seq)) {
      ++removed;
      continue;
    }
    kept.push_back(std::move(e));
  }
  test::writeEvents(out, kept);  // the logger's own writer
  std::cout << "log_without: removed " << removed << " " << channel << (by_seq ? " seq " + std::to_string(seq) : "")
            << " message(s), kept " << kept.size() << "\n";
  return removed > 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--help") {
    std::cout << "usage: log_without LOG OUT CHANNEL [SEQ]   (exit 1: nothing matched)\n";
    return 0;
  }
  if (argc != 4 && argc != 5) {
    std::cerr << "usage: log_without LOG OUT CHANNEL [SEQ]\n";
    return 2;
  }
  try {
    char* end = nullptr;
    const int64_t seq = argc == 5 ? std::strtoll(argv[4], &end, 10) : 0;
    if (argc == 5 && (end == argv[4] || *end != '\0')) throw std::invalid_argument(std::string("SEQ: not a number: ") + argv[4]);
    return run(argv[1], argv[2], argv[3], argc == 5, seq);
  } catch (const std::exception& e) {
    std::cerr << "log_without: " << e.what() << "\n";
    return 2;
  }
}
