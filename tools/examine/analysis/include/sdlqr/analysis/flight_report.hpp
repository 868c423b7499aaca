#pragma once
// Scenario metrics of one flight, computed from its log (or from the in-process closed loop,
// which fills the same FlightLog): how each reference jump settled (Fig. 5), how the vehicle
// came back after each pull (Fig. 4), estimator accuracy against the simulator's truth, message
// rates, solver and loop timing — and a pass/fail check for every criterion of the scenario.
//
// Positions are judged on SIM_TRUTH (where the vehicle really was), not on the estimate.

#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "sdlqr/analysis/path_tracking.hpp"
#include "sdlqr/analysis/recovery.hpp"
#include "sdlqr/analysis/scenario_events.hpp"
#include "sdlqr/calibrate/calibration.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/types.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/tables/statistics.hpp"
#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::analysis {

inline constexpr double kNotReached = std::numeric_limits<double>::quiet_NaN();

// One held setpoint: after take-off or after a reference jump, until the next event.
struct SetpointWindow {
  std::string label;
  bool is_jump = false;           // false for the hold after take-off
  double start = 0.0;             // [s] simulation time of the command
  double end = 0.0;               // [s] next event (or landing)
  Vec3 from = Vec3::Zero();       // [m] previous setpoint
  Vec3 to = Vec3::Zero();         // [m] setpoint held in the window
  double size = 0.0;              // [m] |to - from|
  double settle_time = kNotReached;  // [s] after start, error stays below the settle threshold
  double overshoot = 0.0;         // [-] largest travel beyond `to` along the jump, over size
  double steady_error = kNotReached;  // [m] mean error over the last hover_window of the window
  double max_error_after_settle = kNotReached;  // [m]
  std::string missing;            // why the scenario's window was not flown (its COMMAND not in the log)
};

// A disturbance while holding a setpoint: a force or torque kick, or a spring holding the vehicle.
struct PullWindow {
  std::string label;
  double start = 0.0;             // [s] disturbance start
  double release = 0.0;           // [s] disturbance end
  double end = 0.0;               // [s] next event
  Disturbance disturbance;        // as the mission sent it (force, torque, hold)
  Vec3 setpoint = Vec3::Zero();   // [m]
  double max_deviation = 0.0;     // [m]
  double return_time = kNotReached;  // [s] after release, error stays below the return threshold
  // [-] after release, the largest travel past the setpoint away from where the pull had taken
  // the vehicle (along the deviation at its largest), over that largest deviation (Fig. 4: "very
  // little overshoot")
  double return_overshoot = 0.0;
  std::string missing;            // why the scenario's pull was not judged (its DISTURBANCE not in the log)
};

// A LAND of the scenario and the touchdown that followed it.
struct Landing {
  std::string label;
  double start = 0.0;                  // [s] the LAND command
  double touchdown = kNotReached;      // [s] first ground contact after it (NaN: still airborne at the end)
  double touchdown_speed = kNotReached;  // [m/s] vertical speed just before that contact
  std::string missing;                 // its COMMAND not in the log
};

struct EstimatorAccuracy {
  int64_t samples = 0;
  double position_rms = kNotReached;   // [m] airborne, |v| < 0.3 m/s (hover)
  double attitude_rms_deg = kNotReached;
  double position_rms_all = kNotReached;  // [m] whole airborne flight
  double attitude_rms_deg_all = kNotReached;
  double position_max_all = kNotReached;
};

struct ProcessLoad {
  std::string process;
  double cpu_percent_mean = 0.0;  // [% of one core] over the heartbeats of the flight
  double cpu_percent_max = 0.0;
  int64_t rejected = 0;
  int64_t dropped = 0;
  int64_t deadline_misses = 0;
  int64_t errors = 0;
};

// Saturation where it happens, while airborne: the thrust the control law asked for before its
// clip to [c_min, c_max] (RATE_CMD thrust_demand), and rotor setpoints the mixer left at a rotor
// limit (MOTOR_CMD in rate mode). The clipped command itself can never leave the limits.
struct Saturation {
  int64_t commands = 0;               // RATE_CMD while airborne
  int64_t thrust_demand_outside = 0;  // demand outside [c_min, c_max], or not finite
  double thrust_demand_min = kNotReached;  // [m/s^2]
  double thrust_demand_max = kNotReached;
  int64_t motor_commands = 0;         // MOTOR_CMD in rate mode while airborne
  int64_t rotor_at_limit = 0;         // with a rotor at min_rotor_thrust or max_rotor_thrust
};

// Messages one subscriber never handled on one channel, from the seq gaps it saw: its last
// HEARTBEAT's "lost.<channel>" and "queue_drop.<channel>" counters (summed over restarts), or for
// the recorder the gaps in the log itself (process "log").
struct ChannelLoss {
  std::string process;
  std::string channel;
  int64_t lost = 0;           // every gap: the kernel, LCM's queue or ours
  int64_t queue_dropped = 0;  // of those, dropped by the subscriber's own queue on arrival
};

struct Check {
  std::string name;         // criterion key, with the window label when per window: "key[label]"
  std::string key;          // criterion key (criteria.hpp)
  std::string window;       // label of the window judged, empty for the whole flight
  std::string description;  // what is judged, with the scenario's thresholds filled in
  std::string unit;
  double value = 0.0;
  double limit = 0.0;
  bool upper = true;     // pass when value <= limit (else value >= limit)
  bool pass = false;
  std::string note;      // why a window has no value: "pull +y at 39.0 s: DISTURBANCE not in the log"
};

// A criterion of the scenario that this report cannot judge, and why (no calibration of the
// machine given, an in-process flight without heartbeats).
struct NotJudged {
  std::string key;
  std::string reason;
};

struct FlightReport {
  std::string scenario;
  std::vector<ExpectedEvent> events;  // the scenario's, each looked up in the log (scenario_events.hpp)
  double flight_start = kNotReached;  // [s] first airborne truth sample
  double flight_end = kNotReached;
  std::vector<SetpointWindow> setpoints;
  double settle_error = kNotReached;  // [m] the error a jump settles below (jump_settle_error)
  std::vector<PullWindow> pulls;
  double return_error = kNotReached;  // [m] back after a pull within this (pull_return_error)
  std::vector<Landing> landings;
  std::vector<PathTrackingReport> trajectories;  // one per trajectory event, and per other tracked TRAJECTORY
  std::optional<RecoveryReport> recovery;        // airborne start or throw (recovery.hpp)
  int64_t trajectory_aborts = 0;                 // by the controller's guard (trajectory_aborts.hpp)
  EstimatorAccuracy estimator;
  double imu_rate_hz = 0.0;        // by simulation time
  double state_est_rate_hz = 0.0;
  double rate_cmd_rate_hz = 0.0;
  double gains_rate_hz = 0.0;
  tables::Distribution solve_us;                 // GAINS solve_us
  tables::Distribution iterations;               // GAINS iterations
  tables::Distribution rate_cmd_period_ms;       // RATE_CMD utime intervals
  tables::Distribution rate_cmd_jitter_ms;       // |interval - 10 ms| (stamps the controller set: reported only)
  // Airborne, at the recorder: |interval between RATE_CMDs - interval between the STATE_ESTs they
  // answer|: the controller's wall-clock period beyond its input's.
  tables::Distribution rate_cmd_wall_jitter_us;
  tables::Distribution state_to_command_us;      // STATE_EST -> RATE_CMD, recorder receive clock
  Saturation saturation;
  std::vector<ProcessLoad> processes;
  std::vector<ChannelLoss> message_loss;  // every subscriber and channel with a counter
  double stack_cpu_percent = 0.0;  // sum of the flight processes' means
  // The machine's own figures measured just before the flight (sdlqr-calibrate), when given;
  // the relative figures divide the flight's by them.
  std::optional<calibrate::Calibration> calibration;
  double stack_cpu_relative = kNotReached;        // stack_cpu_percent / calibration cpu_percent
  double state_to_command_relative = kNotReached;  // median latency / calibration one-way median
  double state_to_command_p99_relative = kNotReached;  // p99 latency / calibration one-way p99
  double rate_cmd_wall_jitter_relative = kNotReached;  // wall jitter median / calibration one-way median
  double rate_cmd_wall_jitter_p99_relative = kNotReached;  // wall jitter p99 / calibration one-way p99
  int64_t nonfinite = 0;           // messages with NaN/Inf among estimates, commands, gains
  double max_tilt_deg = 0.0;
  double touchdown_speed = 0.0;    // [m/s] fastest vertical speed at a ground contact
  bool crashed = false;
  std::vector<Check> checks;
  std::vector<NotJudged> not_judged;

  // Every check passes, and there is at least one: a report that judged nothing fails.
  bool passed() const;
};

struct AnalysisOptions {
  double settle_error = 0.05;  // [m] used for settle_time when the scenario has no criterion
  double return_error = 0.10;  // [m]
  double hover_window = 1.5;   // [s]
  double rate_cmd_period_s = 0.01;
  // skip_radius, skip_window and return_error are overridden by the scenario's criteria of the
  // same names (return_error: path_return_error); thrust limits come from the vehicle's lqr:
  // section and are required by the criterion thrust_limit_violations_max.
  PathTrackingOptions path;
  double rotor_thrust_min = -std::numeric_limits<double>::infinity();  // [N] VehicleParams min_rotor_thrust
  double rotor_thrust_max = std::numeric_limits<double>::infinity();   // [N] max_rotor_thrust
  // This machine's figures, measured just before the flight: needed by the relative budgets.
  std::optional<calibrate::Calibration> calibration;
};

// The vehicle's limits the saturation criteria judge against: c_min/c_max of its lqr: section,
// the rotor thrust range of its vehicle: section. analyzeFlight reads them from the scenario's
// vehicle file unless the options carry them.
void setVehicleLimits(AnalysisOptions& options, const LqrParams& lqr, const VehicleParams& vehicle);

// Throws std::invalid_argument for a criterion key it does not know (a typo would otherwise pass).
FlightReport analyzeFlight(const logger::FlightLog& log, const mission::Scenario& scenario,
                           AnalysisOptions options = {});

void writeJson(const FlightReport& report, std::ostream& out);
void writeSummary(const FlightReport& report, std::ostream& out);

}  // namespace sdlqr::analysis
