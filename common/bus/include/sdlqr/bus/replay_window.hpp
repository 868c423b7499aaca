#pragma once
// What a subscriber of a signed bus (signature.hpp) remembers of one channel's signers: the newest
// timestamp accepted from each link. A message is a replay unless its timestamp is after its
// link's newest (kReplayed), and it must lie within `window` of the receiver's clock either way
// (kSignatureWindow): the bound on replaying a message to a subscriber that has not heard its link
// yet (a started or restarted one) and on a signer whose clock is off. Fixed size: up to kLinks
// links per channel; a new one past that replaces the one whose newest timestamp is oldest.
// Clock-free and allocation-free: the caller passes the receiver's time in the same units.

#include <array>
#include <cstddef>
#include <cstdint>

#include "sdlqr/health/reject_reason.hpp"

namespace sdlqr::bus {

class ReplayWindow {
 public:
  static constexpr size_t kLinks = 16;
  static constexpr uint64_t kDefaultWindow = 200'000;  // [10 us] 2 s

  explicit ReplayWindow(uint64_t window = kDefaultWindow) : window_(window) {}
  // For a message whose MAC verified: kNone (and remembered as its link's newest), kReplayed or
  // kSignatureWindow.
  RejectReason offer(uint32_t link, uint64_t timestamp, uint64_t now);
  uint64_t window() const { return window_; }

 private:
  struct Link {
    uint32_t id = 0;
    uint64_t newest = 0;
    bool used = false;
  };
  std::array<Link, kLinks> links_{};
  uint64_t window_;
};

}  // namespace sdlqr::bus
