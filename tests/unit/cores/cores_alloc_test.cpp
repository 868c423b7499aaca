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
#include "sdlqr/messages/in_process_wiring.hpp"
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

// The cores wired by their ports as in the in-process loop, without recording.
class Stack {
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
    wiring_.feedWallTime(1e-6 * static_cast<double>(sim_.simulator().utime()));
    sim_.step(wiring_.outboxOf<sim::SimCore>());
  }
  const sim::SimCore& sim() const { return sim_; }
  const controller::ControllerCore& controller() const { return controller_; }
  const gains::GainsCore& gains() const { return gains_; }

 private:
  mission::MissionCore mission_;
  sim::SimCore sim_;
  estimator::EstimatorCore estimator_;
  gains::GainsCore gains_;
  controller::ControllerCore controller_;
  lowlevel::LowlevelCore lowlevel_;
  NoObserver none_;
  InProcessWiring<NoObserver, lowlevel::LowlevelCore, estimator::EstimatorCore, gains::GainsCore,
                  controller::ControllerCore, mission::MissionCore, sim::SimCore>
      wiring_{none_, lowlevel_, estimator_, gains_, controller_, mission_, sim_};
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
