// Checks an `sdlqr-logger export` of a recorded log against the log itself: for every channel
// of a known type, the CSV holds exactly one row per message of the log, and each row, parsed
// back and re-encoded, gives the very bytes that were recorded (so every field, array element
// and string is identical). Optionally checks that a second, killed recording holds every event
// of the reference log received more than a margin before the kill.
//
//   export_roundtrip_check LOG CSV_DIR
//   export_roundtrip_check --prefix-of LOG KILLED_LOG --before UTIME [--killed-pid PID]
//   export_roundtrip_check --reorder-heartbeats LOG OUT   (LOG with each two HEARTBEATs swapped)
//
// Prints the counts it compared; exit code 1 on any mismatch.

#include <lcm/lcm-cpp.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/logger/csv.hpp"
#include "sdlqr/lcmtypes/generated/lcm_fields.hpp"
#include "sdlqr/lcmtypes/generated/wire_fits.hpp"
#include "sdlqr/logger/csv_row.hpp"
#include "sdlqr/logger/decode.hpp"
#include "sdlqr/logger/log_reader.hpp"
#include "sdlqr/logger/recorder.hpp"
#include "recorded_events.hpp"

namespace {

using namespace sdlqr::logger;
namespace fs = std::filesystem;

using sdlqr::test::RecordedEvent;

std::vector<RecordedEvent> readAll(const std::string& path) { return sdlqr::test::readEvents(path); }

template <class LcmType>
std::vector<uint8_t> encode(const LcmType& message) {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

int checkExport(const std::string& log_path, const fs::path& csv_dir) {
  std::map<std::string, std::vector<const RecordedEvent*>> by_channel;
  const std::vector<RecordedEvent> events = readAll(log_path);
  for (const RecordedEvent& e : events) by_channel[e.channel].push_back(&e);
  int failures = 0;
  int64_t rows_checked = 0, cells_checked = 0;
  for (const auto& [channel, messages] : by_channel) {
    const ChannelType* type = findChannelType(splitChannel(channel).base);
    if (type == nullptr) {
      std::cout << "  " << channel << ": not one of ours, no CSV expected\n";
      continue;
    }
    std::ifstream in(csv_dir / (channel + ".csv"), std::ios::binary);
    if (!in) {
      std::cout << "FAIL " << channel << ": no CSV\n";
      ++failures;
      continue;
    }
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> cells;
    std::string error;
    while (readCsvRecord(in, &cells, &error)) rows.push_back(cells);
    if (!error.empty() || rows.size() != messages.size() + 1) {
      std::cout << "FAIL " << channel << ": " << rows.size() - 1 << " CSV rows for " << messages.size()
                << " messages in the log " << error << "\n";
      ++failures;
      continue;
    }
    int64_t channel_failures = 0;
    sdlqr::lcmtypes::visitLcmType(type->lcm_type, [&](auto tag) {
      using LcmType = typename decltype(tag)::type;
      for (size_t i = 0; i < messages.size(); ++i) {
        LcmType back;
        std::string row_error;
        if (!readCsvRow(rows[i + 1], back, &row_error) || encode(back) != messages[i]->bytes) {
          if (channel_failures++ == 0) {
            std::cout << "FAIL " << channel << " row " << i + 1 << " does not re-encode to the recorded bytes "
                      << row_error << "\n";
          }
          continue;
        }
        cells_checked += static_cast<int64_t>(rows[i + 1].size());
        ++rows_checked;
      }
    });
    if (channel_failures > 0) ++failures;
    std::cout << "  " << channel << ": " << messages.size() << " messages, " << rows.size() - 1 << " rows"
              << (channel_failures ? ", MISMATCH" : ", identical") << "\n";
  }
  std::cout << "[ figures ] " << events.size() << " events on " << by_channel.size() << " channels; " << rows_checked
            << " rows and " << cells_checked << " cells round-tripped exactly\n";
  return failures == 0 ? 0 : 1;
}

// What process `pid` lost on the bus (bus.kernel_dropped + bus.over_capacity) by its last
// heartbeat in `path`; 0 when pid is 0 or it has none.
int64_t lostByProcess(const std::string& path, int32_t pid) {
  if (pid == 0) return 0;
  int64_t lost = 0;
  LogReader reader(path);
  LogEvent event;
  HeartbeatRecord heartbeat;
  while (reader.next(&event)) {
    if (event.channel != "HEARTBEAT" || !decodeMessage(event, &heartbeat) || heartbeat.pid != pid) continue;
    lost = 0;
    for (const HeartbeatCounter& c : heartbeat.counters) {
      if (c.name == "bus.kernel_dropped" || c.name == "bus.over_capacity") lost += c.value;
    }
  }
  return lost;
}

// Every event of `reference` received before `before_utime` is in `killed`, byte for byte, but
// for at most `allowed_missing`. Matched as a multiset per channel, not in order: two senders'
// datagrams on one channel (every process's HEARTBEAT) can reach two receiving sockets in
// opposite orders, as each CPU's loopback backlog delivers its own datagram to every socket.
int checkPrefix(const std::string& reference_path, const std::string& killed_path, int64_t before_utime,
                int64_t allowed_missing) {
  std::map<std::pair<std::string, std::vector<uint8_t>>, int64_t> unmatched;  // (channel, bytes) -> copies
  int64_t killed_events = 0;
  for (RecordedEvent& e : readAll(killed_path)) {
    ++unmatched[{e.channel, std::move(e.bytes)}];
    ++killed_events;
  }
  int64_t expected = 0, missing = 0;
  for (const RecordedEvent& e : readAll(reference_path)) {
    if (e.receive_utime >= before_utime) continue;
    ++expected;
    const auto found = unmatched.find({e.channel, e.bytes});
    if (found == unmatched.end() || found->second == 0) {
      if (missing++ < 5) std::cout << "FAIL missing " << e.channel << " received at " << e.receive_utime << "\n";
      continue;
    }
    --found->second;
  }
  std::cout << "[ figures ] killed log holds " << killed_events << " events; " << expected - missing << " of "
            << expected << " events received before " << before_utime << " found; the killed recorder lost "
            << allowed_missing << " on the bus\n";
  return missing <= allowed_missing && expected > 0 ? 0 : 1;
}

// `in` rewritten to `out` with each two consecutive HEARTBEAT events in the opposite order, as
// another receiving socket may have seen them.
int writeReorderedHeartbeats(const std::string& in, const std::string& out) {
  std::vector<RecordedEvent> events = readAll(in);
  std::vector<size_t> heartbeats;
  for (size_t i = 0; i < events.size(); ++i) {
    if (events[i].channel == "HEARTBEAT") heartbeats.push_back(i);
  }
  for (size_t h = 0; h + 1 < heartbeats.size(); h += 2) std::swap(events[heartbeats[h]], events[heartbeats[h + 1]]);
  sdlqr::test::writeEvents(out, events);  // the logger's own writer
  std::cout << "[ figures ] " << heartbeats.size() / 2 << " pairs of HEARTBEATs swapped\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 3) return checkExport(argv[1], argv[2]);
    if (argc == 4 && std::strcmp(argv[1], "--reorder-heartbeats") == 0) {
      return writeReorderedHeartbeats(argv[2], argv[3]);
    }
    const bool prefix = (argc == 6 || argc == 8) && std::strcmp(argv[1], "--prefix-of") == 0 &&
                        std::strcmp(argv[4], "--before") == 0;
    if (prefix && (argc == 6 || std::strcmp(argv[6], "--killed-pid") == 0)) {
      const int32_t pid = argc == 8 ? std::atoi(argv[7]) : 0;
      return checkPrefix(argv[2], argv[3], std::atoll(argv[5]), lostByProcess(argv[2], pid));
    }
  } catch (const std::exception& e) {
    std::cerr << "export_roundtrip_check: " << e.what() << "\n";
    return 2;
  }
  std::cerr << "usage: export_roundtrip_check LOG CSV_DIR | --prefix-of LOG KILLED_LOG --before UTIME [--killed-pid PID]"
               " | --reorder-heartbeats LOG OUT\n";
  return 2;
}
