#pragma once
// The estimator-fusion emulator: an error-state EKF (position, velocity, attitude, gyro bias,
// accelerometer bias) propagated on IMU windows of the output period and corrected by delayed VIO
// poses at their capture time through a state history (rewind, update, re-propagate).
//
// Pure and clock-free: time is the utime of the inputs. No allocation after construction.
//
//   Estimator est(params);
//   if (auto out = est.onImu(imu)) publish(*out);   // once per output period of IMU time
//   est.onVio(pose);                                  // whenever a pose arrives, however late

#include <array>
#include <cstdint>
#include <optional>

#include "sdlqr/health/reject_reason.hpp"
#include "sdlqr/messages/messages.hpp"
#include "sdlqr/estimator/error_state_ekf.hpp"
#include "sdlqr/estimator/estimator_params.hpp"
#include "sdlqr/estimator/gated_pose_run.hpp"
#include "sdlqr/estimator/imu_downsampler.hpp"
#include "sdlqr/estimator/state_history.hpp"

namespace sdlqr::estimator {

enum class VioOutcome {
  kFused,          // updated at the capture time, newer states recomputed
  kInitialized,    // first pose (or first after a long gap): the filter starts from it
  kPending,        // capture time inside the IMU window still being accumulated: fused when it closes
  kReset,          // gated, but gated poses have agreed with one another for vio_reset_after: the
                   // filter was wrong, and was reset to this pose (position, attitude, velocity)
  kRejected,       // see counters() and lastVioRejection()
};

// Rejections in the common vocabulary, per input stream. IMU: kNonFinite, kOutOfRange,
// kTimeBackwards (utime not after the previous sample, duplicates included), kTimeGap (more than
// imu_max_gap after it). VIO_POSE: kNonFinite, kQuaternionNorm (| ||q|| - 1 | above
// quaternion_norm_tolerance), kOutOfRange (a negative std), kTimeBackwards (capture time not after
// the last fused or pending pose's), kStale (older than the history), kTimeFuture (after the
// newest IMU sample), kGated (innovation beyond the chi-square gate), kSuperseded (a pending pose
// replaced by a newer one before it could be fused).
struct EstimatorCounters {
  std::array<int64_t, kRejectReasonCount> imu_rejected{};
  std::array<int64_t, kRejectReasonCount> vio_rejected{};
  int64_t outputs = 0;
  int64_t imu_windows = 0;
  int64_t vio_fused = 0;
  int64_t initializations = 0;   // includes re-initialisations after a long VIO gap
  int64_t clock_resets = 0;      // restarts on a new IMU clock (simulator restarted, log replayed)
  int64_t vio_resets = 0;        // resets to the VIO after a run of agreeing gated poses
  int64_t accel_clipping = 0;    // accepted IMU samples with an accelerometer axis at the clip level

  int64_t rejectedTotal() const;
  int64_t imuRejected(RejectReason reason) const { return imu_rejected[static_cast<size_t>(reason)]; }
  int64_t vioRejected(RejectReason reason) const { return vio_rejected[static_cast<size_t>(reason)]; }
};

class Estimator {
 public:
  // Throws std::invalid_argument when params are not valid().
  explicit Estimator(const EstimatorParams& params);

  // Validates and integrates one IMU sample; returns the estimate when this sample completes an
  // output period (the newest one if a gap completed several). Rejected samples change nothing.
  std::optional<StateEstimate> onImu(const ImuSample& sample);
  // Validates and fuses one VIO pose at its capture time (pose.utime).
  VioOutcome onVio(const VioPose& pose);

  // Back to the state after construction (counters are kept).
  void reset();

  EstimatorStatus status() const { return status_; }
  bool healthy() const { return status_ == EstimatorStatus::kOk; }
  bool initialized() const { return initialized_; }
  const EstimatorCounters& counters() const { return counters_; }
  // Why the last onImu() / onVio() call refused its input (kNone: accepted).
  RejectReason lastImuRejection() const { return last_imu_rejection_; }
  RejectReason lastVioRejection() const { return last_vio_rejection_; }
  const EstimatorParams& params() const { return params_; }

  // The newest state and its covariance (meaningful once initialized()).
  const NavState& state() const;
  const ErrorCovariance& covariance() const;
  int64_t stateUtime() const;

 private:
  bool imuTimingAcceptable(const ImuSample& sample);
  void onWindow(const ImuWindow& window);
  bool needsInitialization(int64_t capture_utime) const;
  // Initialises or fuses at pose.utime, which the history must cover; returns the outcome.
  VioOutcome fuseAtCaptureTime(const VioPose& pose, bool initialize);
  PoseMeasurement measurementOf(const VioPose& pose) const;
  // Position and attitude from the pose, the given velocity; the bias estimates are kept once
  // there are any. No correlation survives but the biases' among themselves.
  void restartFrom(const PoseMeasurement& pose, const Vec3& velocity, const Vec3& velocity_var, NavState& state,
                   ErrorCovariance& covariance) const;
  void updateStatus();
  StateEstimate makeOutput();
  void rejectImu(RejectReason reason);
  VioOutcome rejectVio(RejectReason reason);  // counts and returns kRejected

  EstimatorParams params_;
  ProcessNoise noise_;
  int64_t period_us_;
  // [us] params_'s limits on the IMU clock, looked at every sample.
  int64_t imu_max_gap_us_, reinit_after_us_, vio_timeout_us_;
  ImuDownsampler downsampler_;
  StateHistory history_;
  GatedPoseRun gated_run_;
  EstimatorCounters counters_;
  RejectReason last_imu_rejection_ = RejectReason::kNone;
  RejectReason last_vio_rejection_ = RejectReason::kNone;

  bool initialized_ = false;
  EstimatorStatus status_ = EstimatorStatus::kInitializing;
  int timing_rejects_in_a_row_ = 0;
  bool window_closed_ = false;    // set by onWindow during one onImu call
  int64_t last_fused_capture_ = 0;
  int64_t last_fused_seq_ = -1;
  bool has_fused_ = false;
  std::optional<VioPose> pending_vio_;
  int64_t output_seq_ = 0;
};

}  // namespace sdlqr::estimator
