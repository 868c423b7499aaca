#pragma once
// What a process outage did to a flight, measured from its log (the kill -9 integration tests).
// Pure: a decoded FlightLog in, figures out. Kill and restart instants are wall times of the
// recorder's clock (LCM receive time, microseconds since the epoch, as `date +%s%6N` prints);
// everything else is simulation time.

#include <cstdint>
#include <limits>
#include <vector>

#include "sdlqr/faults/finding.hpp"
#include "sdlqr/logger/flight_log.hpp"

namespace sdlqr::faults {

// utime of the first SIM_TRUTH received at or after `wall_utime`; -1 if none.
int64_t simTimeAtWall(const logger::FlightLog& log, int64_t wall_utime);

struct GainsOutage {
  int64_t last_gains_utime = -1;     // the killed solver's last GAINS (the newest received before the restart)
  int64_t first_fallback_utime = -1; // first RATE_CMD on the hover K after that
  int64_t fallback_commands = 0;     // RATE_CMD on the hover K before the restart
  // RATE_CMD stamped later than last GAINS + timeout (+ one tick), received before the restart,
  // that were NOT on the hover K: must be 0.
  int64_t late_non_fallback_commands = 0;
  double resume_delay_s = -1.0;      // [s] wall: restart -> first GAINS received (reported only)
  // [s] sim: the restarted solver's first HEARTBEAT -> the estimate time of its first GAINS (NaN:
  // none). Machine speed drops out: how long the process takes to start is not counted, only
  // whether it then solves at once (slightly negative when it solved on an estimate that was
  // already on its way when its first heartbeat went out).
  double resume_after_up_s = std::numeric_limits<double>::quiet_NaN();
  int64_t fresh_commands_after_resume = 0;  // RATE_CMD back on fresh GAINS after the restart
};
GainsOutage measureGainsOutage(const logger::FlightLog& log, int64_t kill_wall, int64_t restart_wall,
                               double fallback_timeout_s);

struct EstimatorOutage {
  int64_t last_estimate_utime = -1;  // newest STATE_EST received before the kill
  int64_t failsafe_utime = -1;       // first MOTOR_CMD in failsafe mode after it
  double failsafe_delay_s = -1.0;    // [s] sim: last estimate -> failsafe
  double max_tilt_deg = 0.0;         // SIM_TRUTH from the last estimate until the restart
  int64_t touchdown_utime = -1;      // first SIM_TRUTH on the ground after it (-1: never landed)
  double touchdown_speed = -1.0;     // [m/s] |v| of the last airborne SIM_TRUTH before touchdown
  bool disarmed_after_touchdown = false;  // a MOTOR_CMD disarmed after touchdown, before the restart
  int64_t disarm_utime = -1;         // that first disarmed MOTOR_CMD
  // After the disarm, to the end of the log (past the restart, while the mission keeps re-sending
  // its TAKEOFF for a restarted controller): MOTOR_CMD armed again (must be 0), and the TAKEOFFs
  // re-sent after the restart (same seq as one sent before; 0: nothing tested the re-arm).
  int64_t rearmed_commands = 0;
  int64_t resent_takeoffs_after_restart = 0;
  bool crashed = false;
};
EstimatorOutage measureEstimatorOutage(const logger::FlightLog& log, int64_t kill_wall, int64_t restart_wall);

struct EstimatorLimits {
  double max_failsafe_delay_s = 0.2;  // simulation time
  double max_tilt_deg = 30.0;
  double max_touchdown_speed = 1.0;   // [m/s]
};
// Failsafe in time, upright, a soft touchdown, disarmed on the ground before the restart, and
// never armed again after it although the mission re-sent its TAKEOFF.
std::vector<Finding> judgeEstimatorOutage(const EstimatorOutage& outage, const EstimatorLimits& limits);

struct ControllerOutage {
  int64_t last_command_utime = -1;   // newest RATE_CMD received before the kill
  int64_t failsafe_utime = -1;       // first MOTOR_CMD in failsafe mode after it
  int64_t resumed_utime = -1;        // first RATE_CMD received after the restart
  double max_gap_tilt_deg = 0.0;     // SIM_TRUTH between the last and the resumed RATE_CMD
  double gap_height_loss = 0.0;      // [m] setpoint z minus the lowest truth z in that gap
  // [s] sim: resumed -> the start of the last stretch within tolerance of the setpoint that lasts
  // until `until_utime`; -1 when the vehicle is outside the tolerance at `until_utime`.
  double return_time_s = -1.0;
  double error_at_resume = 0.0;      // [m] |truth - setpoint| when the controller resumed
  bool crashed = false;
};
ControllerOutage measureControllerOutage(const logger::FlightLog& log, int64_t kill_wall, int64_t restart_wall,
                                         const Vec3& setpoint, double tolerance, int64_t until_utime);

}  // namespace sdlqr::faults
