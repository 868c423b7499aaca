#include "sdlqr/sim/vio_model.hpp"

#include <cmath>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::sim {

namespace {
constexpr uint64_t kVioNoiseStream = 2;
constexpr uint64_t kVioLatencyStream = 3;
}  // namespace

VioModel::VioModel(const VioParams& params, int physics_rate_hz, uint64_t seed)
    : params_(params),
      physics_rate_hz_(physics_rate_hz),
      period_us_(1000000 / physics_rate_hz),
      noise_(seed, kVioNoiseStream),
      latency_(seed, kVioLatencyStream) {}

std::optional<VioPose> VioModel::step(int64_t k, const Vec3& position, const Quat& orientation) {
  // Captures at the steps where floor(k rate / physics_rate) increments: exactly `rate` per
  // second on average, on the physics grid.
  const bool capture = k > 0 && (k * params_.rate_hz) / physics_rate_hz_ > ((k - 1) * params_.rate_hz) / physics_rate_hz_;
  if (capture && count_ < kVioDelayLineCapacity) {
    Pending& p = line_[static_cast<size_t>((head_ + count_) % kVioDelayLineCapacity)];
    const double latency = latency_.uniform(params_.latency_min_s, params_.latency_max_s);
    p.publish_step = k + std::llround(latency * physics_rate_hz_);
    p.pose.utime = k * period_us_;
    p.pose.publish_utime = p.publish_step * period_us_;
    p.pose.position = position + noise_.normal3(params_.position_std);
    p.pose.orientation = quat::multiply(orientation, quat::exp(noise_.normal3(params_.attitude_std))).normalized();
    p.pose.position_std = params_.position_std;
    p.pose.attitude_std = params_.attitude_std;
    ++count_;
  }
  if (count_ == 0) return std::nullopt;
  Pending& front = line_[static_cast<size_t>(head_)];
  if (front.publish_step > k) return std::nullopt;
  front.pose.seq = seq_++;
  head_ = (head_ + 1) % kVioDelayLineCapacity;
  --count_;
  return front.pose;
}

}  // namespace sdlqr::sim
