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
