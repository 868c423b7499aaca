#include "sdlqr/px4emu/streams.hpp"

#include <algorithm>

#include "sdlqr/mavlink/messages.hpp"

namespace sdlqr::px4emu {

namespace {
constexpr int64_t intervalOf(double hz) { return static_cast<int64_t>(1e6 / hz + 0.5); }
}  // namespace

Streams::Streams()
    : streams_{{{mavlink::Heartbeat::kId, intervalOf(1), intervalOf(1)},
                {mavlink::Odometry::kId, intervalOf(30), intervalOf(30)},
                {mavlink::HighresImu::kId, intervalOf(50), intervalOf(50)},
                {mavlink::AttitudeQuaternion::kId, intervalOf(50), intervalOf(50)},
                {mavlink::LocalPositionNed::kId, intervalOf(30), intervalOf(30)},
                {mavlink::ExtendedSysState::kId, intervalOf(5), intervalOf(5)}}} {}

Streams::Stream* Streams::find(uint32_t message_id) {
  auto it = std::find_if(streams_.begin(), streams_.end(), [&](const Stream& s) { return s.id == message_id; });
  return it == streams_.end() ? nullptr : &*it;
}

const Streams::Stream* Streams::find(uint32_t message_id) const {
  return const_cast<Streams*>(this)->find(message_id);
}

uint8_t Streams::setInterval(uint32_t message_id, float interval_us) {
  Stream* s = find(message_id);
  if (s == nullptr || !(interval_us >= -1.0f)) return mavlink::mav_result::kDenied;
  if (interval_us < 0.0f) {
    s->interval_us = -1;
  } else if (interval_us == 0.0f) {
    s->interval_us = s->default_interval_us;
  } else {
    s->interval_us = std::max<int64_t>(1, static_cast<int64_t>(interval_us));
  }
  s->next_us = 0;  // the new rate starts now
  return mavlink::mav_result::kAccepted;
}

bool Streams::due(uint32_t message_id, int64_t now_us) const {
  const Stream* s = find(message_id);
  return s != nullptr && s->interval_us >= 0 && now_us >= s->next_us;
}

void Streams::sent(uint32_t message_id, int64_t now_us) {
  Stream* s = find(message_id);
  if (s == nullptr || s->interval_us < 0) return;
  s->next_us += s->interval_us;
  if (s->next_us <= now_us) s->next_us = now_us + s->interval_us;  // late: no burst to catch up
}

double Streams::rateHz(uint32_t message_id) const {
  const Stream* s = find(message_id);
  return s == nullptr || s->interval_us < 0 ? 0.0 : 1e6 / static_cast<double>(s->interval_us);
}

}  // namespace sdlqr::px4emu
