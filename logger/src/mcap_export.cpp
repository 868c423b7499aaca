#include "sdlqr/logger/mcap_export.hpp"

#include <fstream>
#include <map>
#include <stdexcept>

#include "sdlqr/foxglove/foxglove_schemas.hpp"
#include "sdlqr/foxglove/lcm_json.hpp"
#include "sdlqr/foxglove/mcap_writer.hpp"
#include "sdlqr/foxglove/vehicle_tracker.hpp"
#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/logger/log_reader.hpp"

namespace sdlqr::logger {

namespace {

constexpr int64_t kScenePeriodNs = 500'000'000;  // [ns] a SceneUpdate per vehicle every 0.5 s of log time (trails make them large)

class McapExporter {
 public:
  McapExporter(std::ostream& out, std::size_t chunk_size) : writer_(out, {"", "sdlqr-logger export --mcap", chunk_size}) {}

  void onEvent(const LogEvent& event) {
    const std::string name(event.channel);
    const ChannelName split = splitChannel(name);
    const ChannelType* type = findChannelType(split.base);
    const int64_t log_ns = event.receive_utime * 1000;
    const auto sequence = static_cast<uint32_t>(event.event_number);
    const std::size_t index = channel(name, type ? std::string(type->lcm_type) : std::string());
    ++result_.channels[index].events;
    if (type == nullptr) {
      write(index, sequence, log_ns, std::string_view(reinterpret_cast<const char*>(event.data), event.size));
      return;
    }
    if (!foxglove::lcmBytesToJson(type->lcm_type, event.data, static_cast<std::size_t>(event.size), &json_)) {
      ++result_.channels[index].undecodable;
      return;
    }
    write(index, sequence, log_ns, json_);
    derive(split, event, log_ns);
  }

  McapExportResult finish(const LogFileStatus& status) {
    writer_.finish();
    result_.log = status;
    result_.messages = writer_.statistics().messages;
    result_.chunks = writer_.statistics().chunks;
    return result_;
  }

 private:
  struct Derived {
    foxglove::VehicleTracker tracker;
    int64_t next_scene_ns = 0;
    uint32_t sequence = 0;
  };

  // The index of a topic's channel in the result, created on first use: an LCM type's JSON with
  // its generated schema, a Foxglove schema, or ("" ) the recorded bytes without a schema.
  std::size_t channel(const std::string& topic, const std::string& lcm_type) {
    const auto it = channel_index_.find(topic);
    if (it != channel_index_.end()) return it->second;
    uint16_t schema = 0;
    std::string schema_name;
    if (const lcmtypes::JsonSchemaText* s = lcm_type.empty() ? nullptr : foxglove::jsonSchemaOf(lcm_type)) {
      schema_name = std::string(s->name);
      schema = schemaId(schema_name, s->text);
    }
    const bool json = schema != 0;
    const uint16_t id = writer_.addChannel(schema, topic, json ? "json" : "x-lcm", {{"lcm_type", lcm_type}});
    channel_ids_.push_back(id);
    result_.channels.push_back({topic, schema_name, 0, 0, 0});
    return channel_index_[topic] = result_.channels.size() - 1;
  }

  std::size_t foxgloveChannel(const std::string& topic, const std::string& schema_name, std::string_view schema_text) {
    const auto it = channel_index_.find(topic);
    if (it != channel_index_.end()) return it->second;
    const uint16_t id = writer_.addChannel(schemaId(schema_name, schema_text), topic, "json");
    channel_ids_.push_back(id);
    result_.channels.push_back({topic, schema_name, 0, 0, 0});
    return channel_index_[topic] = result_.channels.size() - 1;
  }

  uint16_t schemaId(const std::string& name, std::string_view text) {
    const auto it = schema_ids_.find(name);
    if (it != schema_ids_.end()) return it->second;
    return schema_ids_[name] = writer_.addSchema(name, "jsonschema", std::string(text));
  }

  void write(std::size_t index, uint32_t sequence, int64_t log_ns, std::string_view data) {
    const auto time = static_cast<uint64_t>(std::max<int64_t>(0, log_ns));
    writer_.writeMessage(channel_ids_[index], sequence, time, time, data);
    ++result_.channels[index].written;
  }

  // The vehicle in Foxglove's schemas, from the message just written.
  void derive(const ChannelName& split, const LogEvent& event, int64_t log_ns) {
    Derived& d = derived_[split.vehicle];
    const auto update = d.tracker.onMessage(split.base, event.data, static_cast<std::size_t>(event.size));
    const foxglove::VehicleState& v = d.tracker.state();
    const std::string& vehicle = split.vehicle;
    using foxglove::foxgloveTopic;
    if (update == foxglove::VehicleTracker::Update::kTruth) {
      write(foxgloveChannel(foxgloveTopic(vehicle, "truth_tf"), "foxglove.FrameTransform", foxglove::kFrameTransformSchema),
            d.sequence++, log_ns, foxglove::dumpJson(foxglove::truthTransform(*v.truth, vehicle, log_ns)));
    } else if (update == foxglove::VehicleTracker::Update::kEstimate) {
      write(foxgloveChannel(foxgloveTopic(vehicle, "estimate_tf"), "foxglove.FrameTransform", foxglove::kFrameTransformSchema),
            d.sequence++, log_ns, foxglove::dumpJson(foxglove::estimateTransform(*v.estimate, vehicle, log_ns)));
      write(foxgloveChannel(foxgloveTopic(vehicle, "estimate_pose"), "foxglove.PoseInFrame", foxglove::kPoseInFrameSchema),
            d.sequence++, log_ns, foxglove::dumpJson(foxglove::estimatePose(*v.estimate, log_ns)));
    }
    if (v.truth && log_ns >= d.next_scene_ns) {
      d.next_scene_ns = log_ns + kScenePeriodNs;
      write(foxgloveChannel(foxgloveTopic(vehicle, "scene"), "foxglove.SceneUpdate", foxglove::kSceneUpdateSchema),
            d.sequence++, log_ns, foxglove::dumpJson(foxglove::sceneUpdate(v, vehicle, foxglove::VehicleGeometry{}, log_ns)));
    }
  }

  foxglove::McapWriter writer_;
  McapExportResult result_;
  std::map<std::string, std::size_t> channel_index_;
  std::vector<uint16_t> channel_ids_;  // per result channel
  std::map<std::string, uint16_t> schema_ids_;
  std::map<std::string, Derived> derived_;  // per vehicle prefix
  std::string json_;
};

}  // namespace

McapExportResult exportMcap(const McapExportOptions& options) {
  LogReader reader(options.log_path);
  LogEvent event;
  readFirstEvent(reader, &event);
  std::ofstream file(options.mcap_path, std::ios::binary | std::ios::trunc);
  if (!file) throw std::runtime_error("cannot write '" + options.mcap_path + "'");
  McapExporter exporter(file, options.chunk_size);
  ReadProgress progress(options.progress);
  for (bool have_event = true; have_event; have_event = reader.next(&event)) {
    exporter.onEvent(event);
    progress.update(reader);
  }
  McapExportResult result = exporter.finish(reader.status());
  file.close();
  if (!file) throw std::runtime_error("writing '" + options.mcap_path + "' failed");
  return result;
}

}  // namespace sdlqr::logger
