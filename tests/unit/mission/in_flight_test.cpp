// Parameters declared once, the in-flight ones too: a key's declaration says which PARAMS group
// changes it (`.inFlight(...)`), and the scenario's `params:` keys, the one check of an update's
// values (bus validation, a running solver's and controller's RuntimeLqrParams, the scenario) and
// its application follow from it.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "sdlqr/health/validate.hpp"
#include "sdlqr/math/in_flight.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/mission/scenario.hpp"
#include "test_paths.hpp"

namespace sdlqr {
namespace {

TEST(InFlight, TheDeclarationsSayWhichKeysPARAMSChangesAndInWhichGroup) {
  std::vector<std::string> declared;
  for (const InFlightParam& p : inFlightParams()) {
    declared.push_back(p.section + "." + p.info.key + "/" + std::to_string(p.info.in_flight));
  }
  const std::vector<std::string> expected = {
      "lqr.q_diag/1", "lqr.r_diag/1", "lqr.omega_max/2", "lqr.c_min/2", "lqr.c_max/2", "lqr.law/16",
      "vehicle.mass/4", "controller.tracking/8"};
  EXPECT_EQ(declared, expected);
  EXPECT_EQ(inFlightGroups(), ParamsUpdate::kWeights | ParamsUpdate::kLimits | ParamsUpdate::kMass |
                                  ParamsUpdate::kTracking | ParamsUpdate::kLaw);
}

ParamsUpdate limits(double omega_max, double c_min, double c_max) {
  ParamsUpdate u;
  u.field_mask = ParamsUpdate::kLimits;
  u.omega_max = omega_max;
  u.c_min = c_min;
  u.c_max = c_max;
  return u;
}

// One check, its verdict and the key it blames, and the bus and the running LQR agree with it.
void expectRefused(const ParamsUpdate& u, InFlightVerdict verdict, const std::string& key, RejectReason on_bus) {
  const InFlightCheck check = checkInFlight(u);
  EXPECT_EQ(check.verdict, verdict) << key;
  EXPECT_EQ(check.key, key);
  EXPECT_EQ(validate(u, ValidationLimits{}), on_bus) << key;
  RuntimeLqrParams running{LqrParams{}};
  ParamsUpdate stamped = u;
  stamped.utime = 1;
  EXPECT_EQ(running.apply(stamped), ParamsOutcome::kInvalid) << key;
}

TEST(InFlight, EveryValueIsCheckedAgainstItsDeclarationByOneCheck) {
  EXPECT_TRUE(checkInFlight(limits(3.0, 1.0, 15.0)).ok());
  ParamsUpdate mass;
  mass.field_mask = ParamsUpdate::kMass;
  mass.mass = 200.0;
  expectRefused(mass, InFlightVerdict::kOutOfRange, "mass", RejectReason::kOutOfRange);
  EXPECT_EQ(checkInFlight(mass).reason, "must be in (0, 100) kg");
  mass.mass = std::nan("");
  expectRefused(mass, InFlightVerdict::kNonFinite, "mass", RejectReason::kNonFinite);
  expectRefused(limits(3.0, 5.0, 4.0), InFlightVerdict::kOutOfRange, "c_max", RejectReason::kOutOfRange);  // c_max > c_min
  expectRefused(limits(-1.0, 1.0, 15.0), InFlightVerdict::kOutOfRange, "omega_max", RejectReason::kOutOfRange);
  ParamsUpdate weights;
  weights.field_mask = ParamsUpdate::kWeights;
  weights.q_diag = State::Ones();
  weights.r_diag = Input::Ones();
  EXPECT_TRUE(checkInFlight(weights).ok());
  weights.q_diag[3] = -1.0;
  expectRefused(weights, InFlightVerdict::kOutOfRange, "q_diag[3]", RejectReason::kOutOfRange);
  ParamsUpdate law;
  law.field_mask = ParamsUpdate::kLaw;
  law.law = static_cast<ControlLaw>(9);
  expectRefused(law, InFlightVerdict::kBadChoice, "law", RejectReason::kBadEnum);
  ParamsUpdate tracking;
  tracking.field_mask = ParamsUpdate::kTracking;
  tracking.tracking = static_cast<ReferenceMode>(7);
  expectRefused(tracking, InFlightVerdict::kBadChoice, "tracking", RejectReason::kBadEnum);
  ParamsUpdate unknown;
  unknown.field_mask = 64;
  expectRefused(unknown, InFlightVerdict::kUnknownGroup, "field_mask", RejectReason::kBadEnum);
  // Whether the rotors lift a mass depends on the vehicle flown: the bodyrate loop's check, not this.
  mass.mass = 0.6;  // more than the default 4 x 1.25 N lift
  EXPECT_TRUE(checkInFlight(mass).ok());
  EXPECT_EQ(validate(mass, ValidationLimits{}), RejectReason::kNone);
  // A value outside its group is not looked at: a mass of 0 with only the limits set passes.
  ParamsUpdate only_limits = limits(3.0, 1.0, 15.0);
  only_limits.mass = 0.0;
  EXPECT_TRUE(checkInFlight(only_limits).ok());
}

TEST(InFlight, ARunningLqrTakesTheKeysItDeclaresForTheGroupsAnUpdateNames) {
  RuntimeLqrParams running{LqrParams{}};
  ParamsUpdate u = limits(3.0, 1.0, 15.0);
  u.field_mask |= ParamsUpdate::kLaw | ParamsUpdate::kMass;
  u.law = ControlLaw::kGeometric;
  u.mass = 0.3;
  u.q_diag = State::Constant(7.0);  // FIELD_WEIGHTS not named: not taken
  u.utime = 1;
  ASSERT_EQ(running.apply(u), ParamsOutcome::kApplied);
  EXPECT_EQ(running.params().omega_max, 3.0);
  EXPECT_EQ(running.params().c_min, 1.0);
  EXPECT_EQ(running.params().c_max, 15.0);
  EXPECT_EQ(running.params().law, ControlLaw::kGeometric);
  EXPECT_EQ(running.params().q_diag, LqrParams{}.q_diag);
}

std::string scenarioWithParams(const std::string& params) {
  return "events:\n  - {at: 1.0, params: " + params + "}\n";
}

ParamsUpdate loadParams(const std::string& params) {
  const std::string path = test::tempPath("in_flight_scenario.yaml");
  std::ofstream(path) << scenarioWithParams(params);
  const mission::Scenario s = mission::Scenario::load(path);
  return s.events.at(0).params;
}

std::string errorOfParams(const std::string& params) {
  try {
    loadParams(params);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(InFlight, AScenarioSetsTheKeysDeclaredInFlightAGroupAtATime) {
  const ParamsUpdate u = loadParams("{omega_max: 3, c_min: 1, c_max: 15, mass: 0.3, tracking: temporal, law: geometric}");
  EXPECT_EQ(u.field_mask, ParamsUpdate::kLimits | ParamsUpdate::kMass | ParamsUpdate::kTracking | ParamsUpdate::kLaw);
  EXPECT_EQ(u.omega_max, 3.0);
  EXPECT_EQ(u.c_max, 15.0);
  EXPECT_EQ(u.mass, 0.3);
  EXPECT_EQ(u.tracking, ReferenceMode::kTemporal);
  EXPECT_EQ(u.law, ControlLaw::kGeometric);
  EXPECT_NE(errorOfParams("{dt: 0.02}").find("events[0].params.dt"), std::string::npos);  // not in flight
  EXPECT_NE(errorOfParams("{q_diag: [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]}").find("q_diag and r_diag go together"),
            std::string::npos);
  EXPECT_NE(errorOfParams("{c_min: 1}").find("omega_max, c_min and c_max go together"), std::string::npos);
  EXPECT_NE(errorOfParams("{mass: 200}").find("events[0].params.mass: must be in (0, 100) kg"), std::string::npos);
  EXPECT_NE(errorOfParams("{omega_max: 3, c_min: 5, c_max: 4}").find("events[0].params.c_max: must be > c_min"),
            std::string::npos);
  EXPECT_NE(errorOfParams("{tracking: sideways}").find("events[0].params.tracking: expected spatial or temporal"),
            std::string::npos);
  EXPECT_NE(errorOfParams("{}").find("sets nothing"), std::string::npos);
}

}  // namespace
}  // namespace sdlqr
