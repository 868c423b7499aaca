#include "sdlqr/estimator/estimator_core.hpp"

namespace sdlqr::estimator {

namespace {

ProcessState processStateOf(EstimatorStatus status) {
  switch (status) {
    case EstimatorStatus::kOk: return ProcessState::kRunning;
    case EstimatorStatus::kVioTimeout: return ProcessState::kDegraded;
    case EstimatorStatus::kInitializing: break;
  }
  return ProcessState::kStarting;
}

}  // namespace

EstimatorCore::EstimatorCore(const EstimatorParams& params)
    : estimator_(params),
      fused_(health_.counters().add("vio.fused")),
      initializations_(health_.counters().add("estimator.initializations")),
      clock_resets_(health_.counters().add("estimator.clock_resets")),
      vio_resets_(health_.counters().add("estimator.vio_resets")),
      clipping_(health_.counters().add("imu.clipping")),
      nonfinite_output_(health_.counters().add("error.non_finite_output")) {}

void EstimatorCore::sync() {
  const EstimatorCounters& now = estimator_.counters();
  // Called at every IMU sample: the reasons are walked only when a rejection was counted.
  const bool rejected = now.imu_rejected != seen_.imu_rejected || now.vio_rejected != seen_.vio_rejected;
  for (int r = 1; rejected && r < kRejectReasonCount; ++r) {
    const auto reason = static_cast<RejectReason>(r);
    for (int64_t n = seen_.imuRejected(reason); n < now.imuRejected(reason); ++n) health_.reject(Stream::kImu, reason);
    for (int64_t n = seen_.vioRejected(reason); n < now.vioRejected(reason); ++n) {
      health_.reject(Stream::kVioPose, reason);
    }
  }
  Counters& c = health_.counters();
  c.increment(fused_, now.vio_fused - seen_.vio_fused);
  c.increment(initializations_, now.initializations - seen_.initializations);
  c.increment(clock_resets_, now.clock_resets - seen_.clock_resets);
  c.increment(vio_resets_, now.vio_resets - seen_.vio_resets);
  c.increment(clipping_, now.accel_clipping - seen_.accel_clipping);
  seen_ = now;
}

RejectReason EstimatorCore::onImu(const ImuSample& sample, Outbox& out) {
  const std::optional<StateEstimate> estimate = estimator_.onImu(sample);
  sync();
  if (!estimate) return estimator_.lastImuRejection();
  health_.setSimTime(estimate->utime);
  health_.setState(processStateOf(estimate->status));
  if (!estimate->state().allFinite() || !estimate->body_rate.allFinite()) {
    health_.countError();
    health_.counters().increment(nonfinite_output_);
    health_.setLastError("non-finite state estimate withheld");
    return RejectReason::kNone;
  }
  out.publish(*estimate);
  return RejectReason::kNone;
}

RejectReason EstimatorCore::onVio(const VioPose& pose) {
  estimator_.onVio(pose);
  sync();
  return estimator_.lastVioRejection();
}

}  // namespace sdlqr::estimator
