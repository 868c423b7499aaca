#include "sdlqr/px4/mavlink_endpoint.hpp"

namespace sdlqr::px4 {

MavlinkEndpoint::MavlinkEndpoint(mavlink::Address self, ByteSink& out, SigningClock clock,
                                 const std::optional<mavlink::SigningKey>& key, uint8_t link_id)
    : mavlink::MessageSinkTo<FrameAndWrite>(FrameAndWrite{this}), writer_(self), out_(out), clock_(std::move(clock)) {
  if (key) {
    writer_.enableSigning(*key, link_id);
    parser_.requireSigning(*key);
  }
}

}  // namespace sdlqr::px4
