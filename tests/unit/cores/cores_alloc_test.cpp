// The process cores allocate nothing on their flight paths: the simulator's step and MOTOR_CMD,
// the estimator's IMU and VIO_POSE, the gain solver's STATE_EST (solve) and REFERENCE, the
// controller's STATE_EST (tick), GAINS (with the closed-loop check) and COMMAND, the lowlevel's
// IMU, RATE_CMD and COMMAND, the mission's clock (its setpoint jump and re-sends included), and
// every core's onWallTime. The cores are wired as on the bus (no recording); hover_short's
// take-off is flown first, then 3 s around its setpoint jump are counted (by the replaced
// operator new of tests/support).

#include <gtest/gtest.h>

#include <iostream>

#include "allocation_counter.hpp"
#include "sdlqr/controller/controller_core.hpp"
#include "sdlqr/estimator/estimator_core.hpp"
#include "sdlqr/gains/gains_core.hpp"
#include "sdlqr/lowlevel/lowlevel_core.hpp"
#include "sdlqr/mission/mission_core.hpp"
#include "sdlqr/sim/sim_core.hpp"

namespace sdlqr {
namespace {

const std::string kVehicle = std::string(SDLQR_SOURCE_DIR) + "/config/quad255.yaml";
const std::string kScenario = std::string(SDLQR_SOURCE_DIR) + "/tests/integration/replay/hover_short.yaml";

struct Config {
  ConfigReader root = loadVehicleConfig(kVehicle);
  VehicleParams vehicle = VehicleParams::load(root.child("vehicle"));
  LqrParams lqr = LqrParams::load(root.child("lqr"));
  FaultParams faults = FaultParams::load(root.child("faults"));
  controller::ControllerParams controller = controller::ControllerParams::load(root.child("controller"));
};

// The channels of the bus, without the bus.
class Stack final : public Outbox {
 public:
  Stack(const Config& c, const mission::Scenario& scenario)
      : mission_(scenario, trajectory::TrajectoryParams::load(c.root.child("trajectory")),
                 {c.lqr, c.controller.guard, c.controller.transition}, {}),
        sim_(c.vehicle, sim::SimParams::load(c.root.child("sim"))),
        estimator_(estimator::EstimatorParams::load(c.root.child("estimator"))),
        gains_(c.lqr, gains::GainsParams::load(c.root.child("gains")), c.faults),
        controller_(c.lqr, c.controller, c.faults),
        lowlevel_(c.vehicle, lowlevel::LowlevelParams::load(c.root.child("lowlevel")), c.lqr.gravity, c.faults) {}

  void step() {
    const double now_s = 1e-6 * static_cast<double>(sim_.simulator().utime());
    controller_.onWallTime(now_s);
    gains_.onWallTime(now_s);
    lowlevel_.onWallTime(now_s);
    sim_.step(*this);
  }
  const sim::SimCore& sim() const { return sim_; }
  const controller::ControllerCore& controller() const { return controller_; }
  const gains::GainsCore& gains() const { return gains_; }

 private:
  void publish(const ImuSample& m) override {
    lowlevel_.onImu(m, *this);
    estimator_.onImu(m, *this);
  }
  void publish(const VioPose& m) override { estimator_.onVio(m); }
  void publish(const SimTruth&) override {}
  void publish(const StateEstimate& m) override {
    gains_.onStateEstimate(m, *this);
    controller_.onStateEstimate(m, *this);
  }
  void publish(const GainSet& m) override { controller_.onGains(m); }
  void publish(const RateCommand& m) override { lowlevel_.onRateCommand(m); }
  void publish(const Reference& m) override { gains_.onReference(m); }
  void publish(const MotorCommand& m) override { sim_.onMotorCommand(m); }
  void publish(const Command& m) override {
    controller_.onCommand(m);
    lowlevel_.onCommand(m);
  }
  void publish(const Disturbance&) override {}
  void publish(const ParamsUpdate&) override {}
  void publish(const Trajectory&) override {}
  void publish(const SimClockTick& m) override { mission_.onClock(m.utime, *this); }

  mission::MissionCore mission_;
  sim::SimCore sim_;
  estimator::EstimatorCore estimator_;
  gains::GainsCore gains_;
  controller::ControllerCore controller_;
  lowlevel::LowlevelCore lowlevel_;
};

TEST(CoresAllocation, AHoverAllocatesNothingInAnyCore) {
  const Config config;
  const mission::Scenario scenario = mission::Scenario::load(kScenario);
  Stack stack(config, scenario);
  for (int i = 0; i < 5000; ++i) stack.step();  // armed at 0.5 s, took off at 1 s: at 1 m
  const int64_t ticks_before = stack.controller().health().counter("controller.ticks");
  const int64_t solves_before = stack.gains().health().counter("gains.solves");

  const testing::AllocationCounter allocations;
  for (int i = 0; i < 3000; ++i) stack.step();
  const long counted = allocations.count();

  const int64_t ticks = stack.controller().health().counter("controller.ticks") - ticks_before;
  const int64_t solves = stack.gains().health().counter("gains.solves") - solves_before;
  std::cout << "3 s of hover: " << counted << " allocations, " << ticks << " controller ticks, " << solves
            << " solves, height " << stack.sim().simulator().body().position.z() << " m\n";
  EXPECT_EQ(counted, 0);
  // What was counted flew: every path above ran.
  EXPECT_GE(ticks, 290);
  EXPECT_GE(solves, 29);
  EXPECT_NEAR(stack.sim().simulator().body().position.z(), 1.0, 0.2);
  EXPECT_GT(stack.sim().simulator().body().position.x(), 0.2);  // the jump to x = 0.5 m was flown
  EXPECT_EQ(stack.controller().health().rejected() + stack.gains().health().rejected(), 0);
}

}  // namespace
}  // namespace sdlqr
