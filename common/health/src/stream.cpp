#include "sdlqr/health/stream.hpp"

namespace sdlqr {

// The names come from kChannels (generated), so the bus and the cores agree on both.
const char* streamName(Stream stream) {
  for (const ChannelInfo& c : kChannels) {
    if (c.stream == stream) return c.stream_name.data();  // a literal: NUL-terminated
  }
  return "other";
}

Stream streamOfChannel(std::string_view base) {
  for (const ChannelInfo& c : kChannels) {
    if (c.name == base) return c.stream;
  }
  return Stream::kOther;
}

}  // namespace sdlqr
