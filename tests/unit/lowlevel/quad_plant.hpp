#pragma once
// Test plant for the bodyrate loop: rigid body with the vehicle's inertia, four rotors with
// first-order lag and saturation, linear rotor drag, a spring-damper ground, and an IMU with
// optional white noise and constant bias. Deterministic for a given seed. Deliberately
// independent of the real simulator: the loop is checked against physics written here.

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/math/vehicle.hpp"

namespace sdlqr::test {

struct ImuErrors {
  double gyro_std = 0.0;          // [rad/s] per sample
  double accel_std = 0.0;         // [m/s^2] per sample
  Vec3 gyro_bias = Vec3::Zero();  // [rad/s]
  Vec3 accel_bias = Vec3::Zero(); // [m/s^2]
  double accel_range = 156.9;     // [m/s^2] readings clip here per axis (16 g), as real sensors do
  unsigned seed = 1;
};

class QuadPlant {
 public:
  QuadPlant(const VehicleParams& vehicle, double gravity, const ImuErrors& imu = ImuErrors())
      : vehicle_(vehicle), effectiveness_(vehicle.effectiveness()), gravity_(gravity), imu_errors_(imu), rng_(imu.seed) {
    // Resting on the ground: the contact spring carries the weight.
    position.z() = -vehicle_.mass * gravity_ / kContactStiffness;
    specific_force_ = Vec3(0.0, 0.0, gravity_);
  }

  // Starts in free air at `height`, rotors already spinning at hover thrust.
  void startHovering(double height) {
    position = Vec3(0.0, 0.0, height);
    rotor_thrust = Vec4::Constant(vehicle_.mass * gravity_ / 4.0 / thrust_scale);
    command_ = rotor_thrust;
    specific_force_ = Vec3(0.0, 0.0, gravity_);
    airborne_ = true;
  }

  void setMotorCommand(const MotorCommand& command) {
    command_ = command.armed ? Vec4(command.thrust.cwiseMax(vehicle_.min_rotor_thrust).cwiseMin(vehicle_.max_rotor_thrust))
                             : Vec4::Zero();
  }

  // Integrates `duration` seconds in sub-steps of `step` seconds.
  void advance(double duration, double step = 1e-4) {
    const int steps = static_cast<int>(std::lround(duration / step));
    for (int i = 0; i < steps; ++i) integrate(step);
  }

  ImuSample imu(int64_t utime, int64_t seq) {
    ImuSample sample;
    sample.utime = utime;
    sample.seq = seq;
    sample.gyro = body_rate + imu_errors_.gyro_bias + noise(imu_errors_.gyro_std);
    sample.accel = (specific_force_ + imu_errors_.accel_bias + noise(imu_errors_.accel_std))
                       .cwiseMax(-imu_errors_.accel_range)
                       .cwiseMin(imu_errors_.accel_range);
    return sample;
  }

  double tilt() const { return quat::tilt(attitude); }
  bool inContact() const { return position.z() < 0.0; }
  double lastTouchdownSpeed() const { return last_touchdown_speed_; }
  int touchdowns() const { return touchdowns_; }

  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Quat attitude = identityQuat();
  Vec3 body_rate = Vec3::Zero();
  Vec4 rotor_thrust = Vec4::Zero();
  double thrust_scale = 1.0;  // actual thrust per commanded newton (battery, calibration)

  static constexpr double kContactStiffness = 3000.0;  // [N/m]

 private:
  static constexpr double kContactDamping = 35.0;       // [N s/m] about 0.6 of critical for 255 g
  static constexpr double kContactFriction = 5.0;       // [N s/m] horizontal
  static constexpr double kContactTiltStiffness = 1.0;  // [N m/rad] the landing gear keeps it level
  static constexpr double kContactTiltDamping = 0.04;   // [N m s/rad]

  Vec3 noise(double std) {
    if (std <= 0.0) return Vec3::Zero();
    std::normal_distribution<double> normal(0.0, std);
    return Vec3(normal(rng_), normal(rng_), normal(rng_));
  }

  void integrate(double h) {
    const double alpha = vehicle_.motor_time_constant > 0.0 ? 1.0 - std::exp(-h / vehicle_.motor_time_constant) : 1.0;
    rotor_thrust += alpha * (command_ - rotor_thrust);
    const Vec4 wrench = effectiveness_ * (thrust_scale * rotor_thrust);
    const Mat3 rotation = quat::rotationMatrix(attitude);
    const Vec3 body_velocity = rotation.transpose() * velocity;

    Vec3 body_force_per_mass(0.0, 0.0, wrench[0] / vehicle_.mass);
    body_force_per_mass -= vehicle_.rotor_drag.cwiseProduct(body_velocity);
    Vec3 torque = wrench.tail<3>();

    Vec3 contact_force = Vec3::Zero();
    if (position.z() < 0.0) {
      if (airborne_) {
        last_touchdown_speed_ = -velocity.z();
        ++touchdowns_;
        airborne_ = false;
      }
      contact_force.z() = std::max(0.0, -kContactStiffness * position.z() - kContactDamping * velocity.z());
      contact_force.x() = -kContactFriction * velocity.x();
      contact_force.y() = -kContactFriction * velocity.y();
      const Vec3 body_z = rotation.col(2);
      const Vec3 level_axis_world = body_z.cross(Vec3::UnitZ());
      torque += kContactTiltStiffness * (rotation.transpose() * level_axis_world) - kContactTiltDamping * body_rate;
    } else if (position.z() > 0.01) {
      airborne_ = true;  // hysteresis: a bounce of a centimetre is still the same landing
    }

    const Vec3 world_specific_force = rotation * body_force_per_mass + contact_force / vehicle_.mass;
    const Vec3 acceleration = world_specific_force - Vec3(0.0, 0.0, gravity_);
    const Mat3 inertia = vehicle_.inertia();
    const Vec3 angular_acceleration = inertia.inverse() * (torque - body_rate.cross(inertia * body_rate));

    velocity += acceleration * h;
    position += velocity * h;
    body_rate += angular_acceleration * h;
    attitude = quat::multiply(attitude, quat::exp(body_rate * h)).normalized();
    specific_force_ = rotation.transpose() * world_specific_force;
  }

  VehicleParams vehicle_;
  Mat44 effectiveness_;
  double gravity_;
  ImuErrors imu_errors_;
  std::mt19937 rng_;
  Vec4 command_ = Vec4::Zero();
  Vec3 specific_force_ = Vec3::Zero();
  bool airborne_ = false;
  double last_touchdown_speed_ = 0.0;
  int touchdowns_ = 0;
};

}  // namespace sdlqr::test
