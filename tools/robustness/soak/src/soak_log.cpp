#include "sdlqr/soak/soak_log.hpp"

#include <unordered_map>

namespace sdlqr::soak {

namespace {
double seconds(int64_t utime) { return static_cast<double>(utime) * 1e-6; }
}  // namespace

bool LogWholeness::passed(double expected_airborne_s) const {
  return file_complete && seq_lost == 0 && !crashed && airborne_sim_s >= expected_airborne_s;
}

LogWholeness checkLogWhole(const logger::FlightLog& log) {
  LogWholeness w;
  w.file_complete = log.file.complete();
  int64_t worst = 0;
  for (const logger::ChannelTimeline& c : log.channels) {
    const logger::ChannelMetrics m = logger::computeChannelMetrics(c, 0, logger::PacingOrigin{});
    // HEARTBEAT interleaves every process's own seq: its gaps mean nothing here.
    if (m.several_publishers) continue;
    w.seq_lost += m.seq_lost;
    if (m.seq_lost > worst) {
      worst = m.seq_lost;
      w.worst_channel = c.channel;
    }
  }
  bool airborne_seen = false;
  double sim_start = 0.0, sim_end = 0.0;
  for (size_t i = 0; i < log.sim_truth.size(); ++i) {
    const SimTruth& s = log.sim_truth[i];
    w.crashed = w.crashed || s.crashed;
    if (s.on_ground) continue;
    const double wall = seconds(log.sim_truth.receive_utime[i]);
    if (!airborne_seen) {
      w.airborne_start = wall;
      sim_start = seconds(s.utime);
      airborne_seen = true;
    }
    w.airborne_end = wall;
    sim_end = seconds(s.utime);
  }
  w.airborne_sim_s = sim_end - sim_start;
  return w;
}

std::vector<LatencySample> commandLatencyOverTime(const logger::FlightLog& log) {
  std::unordered_map<int64_t, int64_t> state_receive;  // STATE_EST seq -> receive time
  for (size_t i = 0; i < log.state_estimate.size(); ++i) {
    state_receive[log.state_estimate[i].seq] = log.state_estimate.receive_utime[i];
  }
  std::vector<LatencySample> out;
  for (size_t i = 0; i < log.rate_command.size(); ++i) {
    const auto it = state_receive.find(log.rate_command[i].state_seq);
    if (it == state_receive.end()) continue;
    const int64_t received = log.rate_command.receive_utime[i];
    out.push_back({seconds(received), static_cast<double>(received - it->second)});
  }
  return out;
}

}  // namespace sdlqr::soak
