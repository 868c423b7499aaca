#include "sdlqr/compare/experiment_flight.hpp"

namespace sdlqr::compare {

batch::BatchContext scenarioContext(const std::string& scenario_path, const std::vector<std::string>& controllers,
                                    long long seed) {
  batch::BatchSpec spec;
  spec.path = scenario_path;
  spec.scenario_path = scenario_path;
  spec.controllers = controllers;
  spec.flights = 1;
  batch::BatchContext context = batch::BatchContext::forSpec(spec);
  if (seed >= 0) context.scenario.seed = seed;
  return context;
}

ExperimentFlight flyExperiment(const batch::BatchContext& context, const std::string& controller) {
  const batch::FlightWorld world{{context.config.vehicle, context.config.sim}, context.scenario};
  batch::FlownFlight flown = batch::fly(context, world, controller, /*record_motor_commands=*/true);
  ExperimentFlight f;
  f.experiment = context.scenario.name;
  f.controller = controller;
  f.seed = context.scenario.seed;
  f.simulated_s = context.scenario.duration;
  f.report = std::move(flown.report);
  const auto& truth = flown.log.sim_truth.messages;
  for (size_t i = 0; i < truth.size(); i += kTrackDecimation) {
    f.track.push_back({1e-6 * static_cast<double>(truth[i].utime), truth[i].position});
  }
  const auto& uploads = flown.log.trajectory.messages;
  for (size_t k = 0; k < uploads.size(); ++k) {
    for (const TrajectorySample& s : uploads[k].samples) {
      f.path.push_back({static_cast<int>(k), Vec3(s.x[0], s.x[1], s.x[2])});
    }
  }
  return f;
}

}  // namespace sdlqr::compare
