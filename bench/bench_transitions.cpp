// Planning an entry into a path and a stop from it (trajectory/transition.hpp), as the controller
// does inside a tick when a TRAJECTORY arrives or a GOTO leaves a path: the agile vehicle
// (config/agile752.yaml, its rotor drag modelled) and its 3 m circle. `gentle` plans as the vehicle
// file says (first within gentle_fraction of the limits); `shortest` with gentle_fraction raised to
// input_fraction (one search, as before gentle entries). `BM_PlanStopInATurn`: a stop only the last
// of the planner's searches finds (the 9 m/s lemniscate pulling 28 m/s^2 into a turn: the four
// gentler searches fail first); `BM_CheckPath`: the scenario check, a stop from every moving sample.
// Figures: docs/agility.md §1 and §5.
//
//   bench_transitions [Google Benchmark flags]

#include <benchmark/benchmark.h>

#include <string>

#include "agile_vehicle.hpp"  // tests/support: the benchmarks' circle and figure eight
#include "sdlqr/config/config.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/trajectory/path_check.hpp"
#include "sdlqr/trajectory/speed_fit.hpp"
#include "sdlqr/trajectory/transition.hpp"

namespace sdlqr::bench {
namespace {

struct AgileVehicle {
  LqrParams lqr;
  trajectory::TransitionParams transition;
};

const AgileVehicle& agileVehicle() {
  static const AgileVehicle vehicle = [] {
    const ConfigReader config = loadVehicleConfig(std::string(SDLQR_SOURCE_DIR) + "/config/agile752.yaml");
    return AgileVehicle{LqrParams::loadWithVehicle(config),
                        trajectory::TransitionParams::declaration().load(config.child("controller").child("transition"))};
  }();
  return vehicle;
}

trajectory::TransitionParams paramsFor(bool gentle) {
  trajectory::TransitionParams params = agileVehicle().transition;
  if (!gentle) params.gentle_fraction = params.input_fraction;
  return params;
}

// The first sample of the 3 m circle at `speed` [m/s]: the end of an entry, the start of a stop.
trajectory::FlatState circleStart(double speed) {
  return trajectory::flatStateAtStart(test::agileCircle(speed), agileVehicle().lqr.gravity);
}

// Args: speed [m/s], gentle (1) or shortest (0). Counters: the plan's duration and its inputs.
template <class Plan>
void timePlanning(benchmark::State& state, const Plan& plan) {
  for (auto _ : state) {
    trajectory::TransitionPlan planned = plan();
    benchmark::DoNotOptimize(planned);
  }
  const trajectory::TransitionPlan planned = plan();
  if (!planned.found) state.SkipWithError("none found");
  state.counters["duration_s"] = planned.transition.duration();
  state.counters["max_omega"] = planned.report.max_body_rate;
  state.counters["max_thrust"] = planned.report.max_thrust;
}

void BM_PlanEntry(benchmark::State& state) {
  const trajectory::FlatState start = circleStart(static_cast<double>(state.range(0)));
  trajectory::FlatState hover;
  hover.position = start.position;
  const trajectory::TransitionParams params = paramsFor(state.range(1) != 0);
  timePlanning(state, [&] { return trajectory::planTransition(hover, start, agileVehicle().lqr, params); });
}
BENCHMARK(BM_PlanEntry)->ArgsProduct({{4, 10}, {1, 0}})->ArgNames({"speed", "gentle"})->Unit(benchmark::kMillisecond);

void BM_PlanStop(benchmark::State& state) {
  const trajectory::FlatState start = circleStart(static_cast<double>(state.range(0)));
  const trajectory::TransitionParams params = paramsFor(state.range(1) != 0);
  timePlanning(state, [&] { return trajectory::planStop(start, agileVehicle().lqr, params); });
}
BENCHMARK(BM_PlanStop)->ArgsProduct({{4, 10}, {1, 0}})->ArgNames({"speed", "gentle"})->Unit(benchmark::kMillisecond);

void BM_PlanStopInATurn(benchmark::State& state) {
  const TrajectorySample& turning = test::agileLemniscate(9.0).samples.at(60);
  const trajectory::FlatState from = trajectory::flatStateOf(turning.x, turning.u, 0.0, agileVehicle().lqr.gravity);
  const trajectory::TransitionParams params = agileVehicle().transition;
  timePlanning(state, [&] { return trajectory::planStop(from, agileVehicle().lqr, params, 9.0); });
}
BENCHMARK(BM_PlanStopInATurn)->Unit(benchmark::kMillisecond);

// Args: speed [m/s]. Counter: the moving samples a stop was planned from.
void BM_CheckPath(benchmark::State& state) {
  const Trajectory path = test::agileLemniscate(static_cast<double>(state.range(0)));
  const LqrParams& lqr = agileVehicle().lqr;
  const auto limits = trajectory::FeasibilityLimits::from(lqr, trajectory::peakSpeed(path) * 1.01, 0.5);
  const Vec3 hover = position(path.samples.front().x);
  trajectory::PathCheck check;
  for (auto _ : state) {
    check = trajectory::checkPath(path, limits, hover, 0.0, lqr, agileVehicle().transition);
    benchmark::DoNotOptimize(check);
  }
  if (!check.feasible()) state.SkipWithError("refused");
  state.counters["stops"] = check.exits_checked;
}
BENCHMARK(BM_CheckPath)->Arg(4)->Arg(9)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sdlqr::bench

BENCHMARK_MAIN();
