#pragma once
// What sdlqr-px4-emulator reads from the `px4_emulator:` section of the vehicle file: the PX4
// parameters it emulates (named as PX4 names them) and its stand-in position loop for PX4's own
// Hold and Land modes. Declared in emulator_params.cpp.

#include <string>

#include "sdlqr/config/param_table.hpp"

namespace sdlqr::px4emu {

struct EmulatorParams : DeclaredParams<EmulatorParams> {
  int mav_sys_id;          // PX4's MAV_SYS_ID
  double com_of_loss_t;    // [s] PX4's COM_OF_LOSS_T: no setpoint this long in OFFBOARD -> failsafe
  int com_obl_rc_act;      // PX4's COM_OBL_RC_ACT: 4 Land, 5 Hold (the two emulated)
  double mpc_land_speed;   // [m/s] PX4's MPC_LAND_SPEED
  double thrust_curve;     // [-] the airframe's thrust over PX4's normalized thrust (THR_MDL_FAC's model)
  Eigen::Matrix<double, 3, 1> position_gain;  // [1/s^2] Hold/Land stand-in (controller/geometric_control.hpp)
  Eigen::Matrix<double, 3, 1> velocity_gain;  // [1/s]
  Eigen::Matrix<double, 3, 1> attitude_gain;  // [1/s]

  EmulatorParams();
  static const ParamTable<EmulatorParams>& declaration();
};

inline constexpr int kLandAction = 4;  // COM_OBL_RC_ACT
inline constexpr int kHoldAction = 5;

}  // namespace sdlqr::px4emu
