#pragma once
// Channel names, one type per channel (see lcmtypes/), with the optional vehicle prefix.

#include <string>
#include <string_view>

namespace sdlqr::channel {

inline constexpr std::string_view kImu = "IMU";                  // imu_t
inline constexpr std::string_view kVioPose = "VIO_POSE";         // vio_pose_t
inline constexpr std::string_view kStateEstimate = "STATE_EST";  // state_estimate_t
inline constexpr std::string_view kRateCommand = "RATE_CMD";     // rate_cmd_t
inline constexpr std::string_view kMotorCommand = "MOTOR_CMD";   // motor_cmd_t
inline constexpr std::string_view kGains = "GAINS";              // gains_t
inline constexpr std::string_view kReference = "REFERENCE";      // reference_t
inline constexpr std::string_view kTrajectory = "TRAJECTORY";    // trajectory_t
inline constexpr std::string_view kDisturbance = "DISTURBANCE";  // disturbance_t
inline constexpr std::string_view kParams = "PARAMS";            // params_t
inline constexpr std::string_view kCommand = "COMMAND";          // command_t
inline constexpr std::string_view kHeartbeat = "HEARTBEAT";      // heartbeat_t
inline constexpr std::string_view kSimTruth = "SIM_TRUTH";       // sim_truth_t
inline constexpr std::string_view kSimClock = "SIM_CLOCK";       // sim_clock_t

// Bus layout. With one multicast port for everything every process's socket receives every
// message of the stack (~2,700 a second) and LCM drops those it did not subscribe to in user
// space; worse, the sender's sendmsg enqueues each datagram on every socket bound to the port and
// wakes every receive thread. The split layout gives each high-rate channel a port of its own,
// counted from the --lcm-url port: a socket then hears only the channels of its port. (Distinct
// groups on one port would not separate them: Linux delivers a datagram to every socket bound
// to the port whose host joined its group, IP_MULTICAST_ALL.) Every other channel stays on the
// base port. Channels one subscriber needs in their send order share a port (IMU and VIO_POSE: the
// estimator's inputs, from one publisher); across ports a process handles messages in the order
// its receive threads hand them over. bench/README.md has the measurements.
inline constexpr struct {
  std::string_view channel;
  int port_offset;  // [-] added to the base port
} kSplitPorts[] = {
    {kImu, 1},         {kVioPose, 1},   {kMotorCommand, 2}, {kStateEstimate, 3},
    {kSimTruth, 4},    {kRateCommand, 5}, {kReference, 6},  {kSimClock, 7},
};

// Port offset of a channel (base name, without vehicle prefix) in the split layout; 0 (the
// base port) for every channel not in kSplitPorts, including names that are not ours.
constexpr int splitPortOffset(std::string_view base) {
  for (const auto& entry : kSplitPorts) {
    if (entry.channel == base) return entry.port_offset;
  }
  return 0;
}

// "QUAD1/IMU" -> "IMU": the part after the last '/' (a vehicle name may itself hold '/').
constexpr std::string_view baseName(std::string_view channel) {
  const size_t slash = channel.rfind('/');
  return slash == std::string_view::npos ? channel : channel.substr(slash + 1);
}

// "IMU" with vehicle "QUAD1" becomes "QUAD1/IMU"; an empty vehicle leaves the name as is.
inline std::string name(std::string_view vehicle, std::string_view channel) {
  std::string out;
  if (!vehicle.empty()) {
    out.append(vehicle);
    out.push_back('/');
  }
  out.append(channel);
  return out;
}

}  // namespace sdlqr::channel
