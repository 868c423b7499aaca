// sdlqr-replay: recomputes a recorded flight (IMU, VIO_POSE, COMMAND, TRAJECTORY, PARAMS through
// fresh estimator, gain solver and controller libraries, with the recorded pairing), writes the
// recomputed STATE_EST, RATE_CMD, REFERENCE and GAINS under a prefix to an LCM log, and compares
// them with the recorded outputs field by field.

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "sdlqr/messages/channels.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/replay/flight_loader.hpp"
#include "sdlqr/replay/output_comparison.hpp"
#include "sdlqr/replay/recomputation.hpp"

namespace {

using namespace sdlqr;

// Writes recomputed outputs to the replay log (and, when live, to the bus) under the prefix.
class OutputWriter {
 public:
  OutputWriter(const std::string& path, std::string prefix, const std::string& vehicle, bus::Node* bus)
      : log_(path, "w"), prefix_(std::move(prefix)), vehicle_(vehicle), bus_(bus) {
    if (!log_.good()) throw std::invalid_argument("--out: cannot write " + path);
  }

  template <class Plain>
  void write(std::string_view base, const Plain& message, int64_t utime) {
    const auto lcm_message = bus::toLcm(message);
    const std::string channel = prefix_ + "/" + channel::name(vehicle_, base);
    buffer_.resize(static_cast<size_t>(lcm_message.getEncodedSize()));
    lcm_message.encode(buffer_.data(), 0, static_cast<int>(buffer_.size()));
    lcm::LogEvent event;
    event.timestamp = utime;  // simulation time: the replay has no receive clock
    event.channel = channel;
    event.datalen = static_cast<int32_t>(buffer_.size());
    event.data = buffer_.data();
    if (log_.writeEvent(&event) != 0) throw std::runtime_error("cannot write the replay log");
    ++written_;
    if (bus_ != nullptr) bus_->publishEncoded(channel, buffer_.data(), static_cast<int>(buffer_.size()));
  }
  int64_t written() const { return written_; }

 private:
  lcm::LogFile log_;
  std::string prefix_;
  std::string vehicle_;
  bus::Node* bus_;
  std::vector<uint8_t> buffer_;
  int64_t written_ = 0;
};

// Writes the outputs computed since the last call.
struct OutputCursor {
  std::size_t state = 0, rate = 0, reference = 0, gains = 0;
  void flush(const replay::ReplayOutputs& out, OutputWriter& writer) {
    for (; state < out.state_estimate.size(); ++state) {
      writer.write(channel::kStateEstimate, out.state_estimate[state], out.state_estimate[state].utime);
    }
    for (; gains < out.gains.size(); ++gains) writer.write(channel::kGains, out.gains[gains], out.gains[gains].utime);
    for (; rate < out.rate_command.size(); ++rate) {
      writer.write(channel::kRateCommand, out.rate_command[rate], out.rate_command[rate].utime);
    }
    for (; reference < out.reference.size(); ++reference) {
      writer.write(channel::kReference, out.reference[reference], out.reference[reference].utime);
    }
  }
};

std::string defaultOutPath(const std::string& log) {
  std::filesystem::path p(log);
  return (p.parent_path() / (p.stem().string() + ".replay.lcmlog")).string();
}

struct ReplayOptions {
  ProcessOptions process;
  std::vector<std::string> positional;
  std::string out_path, prefix = "REPLAY";
  double speed = 0.0, tolerance = 0.0;
  bool fast = false, publish = false;
};

void addReplayOptions(ArgParser& parser, ReplayOptions& o) {
  parser.allowPositional(&o.positional, "LOG");
  addProcessOptions(parser, &o.process);
  parser.addOption("--out", &o.out_path, "FILE", "replay log to write (default: LOG's name with .replay.lcmlog; never overwritten)");
  parser.addOption("--prefix", &o.prefix, "P", "channel prefix of the recomputed outputs (default REPLAY)");
  parser.addFlag("--fast", &o.fast, "as fast as the computer allows (the default)");
  parser.addOption("--speed", &o.speed, "F", "pace the inputs at F x real time of the recorded simulation clock",
                   Range::above(0));
  parser.addFlag("--publish", &o.publish, "also publish the recomputed outputs on the bus (watch them in lcm-spy)");
  parser.addOption("--tolerance", &o.tolerance, "T", "count differences up to T as reproduced (default 0: bit for bit)",
                   Range::atLeast(0));
}

// Parses and checks the command line; every bad option fails before the configuration or log is read.
void parseReplayOptions(int argc, char** argv, ReplayOptions& o) {
  ArgParser parser(
      "sdlqr-replay",
      "Replay that recomputes: feeds a recorded flight's IMU, VIO_POSE, COMMAND, TRAJECTORY and PARAMS\n"
      "into a fresh estimator, gain solver and controller (their libraries, in one thread, with the\n"
      "validation of their processes), each process given the pairing its recorded outputs name\n"
      "(RATE_CMD.gains_seq, GAINS.reference_seq, ...). Writes the recomputed STATE_EST, RATE_CMD,\n"
      "REFERENCE and GAINS as PREFIX/<channel> to an LCM log and compares them with the recorded ones:\n"
      "bit for bit, else the first differing message and the largest difference of each field.");
  addReplayOptions(parser, o);
  parser.setEpilog(
      "--config must be the vehicle file the flight used (./sdlqr replay defaults to config/quad255.yaml).\n"
      "example: sdlqr-replay runs/20240501-101500-hover_jumps/flight.lcmlog --config config/quad255.yaml\n"
      "exit codes: 0 outputs reproduced (bit for bit, or within --tolerance), 1 outputs differ,\n"
      "            2 bad option, configuration or log");
  parser.parseOrExit(argc, argv);
  if (o.positional.size() != 1) throw std::invalid_argument("expected one LOG, got " + std::to_string(o.positional.size()));
  if (o.process.config_path.empty()) throw std::invalid_argument("--config: the vehicle file of the flight is required");
  if (o.fast && o.speed > 0.0) throw std::invalid_argument("--fast and --speed exclude each other");
  if (o.prefix.empty() || o.prefix.find('/') != std::string::npos) {
    throw std::invalid_argument("--prefix: one non-empty word without '/'");
  }
  if (o.out_path.empty()) o.out_path = defaultOutPath(o.positional[0]);
  if (std::filesystem::exists(o.out_path)) throw std::invalid_argument("--out: refusing to overwrite " + o.out_path);
}

replay::ReplayParams loadReplayParams(const ConfigReader& config) {
  replay::ReplayParams params;
  params.estimator = estimator::EstimatorParams::load(config.child("estimator"));
  params.lqr = LqrParams::loadWithVehicle(config);
  params.controller = controller::ControllerParams::load(config.child("controller"));
  params.gains = gains::GainsParams::load(config.child("gains"));
  params.faults = FaultParams::load(config.child("faults"));
  params.validation = ValidationLimits::load(config.child("validation"));
  return params;
}

void printReplayConfig(const std::string& config_path, const replay::ReplayParams& params) {
  printProcessConfig(std::cout, "sdlqr-replay", config_path,
                     {printedSection("lqr", params.lqr), printedSection("estimator", params.estimator),
                      printedSection("controller", params.controller), printedSection("gains", params.gains),
                      printedSection("faults", params.faults), printedSection("validation", params.validation)});
}

// The recorded inputs, with a line saying how many of each; a log without IMU has nothing to replay.
replay::RecordedFlight loadFlight(const std::string& log_path, const std::string& vehicle) {
  replay::LoadStats load;
  replay::RecordedFlight flight = replay::loadRecordedFlight(log_path, vehicle, &load);
  if (flight.imu.empty()) {
    throw std::invalid_argument(log_path + ": no " + channel::name(vehicle, channel::kImu) +
                                " messages to replay (wrong --vehicle?)");
  }
  std::cout << "sdlqr-replay: " << log_path << ": " << load.events << " events, replaying " << flight.imu.size()
            << " IMU, " << flight.vio_pose.size() << " VIO_POSE, " << flight.command.size() << " COMMAND, "
            << flight.trajectory.size() << " TRAJECTORY, " << flight.params.size() << " PARAMS"
            << (load.complete ? "" : " (log truncated)") << (load.decode_failures ? " (decode failures)" : "")
            << "\n";
  return flight;
}

// How the recomputation went: the simulation time it covered, from when, and whether the bus stopped it.
struct RunStats {
  std::chrono::steady_clock::time_point start;
  int64_t first_utime = 0, last_utime = 0;
  bool interrupted = false;
};

// Steps the recomputation through the flight, paced at `speed` x the recorded clock when > 0,
// writing each step's outputs as they come.
RunStats recompute(replay::Recomputation& recomputation, OutputWriter& writer, bus::Node* bus, double speed) {
  OutputCursor cursor;
  RunStats run;
  run.start = std::chrono::steady_clock::now();
  run.first_utime = recomputation.done() ? 0 : recomputation.nextUtime();
  run.last_utime = run.first_utime;
  while (!recomputation.done()) {
    run.last_utime = recomputation.nextUtime();
    if (speed > 0.0) {
      const auto due =
          run.start + std::chrono::microseconds(static_cast<int64_t>((run.last_utime - run.first_utime) / speed));
      if (due > std::chrono::steady_clock::now()) std::this_thread::sleep_until(due);
    }
    recomputation.step();
    cursor.flush(recomputation.outputs(), writer);
    if (bus && !bus->spin(0)) {
      run.interrupted = true;
      break;
    }
  }
  recomputation.finish();
  cursor.flush(recomputation.outputs(), writer);
  return run;
}

void printPairing(const replay::Recomputation& recomputation) {
  const replay::PairingStats& pairing = recomputation.pairing();
  std::printf("pairing: GAINS fed as named by RATE_CMD %lld (from the recording: %lld), REFERENCE fed as named by "
              "GAINS %lld (from the recording: %lld), unpaired solves %lld, rejected inputs %lld, solve failures %lld;\n"
              "         STATE_EST missed on the bus (one-message queues) by the controller %lld, by the solver %lld\n",
              static_cast<long long>(pairing.gains_from_replay), static_cast<long long>(pairing.gains_from_record),
              static_cast<long long>(pairing.references_from_replay),
              static_cast<long long>(pairing.references_from_record),
              static_cast<long long>(pairing.solves_unpaired), static_cast<long long>(pairing.rejected),
              static_cast<long long>(pairing.solve_failures),
              static_cast<long long>(pairing.estimates_missed_by_controller),
              static_cast<long long>(pairing.estimates_missed_by_solver));
  std::printf("foreign inputs (recorded outputs the replay did not compute, judged by the cores): STATE_EST %lld, "
              "GAINS %lld\n",
              static_cast<long long>(pairing.foreign_estimates), static_cast<long long>(pairing.foreign_gains));
  for (const auto& [process, health] : {std::pair{"sdlqr-estimator", &recomputation.estimator().health()},
                                        std::pair{"sdlqr-gains", &recomputation.gains().health()},
                                        std::pair{"sdlqr-controller", &recomputation.controller().health()}}) {
    std::printf("rejections %s: %s\n", process, health->describeRejections().c_str());
  }
}

int replayFlight(const ReplayOptions& o) {
  const ConfigReader config = loadVehicleConfig(o.process.config_path);
  const replay::ReplayParams params = loadReplayParams(config);
  if (o.process.print_config) {
    printReplayConfig(o.process.config_path, params);
    return 0;
  }

  const auto load_start = std::chrono::steady_clock::now();
  const replay::RecordedFlight flight = loadFlight(o.positional[0], o.process.vehicle);
  std::unique_ptr<bus::Node> bus;
  if (o.publish) bus = std::make_unique<bus::Node>("sdlqr-replay", o.process);
  OutputWriter writer(o.out_path, o.prefix, o.process.vehicle, bus.get());
  replay::Recomputation recomputation(params, flight);
  const RunStats run = recompute(recomputation, writer, bus.get(), o.speed);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - run.start).count();
  const double load_s = std::chrono::duration<double>(run.start - load_start).count();
  const double flight_s = static_cast<double>(run.last_utime - run.first_utime) * 1e-6;
  if (bus) bus->shutdown();

  std::printf("recomputed %.1f s of flight in %.3f s (%.0fx real time; log read in %.2f s)%s\n", flight_s, wall_s,
              wall_s > 0 ? flight_s / wall_s : 0.0, load_s, run.interrupted ? " -- INTERRUPTED" : "");
  printPairing(recomputation);
  const replay::Comparison comparison = replay::compareOutputs(flight, recomputation.outputs(), o.tolerance);
  std::cout << replay::formatComparison(comparison);
  std::cout << "replay log: " << o.out_path << " (" << writer.written() << " messages under " << o.prefix << "/)\n";
  if (run.interrupted) return 1;
  return comparison.bitForBit() || comparison.withinTolerance() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-replay", [&] {
    ReplayOptions options;
    parseReplayOptions(argc, argv, options);
    return replayFlight(options);
  });
}
