#pragma once
// The bus types the message harness walks, in the order of the input's first (selector) byte.

#include <tuple>

#include "sdlqr/bus/convert.hpp"

namespace sdlqr::fuzz {

using BusTypes = std::tuple<imu_t, vio_pose_t, state_estimate_t, rate_cmd_t, motor_cmd_t, gains_t, reference_t,
                            trajectory_t, disturbance_t, params_t, command_t, sim_truth_t>;
inline constexpr int kBusTypeCount = std::tuple_size_v<BusTypes>;

}  // namespace sdlqr::fuzz
