#include "sdlqr/inspect/bus_monitor.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace sdlqr::inspect {

void BusMonitor::onMessage(std::string_view channel, int64_t size, int64_t receive_utime) {
  auto it = channels_.find(channel);
  if (it == channels_.end()) it = channels_.emplace(std::string(channel), ChannelStats{}).first;
  ChannelStats& stats = it->second;
  ++stats.messages;
  stats.bytes += size;
  stats.last_size = size;
  stats.last_utime = receive_utime;
  if (first_utime_ < 0) first_utime_ = receive_utime;
}

void BusMonitor::onHeartbeat(std::string_view channel, const logger::HeartbeatRecord& heartbeat,
                             int64_t receive_utime) {
  ProcessStats& stats = processes_[{std::string(channel), heartbeat.process}];
  stats.heartbeat = heartbeat;
  stats.last_utime = receive_utime;
}

BusReport BusMonitor::report(int64_t now_utime) {
  BusReport out;
  out.utime = now_utime;
  const int64_t since = last_report_utime_ >= 0 ? last_report_utime_ : first_utime_;
  out.period_s = since >= 0 ? static_cast<double>(now_utime - since) * 1e-6 : 0.0;
  for (auto& [name, stats] : channels_) {
    ChannelRow row;
    row.channel = name;
    if (out.period_s > 0.0) {
      row.rate_hz = static_cast<double>(stats.messages - stats.messages_at_report) / out.period_s;
      row.bytes_per_s = static_cast<double>(stats.bytes - stats.bytes_at_report) / out.period_s;
    }
    row.age_ms = static_cast<double>(now_utime - stats.last_utime) * 1e-3;
    row.last_size = stats.last_size;
    row.messages = stats.messages;
    stats.messages_at_report = stats.messages;
    stats.bytes_at_report = stats.bytes;
    out.channels.push_back(std::move(row));
  }
  constexpr int8_t kStopping = 4;  // heartbeat_t STATE_STOPPING
  for (const auto& [key, stats] : processes_) {
    ProcessRow row;
    row.channel = key.first;
    row.heartbeat = stats.heartbeat;
    row.age_s = static_cast<double>(now_utime - stats.last_utime) * 1e-6;
    row.alive = row.age_s <= silence_limit_s_ && stats.heartbeat.state != kStopping;
    out.processes.push_back(std::move(row));
  }
  last_report_utime_ = now_utime;
  return out;
}

std::string formatReport(const BusReport& report) {
  std::string text;
  char line[512];
  std::snprintf(line, sizeof line, "%-28s %10s %10s %8s %11s %10s\n", "CHANNEL", "RATE[Hz]", "AGE[ms]", "SIZE[B]",
                "KB/s", "MESSAGES");
  text += line;
  for (const ChannelRow& c : report.channels) {
    std::snprintf(line, sizeof line, "%-28s %10.1f %10.1f %8lld %11.1f %10lld\n", c.channel.c_str(), c.rate_hz,
                  c.age_ms, static_cast<long long>(c.last_size), c.bytes_per_s / 1024.0,
                  static_cast<long long>(c.messages));
    text += line;
  }
  text += "\n";
  // The process column is as wide as its longest name: a vehicle prefix (QUAD1/sdlqr-controller)
  // would otherwise push that row's columns out of line with the header.
  std::vector<std::string> names;
  int name_width = 20;
  for (const ProcessRow& p : report.processes) {
    const std::string prefix = p.channel.size() > 9 ? p.channel.substr(0, p.channel.size() - 9) : "";
    names.push_back(prefix + p.heartbeat.process);
    name_width = std::max(name_width, static_cast<int>(names.back().size()));
  }
  std::snprintf(line, sizeof line, "%-*s %-8s %-9s %7s %6s %10s %10s %7s %7s %6s  %s\n", name_width, "PROCESS", "HEALTH",
                "STATE", "PID", "CPU[%]", "RECEIVED", "PUBLISHED", "DROPPED", "REJECT", "ERRORS", "LAST ERROR");
  text += line;
  for (size_t i = 0; i < report.processes.size(); ++i) {
    const ProcessRow& p = report.processes[i];
    const logger::HeartbeatRecord& h = p.heartbeat;
    std::snprintf(line, sizeof line, "%-*s %-8s %-9s %7d %6.1f %10lld %10lld %7lld %7lld %6lld  %s\n", name_width,
                  names[i].c_str(), p.alive ? "alive" : h.state == 4 ? "stopped" : "SILENT",
                  logger::processStateName(h.state).c_str(), h.pid, h.cpu_percent,
                  static_cast<long long>(h.received), static_cast<long long>(h.published),
                  static_cast<long long>(h.dropped), static_cast<long long>(h.rejected),
                  static_cast<long long>(h.errors), h.last_error.c_str());
    text += line;
  }
  return text;
}

}  // namespace sdlqr::inspect
