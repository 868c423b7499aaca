#include "sdlqr/bus/convert.hpp"

namespace sdlqr::bus {

namespace {

template <int N, class Vector>
void copyIn(const double (&from)[N], Vector& to) {
  for (int i = 0; i < N; ++i) to[i] = from[i];
}

template <int N, class Vector>
void copyOut(const Vector& from, double (&to)[N]) {
  for (int i = 0; i < N; ++i) to[i] = from[i];
}

}  // namespace

ImuSample fromLcm(const imu_t& m) {
  ImuSample s;
  s.utime = m.utime;
  s.seq = m.seq;
  copyIn(m.gyro, s.gyro);
  copyIn(m.accel, s.accel);
  return s;
}

imu_t toLcm(const ImuSample& s) {
  imu_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  copyOut(s.gyro, m.gyro);
  copyOut(s.accel, m.accel);
  return m;
}

VioPose fromLcm(const vio_pose_t& m) {
  VioPose s;
  s.utime = m.utime;
  s.seq = m.seq;
  s.publish_utime = m.publish_utime;
  copyIn(m.position, s.position);
  copyIn(m.orientation, s.orientation);
  s.position_std = m.position_std;
  s.attitude_std = m.attitude_std;
  return s;
}

vio_pose_t toLcm(const VioPose& s) {
  vio_pose_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  m.publish_utime = s.publish_utime;
  copyOut(s.position, m.position);
  copyOut(s.orientation, m.orientation);
  m.position_std = s.position_std;
  m.attitude_std = s.attitude_std;
  return m;
}

StateEstimate fromLcm(const state_estimate_t& m) {
  StateEstimate s;
  s.utime = m.utime;
  s.seq = m.seq;
  copyIn(m.position, s.position);
  copyIn(m.orientation, s.orientation);
  copyIn(m.velocity, s.velocity);
  copyIn(m.body_rate, s.body_rate);
  copyIn(m.gyro_bias, s.gyro_bias);
  copyIn(m.accel_bias, s.accel_bias);
  copyIn(m.position_std, s.position_std);
  copyIn(m.attitude_std, s.attitude_std);
  s.imu_seq = m.imu_seq;
  s.vio_seq = m.vio_seq;
  s.status = static_cast<EstimatorStatus>(m.status);
  return s;
}

state_estimate_t toLcm(const StateEstimate& s) {
  state_estimate_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  copyOut(s.position, m.position);
  copyOut(s.orientation, m.orientation);
  copyOut(s.velocity, m.velocity);
  copyOut(s.body_rate, m.body_rate);
  copyOut(s.gyro_bias, m.gyro_bias);
  copyOut(s.accel_bias, m.accel_bias);
  copyOut(s.position_std, m.position_std);
  copyOut(s.attitude_std, m.attitude_std);
  m.imu_seq = s.imu_seq;
  m.vio_seq = s.vio_seq;
  m.status = static_cast<int8_t>(s.status);
  return m;
}

RateCommand fromLcm(const rate_cmd_t& m) {
  RateCommand s;
  s.utime = m.utime;
  s.seq = m.seq;
  copyIn(m.body_rate, s.body_rate);
  s.thrust = m.thrust;
  s.state_seq = m.state_seq;
  s.gains_seq = m.gains_seq;
  s.reference_seq = m.reference_seq;
  s.saturated = m.saturated;
  s.gains_status = static_cast<GainsFreshness>(m.gains_status);
  return s;
}

rate_cmd_t toLcm(const RateCommand& s) {
  rate_cmd_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  copyOut(s.body_rate, m.body_rate);
  m.thrust = s.thrust;
  m.state_seq = s.state_seq;
  m.gains_seq = s.gains_seq;
  m.reference_seq = s.reference_seq;
  m.saturated = s.saturated;
  m.gains_status = static_cast<int8_t>(s.gains_status);
  return m;
}

MotorCommand fromLcm(const motor_cmd_t& m) {
  MotorCommand s;
  s.utime = m.utime;
  s.seq = m.seq;
  copyIn(m.thrust, s.thrust);
  s.imu_seq = m.imu_seq;
  s.armed = m.armed != 0;
  s.mode = static_cast<MotorMode>(m.mode);
  return s;
}

motor_cmd_t toLcm(const MotorCommand& s) {
  motor_cmd_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  copyOut(s.thrust, m.thrust);
  m.imu_seq = s.imu_seq;
  m.armed = s.armed ? 1 : 0;
  m.mode = static_cast<int8_t>(s.mode);
  return m;
}

GainSet fromLcm(const gains_t& m) {
  GainSet s;
  s.utime = m.utime;
  s.seq = m.seq;
  for (int r = 0; r < kInputDim; ++r) {
    for (int c = 0; c < kStateDim; ++c) s.K(r, c) = m.K[r * kStateDim + c];
  }
  copyIn(m.x_lin, s.x_lin);
  copyIn(m.u_lin, s.u_lin);
  copyIn(m.q_diag, s.q_diag);
  copyIn(m.r_diag, s.r_diag);
  s.dt = m.dt;
  s.solve_us = m.solve_us;
  s.residual = m.residual;
  s.iterations = m.iterations;
  s.state_seq = m.state_seq;
  s.params_seq = m.params_seq;
  s.reference_seq = m.reference_seq;
  s.method = static_cast<GainsMethod>(m.method);
  s.status = static_cast<SolveStatus>(m.status);
  return s;
}

gains_t toLcm(const GainSet& s) {
  gains_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  for (int r = 0; r < kInputDim; ++r) {
    for (int c = 0; c < kStateDim; ++c) m.K[r * kStateDim + c] = s.K(r, c);
  }
  copyOut(s.x_lin, m.x_lin);
  copyOut(s.u_lin, m.u_lin);
  copyOut(s.q_diag, m.q_diag);
  copyOut(s.r_diag, m.r_diag);
  m.dt = s.dt;
  m.solve_us = s.solve_us;
  m.residual = s.residual;
  m.iterations = s.iterations;
  m.state_seq = s.state_seq;
  m.params_seq = s.params_seq;
  m.reference_seq = s.reference_seq;
  m.method = static_cast<int8_t>(s.method);
  m.status = static_cast<int8_t>(s.status);
  return m;
}

Reference fromLcm(const reference_t& m) {
  Reference s;
  s.utime = m.utime;
  s.seq = m.seq;
  copyIn(m.x, s.x);
  copyIn(m.u, s.u);
  s.index = m.index;
  s.gamma = m.gamma;
  s.trajectory_seq = m.trajectory_seq;
  s.state_seq = m.state_seq;
  s.command_seq = m.command_seq;
  s.params_seq = m.params_seq;
  s.mode = static_cast<ReferenceMode>(m.mode);
  return s;
}

reference_t toLcm(const Reference& s) {
  reference_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  copyOut(s.x, m.x);
  copyOut(s.u, m.u);
  m.index = s.index;
  m.gamma = s.gamma;
  m.trajectory_seq = s.trajectory_seq;
  m.state_seq = s.state_seq;
  m.command_seq = s.command_seq;
  m.params_seq = s.params_seq;
  m.mode = static_cast<int8_t>(s.mode);
  return m;
}

Trajectory fromLcm(const trajectory_t& m) {
  Trajectory s;
  s.utime = m.utime;
  s.seq = m.seq;
  s.start_utime = m.start_utime;
  s.tracking = static_cast<ReferenceMode>(m.tracking);
  s.closed = m.closed != 0;
  const size_t n = m.num_samples > 0 ? static_cast<size_t>(m.num_samples) : 0;
  s.samples.resize(n);
  for (size_t i = 0; i < n; ++i) {
    s.samples[i].t = m.t[i];
    for (int j = 0; j < kStateDim; ++j) s.samples[i].x[j] = m.x[i][static_cast<size_t>(j)];
    for (int j = 0; j < kInputDim; ++j) s.samples[i].u[j] = m.u[i][static_cast<size_t>(j)];
  }
  return s;
}

trajectory_t toLcm(const Trajectory& s) {
  trajectory_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  m.start_utime = s.start_utime;
  m.tracking = static_cast<int8_t>(s.tracking);
  m.closed = s.closed ? 1 : 0;
  m.num_samples = static_cast<int32_t>(s.samples.size());
  m.t.resize(s.samples.size());
  m.x.assign(s.samples.size(), std::vector<double>(kStateDim));
  m.u.assign(s.samples.size(), std::vector<double>(kInputDim));
  for (size_t i = 0; i < s.samples.size(); ++i) {
    m.t[i] = s.samples[i].t;
    for (int j = 0; j < kStateDim; ++j) m.x[i][static_cast<size_t>(j)] = s.samples[i].x[j];
    for (int j = 0; j < kInputDim; ++j) m.u[i][static_cast<size_t>(j)] = s.samples[i].u[j];
  }
  return m;
}

Disturbance fromLcm(const disturbance_t& m) {
  Disturbance s;
  s.utime = m.utime;
  s.seq = m.seq;
  s.start_utime = m.start_utime;
  s.duration = m.duration;
  copyIn(m.force, s.force);
  copyIn(m.torque, s.torque);
  copyIn(m.hold_position, s.hold_position);
  s.hold_stiffness = m.hold_stiffness;
  s.hold_damping = m.hold_damping;
  s.mode = static_cast<DisturbanceMode>(m.mode);
  return s;
}

disturbance_t toLcm(const Disturbance& s) {
  disturbance_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  m.start_utime = s.start_utime;
  m.duration = s.duration;
  copyOut(s.force, m.force);
  copyOut(s.torque, m.torque);
  copyOut(s.hold_position, m.hold_position);
  m.hold_stiffness = s.hold_stiffness;
  m.hold_damping = s.hold_damping;
  m.mode = static_cast<int8_t>(s.mode);
  return m;
}

ParamsUpdate fromLcm(const params_t& m) {
  ParamsUpdate s;
  s.utime = m.utime;
  s.seq = m.seq;
  s.field_mask = m.field_mask;
  copyIn(m.q_diag, s.q_diag);
  copyIn(m.r_diag, s.r_diag);
  s.omega_max = m.omega_max;
  s.c_min = m.c_min;
  s.c_max = m.c_max;
  s.mass = m.mass;
  s.tracking = static_cast<ReferenceMode>(m.tracking);
  return s;
}

params_t toLcm(const ParamsUpdate& s) {
  params_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  m.field_mask = s.field_mask;
  copyOut(s.q_diag, m.q_diag);
  copyOut(s.r_diag, m.r_diag);
  m.omega_max = s.omega_max;
  m.c_min = s.c_min;
  m.c_max = s.c_max;
  m.mass = s.mass;
  m.tracking = static_cast<int8_t>(s.tracking);
  return m;
}

Command fromLcm(const command_t& m) {
  Command s;
  s.utime = m.utime;
  s.seq = m.seq;
  s.command = static_cast<CommandType>(m.command);
  copyIn(m.position, s.position);
  s.yaw = m.yaw;
  return s;
}

command_t toLcm(const Command& s) {
  command_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  m.command = static_cast<int8_t>(s.command);
  copyOut(s.position, m.position);
  m.yaw = s.yaw;
  return m;
}

SimTruth fromLcm(const sim_truth_t& m) {
  SimTruth s;
  s.utime = m.utime;
  s.seq = m.seq;
  copyIn(m.position, s.position);
  copyIn(m.orientation, s.orientation);
  copyIn(m.velocity, s.velocity);
  copyIn(m.body_rate, s.body_rate);
  copyIn(m.acceleration, s.acceleration);
  copyIn(m.rotor_thrust, s.rotor_thrust);
  copyIn(m.gyro_bias, s.gyro_bias);
  copyIn(m.accel_bias, s.accel_bias);
  copyIn(m.external_force, s.external_force);
  s.battery_voltage = m.battery_voltage;
  s.thrust_scale = m.thrust_scale;
  s.on_ground = m.on_ground != 0;
  s.crashed = m.crashed != 0;
  return s;
}

sim_truth_t toLcm(const SimTruth& s) {
  sim_truth_t m{};
  m.utime = s.utime;
  m.seq = s.seq;
  copyOut(s.position, m.position);
  copyOut(s.orientation, m.orientation);
  copyOut(s.velocity, m.velocity);
  copyOut(s.body_rate, m.body_rate);
  copyOut(s.acceleration, m.acceleration);
  copyOut(s.rotor_thrust, m.rotor_thrust);
  copyOut(s.gyro_bias, m.gyro_bias);
  copyOut(s.accel_bias, m.accel_bias);
  copyOut(s.external_force, m.external_force);
  m.battery_voltage = s.battery_voltage;
  m.thrust_scale = s.thrust_scale;
  m.on_ground = s.on_ground ? 1 : 0;
  m.crashed = s.crashed ? 1 : 0;
  return m;
}

}  // namespace sdlqr::bus
