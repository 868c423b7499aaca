#include "sdlqr/estimator/estimator.hpp"

#include <cmath>
#include <stdexcept>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::estimator {

namespace {

bool allFinite(const Vec3& v) { return v.allFinite(); }

int64_t secondsToUs(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e6)); }

// [std] a gated run's innovation drift corrects the velocity only beyond this many of its stds.
constexpr double kDriftSignificance = 3.0;

}  // namespace

int64_t EstimatorCounters::rejectedTotal() const {
  int64_t total = 0;
  for (int64_t n : imu_rejected) total += n;
  for (int64_t n : vio_rejected) total += n;
  return total;
}

Estimator::Estimator(const EstimatorParams& params)
    : params_(params),
      noise_(ProcessNoise::from(params)),
      period_us_(params.outputPeriodUs()),
      imu_max_gap_us_(secondsToUs(params.imu_max_gap)),
      reinit_after_us_(secondsToUs(params.reinit_after)),
      vio_timeout_us_(secondsToUs(params.vio_timeout)),
      downsampler_(params.outputPeriodUs(), params.accel_clip_level),
      history_(params.valid() ? params.historyCapacity() : 2),
      gated_run_(params.gate_chi2, secondsToUs(params.vio_reset_after)) {
  const std::string reason = params.invalidReason();
  if (!reason.empty()) throw std::invalid_argument("estimator." + reason);
}

void Estimator::reset() {
  downsampler_.reset();
  history_.clear();
  initialized_ = false;
  has_fused_ = false;
  last_fused_seq_ = -1;
  pending_vio_.reset();
  gated_run_.clear();
  timing_rejects_in_a_row_ = 0;
  status_ = EstimatorStatus::kInitializing;
}

const NavState& Estimator::state() const {
  static const NavState kNone;
  return history_.empty() ? kNone : history_.newest().state;
}

const ErrorCovariance& Estimator::covariance() const {
  static const ErrorCovariance kNone = ErrorCovariance::Zero();
  return history_.empty() ? kNone : history_.newest().covariance;
}

int64_t Estimator::stateUtime() const { return history_.empty() ? 0 : history_.newest().utime; }

void Estimator::rejectImu(RejectReason reason) {
  ++counters_.imu_rejected[static_cast<size_t>(reason)];
  last_imu_rejection_ = reason;
}

VioOutcome Estimator::rejectVio(RejectReason reason) {
  ++counters_.vio_rejected[static_cast<size_t>(reason)];
  last_vio_rejection_ = reason;
  return VioOutcome::kRejected;
}

// ---- IMU ----------------------------------------------------------------------------------------

bool Estimator::imuTimingAcceptable(const ImuSample& sample) {
  if (!downsampler_.started()) return true;
  const int64_t step = sample.utime - downsampler_.lastSampleTime();
  RejectReason reason;
  if (step <= 0) {
    reason = RejectReason::kTimeBackwards;
  } else if (step > imu_max_gap_us_) {
    reason = RejectReason::kTimeGap;
  } else {
    timing_rejects_in_a_row_ = 0;
    return true;
  }
  rejectImu(reason);
  // One bad timestamp is dropped; a sustained run means the clock itself changed (a restarted
  // simulator, a replayed log, a long outage): start over on the new clock.
  if (++timing_rejects_in_a_row_ < params_.imu_time_reset_count) return false;
  reset();
  ++counters_.clock_resets;
  return true;
}

std::optional<StateEstimate> Estimator::onImu(const ImuSample& sample) {
  last_imu_rejection_ = RejectReason::kNone;
  if (!allFinite(sample.gyro) || !allFinite(sample.accel)) {
    rejectImu(RejectReason::kNonFinite);
    return std::nullopt;
  }
  if (sample.gyro.cwiseAbs().maxCoeff() > params_.gyro_range || sample.accel.cwiseAbs().maxCoeff() > params_.accel_range) {
    rejectImu(RejectReason::kOutOfRange);
    return std::nullopt;
  }
  if (!imuTimingAcceptable(sample)) return std::nullopt;
  if (sample.accel.cwiseAbs().maxCoeff() >= params_.accel_clip_level) ++counters_.accel_clipping;

  if (!downsampler_.started()) {
    // The stream's first instant gets a history entry too, so a pose captured exactly then (the
    // simulator's first frame) can initialise the filter.
    HistoryEntry& entry = history_.pushNewest();
    entry = HistoryEntry();
    entry.utime = sample.utime;
    entry.imu_seq = sample.seq;
  }
  window_closed_ = false;
  downsampler_.add(sample, [this](const ImuWindow& window) { onWindow(window); });
  if (!window_closed_) return std::nullopt;
  if (pending_vio_ && pending_vio_->utime <= history_.newest().utime) {
    const VioPose pose = *pending_vio_;
    pending_vio_.reset();
    // Only the first window of a stream can start after a pose that was pending in it.
    if (pose.utime < history_.oldest().utime) {
      rejectVio(RejectReason::kStale);
    } else {
      fuseAtCaptureTime(pose, needsInitialization(pose.utime));
    }
  }
  updateStatus();
  return makeOutput();
}

void Estimator::onWindow(const ImuWindow& window) {
  // The newest entry keeps its slot when a new one is pushed (the capacity is at least 2).
  const HistoryEntry* previous = initialized_ && !history_.empty() ? &history_.newest() : nullptr;
  HistoryEntry& entry = history_.pushNewest();
  if (previous != nullptr) {
    propagate(previous->state, previous->covariance, window.delta, noise_, entry.state, entry.covariance);
  } else {
    entry.state = NavState();
    entry.covariance.setZero();
  }
  entry.utime = window.end_utime;
  entry.input = window.delta;
  entry.imu_seq = window.last_imu_seq;
  ++counters_.imu_windows;
  window_closed_ = true;
}

// ---- VIO ----------------------------------------------------------------------------------------

bool Estimator::needsInitialization(int64_t capture_utime) const {
  return !initialized_ || capture_utime - last_fused_capture_ > reinit_after_us_;
}

VioOutcome Estimator::onVio(const VioPose& pose) {
  last_vio_rejection_ = RejectReason::kNone;
  if (!allFinite(pose.position) || !pose.orientation.allFinite() || !std::isfinite(pose.position_std) ||
      !std::isfinite(pose.attitude_std)) {
    return rejectVio(RejectReason::kNonFinite);
  }
  if (pose.position_std < 0.0 || pose.attitude_std < 0.0) return rejectVio(RejectReason::kOutOfRange);
  if (std::abs(pose.orientation.norm() - 1.0) > params_.quaternion_norm_tolerance) {
    return rejectVio(RejectReason::kQuaternionNorm);
  }
  const int64_t t = pose.utime;
  if (has_fused_ && t <= last_fused_capture_) return rejectVio(RejectReason::kTimeBackwards);
  if (pending_vio_ && t <= pending_vio_->utime) return rejectVio(RejectReason::kTimeBackwards);
  if (!downsampler_.started() || t > downsampler_.lastSampleTime()) return rejectVio(RejectReason::kTimeFuture);
  if (!history_.empty() && t < history_.oldest().utime) return rejectVio(RejectReason::kStale);
  if (history_.empty() || t > history_.newest().utime) {
    // Captured inside the IMU window still being integrated: fuse it when that window closes.
    if (pending_vio_) rejectVio(RejectReason::kSuperseded);
    pending_vio_ = pose;
    return VioOutcome::kPending;
  }
  return fuseAtCaptureTime(pose, needsInitialization(t));
}

PoseMeasurement Estimator::measurementOf(const VioPose& pose) const {
  PoseMeasurement z;
  z.position = pose.position;
  z.orientation = pose.orientation.normalized();
  const double position_std = pose.position_std > 0.0 ? pose.position_std : params_.vio_position_std;
  const double attitude_std = pose.attitude_std > 0.0 ? pose.attitude_std : params_.vio_attitude_std;
  z.position_var = position_std * position_std;
  z.attitude_var = attitude_std * attitude_std;
  return z;
}

void Estimator::restartFrom(const PoseMeasurement& pose, const Vec3& velocity, const Vec3& velocity_var,
                            NavState& state, ErrorCovariance& covariance) const {
  ErrorCovariance p = ErrorCovariance::Zero();
  p.diagonal().segment<3>(kErrPos).setConstant(pose.position_var);
  p.diagonal().segment<3>(kErrVel) = velocity_var;
  p.diagonal().segment<3>(kErrRot).setConstant(pose.attitude_var);
  NavState start;
  if (initialized_) {
    // Neither a VIO gap nor a wrong position / velocity invalidates the bias estimates.
    start.gyro_bias = state.gyro_bias;
    start.accel_bias = state.accel_bias;
    p.block<6, 6>(kErrGyroBias, kErrGyroBias) = covariance.block<6, 6>(kErrGyroBias, kErrGyroBias);
  } else {
    p.diagonal().segment<3>(kErrGyroBias).setConstant(params_.initial_gyro_bias_std * params_.initial_gyro_bias_std);
    p.diagonal().segment<3>(kErrAccelBias).setConstant(params_.initial_accel_bias_std * params_.initial_accel_bias_std);
  }
  start.position = pose.position;
  start.orientation = pose.orientation;
  start.velocity = velocity;
  state = start;
  covariance = p;
}

VioOutcome Estimator::fuseAtCaptureTime(const VioPose& pose, bool initialize) {
  const int64_t t = pose.utime;
  const int base = history_.indexAtOrBefore(t);  // callers guarantee oldest <= t <= newest
  const PoseMeasurement z = measurementOf(pose);

  NavState state = history_.at(base).state;
  ErrorCovariance covariance = history_.at(base).covariance;
  ImuDelta rest;
  int first_to_recompute = base + 1;
  const bool inside_window = t > history_.at(base).utime;
  if (inside_window) {
    // Advance to the capture time itself with the matching part of the next window.
    const HistoryEntry& next = history_.at(base + 1);
    const double fraction =
        static_cast<double>(t - history_.at(base).utime) / static_cast<double>(next.utime - history_.at(base).utime);
    const ImuDeltaSplit parts = split(next.input, fraction);
    if (initialized_) propagate(state, covariance, parts.first, noise_);
    rest = parts.rest;
  }

  VioOutcome outcome = VioOutcome::kFused;
  if (initialize) {
    // Velocity zero: its std covers a restart in mid-flight.
    const double velocity_var = params_.initial_velocity_std * params_.initial_velocity_std;
    restartFrom(z, Vec3::Zero(), Vec3::Constant(velocity_var), state, covariance);
    gated_run_.clear();
    outcome = VioOutcome::kInitialized;
  } else {
    const PoseUpdateResult update = updatePose(state, covariance, z, params_.gate_chi2);
    if (update.accepted) {
      gated_run_.clear();
    } else if (!gated_run_.add(t, update)) {
      return rejectVio(RejectReason::kGated);
    } else {
      // The run's poses agree and the filter does not: trust the VIO. The innovation's drift
      // over the run measures the filter's velocity error; it is applied where it stands out of
      // the regression's noise (a VIO frame jump carries no velocity error, and that noise would
      // only spoil a good velocity). The velocity is then uncertain by that noise and by no less
      // than the filter thought before (the run may have begun after the velocity went wrong).
      const double drift_var = gated_run_.positionDriftRateVariance(z.position_var);
      const Vec3 drift = gated_run_.positionDriftRate();
      const Vec3 significant = (drift.array().square() > kDriftSignificance * kDriftSignificance * drift_var)
                                   .select(drift, Vec3::Zero());
      const Vec3 velocity_var = covariance.diagonal().segment<3>(kErrVel) + Vec3::Constant(drift_var);
      restartFrom(z, state.velocity + significant, velocity_var, state, covariance);
      gated_run_.clear();
      outcome = VioOutcome::kReset;
    }
  }

  int updated = base;
  if (inside_window) {
    propagate(state, covariance, rest, noise_);
    updated = base + 1;
  }
  history_.at(updated).state = state;
  history_.at(updated).covariance = covariance;
  for (first_to_recompute = updated + 1; first_to_recompute < history_.size(); ++first_to_recompute) {
    HistoryEntry& entry = history_.at(first_to_recompute);
    const HistoryEntry& previous = history_.at(first_to_recompute - 1);
    propagate(previous.state, previous.covariance, entry.input, noise_, entry.state, entry.covariance);
  }

  initialized_ = true;
  has_fused_ = true;
  last_fused_capture_ = t;
  last_fused_seq_ = pose.seq;
  switch (outcome) {
    case VioOutcome::kInitialized: ++counters_.initializations; break;
    case VioOutcome::kReset: ++counters_.vio_resets; break;
    default: ++counters_.vio_fused; break;
  }
  updateStatus();
  return outcome;
}

// ---- output -------------------------------------------------------------------------------------

void Estimator::updateStatus() {
  if (!initialized_) {
    status_ = EstimatorStatus::kInitializing;
  } else if (stateUtime() - last_fused_capture_ > vio_timeout_us_) {
    status_ = EstimatorStatus::kVioTimeout;
  } else {
    status_ = EstimatorStatus::kOk;
  }
}

StateEstimate Estimator::makeOutput() {
  const HistoryEntry& newest = history_.newest();
  StateEstimate out;
  out.utime = newest.utime;
  out.seq = output_seq_++;
  out.imu_seq = newest.imu_seq;
  out.vio_seq = last_fused_seq_;
  out.status = status_;
  if (initialized_) {
    const NavState& x = newest.state;
    out.position = x.position;
    out.orientation = x.orientation;
    out.velocity = x.velocity;
    out.gyro_bias = x.gyro_bias;
    out.accel_bias = x.accel_bias;
    out.body_rate = correctedBodyRate(newest.input, x.gyro_bias);
    out.position_std = newest.covariance.diagonal().segment<3>(kErrPos).cwiseSqrt();
    out.attitude_std = newest.covariance.diagonal().segment<3>(kErrRot).cwiseSqrt();
  } else {
    out.body_rate = correctedBodyRate(newest.input, Vec3::Zero());
  }
  ++counters_.outputs;
  return out;
}

}  // namespace sdlqr::estimator
