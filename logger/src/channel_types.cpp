#include "sdlqr/logger/channel_types.hpp"

#include "sdlqr/messages/channels.hpp"

namespace sdlqr::logger {

// One entry per channel of lcmtypes/*.lcm (kChannels, generated from their @channel).
const std::vector<ChannelType>& channelTypes() {
  static const std::vector<ChannelType> table = [] {
    std::vector<ChannelType> out;
    for (const ChannelInfo& c : kChannels) out.push_back({c.name, c.stream, c.lcm_type});
    return out;
  }();
  return table;
}

const ChannelType* findChannelType(std::string_view base) {
  for (const ChannelType& entry : channelTypes()) {
    if (entry.base == base) return &entry;
  }
  return nullptr;
}

ChannelName splitChannel(std::string_view channel) {
  const size_t slash = channel.rfind('/');
  if (slash == std::string_view::npos) return {std::string(), std::string(channel)};
  return {std::string(channel.substr(0, slash)), std::string(channel.substr(slash + 1))};
}

}  // namespace sdlqr::logger
