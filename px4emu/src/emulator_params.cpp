#include "sdlqr/px4emu/emulator_params.hpp"

namespace sdlqr::px4emu {

EmulatorParams::EmulatorParams() { declaration().setDefaults(*this); }

const ParamTable<EmulatorParams>& EmulatorParams::declaration() {
  static const ParamTable<EmulatorParams> table = [] {
    using P = EmulatorParams;
    ParamTable<P> t("emulated PX4 (sdlqr-px4-emulator): its PX4 parameters and Hold/Land stand-in (docs/px4.md)");
    t.integer("mav_sys_id", &P::mav_sys_id, 1, "-", Range::closed(1, 255), "PX4's MAV_SYS_ID");
    t.number("com_of_loss_t", &P::com_of_loss_t, 1.0, "s", Range::closed(0.0, 60.0),
             "PX4's COM_OF_LOSS_T: in OFFBOARD without a setpoint this long, the failsafe of com_obl_rc_act "
             "(default of recent PX4 releases)");
    t.integer("com_obl_rc_act", &P::com_obl_rc_act, kLandAction, "-", Range::closed(kLandAction, kHoldAction),
              "PX4's COM_OBL_RC_ACT: 4 Land, 5 Hold (the others are not emulated)");
    t.number("mpc_land_speed", &P::mpc_land_speed, 0.7, "m/s", Range::closed(0.1, 3.0), "PX4's MPC_LAND_SPEED");
    t.number("thrust_curve", &P::thrust_curve, 0.0, "-", Range::closed(0.0, 1.0),
             "the airframe's relative thrust (1 - k) T + k T^2 over PX4's normalized thrust T: 0 when PX4's "
             "THR_MDL_FAC matches the motors (px4.thrust.curve must equal it)");
    t.list<3>("position_gain", &P::position_gain, {4.0, 4.0, 6.0}, "1/s^2", Range::above(0.0),
              "Hold/Land stand-in for PX4's position loop: kp x, y, z");
    t.list<3>("velocity_gain", &P::velocity_gain, {4.0, 4.0, 5.0}, "1/s", Range::above(0.0), "kd x, y, z");
    t.list<3>("attitude_gain", &P::attitude_gain, {8.0, 8.0, 2.0}, "1/s", Range::above(0.0), "roll, pitch, yaw");
    return t;
  }();
  return table;
}

}  // namespace sdlqr::px4emu
