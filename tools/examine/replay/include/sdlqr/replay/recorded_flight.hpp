#pragma once
// A recorded flight as the replay needs it: the inputs of the estimator, the gain solver and the
// controller (IMU, VIO_POSE, COMMAND, TRAJECTORY, PARAMS) and the recorded STATE_EST in the order
// the recorder received them, plus the recorded outputs (STATE_EST, RATE_CMD, REFERENCE, GAINS) to
// take the pairing from and to compare with. Plain structs, no LCM.

#include <cstdint>
#include <vector>

#include "sdlqr/health/reject_reason.hpp"
#include "sdlqr/health/stream.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr::replay {

// kStateEstimate and kGains mark where a recorded output was heard: a recomputed one takes its
// place there, a foreign one (forged, replayed) is fed to the cores as it was on the bus.
// kUndecodable is a message of an input channel the bus's decode step refused (size walk, decode).
enum class InputKind : uint8_t { kImu, kVioPose, kStateEstimate, kCommand, kTrajectory, kParams, kGains, kUndecodable };

struct UndecodableInput {
  int64_t utime = 0;  // [us] of the input before it (its own bytes hold no time to trust)
  Stream stream = Stream::kOther;
  RejectReason reason = RejectReason::kNone;
};

struct LogPosition {
  InputKind kind;
  int32_t index;  // into the series of that kind
};

struct RecordedFlight {
  // Every message below but RATE_CMD and REFERENCE, in the order the recorder received them.
  std::vector<LogPosition> order;

  std::vector<ImuSample> imu;
  std::vector<VioPose> vio_pose;
  std::vector<Command> command;
  std::vector<Trajectory> trajectory;
  std::vector<ParamsUpdate> params;
  std::vector<UndecodableInput> undecodable;

  // Recorded outputs, each in log order.
  std::vector<StateEstimate> state_estimate;
  std::vector<RateCommand> rate_command;
  std::vector<Reference> reference;
  std::vector<GainSet> gains;

  int64_t utimeAt(const LogPosition& p) const;
};

// The recomputed outputs, in the order they were computed.
struct ReplayOutputs {
  std::vector<StateEstimate> state_estimate;
  std::vector<RateCommand> rate_command;
  std::vector<Reference> reference;
  std::vector<GainSet> gains;
};

}  // namespace sdlqr::replay
