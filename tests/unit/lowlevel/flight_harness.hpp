#pragma once
// Closes the loop for tests: the test plant, the bodyrate loop stepped on every 1 kHz IMU
// sample, and a truth-based position controller standing in for the LQR at 100 Hz.

#include <cmath>
#include <cstdint>

#include <Eigen/Geometry>

#include "quad_plant.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/lowlevel/bodyrate_loop.hpp"

namespace sdlqr::test {

inline constexpr double kGravity = 9.81;
inline constexpr int64_t kImuPeriodUs = 1000;

// Rate command that flies the plant to `target` (position hold from truth, zero yaw rate).
inline RateCommand holdPosition(const QuadPlant& plant, const Vec3& target, int64_t utime) {
  Vec3 acceleration = 4.0 * (target - plant.position) - 3.0 * plant.velocity;
  const double horizontal = acceleration.head<2>().norm();
  if (horizontal > 4.0) acceleration.head<2>() *= 4.0 / horizontal;
  acceleration.z() = std::clamp(acceleration.z(), -6.0, 6.0);
  acceleration.z() += kGravity;
  const Vec3 body_z = quat::bodyZ(plant.attitude);
  const Vec3 desired_z = acceleration.normalized();
  const Vec3 axis = body_z.cross(desired_z);
  const double angle = std::atan2(axis.norm(), body_z.dot(desired_z));
  RateCommand command;
  command.utime = utime;
  if (axis.norm() > 1e-9) command.body_rate = 6.0 * angle * quat::rotateInverse(plant.attitude, axis.normalized());
  command.body_rate.z() = 0.0;
  command.body_rate = command.body_rate.cwiseMax(-3.0).cwiseMin(3.0);
  command.thrust = std::clamp(acceleration.dot(body_z), 2.0, 18.0);
  return command;
}

class FlightHarness {
 public:
  explicit FlightHarness(const ImuErrors& imu = ImuErrors(), const lowlevel::LowlevelParams& params = lowlevel::LowlevelParams(),
                         const VehicleParams& vehicle = VehicleParams())
      : vehicle(vehicle), loop(vehicle, params, ValidationLimits(), kGravity), plant(vehicle, kGravity, imu) {}

  // One IMU period: the plant moves, the loop sees the sample, the rotors get the command.
  const MotorCommand& tick() {
    plant.advance(1e-3 * kImuPeriodUs / 1000.0);
    utime += kImuPeriodUs;
    last = loop.step(plant.imu(utime, seq++));
    plant.setMotorCommand(last);
    return last;
  }

  void command(CommandType type) {
    Command command;
    command.utime = utime;
    command.command = type;
    loop.handleCommand(command);
  }

  RejectReason sendRate(const Vec3& rate, double thrust) {
    RateCommand command;
    command.utime = utime;
    command.body_rate = rate;
    command.thrust = thrust;
    return loop.setRateCommand(command);
  }

  // Flies `seconds` holding `target`, a new command every 10 ms.
  void holdFor(const Vec3& target, double seconds) {
    const int ticks = static_cast<int>(std::lround(seconds * 1e6 / kImuPeriodUs));
    for (int i = 0; i < ticks; ++i) {
      if (i % 10 == 0) loop.setRateCommand(holdPosition(plant, target, utime));
      tick();
    }
  }

  double seconds() const { return 1e-6 * static_cast<double>(utime); }

  VehicleParams vehicle;
  lowlevel::BodyrateLoop loop;
  QuadPlant plant;
  int64_t utime = 0;
  int64_t seq = 0;
  MotorCommand last;
};

}  // namespace sdlqr::test
