#pragma once
// Which LCM URL each channel travels on: one URL for everything (single), or the high-rate
// channels on ports of their own above the --lcm-url port (split; each channel's @split_port in
// its .lcm file, kChannels in sdlqr/messages/channels.hpp). Pure functions of the URL text, for Node and the tools that
// must hear every channel (recorder, sdlqr-top, the spy bridge).

#include <string>
#include <string_view>
#include <vector>

namespace sdlqr::bus {

enum class BusLayout { kSingle, kSplit };

// "single" or "split"; anything else throws std::invalid_argument naming --bus-layout.
BusLayout parseBusLayout(const std::string& text);
const char* toString(BusLayout layout);

// The URL LCM opens for an empty --lcm-url: $LCM_DEFAULT_URL, else LCM's own default.
std::string resolveLcmUrl(const std::string& url);

// Only udpm:// URLs have ports to separate channels; any other provider (memq://, file://)
// carries every channel on its one URL whatever the layout.
bool isUdpmUrl(const std::string& url);

// The parts of udpm://ADDR:PORT?OPTIONS (ADDR and PORT default to LCM's 239.255.76.67 and
// 7667; options is the text after '?', or empty). Throws std::invalid_argument naming --lcm-url
// on a port that is not a number in [0, 65535]; url must be a udpm:// URL.
struct UdpmUrl {
  std::string address;
  int port = 0;
  std::string options;
};
UdpmUrl parseUdpmUrl(const std::string& url);

// udpm://ADDR:PORT?OPTIONS with PORT raised by `offset` (ADDR and PORT default to LCM's
// 239.255.76.67 and 7667); any other URL is returned unchanged. Throws std::invalid_argument
// naming --lcm-url on a malformed udpm URL or a port past 65535.
std::string urlWithPortOffset(const std::string& url, int offset);

// The URL `channel` (full name, a vehicle prefix is ignored) travels on under `layout`.
std::string channelUrl(BusLayout layout, const std::string& base_url, std::string_view channel);

// Every distinct URL of the layout, the base URL first: what a recorder listens on.
std::vector<std::string> layoutUrls(BusLayout layout, const std::string& base_url);

// Where `sdlqr-bridge merge` (and so ./sdlqr spy) republishes every channel of a split bus by
// default: the base URL with its port raised by 10, above every port of the layout.
inline constexpr int kMonitorPortOffset = 10;

}  // namespace sdlqr::bus
