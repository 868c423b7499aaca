// sdlqr-sim: the plant on the bus. Steps the simulator library at its physics rate, paced
// against the wall clock by --rate, applies MOTOR_CMD and DISTURBANCE between steps, and
// publishes IMU, VIO_POSE and SIM_TRUTH stamped with the simulation time it owns.

#include <sys/select.h>

#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/sim/simulator.hpp"

namespace sdlqr {
namespace {

using Clock = std::chrono::steady_clock;

// After a stall the schedule restarts from now instead of replaying every missed step at once:
// a burst of hundreds of IMU samples would be worse for the stack than a short slow-down.
constexpr int64_t kMaxCatchUpSteps = 20;

struct Options {
  ProcessOptions process;
  double rate = 1.0;
  long long seed = -1;
  double duration = 0.0;
};

Options parseOptions(int argc, char** argv) {
  Options o;
  ArgParser parser("sdlqr-sim", "Simulated quadrotor (DESIGN §6): publishes IMU, VIO_POSE and SIM_TRUTH, takes\n"
                                "MOTOR_CMD and DISTURBANCE, and owns the simulation clock.");
  addProcessOptions(parser, &o.process);
  parser.addOption("--rate", &o.rate, "FACTOR", "simulated seconds per wall second (1 real time, 2 twice as fast)");
  parser.addOption("--seed", &o.seed, "N", "noise seed, >= 0 (default: sim.seed of the config)");
  parser.addOption("--duration", &o.duration, "S", "simulated seconds to run, 0 = until stopped (default 0)");
  parser.setEpilog(
      "The vehicle starts landed at sim.initial_position; see the `sim:` section of config/quad255.yaml.\n"
      "Exit codes: 0 stopped (SIGINT/SIGTERM or --duration), 2 bad option or configuration, 1 runtime error.");
  parser.parseOrExit(argc, argv);
  if (!(o.rate > 0.0 && o.rate <= 1000.0)) throw std::invalid_argument("--rate: must be in (0, 1000]");
  if (o.seed < -1) throw std::invalid_argument("--seed: must be >= 0");
  if (!(o.duration >= 0.0)) throw std::invalid_argument("--duration: must be >= 0");
  return o;
}

bool waitReadable(int fd, Clock::duration timeout) {
  const auto us = std::chrono::duration_cast<std::chrono::microseconds>(timeout).count();
  timeval tv{};
  tv.tv_sec = static_cast<time_t>(us / 1000000);
  tv.tv_usec = static_cast<suseconds_t>(us % 1000000);
  fd_set readable;
  FD_ZERO(&readable);
  FD_SET(fd, &readable);
  return select(fd + 1, &readable, nullptr, nullptr, &tv) > 0;
}

// Handles messages as they arrive until the deadline, so a MOTOR_CMD reaches the next step.
void serviceBusUntil(bus::Node& node, Clock::time_point deadline) {
  const int fd = node.lcm().getFileno();
  while (node.running()) {
    const auto remaining = deadline - Clock::now();
    if (remaining <= Clock::duration::zero()) break;
    if (waitReadable(fd, remaining)) node.spin(0);
  }
}

int run(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  const ConfigReader config = loadVehicleConfig(options.process.config_path);
  const VehicleParams vehicle = VehicleParams::load(config.child("vehicle"));
  sim::SimParams params = sim::SimParams::load(config.child("sim"));
  if (options.seed >= 0) params.seed = options.seed;
  if (options.process.print_config) {
    printProcessConfig(std::cout, "sdlqr-sim", options.process.config_path,
                       {printedSection("vehicle", vehicle), printedSection("sim", params)});
    return 0;
  }
  sim::Simulator simulator(vehicle, params);

  bus::Node node("sdlqr-sim", options.process);
  auto& counters = node.counters();
  // Counter ids indexed by fault value.
  static_assert(static_cast<size_t>(sim::MotorCommandFault::kMode) < 8);
  static_assert(static_cast<size_t>(sim::DisturbanceFault::kQueueFull) < 8);
  std::array<bus::Counters::Id, 8> motor_reject{};
  for (sim::MotorCommandFault f : sim::kAllMotorCommandFaults) {
    motor_reject[static_cast<size_t>(f)] = counters.add(sim::counterName(f));
  }
  std::array<bus::Counters::Id, 8> disturbance_reject{};
  for (sim::DisturbanceFault f : sim::kAllDisturbanceFaults) {
    disturbance_reject[static_cast<size_t>(f)] = counters.add(sim::counterName(f));
  }
  const bus::Counters::Id disturbances_accepted = counters.add("disturbance.accepted");
  const bus::Counters::Id crashes = counters.add("sim.crash");
  // Replayed or forged times: a motor command older than the last applied one, or stamped ahead
  // of the simulation clock, is not the lowlevel's answer to the current IMU sample.
  const bus::Counters::Id motor_backwards = counters.add("reject.motor_cmd.time_backwards");
  const bus::Counters::Id motor_future = counters.add("reject.motor_cmd.time_future");
  const bus::Counters::Id disturbance_order = counters.add("reject.disturbance.order");
  TimeGate motor_time(0);
  OrderGate disturbance_gate;

  node.subscribe<motor_cmd_t>(channel::kMotorCommand, [&](const motor_cmd_t& m) {
    const RejectReason time = motor_time.check(m.utime, simulator.utime());
    if (time != RejectReason::kNone) {
      node.countRejected(time == RejectReason::kTimeBackwards ? motor_backwards : motor_future);
      return;
    }
    motor_time.accept(m.utime);
    const sim::MotorCommandFault fault = simulator.setMotorCommand(bus::fromLcm(m));
    if (fault != sim::MotorCommandFault::kNone) node.countRejected(motor_reject[static_cast<size_t>(fault)]);
  }, 1);
  // Every disturbance request matters, so they queue rather than replace each other.
  node.subscribe<disturbance_t>(channel::kDisturbance, [&](const disturbance_t& m) {
    if (disturbance_gate.offer(m.utime, m.seq, simulator.utime()) != RejectReason::kNone) {
      node.countRejected(disturbance_order);
      return;
    }
    const sim::DisturbanceFault fault = simulator.addDisturbance(bus::fromLcm(m));
    if (fault == sim::DisturbanceFault::kNone) {
      counters.increment(disturbances_accepted);
    } else {
      node.countRejected(disturbance_reject[static_cast<size_t>(fault)]);
    }
  }, 16);

  std::cerr << "sdlqr-sim: " << params.physics_rate_hz << " Hz physics, rate x" << options.rate << ", seed "
            << params.seed << ", channel prefix '" << options.process.vehicle << "'\n";

  const auto wall_period = std::chrono::duration<double>(simulator.period() / options.rate);
  const int64_t last_step = options.duration > 0.0 ? std::llround(options.duration * params.physics_rate_hz) : -1;
  Clock::time_point anchor = Clock::now();
  int64_t anchor_step = simulator.stepCount();
  int64_t deadline_misses = 0;
  bool crash_reported = false;
  node.setState(bus::ProcessState::kRunning);
  node.setSimTime(simulator.utime());
  node.publishHeartbeat();

  while (node.running() && (last_step < 0 || simulator.stepCount() < last_step)) {
    const int64_t next_step = simulator.stepCount() + 1;
    const auto deadline =
        anchor + std::chrono::duration_cast<Clock::duration>((next_step - anchor_step) * wall_period);
    serviceBusUntil(node, deadline);
    if (!node.spin(0)) break;  // drains a last message and publishes the heartbeat when due
    const auto lateness = Clock::now() - deadline;
    if (lateness > wall_period) {
      node.countDeadlineMiss();
      ++deadline_misses;
      if (lateness > kMaxCatchUpSteps * wall_period) {
        anchor = Clock::now();
        anchor_step = next_step;
      }
    }

    const sim::StepOutput out = simulator.step();
    node.setSimTime(simulator.utime());
    if (out.imu) node.publish(channel::kImu, bus::toLcm(*out.imu));
    if (out.vio) node.publish(channel::kVioPose, bus::toLcm(*out.vio));
    if (out.truth) node.publish(channel::kSimTruth, bus::toLcm(*out.truth));
    if (simulator.crashed() && !crash_reported) {
      crash_reported = true;
      counters.increment(crashes);
      node.setLastError("vehicle crashed at t=" + std::to_string(simulator.utime() * 1e-6) + " s");
      std::cerr << "sdlqr-sim: vehicle crashed at t=" << simulator.utime() * 1e-6 << " s\n";
    }
  }

  node.shutdown();
  std::cerr << "sdlqr-sim: stopped at t=" << simulator.utime() * 1e-6 << " s after " << simulator.stepCount()
            << " steps, " << deadline_misses << " deadline misses" << (simulator.crashed() ? ", crashed" : "") << "\n";
  return 0;
}

}  // namespace
}  // namespace sdlqr

int main(int argc, char** argv) {
  return sdlqr::runMain("sdlqr-sim", [&] { return sdlqr::run(argc, argv); });
}
