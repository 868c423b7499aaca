#pragma once
// Field-for-field conversion between generated LCM types and the plain structs of
// common/messages.hpp. Converting copies only; validation lives in the libraries.

#include "sdlqr/command_t.hpp"
#include "sdlqr/messages/messages.hpp"
#include "sdlqr/disturbance_t.hpp"
#include "sdlqr/gains_t.hpp"
#include "sdlqr/imu_t.hpp"
#include "sdlqr/motor_cmd_t.hpp"
#include "sdlqr/params_t.hpp"
#include "sdlqr/rate_cmd_t.hpp"
#include "sdlqr/reference_t.hpp"
#include "sdlqr/sim_truth_t.hpp"
#include "sdlqr/state_estimate_t.hpp"
#include "sdlqr/trajectory_t.hpp"
#include "sdlqr/vio_pose_t.hpp"

namespace sdlqr::bus {

ImuSample fromLcm(const imu_t& m);
imu_t toLcm(const ImuSample& s);

VioPose fromLcm(const vio_pose_t& m);
vio_pose_t toLcm(const VioPose& s);

StateEstimate fromLcm(const state_estimate_t& m);
state_estimate_t toLcm(const StateEstimate& s);

RateCommand fromLcm(const rate_cmd_t& m);
rate_cmd_t toLcm(const RateCommand& s);

MotorCommand fromLcm(const motor_cmd_t& m);
motor_cmd_t toLcm(const MotorCommand& s);

GainSet fromLcm(const gains_t& m);
gains_t toLcm(const GainSet& s);

Reference fromLcm(const reference_t& m);
reference_t toLcm(const Reference& s);

// A trajectory_t whose arrays disagree with num_samples cannot be produced by decode; the
// sample count is taken from num_samples.
Trajectory fromLcm(const trajectory_t& m);
trajectory_t toLcm(const Trajectory& s);

Disturbance fromLcm(const disturbance_t& m);
disturbance_t toLcm(const Disturbance& s);

ParamsUpdate fromLcm(const params_t& m);
params_t toLcm(const ParamsUpdate& s);

Command fromLcm(const command_t& m);
command_t toLcm(const Command& s);

SimTruth fromLcm(const sim_truth_t& m);
sim_truth_t toLcm(const SimTruth& s);

}  // namespace sdlqr::bus
