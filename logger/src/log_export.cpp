#include "sdlqr/logger/log_export.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>
#include <unordered_map>

#include "lcm_decode.hpp"
#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/lcmtypes/generated/lcm_fields.hpp"
#include "sdlqr/logger/csv_row.hpp"
#include "sdlqr/logger/log_naming.hpp"
#include "sdlqr/logger/log_reader.hpp"
#include "sdlqr/bus/convert.hpp"

namespace sdlqr::logger {

namespace {

namespace fs = std::filesystem;

// Messages that metrics.json looks into beyond utime and seq.
template <class LcmType>
void collect(const LcmType&, const std::string&, int64_t, MetricsInput&) {}
void collect(const gains_t& m, const std::string& channel, int64_t, MetricsInput& input) {
  input.gains[channel].push_back(bus::fromLcm(m));
}
void collect(const rate_cmd_t& m, const std::string& channel, int64_t, MetricsInput& input) {
  input.rate_commands[channel].push_back(bus::fromLcm(m));
}
void collect(const heartbeat_t& m, const std::string& channel, int64_t receive_utime, MetricsInput& input) {
  HeartbeatSeries& series = input.heartbeats[channel];
  series.records.push_back(bus::fromLcm(m));
  series.receive_utime.push_back(receive_utime);
}

class ChannelSink {
 public:
  virtual ~ChannelSink() = default;
  virtual void consume(const LogEvent& event, ChannelTimeline& timeline, MetricsInput& input) = 0;
  virtual int64_t rows() const = 0;
  virtual void close() = 0;
};

template <class LcmType>
class CsvSink : public ChannelSink {
 public:
  explicit CsvSink(const fs::path& path) : path_(path), file_(path, std::ios::binary | std::ios::trunc), writer_(file_) {
    if (!file_) throw std::runtime_error("cannot write '" + path.string() + "'");
    const lcmtypes::TypeDescriptor& type = lcmtypes::LcmFields<LcmType>::type;
    for (std::size_t i = 0; i < type.num_columns; ++i) writer_.name(type.columns[i]);
    writer_.endRow();
  }

  void consume(const LogEvent& event, ChannelTimeline& timeline, MetricsInput& input) override {
    if (!detail::decodeEvent(event, &message_)) {
      ++timeline.decode_failures;
      return;
    }
    writeCsvRow(writer_, message_);
    timeline.addDecoded(event.receive_utime, message_.utime, message_.seq);
    collect(message_, timeline.channel, event.receive_utime, input);
  }

  int64_t rows() const override { return writer_.rows() - 1; }

  void close() override {
    file_.close();
    if (!file_) throw std::runtime_error("writing '" + path_.string() + "' failed");
  }

 private:
  fs::path path_;
  std::ofstream file_;
  CsvWriter writer_;
  LcmType message_;
};

struct ChannelState {
  size_t timeline = 0;
  std::unique_ptr<ChannelSink> sink;
  std::string csv_path;
};

std::unique_ptr<ChannelSink> makeSink(std::string_view lcm_type, const fs::path& path) {
  std::unique_ptr<ChannelSink> sink;
  lcmtypes::visitLcmType(lcm_type, [&](auto tag) {
    using LcmType = typename decltype(tag)::type;
    sink = std::make_unique<CsvSink<LcmType>>(path);
  });
  return sink;
}

}  // namespace

ExportResult exportLog(const ExportOptions& options) {
  LogReader reader(options.log_path);
  LogEvent event;
  readFirstEvent(reader, &event);
  const fs::path out_dir = options.out_dir;
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error) throw std::runtime_error("cannot create '" + out_dir.string() + "': " + error.message());

  MetricsInput input;
  std::unordered_map<std::string, ChannelState> channels;
  ReadProgress progress(options.progress);
  for (bool have_event = true; have_event; have_event = reader.next(&event)) {
    const std::string name(event.channel);
    auto [it, inserted] = channels.try_emplace(name);
    ChannelState& state = it->second;
    if (inserted) {
      state.timeline = input.channels.size();
      ChannelTimeline timeline;
      timeline.channel = name;
      if (const ChannelType* type = findChannelType(splitChannel(name).base)) {
        timeline.lcm_type = std::string(type->lcm_type);
        state.csv_path = channelCsvPath(name);
        const fs::path path = out_dir / state.csv_path;
        fs::create_directories(path.parent_path());
        state.sink = makeSink(type->lcm_type, path);
      }
      input.channels.push_back(std::move(timeline));
    }
    ChannelTimeline& timeline = input.channels[state.timeline];
    timeline.addEvent(event.receive_utime, event.size);
    if (state.sink) state.sink->consume(event, timeline, input);
    progress.update(reader);
  }
  input.log = reader.status();

  ExportResult result;
  result.log = input.log;
  std::map<std::string, ExportedChannel> sorted;
  for (auto& [name, state] : channels) {
    const ChannelTimeline& timeline = input.channels[state.timeline];
    ExportedChannel out;
    out.channel = name;
    out.lcm_type = timeline.lcm_type;
    out.events = timeline.events;
    out.decode_failures = timeline.decode_failures;
    if (state.sink) {
      state.sink->close();
      out.rows = state.sink->rows();
      out.csv_path = (out_dir / state.csv_path).string();
    }
    sorted[name] = out;
  }
  for (auto& [name, channel] : sorted) result.channels.push_back(std::move(channel));

  result.metrics = computeLogMetrics(input, options.metrics);
  result.metrics_path = (out_dir / "metrics.json").string();
  std::ofstream metrics(result.metrics_path, std::ios::trunc);
  writeMetricsJson(metrics, result.metrics);
  metrics.close();
  if (!metrics) throw std::runtime_error("writing '" + result.metrics_path + "' failed");
  return result;
}

}  // namespace sdlqr::logger
