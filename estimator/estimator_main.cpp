// sdlqr-estimator: wires IMU and VIO_POSE from the bus into the estimator library and publishes
// STATE_EST on the IMU-time output grid. All logic lives in sdlqr_estimator.

#include <chrono>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "sdlqr/messages/channels.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/estimator/estimator.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"

namespace {

using sdlqr::estimator::Estimator;
using sdlqr::estimator::EstimatorCounters;
using sdlqr::estimator::Rejection;

// Every IMU sample is integrated, so the IMU subscription queues 64 samples (64 ms at 1 kHz) to
// ride out a descheduled process without losing data; a lost sample would leave a hole bridged
// only by interpolation. Poses are few and each one is worth fusing, even late.
constexpr int kImuQueueCapacity = 64;
// An IMU sample handled slower than the IMU period (1 kHz) is a missed deadline.
constexpr std::chrono::microseconds kImuBudget{1000};
constexpr int kVioQueueCapacity = 4;

// Mirrors the library's counters into the heartbeat, adding only what changed since last time.
class CounterBridge {
 public:
  explicit CounterBridge(sdlqr::bus::Node& node) : node_(node) {
    for (int i = 0; i < sdlqr::estimator::kRejectionCount; ++i) {
      reject_ids_.push_back(node.counters().add(sdlqr::estimator::counterName(static_cast<Rejection>(i))));
    }
    fused_id_ = node.counters().add("vio.fused");
    init_id_ = node.counters().add("estimator.initializations");
    clock_reset_id_ = node.counters().add("estimator.clock_resets");
    vio_reset_id_ = node.counters().add("estimator.vio_resets");
    clipping_id_ = node.counters().add("imu.clipping");
    nan_output_id_ = node.counters().add("error.non_finite_output");
  }

  void sync(const EstimatorCounters& now) {
    for (int i = 0; i < sdlqr::estimator::kRejectionCount; ++i) {
      const size_t k = static_cast<size_t>(i);
      for (int64_t n = seen_.rejected[k]; n < now.rejected[k]; ++n) node_.countRejected(reject_ids_[k]);
    }
    node_.counters().increment(fused_id_, now.vio_fused - seen_.vio_fused);
    node_.counters().increment(init_id_, now.initializations - seen_.initializations);
    node_.counters().increment(clock_reset_id_, now.clock_resets - seen_.clock_resets);
    node_.counters().increment(vio_reset_id_, now.vio_resets - seen_.vio_resets);
    node_.counters().increment(clipping_id_, now.accel_clipping - seen_.accel_clipping);
    seen_ = now;
  }

  void countNonFiniteOutput() {
    node_.countError();
    node_.counters().increment(nan_output_id_);
    node_.setLastError("non-finite state estimate withheld");
  }

 private:
  sdlqr::bus::Node& node_;
  EstimatorCounters seen_;
  std::vector<sdlqr::bus::Counters::Id> reject_ids_;
  sdlqr::bus::Counters::Id fused_id_ = 0;
  sdlqr::bus::Counters::Id init_id_ = 0;
  sdlqr::bus::Counters::Id clock_reset_id_ = 0;
  sdlqr::bus::Counters::Id vio_reset_id_ = 0;
  sdlqr::bus::Counters::Id clipping_id_ = 0;
  sdlqr::bus::Counters::Id nan_output_id_ = 0;
};

sdlqr::bus::ProcessState processStateOf(sdlqr::EstimatorStatus status) {
  switch (status) {
    case sdlqr::EstimatorStatus::kOk: return sdlqr::bus::ProcessState::kRunning;
    case sdlqr::EstimatorStatus::kVioTimeout: return sdlqr::bus::ProcessState::kDegraded;
    case sdlqr::EstimatorStatus::kInitializing: break;
  }
  return sdlqr::bus::ProcessState::kStarting;
}

}  // namespace

int main(int argc, char** argv) {
  sdlqr::ArgParser parser("sdlqr-estimator",
                          "Error-state EKF: fuses IMU with delayed VIO poses at their capture time and publishes\n"
                          "STATE_EST at the configured rate (default 250 Hz) on the IMU-time grid. Reads the\n"
                          "`estimator:` section of the vehicle file. Never reads SIM_TRUTH.");
  sdlqr::ProcessOptions options;
  sdlqr::addProcessOptions(parser, &options);
  parser.setEpilog(
      "channels: in IMU, VIO_POSE; out STATE_EST, HEARTBEAT (with the vehicle prefix if given)\n"
      "exit codes: 0 stopped by SIGINT/SIGTERM, 1 runtime failure, 2 bad option or configuration");
  parser.parseOrExit(argc, argv);

  return sdlqr::runMain(parser.program(), [&]() {
    sdlqr::estimator::EstimatorParams params;
    if (!options.config_path.empty()) {
      // The vehicle file's reader: an unknown section is an error here as in every process.
      const sdlqr::ConfigReader root = sdlqr::loadVehicleConfig(options.config_path);
      params = sdlqr::estimator::EstimatorParams::load(root.child("estimator"));
    }
    if (options.print_config) {
      sdlqr::printProcessConfig(std::cout, "sdlqr-estimator", options.config_path,
                                {sdlqr::printedSection("estimator", params)});
      return 0;
    }
    Estimator estimator(params);

    sdlqr::bus::Node node("sdlqr-estimator", options);
    CounterBridge counters(node);

    node.subscribe<sdlqr::imu_t>(
        sdlqr::channel::kImu,
        [&](const sdlqr::imu_t& msg) {
          const sdlqr::ImuSample sample = sdlqr::bus::fromLcm(msg);
          const auto estimate = estimator.onImu(sample);
          counters.sync(estimator.counters());
          if (!estimate) return;
          node.setSimTime(estimate->utime);
          node.setState(processStateOf(estimate->status));
          if (!estimate->state().allFinite() || !estimate->body_rate.allFinite()) {
            counters.countNonFiniteOutput();
            return;
          }
          node.publish(sdlqr::channel::kStateEstimate, sdlqr::bus::toLcm(*estimate));
        },
        kImuQueueCapacity, kImuBudget);
    node.subscribe<sdlqr::vio_pose_t>(
        sdlqr::channel::kVioPose,
        [&](const sdlqr::vio_pose_t& msg) {
          estimator.onVio(sdlqr::bus::fromLcm(msg));
          counters.sync(estimator.counters());
        },
        kVioQueueCapacity);

    while (node.spin(100)) {
    }
    node.shutdown();
    return 0;
  });
}
