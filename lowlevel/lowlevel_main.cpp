// sdlqr-lowlevel: wires the bus to the 1 kHz bodyrate loop (lowlevel/ library). One MOTOR_CMD
// per accepted IMU sample; RATE_CMD, COMMAND and PARAMS only update the loop's inputs.

#include <algorithm>
#include <array>
#include <chrono>
#include <iostream>
#include <string>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/lowlevel/bodyrate_loop.hpp"
#include "sdlqr/lowlevel/param_check.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/watchdog_report.hpp"

using namespace sdlqr;

namespace {

// Loop counters that are not message rejections, mirrored into HEARTBEAT by their increase.
struct EventCounter {
  bus::Counters::Id id;
  const int64_t* value;
  int64_t reported = 0;
};

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-lowlevel", [&] {
    ProcessOptions options;
    ArgParser parser("sdlqr-lowlevel",
                     "Bodyrate loop, one step per IMU sample (1 kHz): rate PID, mixer with desaturation,\n"
                     "arming, and the RATE_CMD-silent failsafe (level, descend, disarm on the ground).\n"
                     "In: IMU, RATE_CMD, COMMAND, PARAMS (FIELD_MASS).  Out: MOTOR_CMD, HEARTBEAT.");
    addProcessOptions(parser, &options);
    parser.setEpilog("exit codes: 0 stopped by SIGINT/SIGTERM, 1 runtime failure, 2 bad option or configuration");
    parser.parseOrExit(argc, argv);

    const ConfigReader config = loadVehicleConfig(options.config_path);
    const VehicleParams vehicle = VehicleParams::load(config.child("vehicle"));
    const LqrParams lqr = LqrParams::load(config.child("lqr"));
    const double gravity = lqr.gravity;
    const ConfigReader lowlevel_config = config.child("lowlevel");
    const lowlevel::LowlevelParams params = lowlevel::LowlevelParams::load(lowlevel_config);
    lowlevel::throwIfInvalid(lowlevel_config, params.invalidReasonFor(vehicle, gravity));
    const ValidationLimits limits = ValidationLimits::load(config.child("validation"));
    lowlevel::throwIfInvalid(lowlevel_config, params.invalidReasonFor(limits));
    const FaultParams faults = FaultParams::load(config.child("faults"));
    if (options.print_config) {
      printProcessConfig(std::cout, "sdlqr-lowlevel", options.config_path,
                         {printedSection("vehicle", vehicle), printedSection("lqr", lqr),
                          printedSection("lowlevel", params), printedSection("faults", faults),
                          printedSection("validation", limits)});
      return 0;
    }
    lowlevel::BodyrateLoop loop(vehicle, params, limits, gravity);

    bus::Node bus("sdlqr-lowlevel", options);
    bus::Counters& counters = bus.counters();
    std::array<bus::Counters::Id, lowlevel::kImuRejectCount> imu_reject_ids{};
    for (int i = 1; i < lowlevel::kImuRejectCount; ++i) {
      imu_reject_ids[i] = counters.add(std::string("reject.imu.") + toString(static_cast<lowlevel::ImuReject>(i)));
    }
    std::array<bus::Counters::Id, lowlevel::kRateCommandRejectCount> rate_reject_ids{};
    for (int i = 1; i < lowlevel::kRateCommandRejectCount; ++i) {
      rate_reject_ids[i] =
          counters.add(std::string("reject.rate_cmd.") + toString(static_cast<lowlevel::RateCommandReject>(i)));
    }
    const auto command_reject_id = counters.add("reject.command.invalid");
    const auto command_replay_id = counters.add("reject.command.time_backwards");
    const auto command_future_id = counters.add("reject.command.time_future");
    const auto params_reject_id = counters.add("reject.params.invalid");
    const auto mass_reject_id = counters.add("reject.params.mass");
    // IMU age on wall time (a silent simulator brings no IMU time); RATE_CMD age is judged by the
    // loop in IMU time (lowlevel.rate_cmd_timeout, the failsafe) and mirrored here on wall time.
    Watchdog imu_watchdog(faults.lowlevel_imu_timeout_s);
    Watchdog rate_watchdog(params.rate_cmd_timeout);
    bus::WatchdogReport imu_report(counters, "imu");
    bus::WatchdogReport rate_report(counters, "rate_cmd");
    // COMMAND and PARAMS are rare and each one changes the flight: a replayed old one (same or
    // older utime and seq) or one from the future is refused.
    OrderGate command_order, params_order;
    int64_t imu_utime = -1;
    const lowlevel::LowlevelCounters& loop_counters = loop.counters();
    std::array<EventCounter, 8> events{{
        {counters.add("imu.resyncs"), &loop_counters.imu_resyncs},
        {counters.add("arm.refused"), &loop_counters.arm_refused},
        {counters.add("failsafe.entries"), &loop_counters.failsafe_entries},
        {counters.add("failsafe.recoveries"), &loop_counters.failsafe_recoveries},
        {counters.add("failsafe.touchdowns"), &loop_counters.failsafe_touchdowns},
        {counters.add("disarm.auto"), &loop_counters.auto_disarms},
        {counters.add("mixer.saturated_steps"), &loop_counters.saturated_steps},
        {counters.add("output.nonfinite"), &loop_counters.nonfinite_outputs},
    }};

    motor_cmd_t motor_msg;
    bus.subscribe<imu_t>(channel::kImu, [&](const imu_t& msg) {
      const MotorCommand command = loop.step(bus::fromLcm(msg));
      const lowlevel::ImuReject reason = loop.lastImuReject();
      if (reason != lowlevel::ImuReject::kNone) {
        bus.countRejected(imu_reject_ids[static_cast<size_t>(reason)]);
        return;
      }
      imu_watchdog.feed(bus::monotonicSeconds());
      imu_utime = command.utime;
      motor_msg = bus::toLcm(command);
      bus.publish(channel::kMotorCommand, motor_msg);
      bus.setSimTime(command.utime);
      for (EventCounter& event : events) {
        if (*event.value != event.reported) {
          counters.increment(event.id, *event.value - event.reported);
          event.reported = *event.value;
        }
      }
      bus.setState(command.mode == MotorMode::kFailsafe ? bus::ProcessState::kFailsafe : bus::ProcessState::kRunning);
    }, 64, std::chrono::microseconds(1000));  // a step longer than the IMU period is a missed deadline
    bus.subscribe<rate_cmd_t>(channel::kRateCommand, [&](const rate_cmd_t& msg) {
      const lowlevel::RateCommandReject reason = loop.setRateCommand(bus::fromLcm(msg));
      if (reason != lowlevel::RateCommandReject::kNone) {
        bus.countRejected(rate_reject_ids[static_cast<size_t>(reason)]);
        return;
      }
      rate_watchdog.feed(bus::monotonicSeconds());
    }, 1);
    int64_t last_command_seq = -1;
    bus.subscribe<command_t>(channel::kCommand, [&](const command_t& msg) {
      const Command command = bus::fromLcm(msg);
      if (validate(command, limits) != RejectReason::kNone) {
        bus.countRejected(command_reject_id);
        return;
      }
      const RejectReason order = command_order.offer(command.utime, command.seq, imu_utime);
      if (order != RejectReason::kNone) {
        bus.countRejected(order == RejectReason::kTimeBackwards ? command_replay_id : command_future_id);
        return;
      }
      // The mission re-sends its current command (same seq) for a restarted controller: acting on
      // it again would re-arm a vehicle the failsafe has landed.
      if (command.seq == last_command_seq) return;
      last_command_seq = command.seq;
      loop.handleCommand(command);  // a refused arm is counted by the loop ("arm.refused")
    }, 16);
    bus.subscribe<params_t>(channel::kParams, [&](const params_t& msg) {
      const ParamsUpdate update = bus::fromLcm(msg);
      if (validate(update, limits) != RejectReason::kNone ||
          params_order.offer(update.utime, update.seq, imu_utime) != RejectReason::kNone) {
        bus.countRejected(params_reject_id);
        return;
      }
      if ((update.field_mask & ParamsUpdate::kMass) != 0 && !loop.setMass(update.mass)) bus.countRejected(mass_reject_id);
    }, 16);

    const int spin_ms = std::max(1, static_cast<int>(faults.lowlevel_imu_timeout_s * 1e3 / 4));
    while (bus.spin(spin_ms)) {
      const double now = bus::monotonicSeconds();
      // Without IMU samples nothing can be computed or sent: the state says so.
      if (imu_watchdog.check(now)) bus.setState(bus::ProcessState::kFailsafe);
      rate_watchdog.check(now);
      imu_report.update(imu_watchdog, now);
      rate_report.update(rate_watchdog, now);
    }
    bus.shutdown();
    return 0;
  });
}
