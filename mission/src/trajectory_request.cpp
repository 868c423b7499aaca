#include "sdlqr/mission/trajectory_request.hpp"

#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/sampling.hpp"
#include "sdlqr/trajectory/trajectory_csv.hpp"

namespace sdlqr::mission {

Trajectory buildTrajectory(const TrajectoryRequest& request, const trajectory::TrajectoryParams& base,
                           const LqrParams& lqr, const std::string& key) {
  trajectory::TrajectoryParams params = base;
  if (request.laps > 0) params.laps = request.laps;
  if (request.height_offset >= 0.0) params.height_offset = request.height_offset;
  if (request.sample_dt > 0.0) params.sample_dt = request.sample_dt;
  if (!params.valid()) throw ConfigError(key, params.invalidReason());

  Trajectory out;
  try {
    if (request.generator == "minsnap_fast") {
      out = trajectory::sampleTrajectory(trajectory::paperMinSnapFast(params), params.sample_dt, lqr.gravity);
    } else if (request.generator == "minsnap_slow") {
      out = trajectory::sampleTrajectory(trajectory::paperMinSnapSlow(params), params.sample_dt, lqr.gravity);
    } else if (request.generator == "ellipse") {
      out = trajectory::paperEllipse(params, lqr.gravity);
    } else {
      out = trajectory::readTrajectoryCsv(request.csv_path, params.sampleChecks());
    }
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    throw ConfigError(key, e.what());
  }
  out.tracking = request.tracking;
  return out;
}

}  // namespace sdlqr::mission
