#pragma once
// The estimator process, bus-free: the estimator's own input checks (its rejections in the
// common vocabulary, estimator.hpp), the counters and the state published. One method per input
// message, each returning the rejection (kNone: accepted). sdlqr-estimator binds the bus to it;
// the replay and the in-process loop drive the same object.
//
//   IMU       checked and integrated; STATE_EST through the Outbox once per output period
//             (a non-finite estimate is withheld and counted as an error)
//   VIO_POSE  checked and fused at its capture time
// No allocation on either path.

#include "sdlqr/estimator/estimator.hpp"
#include "sdlqr/health/process_health.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"

namespace sdlqr::estimator {

class EstimatorCore {
 public:
  explicit EstimatorCore(const EstimatorParams& params);

  RejectReason onImu(const ImuSample& sample, Outbox& out);
  RejectReason onVio(const VioPose& pose);

  // Ports (sdlqr/messages/ports.hpp). Every IMU sample is integrated: 64 queued (64 ms at 1 kHz)
  // ride out a descheduled process (a lost sample leaves a hole bridged only by interpolation);
  // one handled slower than the IMU period is a missed deadline. Poses are few and each one is
  // worth fusing, even late.
  static constexpr auto inputs() {
    return std::tuple{
        ports::Input{&EstimatorCore::onImu, 64, std::chrono::microseconds(1000)},
        ports::Input{&EstimatorCore::onVio, 4},
    };
  }
  using Outputs = ports::Publishes<StateEstimate>;

  ProcessHealth& health() { return health_; }
  const ProcessHealth& health() const { return health_; }
  const Estimator& estimator() const { return estimator_; }

 private:
  // Mirrors what the estimator counted since the last call into the health.
  void sync();

  Estimator estimator_;
  ProcessHealth health_;
  EstimatorCounters seen_;
  Counters::Id fused_, initializations_, clock_resets_, vio_resets_, clipping_, nonfinite_output_;
};

}  // namespace sdlqr::estimator
