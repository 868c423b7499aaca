#include "sdlqr/bus/replay_window.hpp"

namespace sdlqr::bus {

RejectReason ReplayWindow::offer(uint32_t link, uint64_t timestamp, uint64_t now) {
  Link* known = nullptr;
  Link* oldest = &links_[0];
  for (Link& l : links_) {
    if (l.used && l.id == link) known = &l;
    if (!l.used || (oldest->used && l.newest < oldest->newest)) oldest = &l;
  }
  if (known != nullptr && timestamp <= known->newest) return RejectReason::kReplayed;
  // In both directions, without unsigned wrap-around.
  if (timestamp + window_ < now || timestamp > now + window_) return RejectReason::kSignatureWindow;
  Link& slot = known != nullptr ? *known : *oldest;
  slot = Link{link, timestamp, true};
  return RejectReason::kNone;
}

}  // namespace sdlqr::bus
