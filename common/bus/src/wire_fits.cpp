// encodingFits<T> for every bus type, from the logger's generated walk of lcmtypes/*.lcm (one
// definition of the wire layout, regenerated when a .lcm file changes).

#include "sdlqr/logger/generated/lcm_csv_rows.hpp"
#include "sdlqr/bus/node.hpp"

namespace sdlqr::bus {

#define SDLQR_ENCODING_FITS(TYPE)                                                     \
  template <>                                                                         \
  bool encodingFits<::sdlqr::TYPE>(const uint8_t* data, int64_t size) {               \
    return logger::generated::encodingFits(static_cast<const ::sdlqr::TYPE*>(nullptr), data, size); \
  }

SDLQR_ENCODING_FITS(command_t)
SDLQR_ENCODING_FITS(disturbance_t)
SDLQR_ENCODING_FITS(gains_t)
SDLQR_ENCODING_FITS(heartbeat_t)
SDLQR_ENCODING_FITS(imu_t)
SDLQR_ENCODING_FITS(motor_cmd_t)
SDLQR_ENCODING_FITS(params_t)
SDLQR_ENCODING_FITS(rate_cmd_t)
SDLQR_ENCODING_FITS(reference_t)
SDLQR_ENCODING_FITS(sim_clock_t)
SDLQR_ENCODING_FITS(sim_truth_t)
SDLQR_ENCODING_FITS(state_estimate_t)
SDLQR_ENCODING_FITS(trajectory_t)
SDLQR_ENCODING_FITS(vio_pose_t)

#undef SDLQR_ENCODING_FITS

}  // namespace sdlqr::bus
