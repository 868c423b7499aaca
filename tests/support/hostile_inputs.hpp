#pragma once
// One set of hostile inputs and the rejections every path must count for them: the bus (real
// executables, read from HEARTBEAT), the replay (a log containing them) and the in-process loop
// (injected). Built from what a foreign publisher mid-flight has just heard, so each one is
// refused by a check of the receiving core and by nothing else:
//   far-future STATE_EST  the newest estimate 100 s later        ClockGate        gains, controller
//   destabilizing K       the newest GAINS with K negated         closed-loop check  controller
//   replayed COMMAND      the newest COMMAND, byte for byte       OrderGate        controller, lowlevel
//   NaN PARAMS            weights with a NaN                      validate         gains, controller, lowlevel
//   NaN IMU               the newest sample's time, NaN gyro      input checks     estimator, lowlevel
//   future RATE_CMD       10 s ahead of the IMU clock             lead check       lowlevel
//   NaN MOTOR_CMD         NaN thrust                              input checks     sim
//   NaN REFERENCE         NaN thrust input                        validate         gains
//   truncated GAINS       the newest GAINS' bytes less 8          size walk        controller
//                         (bytes exist on the bus and in a log only, not in the in-process loop)

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "sdlqr/messages/messages.hpp"

namespace sdlqr::testing {

struct HeardMessages {
  StateEstimate estimate;
  GainSet gains;
  Command command;
  ImuSample imu;
  Reference reference;
  RateCommand rate_command;    // for the seq only: a forged message repeats the newest seq, so
  MotorCommand motor_command;  // the bus counts no gap (loss) for it
};

struct HostileInputs {
  StateEstimate far_future_estimate;
  GainSet destabilizing_gains;
  Command replayed_command;
  ParamsUpdate nan_params;
  ImuSample nan_imu;
  RateCommand future_rate_command;
  MotorCommand nan_motor_command;
  Reference nan_reference;
};

inline HostileInputs makeHostileInputs(const HeardMessages& heard) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  HostileInputs h;
  h.far_future_estimate = heard.estimate;  // same seq: no gap or restart for the bus to count
  h.far_future_estimate.utime += 100'000'000;
  h.destabilizing_gains = heard.gains;
  h.destabilizing_gains.K = -heard.gains.K;
  // At the controller's clock: not older than the GAINS it accepted last.
  // 50 ms after the controller's clock: not older than any GAINS it may have accepted meanwhile.
  h.destabilizing_gains.utime = std::max(heard.gains.utime, heard.estimate.utime) + 50'000;
  h.replayed_command = heard.command;
  h.nan_params.utime = heard.estimate.utime;
  h.nan_params.seq = 0;
  h.nan_params.field_mask = ParamsUpdate::kWeights;
  h.nan_params.q_diag = State::Ones();
  h.nan_params.q_diag[0] = kNan;
  h.nan_params.r_diag = Input::Ones();
  h.nan_imu = heard.imu;  // not newer: the mission's clock stays where it is
  h.nan_imu.gyro[0] = kNan;
  h.future_rate_command.utime = heard.imu.utime + 10'000'000;
  h.future_rate_command.seq = heard.rate_command.seq;
  h.future_rate_command.thrust = 9.81;
  h.nan_motor_command.utime = heard.imu.utime;
  h.nan_motor_command.seq = heard.motor_command.seq;
  h.nan_motor_command.mode = MotorMode::kRate;
  h.nan_motor_command.thrust = Vec4::Constant(kNan);
  h.nan_reference = heard.reference;
  h.nan_reference.u[kThrust] = kNan;
  return h;
}

enum class Path { kBus, kReplay, kClosedLoop };

// The inputs of the set, to count the copies of each a publisher sent.
enum class Hostile {
  kFarFutureEstimate, kDestabilizingGains, kReplayedCommand, kNanParams, kNanImu,
  kFutureRateCommand, kNanMotorCommand, kNanReference, kTruncatedGains, kCount
};
inline const char* nameOf(Hostile h) {
  static const char* const names[] = {"far_future_estimate", "destabilizing_gains", "replayed_command",
                                      "nan_params", "nan_imu", "future_rate_command",
                                      "nan_motor_command", "nan_reference", "truncated_gains"};
  return names[static_cast<int>(h)];
}

struct ExpectedRejection {
  Hostile input;
  std::string process;  // as in HEARTBEAT
  std::string counter;
  bool in_replay;       // the replay recomputes the estimator, the gain solver and the controller
  bool in_closed_loop = true;
  bool on(Path path) const { return path == Path::kBus || (path == Path::kReplay ? in_replay : in_closed_loop); }
};

// Each counted once per copy received. REFERENCE is no replay input (the replay pairs recomputed ones).
inline const std::vector<ExpectedRejection>& expectedRejections() {
  static const std::vector<ExpectedRejection> table = {
      {Hostile::kFarFutureEstimate, "sdlqr-controller", "reject.state_est.time_future", true},
      {Hostile::kDestabilizingGains, "sdlqr-controller", "reject.gains.unstable", true},
      {Hostile::kReplayedCommand, "sdlqr-controller", "reject.command.time_backwards", true},
      {Hostile::kNanParams, "sdlqr-controller", "reject.params.nonfinite", true},
      {Hostile::kTruncatedGains, "sdlqr-controller", "reject.gains.size", true, false},
      {Hostile::kFarFutureEstimate, "sdlqr-gains", "reject.state_est.time_future", true},
      {Hostile::kNanParams, "sdlqr-gains", "reject.params.nonfinite", true},
      {Hostile::kNanReference, "sdlqr-gains", "reject.reference.nonfinite", false},
      {Hostile::kNanImu, "sdlqr-estimator", "reject.imu.nonfinite", true},
      {Hostile::kNanImu, "sdlqr-lowlevel", "reject.imu.nonfinite", false},
      {Hostile::kReplayedCommand, "sdlqr-lowlevel", "reject.command.time_backwards", false},
      {Hostile::kNanParams, "sdlqr-lowlevel", "reject.params.nonfinite", false},
      {Hostile::kFutureRateCommand, "sdlqr-lowlevel", "reject.rate_cmd.time_future", false},
      {Hostile::kNanMotorCommand, "sdlqr-sim", "reject.motor_cmd.nonfinite", false},
  };
  return table;
}

// The rows of expectedRejections() a path did not count as it must, as readable lines (empty:
// every rejection as expected). counter(process, name) gives -1 for a process the path lacks;
// copies(input) how many copies of an input were sent. The replay and the in-process loop see
// every copy and count each; on the bus a copy can also be dropped on arrival (a one-message
// queue holding a newer message: bus.over_capacity), so the bus counts at least one of them.
template <class CounterOf, class CopiesOf>
std::vector<std::string> rejectionMismatches(CounterOf counter, Path path, CopiesOf copies) {
  std::vector<std::string> mismatches;
  for (const ExpectedRejection& row : expectedRejections()) {
    if (!row.on(path)) continue;
    const int64_t value = counter(row.process, row.counter);
    const int64_t sent = copies(row.input);
    const bool ok = path == Path::kBus ? value >= 1 && value <= sent : value == sent;
    if (ok) continue;
    const std::string expected = path == Path::kBus ? "1 to " + std::to_string(sent) : std::to_string(sent);
    mismatches.push_back(row.process + " " + row.counter + " = " + std::to_string(value) + ", expected " + expected);
  }
  return mismatches;
}

template <class CounterOf>
std::vector<std::string> rejectionMismatches(CounterOf counter, Path path) {
  return rejectionMismatches(counter, path, [](Hostile) -> int64_t { return 1; });
}

}  // namespace sdlqr::testing
