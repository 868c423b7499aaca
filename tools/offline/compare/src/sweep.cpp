#include "sdlqr/compare/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "sdlqr/batch/metric.hpp"
#include "sdlqr/mission/mission_core.hpp"

namespace sdlqr::compare {

namespace {

bool hasSpeed(const mission::ScenarioEvent& event) {
  const std::string& g = event.trajectory.generator;
  return event.kind == mission::ScenarioEvent::Kind::kTrajectory && (g == "circle" || g == "lemniscate" || g == "waypoints");
}

}  // namespace

size_t sweptEventIndex(const mission::Scenario& scenario, const std::string& where) {
  size_t found = scenario.events.size();
  for (size_t i = 0; i < scenario.events.size(); ++i) {
    if (!hasSpeed(scenario.events[i])) continue;
    if (found != scenario.events.size()) {
      throw ConfigError(where, scenario.path + ": more than one trajectory with a speed (the sweep sets one)");
    }
    found = i;
  }
  if (found == scenario.events.size()) {
    throw ConfigError(where, scenario.path + ": no circle, lemniscate or waypoints trajectory whose speed the sweep could set");
  }
  return found;
}

mission::Scenario atSpeed(const mission::Scenario& scenario, double speed) {
  mission::Scenario out = scenario;
  mission::TrajectoryRequest& request = out.events[sweptEventIndex(scenario, "speed_sweep.scenario")].trajectory;
  request.speed = speed;
  request.v_max = -1.0;               // the check's speed limit follows the speed asked
  request.on_infeasible = mission::OnInfeasible::kRefuse;  // a sweep flies the speed it names, or none
  return out;
}

std::vector<std::string> sweepRefusals(const batch::BatchContext& context, const std::vector<double>& speeds) {
  std::vector<std::string> out;
  const mission::PathLimits limits{context.config.lqr, context.config.controller.guard,
                                   context.config.controller.transition};
  for (double speed : speeds) {
    const mission::Scenario scenario = atSpeed(context.scenario, speed);
    try {
      // The mission's own check, from the hover the scenario flies before the path.
      const mission::MissionCore check(scenario, context.config.trajectory, limits, mission::MissionOptions());
      out.emplace_back();
    } catch (const ConfigError& e) {
      out.emplace_back(e.what());
    }
  }
  return out;
}

std::vector<long long> sweepSeeds(const Benchmark& benchmark, const mission::Scenario& scenario) {
  if (benchmark.seed >= 0) return {benchmark.seed};
  return benchmark.sweep.seeds.empty() ? std::vector<long long>{scenario.seed} : benchmark.sweep.seeds;
}

bool sweepFlightPasses(const analysis::FlightReport& report, const std::vector<std::string>& fail_on) {
  int judged = 0, passed = 0;
  for (const analysis::Check& c : report.checks) {
    if (std::find(fail_on.begin(), fail_on.end(), c.key) == fail_on.end()) continue;
    ++judged;
    passed += c.pass ? 1 : 0;
  }
  return judged > 0 && passed == judged && !report.crashed;
}

SweepFlight flySweepSpeed(const batch::BatchContext& context, const std::vector<std::string>& fail_on,
                          const std::string& controller, double speed, const std::vector<long long>& seeds) {
  SweepFlight f;
  f.speed = speed;
  f.pass = true;
  auto worst = [](double& into, double v) { into = std::isnan(into) || v > into || std::isnan(v) ? v : into; };
  for (long long seed : seeds) {
    batch::FlightWorld world{{context.config.vehicle, context.config.sim}, atSpeed(context.scenario, speed)};
    world.scenario.seed = seed;
    const analysis::FlightReport r = batch::fly(context, world, controller).report;
    const std::string prefix = seeds.size() > 1 ? "seed " + std::to_string(seed) + ": " : "";
    for (const analysis::Check& c : r.checks) {
      if (!c.pass) f.failed.push_back(prefix + c.name);
    }
    f.pass = f.pass && sweepFlightPasses(r, fail_on);
    worst(f.path_error_rms, batch::largestOf(r.trajectories, [](const analysis::PathTrackingReport& t) { return t.path_error_rms; }));
    worst(f.path_error_max, batch::largestOf(r.trajectories, [](const analysis::PathTrackingReport& t) { return t.path_error_max; }));
    worst(f.max_tilt_deg, r.max_tilt_deg);
    ++f.flights;
    f.simulated_s += world.scenario.duration;
  }
  return f;
}

SweepResult flySweep(const batch::BatchContext& context, const SpeedSweep& sweep, const std::vector<long long>& seeds,
                     const std::vector<std::string>& refusals, const std::string& controller,
                     const std::function<void(const SweepFlight&)>& landed) {
  SweepResult result;
  result.controller = controller;
  for (size_t i = 0; i < sweep.speeds.size(); ++i) {
    const double speed = sweep.speeds[i];
    if (!refusals[i].empty()) {
      SweepFlight refused;
      refused.speed = speed;
      refused.feasible = false;
      refused.failed.push_back(refusals[i]);
      result.flights.push_back(refused);
      if (landed) landed(refused);
      break;
    }
    result.flights.push_back(flySweepSpeed(context, sweep.fail_on, controller, speed, seeds));
    if (landed) landed(result.flights.back());
    if (!result.flights.back().pass) {
      result.first_failing_speed = speed;
      break;
    }
    result.highest_passing_speed = speed;
  }
  return result;
}

}  // namespace sdlqr::compare
