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

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/estimator/error_state_ekf.hpp"
#include "sdlqr/estimator/estimator_params.hpp"
#include "sdlqr/estimator/gated_pose_run.hpp"
#include "sdlqr/estimator/imu_downsampler.hpp"
#include "sdlqr/estimator/state_history.hpp"

namespace sdlqr::estimator {

enum class Rejection : int {
  kImuNonFinite = 0,
  kImuOutOfRange,
  kImuTimeBackwards,   // utime not after the previous sample (includes duplicates)
  kImuTimeGap,         // utime more than imu_max_gap after the previous sample
  kVioNonFinite,
  kVioBadQuaternion,   // | ||q|| - 1 | > quaternion_norm_tolerance
  kVioBadStd,          // negative std
  kVioOutOfOrder,      // capture time not after the last fused pose's
  kVioTooOld,          // capture time older than the history
  kVioFuture,          // capture time after the newest IMU sample
  kVioGated,           // innovation beyond the chi-square gate
  kVioSuperseded,      // a pending pose replaced by a newer one before it could be fused
};
inline constexpr int kRejectionCount = 12;
static_assert(static_cast<int>(Rejection::kVioSuperseded) + 1 == kRejectionCount, "one counter per reason");
// Counter name, e.g. "reject.vio.too_old".
const char* counterName(Rejection reason);

enum class VioOutcome {
  kFused,          // updated at the capture time, newer states recomputed
  kInitialized,    // first pose (or first after a long gap): the filter starts from it
  kPending,        // capture time inside the IMU window still being accumulated: fused when it closes
  kReset,          // gated, but gated poses have agreed with one another for vio_reset_after: the
                   // filter was wrong, and was reset to this pose (position, attitude, velocity)
  kRejected,       // see counters() and lastRejection()
};

struct EstimatorCounters {
  std::array<int64_t, kRejectionCount> rejected{};
  int64_t outputs = 0;
  int64_t imu_windows = 0;
  int64_t vio_fused = 0;
  int64_t initializations = 0;   // includes re-initialisations after a long VIO gap
  int64_t clock_resets = 0;      // restarts on a new IMU clock (simulator restarted, log replayed)
  int64_t vio_resets = 0;        // resets to the VIO after a run of agreeing gated poses
  int64_t accel_clipping = 0;    // accepted IMU samples with an accelerometer axis at the clip level

  int64_t rejectedTotal() const;
  int64_t rejectedFor(Rejection reason) const { return rejected[static_cast<size_t>(reason)]; }
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
  std::optional<Rejection> lastRejection() const { return last_rejection_; }
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
  VioOutcome reject(Rejection reason);  // counts and returns kRejected

  EstimatorParams params_;
  ProcessNoise noise_;
  int64_t period_us_;
  ImuDownsampler downsampler_;
  StateHistory history_;
  GatedPoseRun gated_run_;
  EstimatorCounters counters_;
  std::optional<Rejection> last_rejection_;

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
