#pragma once
// A received frame to the handler overload of its message: handle(const Message&) for the one
// generated message whose id the frame carries (messages.hpp AllMessages). The handler takes
// every message type (an overload set with a template catch-all for the ones it ignores).

#include <tuple>

#include "sdlqr/mavlink/messages.hpp"
#include "sdlqr/mavlink/parser.hpp"

namespace sdlqr::mavlink {

template <class Handler>
void dispatch(const Frame& frame, Handler&& handle) {
  std::apply(
      [&](auto... message) {
        ((frame.id == decltype(message)::kId ? (handle(frame.template as<decltype(message)>()), 0) : 0), ...);
      },
      AllMessages{});
}

}  // namespace sdlqr::mavlink
