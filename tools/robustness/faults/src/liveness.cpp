#include "sdlqr/faults/liveness.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <utility>

namespace sdlqr::faults {

namespace {

// A sender's heartbeats go out once a second; a recorder that misses a few still sees the seq
// grow by a few. A replay repeats an old seq, a mutation jumps far.
constexpr int64_t kMaxSeqStep = 5;
constexpr int8_t kStopping = 4;  // heartbeat_t STATE_STOPPING

struct Sender {
  int64_t last_seq = -1;
  std::vector<size_t> beats;  // indices into the heartbeat series
};

// Every event's receive time, of every channel, in order. A log built in memory (tests) has no
// channel timelines: its series say the same.
std::vector<int64_t> receiveTimes(const logger::FlightLog& log) {
  std::vector<int64_t> times;
  for (const logger::ChannelTimeline& c : log.channels) {
    times.insert(times.end(), c.event_receive_utime.begin(), c.event_receive_utime.end());
  }
  if (times.empty()) {
    for (const std::vector<int64_t>* series : {&log.heartbeat.receive_utime, &log.sim_truth.receive_utime,
                                               &log.motor_command.receive_utime, &log.rate_command.receive_utime,
                                               &log.state_estimate.receive_utime}) {
      times.insert(times.end(), series->begin(), series->end());
    }
  }
  std::sort(times.begin(), times.end());
  return times;
}

struct Stall {
  int64_t from = 0, to = 0;  // [us] wall: two consecutive events over kMachineStallS apart
};

std::vector<Stall> machineStalls(const std::vector<int64_t>& times) {
  std::vector<Stall> stalls;
  const auto threshold = static_cast<int64_t>(kMachineStallS * 1e6);
  for (size_t i = 1; i < times.size(); ++i) {
    if (times[i] - times[i - 1] > threshold) stalls.push_back({times[i - 1], times[i]});
  }
  return stalls;
}

// [us] of the machine's stalls inside (from, to).
int64_t stalledWithin(const std::vector<Stall>& stalls, int64_t from, int64_t to) {
  int64_t total = 0;
  for (const Stall& s : stalls) total += std::max<int64_t>(0, std::min(to, s.to) - std::max(from, s.from));
  return total;
}

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f s", s);
  return text;
}

bool listed(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

Liveness measureLiveness(const logger::FlightLog& log) {
  std::map<std::pair<std::string, int32_t>, Sender> senders;
  std::map<std::string, int64_t> offered;
  for (size_t i = 0; i < log.heartbeat.size(); ++i) {
    const logger::HeartbeatRecord& hb = log.heartbeat[i];
    ++offered[hb.process];
    Sender& s = senders[{hb.process, hb.pid}];
    const bool continues = s.beats.empty() || (hb.seq > s.last_seq && hb.seq <= s.last_seq + kMaxSeqStep);
    if (!continues) continue;
    s.last_seq = hb.seq;
    s.beats.push_back(i);
  }
  // Every counted heartbeat of a name, in receive order; a sender that never beat twice is forged.
  std::map<std::string, std::vector<size_t>> beats_of;
  std::map<std::string, int> senders_of;
  for (const auto& [key, sender] : senders) {
    if (sender.beats.size() < 2) continue;
    ++senders_of[key.first];
    std::vector<size_t>& all = beats_of[key.first];
    all.insert(all.end(), sender.beats.begin(), sender.beats.end());
  }
  Liveness out;
  const std::vector<int64_t> times = receiveTimes(log);
  out.log_end_utime = times.empty() ? -1 : times.back();
  const std::vector<Stall> stalls = machineStalls(times);
  for (const Stall& s : stalls) {
    out.longest_machine_stall_s = std::max(out.longest_machine_stall_s, 1e-6 * static_cast<double>(s.to - s.from));
  }
  for (const auto& [process, count] : offered) {
    ProcessLiveness p;
    p.process = process;
    std::vector<size_t> beats = beats_of[process];
    std::sort(beats.begin(), beats.end());
    p.beats = static_cast<int64_t>(beats.size());
    p.ignored = count - p.beats;
    p.senders = senders_of[process];
    for (size_t k = 0; k < beats.size(); ++k) {
      const int64_t t = log.heartbeat.receive_utime[beats[k]];
      if (k == 0) {
        p.first_receive_utime = t;
      } else {
        const int64_t stalled = stalledWithin(stalls, p.last_receive_utime, t);
        p.longest_gap_s = std::max(p.longest_gap_s, 1e-6 * static_cast<double>(t - p.last_receive_utime - stalled));
        p.stall_not_counted_s = std::max(p.stall_not_counted_s, 1e-6 * static_cast<double>(stalled));
      }
      p.last_receive_utime = t;
      p.last_state = log.heartbeat[beats[k]].state;
      p.last_index = static_cast<std::ptrdiff_t>(beats[k]);
    }
    if (p.beats > 0) {
      p.silent_at_end_s = 1e-6 * static_cast<double>(out.log_end_utime - p.last_receive_utime -
                                                      stalledWithin(stalls, p.last_receive_utime, out.log_end_utime));
    }
    out.processes.push_back(p);
  }
  return out;
}

std::vector<Finding> judgeLiveness(const Liveness& liveness, const LivenessRules& rules) {
  std::vector<Finding> findings;
  for (const std::string& name : rules.expected) {
    const bool seen = std::any_of(liveness.processes.begin(), liveness.processes.end(),
                                  [&](const ProcessLiveness& p) { return p.process == name && p.beats > 0; });
    if (!seen) findings.push_back({false, name + ": never sent a heartbeat"});
  }
  for (const ProcessLiveness& p : liveness.processes) {
    const std::string ignored = p.ignored > 0 ? " (" + std::to_string(p.ignored) + " replayed or forged ignored)" : "";
    if (p.beats == 0) {
      // Only forged heartbeats under this name: not a process of the flight unless expected (above).
      findings.push_back({true, p.process + ": no heartbeat of its own" + ignored});
      continue;
    }
    const bool gap_ok = listed(rules.killed, p.process) || p.longest_gap_s <= rules.max_silence_s;
    const std::string stall = p.stall_not_counted_s > 0.0
                                  ? ", not counting a " + seconds(p.stall_not_counted_s) + " stall of the whole bus"
                                  : "";
    findings.push_back({gap_ok, p.process + ": longest heartbeat gap " + seconds(p.longest_gap_s) + stall + " (limit " +
                                    seconds(rules.max_silence_s) +
                                    (listed(rules.killed, p.process) ? ", killed on purpose" : "") + ")" + ignored});
    const bool stopped = p.last_state == kStopping && listed(rules.may_stop, p.process);
    const bool end_ok = stopped || p.silent_at_end_s <= rules.max_silence_s;
    findings.push_back({end_ok, p.process + ": last heartbeat " + seconds(p.silent_at_end_s) +
                                    " before the end of the log" +
                                    (stopped ? " (stopped, as it may)" : end_ok ? "" : " (hung for good?)")});
  }
  return findings;
}

}  // namespace sdlqr::faults
