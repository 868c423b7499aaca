#include "estimator_run.hpp"

#include <algorithm>
#include <cmath>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::estimator::test {

namespace {

template <class Get>
double rms(const std::vector<OutputRecord>& outputs, double from, double to, Get get) {
  double sum = 0.0;
  int n = 0;
  for (const OutputRecord& r : outputs) {
    const double t = 1e-6 * static_cast<double>(r.estimate.utime);
    if (t < from || t >= to || r.estimate.status != EstimatorStatus::kOk) continue;
    const double e = get(r);
    sum += e * e;
    ++n;
  }
  return n > 0 ? std::sqrt(sum / n) : std::nan("");
}

}  // namespace

double RunResult::positionRms(double from, double to) const {
  return rms(outputs, from, to, [](const OutputRecord& r) { return r.position_error; });
}

double RunResult::attitudeRmsDeg(double from, double to) const {
  return rms(outputs, from, to, [](const OutputRecord& r) { return r.attitude_error; }) * 180.0 / M_PI;
}

double RunResult::velocityRms(double from, double to) const {
  return rms(outputs, from, to, [](const OutputRecord& r) { return r.velocity_error; });
}

double RunResult::maxPositionError(double from, double to) const {
  double worst = 0.0;
  for (const OutputRecord& r : outputs) {
    const double t = 1e-6 * static_cast<double>(r.estimate.utime);
    if (t >= from && t < to) worst = std::max(worst, r.position_error);
  }
  return worst;
}

int RunResult::countStatus(EstimatorStatus status) const {
  return static_cast<int>(std::count_if(outputs.begin(), outputs.end(),
                                        [status](const OutputRecord& r) { return r.estimate.status == status; }));
}

RunResult runEstimator(Estimator& estimator, const SensorSimulator& sensors, const std::vector<SensorEvent>& events,
                       const VioFilter& vio_filter) {
  RunResult result;
  result.outputs.reserve(events.size() / 4 + 1);
  for (const SensorEvent& event : events) {
    if (event.kind == SensorEvent::Kind::kVio) {
      VioPose pose = event.vio;
      if (vio_filter && !vio_filter(pose)) continue;
      result.vio_outcomes.push_back(estimator.onVio(pose));
      continue;
    }
    const auto estimate = estimator.onImu(event.imu);
    if (!estimate) continue;
    const TruthSample truth = sensors.truthAt(estimate->utime);
    OutputRecord record;
    record.estimate = *estimate;
    record.position_error = (estimate->position - truth.position).norm();
    record.attitude_error = quat::boxMinus(estimate->orientation, truth.orientation).norm();
    record.velocity_error = (estimate->velocity - truth.velocity).norm();
    result.outputs.push_back(record);
  }
  return result;
}

}  // namespace sdlqr::estimator::test
