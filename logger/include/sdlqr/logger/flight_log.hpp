#pragma once
// A recorded flight, decoded into the plain structs of common/messages.hpp: the entry point for
// scenario metrics (settling times, tracking errors, ...) and tools.
//
//   const auto log = sdlqr::logger::FlightLog::load("runs/20240501-101500-hover.lcmlog", "QUAD1");
//   for (size_t i = 0; i < log.state_estimate.size(); ++i) {
//     const sdlqr::StateEstimate& s = log.state_estimate[i];   // s.utime: simulation clock
//     int64_t received = log.state_estimate.receive_utime[i];   // recorder wall clock
//   }
//   auto k = log.sim_truth.indexAtOrBefore(s.utime);           // truth at that instant
//
// Only the channels of `vehicle` ("QUAD1/IMU"; "" for unprefixed names) are decoded; every
// channel of the log, of any vehicle, appears in `channels` with its counts. Messages stay in
// log order. A message that does not decode is counted in its series' decode_failures and left
// out. `file` says whether the log was complete; a truncated last event (kill -9) is
// tolerated, a log without any event throws LogError.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/logger/heartbeat_record.hpp"
#include "sdlqr/logger/log_file_status.hpp"
#include "sdlqr/logger/metrics.hpp"

namespace sdlqr::logger {

template <class T>
struct Series {
  std::vector<T> messages;
  std::vector<int64_t> receive_utime;  // [us] recorder wall clock, one per message
  int64_t decode_failures = 0;

  std::size_t size() const { return messages.size(); }
  bool empty() const { return messages.empty(); }
  const T& operator[](std::size_t i) const { return messages[i]; }
  const T& back() const { return messages.back(); }
  // Empty, keeping the memory (a recorder that fills flight after flight allocates it once).
  void clear() {
    messages.clear();
    receive_utime.clear();
    decode_failures = 0;
  }
  void reserve(std::size_t count) {
    messages.reserve(count);
    receive_utime.reserve(count);
  }

  // Index of the last message whose utime is <= `utime`, or -1. Binary search: assumes the
  // series is in utime order, as every publisher sends it.
  std::ptrdiff_t indexAtOrBefore(int64_t utime) const {
    std::ptrdiff_t lo = 0;
    std::ptrdiff_t hi = static_cast<std::ptrdiff_t>(messages.size());
    while (lo < hi) {
      const std::ptrdiff_t mid = lo + (hi - lo) / 2;
      if (messages[static_cast<std::size_t>(mid)].utime <= utime) lo = mid + 1;
      else hi = mid;
    }
    return lo - 1;
  }
};

namespace detail {
template <class T, class Tuple>
struct TupleHas;
template <class T, class... E>
struct TupleHas<T, std::tuple<E...>> : std::bool_constant<(std::is_same_v<T, E> || ...)> {};
}  // namespace detail

struct FlightLog {
  std::string vehicle;
  LogFileStatus file;

  Series<ImuSample> imu;                    // IMU
  Series<VioPose> vio_pose;                 // VIO_POSE
  Series<StateEstimate> state_estimate;     // STATE_EST
  Series<RateCommand> rate_command;         // RATE_CMD
  Series<MotorCommand> motor_command;       // MOTOR_CMD
  Series<GainSet> gains;                    // GAINS
  Series<Reference> reference;              // REFERENCE
  Series<Trajectory> trajectory;            // TRAJECTORY
  Series<Disturbance> disturbance;          // DISTURBANCE
  Series<ParamsUpdate> params;              // PARAMS
  Series<Command> command;                  // COMMAND
  Series<HeartbeatRecord> heartbeat;        // HEARTBEAT, all processes
  Series<SimTruth> sim_truth;               // SIM_TRUTH
  Series<SimClockTick> sim_clock;           // SIM_CLOCK

  // Every series above, once: the loader decodes into them and recorders append by type.
  auto allSeries() {
    return std::tie(imu, vio_pose, state_estimate, rate_command, motor_command, gains, reference, trajectory,
                    disturbance, params, command, heartbeat, sim_truth, sim_clock);
  }
  // The series of message type Msg (FlightLogRecords<Msg> says whether there is one).
  template <class Msg>
  Series<Msg>& series() {
    return std::get<Series<Msg>&>(allSeries());
  }

  // Every channel in the log in order of first appearance. For the vehicle's channels the
  // decoded utime/seq are filled in; other channels carry event counts and receive times.
  std::vector<ChannelTimeline> channels;

  // As a log just constructed, but every series keeps its memory: a 52 s flight records ~25 MB,
  // and a batch worker that refills one log flight after flight neither allocates nor page-faults
  // it in again.
  void clear();

  // Throws LogError when the file is missing, unreadable or holds no event.
  static FlightLog load(const std::string& path, const std::string& vehicle = "");

  const ChannelTimeline* channel(std::string_view name) const;
  // Input for computeLogMetrics (metrics.hpp) restricted to what was decoded.
  MetricsInput metricsInput() const;
};

// Whether a FlightLog has a series of message type Msg. Outside the struct: within it the struct
// is incomplete, and clang (the sanitizer build) refuses allSeries() there.
template <class Msg>
inline constexpr bool kFlightLogRecords =
    detail::TupleHas<Series<Msg>&, decltype(std::declval<FlightLog&>().allSeries())>::value;

}  // namespace sdlqr::logger
