#pragma once
// The message a fuzzer replays on one channel: one heard at least `age` seconds ago, at most twice
// that. Two slots turned over every `age` seconds — the replayed one and the next candidate — so a
// replay is ready from `age` seconds after the first message onward, however fast the channel is.
// Pure: the caller passes its own clock in seconds.

#include <cstdint>
#include <vector>

namespace sdlqr::faults {

class ReplaySource {
 public:
  explicit ReplaySource(double age_s) : age_s_(age_s) {}

  // A valid encoding heard at time `now_s`.
  void heard(const uint8_t* data, uint32_t size, double now_s);
  // The message to replay at `now_s`, or nullptr while none is old enough.
  const std::vector<uint8_t>* replayable(double now_s) const;

 private:
  double age_s_;
  std::vector<uint8_t> candidate_;  // the first message heard since the last turnover
  double candidate_taken_s_ = -1.0;
  std::vector<uint8_t> replayed_;   // the candidate of the turnover before
  double replayed_taken_s_ = -1.0;
};

}  // namespace sdlqr::faults
