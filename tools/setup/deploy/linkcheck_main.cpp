// sdlqr-linkcheck: what the links between emulated hosts carried (bandwidth per channel), what
// crossing them cost (latency, from recorders on two hosts) and what a recorder missed while a
// link was down (scripts/deploy --link-down).

#include <cstdio>
#include <iostream>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/deploy/link_report.hpp"

using namespace sdlqr;

namespace {

std::pair<std::string, std::string> splitPair(const std::string& option, const std::string& text) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos || comma == 0 || comma + 1 == text.size()) {
    throw std::invalid_argument(option + ": expected A,B, got '" + text + "'");
  }
  return {text.substr(0, comma), text.substr(comma + 1)};
}

int64_t parseWallUs(const std::string& option, const std::string& text) {
  size_t used = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || value <= 0) throw std::invalid_argument(option + ": expected wall microseconds, got '" + text + "'");
  return value;
}

void printBandwidth(const logger::FlightLog& log) {
  std::printf("%-14s %9s %9s %12s %12s\n", "channel", "messages", "rate Hz", "payload kB/s", "wire kbit/s");
  for (const deploy::ChannelBandwidth& row : deploy::channelBandwidth(log)) {
    std::printf("%-14s %9lld %9.1f %12.2f %12.1f\n", row.channel.c_str(), static_cast<long long>(row.messages), row.rate_hz,
                1e-3 * row.payload_bytes_per_s, 8e-3 * row.wire_bytes_per_s);
  }
}

void printDistribution(const char* what, const tables::Distribution& d) {
  std::printf("%s: %lld pairs, median %.0f us, p99 %.0f us, max %.0f us\n", what, static_cast<long long>(d.count), d.median,
              d.p99, d.max);
}

const char* verdict(bool ok) { return ok ? "ok  " : "FAIL"; }

// Every fast channel of the vehicle shows the silence, and lost nothing outside it.
bool checkGap(const logger::FlightLog& log, int64_t down, int64_t up) {
  bool ok = true;
  const double window_s = 1e-6 * static_cast<double>(up - down);
  for (const char* name : {"IMU", "STATE_EST", "RATE_CMD", "MOTOR_CMD", "SIM_TRUTH"}) {
    const std::string channel = log.vehicle.empty() ? name : log.vehicle + "/" + name;
    const logger::ChannelTimeline* timeline = log.channel(channel);
    if (timeline == nullptr || timeline->events == 0) {
      std::cout << "FAIL " << channel << ": not in the log\n";
      ok = false;
      continue;
    }
    const deploy::LinkGap gap = deploy::measureLinkGap(*timeline, down, up);
    const double gap_s = 1e-6 * static_cast<double>(gap.longest_gap_us);
    const bool channel_ok = gap_s >= 0.9 * window_s && gap.received_inside == 0 && gap.missing > 0 && gap.missing_outside == 0;
    std::printf("%s %s: silent %.3f s over the %.3f s the link was down, %lld received inside, %lld lost (%lld outside the window)\n",
                verdict(channel_ok), channel.c_str(), gap_s, window_s, static_cast<long long>(gap.received_inside),
                static_cast<long long>(gap.missing), static_cast<long long>(gap.missing_outside));
    ok = ok && channel_ok;
  }
  const deploy::FailsafeEntries failsafe = deploy::lowlevelFailsafeEntries(log.heartbeat, down, up);
  const bool flew_on = failsafe.around_outage == 0;
  std::cout << verdict(flew_on) << " the vehicle flew on: lowlevel failsafe entries " << failsafe.around_outage
            << " from before the link went down to " << 1e-6 * deploy::kFailsafeSettleUs << " s after it came up"
            << (failsafe.around_outage < 0 ? " (no lowlevel heartbeat on one side)" : "") << "; "
            << failsafe.whole_flight << " over the whole flight\n";
  return ok && flew_on;
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-linkcheck", [&] {
    std::string bandwidth_log, latency_logs, gap_log, down_text, vehicle;
    double min_median_us = -1.0;
    ArgParser parser("sdlqr-linkcheck", "Links between emulated hosts (scripts/deploy), measured from flight logs.");
    parser.addOption("--bandwidth", &bandwidth_log, "LOG", "messages, rate, payload and on-the-wire bandwidth per channel");
    parser.addOption("--latency", &latency_logs, "CONTROLLER_LOG,LOWLEVEL_LOG",
                     "STATE_EST -> RATE_CMD and RATE_CMD -> MOTOR_CMD across hosts, from a recorder on the\n"
                     "controller's host and one on the lowlevel's host");
    parser.addOption("--min-median-us", &min_median_us, "US",
                     "with --latency: fail unless the STATE_EST -> RATE_CMD median is at least US (an added delay\n"
                     "shows; the same log twice measures at one recorder)");
    parser.addOption("--gap", &gap_log, "LOG", "check that LOG's recorder missed the vehicle's fast channels while\n"
                     "its link was down (--down), lost nothing else, and that the vehicle did not enter failsafe\n"
                     "from before the link went down to 1 s after it came up");
    parser.addOption("--down", &down_text, "DOWN_US,UP_US", "wall instants the link went down and up (deploy --events)");
    parser.addOption("--vehicle", &vehicle, "PREFIX", "channel prefix of the vehicle");
    parser.setEpilog("exit codes: 0 done / every check held, 1 a check failed, 2 bad option or log");
    parser.parseOrExit(argc, argv);
    const int actions = !bandwidth_log.empty() + !latency_logs.empty() + !gap_log.empty();
    if (actions != 1) throw std::invalid_argument("give exactly one of --bandwidth, --latency, --gap");
    if (!bandwidth_log.empty()) {
      printBandwidth(logger::FlightLog::load(bandwidth_log, vehicle));
      return 0;
    }
    if (!latency_logs.empty()) {
      const auto [controller_log, lowlevel_log] = splitPair("--latency", latency_logs);
      const deploy::CrossHostLatency latency =
          deploy::crossHostLatency(logger::FlightLog::load(controller_log, vehicle), logger::FlightLog::load(lowlevel_log, vehicle));
      printDistribution("STATE_EST -> RATE_CMD", latency.state_to_command_us);
      printDistribution("RATE_CMD -> MOTOR_CMD", latency.command_to_motor_us);
      bool ok = latency.state_to_command_us.count > 0 && latency.command_to_motor_us.count > 0;
      if (min_median_us >= 0.0) {
        const bool slow_enough = latency.state_to_command_us.median >= min_median_us;
        std::cout << verdict(slow_enough) << " STATE_EST -> RATE_CMD median " << latency.state_to_command_us.median
                  << " us, at least " << min_median_us << " us\n";
        ok = ok && slow_enough;
      }
      return ok ? 0 : 1;
    }
    if (down_text.empty()) throw std::invalid_argument("--gap needs --down DOWN_US,UP_US");
    const auto [down_word, up_word] = splitPair("--down", down_text);
    const int64_t down = parseWallUs("--down", down_word), up = parseWallUs("--down", up_word);
    if (up <= down) throw std::invalid_argument("--down: the link must come up after it went down");
    return checkGap(logger::FlightLog::load(gap_log, vehicle), down, up) ? 0 : 1;
  });
}
