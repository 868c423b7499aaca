#include "sdlqr/logger/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "sdlqr/math/solve_status.hpp"
#include "sdlqr/tables/json_document.hpp"

namespace sdlqr::logger {

using tables::describe;
using tables::JsonDocument;
using tables::toJson;
using tables::writeJsonDocument;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kUsToMs = 1e-3;
constexpr double kUsToS = 1e-6;

// A log's contents are untrusted: integer differences saturate instead of overflowing, and time
// spans are taken in double (exact below 2^53 us, i.e. for any real clock).
int64_t difference(int64_t a, int64_t b) {
  int64_t out = 0;
  if (__builtin_sub_overflow(a, b, &out)) return a > b ? std::numeric_limits<int64_t>::max() : std::numeric_limits<int64_t>::min();
  return out;
}

int64_t sum(int64_t a, int64_t b) {
  int64_t out = 0;
  if (__builtin_add_overflow(a, b, &out)) return a > 0 ? std::numeric_limits<int64_t>::max() : std::numeric_limits<int64_t>::min();
  return out;
}

double spanUs(int64_t later, int64_t earlier) { return static_cast<double>(later) - static_cast<double>(earlier); }

Distribution intervalsMs(const std::vector<int64_t>& times) {
  std::vector<double> intervals;
  if (times.size() > 1) intervals.reserve(times.size() - 1);
  for (size_t i = 1; i < times.size(); ++i) intervals.push_back(spanUs(times[i], times[i - 1]) * kUsToMs);
  return describe(std::move(intervals));
}

double rateHz(size_t count, double span_us) {
  if (count < 2 || !(span_us > 0.0)) return kNaN;
  return static_cast<double>(count - 1) / (span_us * kUsToS);
}

const char* methodName(GainsMethod method) {
  switch (method) {
    case GainsMethod::kTangent: return "tangent";
    case GainsMethod::kIterative: return "iterative";
  }
  return "unknown";
}

const char* freshnessName(GainsFreshness freshness) {
  switch (freshness) {
    case GainsFreshness::kFresh: return "fresh";
    case GainsFreshness::kStale: return "stale";
    case GainsFreshness::kFallback: return "fallback";
  }
  return "unknown";
}

bool isHeartbeat(const ChannelTimeline& timeline) { return timeline.lcm_type == "heartbeat_t"; }

PacingOrigin findOrigin(const std::vector<ChannelTimeline>& channels) {
  PacingOrigin origin;
  for (const ChannelTimeline& c : channels) {
    if (isHeartbeat(c) || c.receive_utime.empty()) continue;
    if (!origin.valid || c.receive_utime.front() < origin.receive_utime) {
      origin.valid = true;
      origin.channel = c.channel;
      origin.receive_utime = c.receive_utime.front();
      origin.utime = c.utime.front();
    }
  }
  return origin;
}

JsonDocument counts(const std::map<std::string, int64_t>& values) {
  JsonDocument out = JsonDocument::object();
  for (const auto& [key, value] : values) out[key] = value;
  return out;
}

JsonDocument channelJson(const ChannelMetrics& c) {
  JsonDocument out;
  out["type"] = c.lcm_type.empty() ? JsonDocument() : JsonDocument(c.lcm_type);
  out["events"] = c.events;
  out["bytes"] = c.bytes;
  out["decoded"] = c.decoded;
  out["decode_failures"] = c.decode_failures;
  out["receive"] = {{"first_s", c.first_receive_s}, {"last_s", c.last_receive_s}, {"rate_hz", c.receive_rate_hz},
                    {"interval_ms", toJson(c.receive_interval_ms)}};
  if (c.several_publishers) {
    out["note"] = "several processes publish here: see \"heartbeat\" for per-process figures";
  } else if (c.decoded > 0) {
    out["sim"] = {{"first_utime", c.first_utime}, {"last_utime", c.last_utime}, {"duration_s", c.sim_duration_s},
                  {"rate_hz", c.sim_rate_hz}, {"interval_ms", toJson(c.sim_interval_ms)},
                  {"utime_not_increasing", c.utime_not_increasing}};
    out["seq"] = {{"first", c.first_seq}, {"last", c.last_seq}, {"lost", c.seq_lost}, {"restarts", c.seq_restarts},
                  {"repeats", c.seq_repeats}};
  }
  if (c.has_pacing) out["pacing_lag_ms"] = toJson(c.pacing_lag_ms);
  return out;
}

JsonDocument heartbeatJson(const ProcessHeartbeatMetrics& p) {
  const HeartbeatRecord& h = p.last;
  JsonDocument last = {{"state", processStateName(h.state)}, {"utime", h.utime}, {"seq", h.seq}, {"pid", h.pid},
                       {"received", h.received}, {"published", h.published}, {"dropped", h.dropped},
                       {"rejected", h.rejected}, {"deadline_misses", h.deadline_misses}, {"errors", h.errors},
                       {"cpu_percent", h.cpu_percent}};
  last["counters"] = JsonDocument::object();
  for (const auto& [name, value] : h.counters) last["counters"][name] = value;
  last["last_error"] = h.last_error;
  return {{"heartbeats", p.heartbeats}, {"distinct_pids", p.distinct_pids}, {"seq_lost", p.seq_lost},
          {"first_receive_s", p.first_receive_s}, {"last_receive_s", p.last_receive_s},
          {"max_interval_s", p.max_interval_s}, {"last", last}};
}

}  // namespace

ChannelMetrics computeChannelMetrics(const ChannelTimeline& t, int64_t log_start_receive_utime,
                                     const PacingOrigin& origin) {
  ChannelMetrics m;
  m.channel = t.channel;
  m.lcm_type = t.lcm_type;
  m.events = t.events;
  m.bytes = t.bytes;
  m.decoded = static_cast<int64_t>(t.utime.size());
  m.decode_failures = t.decode_failures;
  if (!t.event_receive_utime.empty()) {
    m.first_receive_s = spanUs(t.event_receive_utime.front(), log_start_receive_utime) * kUsToS;
    m.last_receive_s = spanUs(t.event_receive_utime.back(), log_start_receive_utime) * kUsToS;
    m.receive_rate_hz =
        rateHz(t.event_receive_utime.size(), spanUs(t.event_receive_utime.back(), t.event_receive_utime.front()));
  } else {
    m.receive_rate_hz = kNaN;
  }
  m.receive_interval_ms = intervalsMs(t.event_receive_utime);

  m.sim_rate_hz = kNaN;
  if (isHeartbeat(t)) {
    m.several_publishers = true;
    return m;
  }
  m.sim_interval_ms = intervalsMs(t.utime);
  if (!t.utime.empty()) {
    m.first_utime = t.utime.front();
    m.last_utime = t.utime.back();
    m.sim_duration_s = spanUs(m.last_utime, m.first_utime) * kUsToS;
    m.sim_rate_hz = rateHz(t.utime.size(), spanUs(m.last_utime, m.first_utime));
    m.first_seq = t.seq.front();
    m.last_seq = t.seq.back();
  }
  for (size_t i = 1; i < t.utime.size(); ++i) {
    if (t.utime[i] <= t.utime[i - 1]) ++m.utime_not_increasing;
    const int64_t step = difference(t.seq[i], t.seq[i - 1]);
    if (step > 1) m.seq_lost = sum(m.seq_lost, step - 1);
    else if (step < 0) ++m.seq_restarts;
    else if (step == 0) ++m.seq_repeats;
  }

  if (origin.valid && !t.utime.empty()) {
    std::vector<double> lags;
    lags.reserve(t.utime.size());
    for (size_t i = 0; i < t.utime.size(); ++i) {
      const double lag_us = spanUs(t.receive_utime[i], origin.receive_utime) - spanUs(t.utime[i], origin.utime);
      lags.push_back(lag_us * kUsToMs);
    }
    m.has_pacing = true;
    m.pacing_lag_ms = describe(std::move(lags));
  }
  return m;
}

GainsMetrics computeGainsMetrics(const std::vector<GainSet>& gains) {
  GainsMetrics m;
  m.count = static_cast<int64_t>(gains.size());
  std::vector<double> solve_us;
  std::vector<double> iterations;
  std::vector<double> residual;
  for (const GainSet& g : gains) {
    solve_us.push_back(g.solve_us);
    iterations.push_back(static_cast<double>(g.iterations));
    residual.push_back(g.residual);
    ++m.status[toString(g.status)];
    ++m.method[methodName(g.method)];
  }
  m.solve_us = describe(std::move(solve_us));
  m.iterations = describe(std::move(iterations));
  m.residual = describe(std::move(residual));
  return m;
}

RateCommandMetrics computeRateCommandMetrics(const std::vector<RateCommand>& commands, double nominal_period_s) {
  RateCommandMetrics m;
  m.count = static_cast<int64_t>(commands.size());
  m.nominal_period_ms = nominal_period_s * 1e3;
  std::vector<double> periods;
  std::vector<double> jitter;
  for (size_t i = 0; i < commands.size(); ++i) {
    const RateCommand& c = commands[i];
    if (c.saturated & 1) ++m.rate_saturated;
    if (c.saturated & 2) ++m.thrust_saturated;
    ++m.gains_status[freshnessName(c.gains_status)];
    if (i == 0) continue;
    if (c.utime <= commands[i - 1].utime) {
      ++m.utime_not_increasing;
      continue;
    }
    const double period_ms = spanUs(c.utime, commands[i - 1].utime) * kUsToMs;
    periods.push_back(period_ms);
    jitter.push_back(std::abs(period_ms - m.nominal_period_ms));
  }
  m.period_ms = describe(std::move(periods));
  m.jitter_ms = describe(std::move(jitter));
  return m;
}

std::vector<ProcessHeartbeatMetrics> computeHeartbeatMetrics(const HeartbeatSeries& series,
                                                             int64_t log_start_receive_utime) {
  std::map<std::string, ProcessHeartbeatMetrics> by_process;
  std::map<std::string, std::set<int32_t>> pids;
  std::map<std::string, int64_t> last_receive;
  for (size_t i = 0; i < series.records.size(); ++i) {
    const HeartbeatRecord& h = series.records[i];
    const int64_t receive = series.receive_utime[i];
    const double receive_s = spanUs(receive, log_start_receive_utime) * kUsToS;
    ProcessHeartbeatMetrics& p = by_process[h.process];
    if (p.heartbeats == 0) {
      p.process = h.process;
      p.first_receive_s = receive_s;
    } else {
      p.max_interval_s = std::max(p.max_interval_s, spanUs(receive, last_receive[h.process]) * kUsToS);
      const int64_t step = difference(h.seq, p.last.seq);
      if (h.pid == p.last.pid && step > 1) p.seq_lost = sum(p.seq_lost, step - 1);
    }
    ++p.heartbeats;
    p.last_receive_s = receive_s;
    p.last = h;
    last_receive[h.process] = receive;
    pids[h.process].insert(h.pid);
    p.distinct_pids = static_cast<int64_t>(pids[h.process].size());
  }
  std::vector<ProcessHeartbeatMetrics> out;
  for (auto& [name, p] : by_process) out.push_back(std::move(p));
  return out;
}

LogMetrics computeLogMetrics(const MetricsInput& input, const MetricsOptions& options) {
  LogMetrics m;
  m.log = input.log;
  m.origin = findOrigin(input.channels);
  const int64_t start = input.log.first_receive_utime;

  std::vector<const ChannelTimeline*> sorted;
  for (const ChannelTimeline& c : input.channels) sorted.push_back(&c);
  std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->channel < b->channel; });
  const ChannelTimeline* clock = nullptr;
  for (const ChannelTimeline* c : sorted) {
    m.channels.push_back(computeChannelMetrics(*c, start, m.origin));
    if (!isHeartbeat(*c) && c->utime.size() >= 2 && (!clock || c->utime.size() > clock->utime.size())) clock = c;
  }
  m.real_time_factor = kNaN;
  if (clock) {
    m.clock_channel = clock->channel;
    const double receive_span = spanUs(clock->receive_utime.back(), clock->receive_utime.front());
    if (receive_span > 0.0) m.real_time_factor = spanUs(clock->utime.back(), clock->utime.front()) / receive_span;
  }
  for (const auto& [channel, gains] : input.gains) m.gains[channel] = computeGainsMetrics(gains);
  for (const auto& [channel, commands] : input.rate_commands) {
    m.rate_commands[channel] = computeRateCommandMetrics(commands, options.rate_command_period_s);
  }
  for (const auto& [channel, series] : input.heartbeats) m.heartbeats[channel] = computeHeartbeatMetrics(series, start);
  return m;
}

namespace {

JsonDocument logJson(const LogMetrics& m) {
  return {{"path", m.log.path}, {"file_bytes", m.log.file_bytes}, {"events", m.log.events},
          {"complete", m.log.complete()}, {"readable_bytes", m.log.readable_bytes},
          {"skipped_bytes", m.log.skipped_bytes}, {"truncated_tail_bytes", m.log.truncated_tail_bytes},
          {"first_receive_utime", m.log.first_receive_utime}, {"last_receive_utime", m.log.last_receive_utime},
          {"receive_duration_s", spanUs(m.log.last_receive_utime, m.log.first_receive_utime) * kUsToS}};
}

JsonDocument pacingJson(const LogMetrics& m) {
  JsonDocument out = JsonDocument::object();
  if (m.origin.valid) {
    out["origin_channel"] = m.origin.channel;
    out["origin_receive_utime"] = m.origin.receive_utime;
    out["origin_utime"] = m.origin.utime;
  }
  if (!m.clock_channel.empty()) out["clock_channel"] = m.clock_channel;
  out["real_time_factor"] = m.real_time_factor;
  return out;
}

JsonDocument gainsJson(const GainsMetrics& g) {
  return {{"count", g.count}, {"solve_us", toJson(g.solve_us)}, {"iterations", toJson(g.iterations)},
          {"residual", toJson(g.residual)}, {"status", counts(g.status)}, {"method", counts(g.method)}};
}

JsonDocument rateCommandJson(const RateCommandMetrics& r) {
  return {{"count", r.count}, {"nominal_period_ms", r.nominal_period_ms}, {"period_ms", toJson(r.period_ms)},
          {"jitter_ms", toJson(r.jitter_ms)}, {"utime_not_increasing", r.utime_not_increasing},
          {"rate_saturated", r.rate_saturated}, {"thrust_saturated", r.thrust_saturated},
          {"gains_status", counts(r.gains_status)}};
}

}  // namespace

void writeMetricsJson(std::ostream& out, const LogMetrics& m) {
  JsonDocument document = {{"log", logJson(m)}, {"pacing", pacingJson(m)}};
  JsonDocument& channels = document["channels"] = JsonDocument::object();
  for (const ChannelMetrics& c : m.channels) channels[c.channel] = channelJson(c);
  JsonDocument& gains = document["gains"] = JsonDocument::object();
  for (const auto& [channel, g] : m.gains) gains[channel] = gainsJson(g);
  JsonDocument& rate_cmd = document["rate_cmd"] = JsonDocument::object();
  for (const auto& [channel, r] : m.rate_commands) rate_cmd[channel] = rateCommandJson(r);
  JsonDocument& heartbeat = document["heartbeat"] = JsonDocument::object();
  for (const auto& [channel, processes] : m.heartbeats) {
    JsonDocument& by_process = heartbeat[channel] = JsonDocument::object();
    for (const ProcessHeartbeatMetrics& p : processes) by_process[p.process] = heartbeatJson(p);
  }
  writeJsonDocument(out, document);
}

}  // namespace sdlqr::logger
