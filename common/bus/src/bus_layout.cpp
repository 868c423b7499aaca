#include "sdlqr/bus/bus_layout.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "sdlqr/messages/channels.hpp"

namespace sdlqr::bus {

namespace {

constexpr std::string_view kUdpmScheme = "udpm://";
constexpr std::string_view kLcmDefaultUrl = "udpm://239.255.76.67:7667?ttl=0";
constexpr std::string_view kLcmDefaultAddress = "239.255.76.67";
constexpr int kLcmDefaultPort = 7667;

int parsePort(const std::string& url, const std::string& text) {
  if (text.empty() || text.size() > 5 || text.find_first_not_of("0123456789") != std::string::npos ||
      std::stoi(text) > 65535) {
    throw std::invalid_argument("--lcm-url '" + url + "': bad port '" + text + "'");
  }
  return std::stoi(text);
}

}  // namespace

BusLayout parseBusLayout(const std::string& text) {
  if (text == "single") return BusLayout::kSingle;
  if (text == "split") return BusLayout::kSplit;
  throw std::invalid_argument("--bus-layout: expected single or split, got '" + text + "'");
}

const char* toString(BusLayout layout) { return layout == BusLayout::kSingle ? "single" : "split"; }

std::string resolveLcmUrl(const std::string& url) {
  if (!url.empty()) return url;
  const char* from_environment = std::getenv("LCM_DEFAULT_URL");
  if (from_environment != nullptr && from_environment[0] != '\0') return from_environment;
  return std::string(kLcmDefaultUrl);
}

bool isUdpmUrl(const std::string& url) { return url.rfind(kUdpmScheme, 0) == 0; }

UdpmUrl parseUdpmUrl(const std::string& url) {
  const size_t network_start = kUdpmScheme.size();
  const size_t options_start = std::min(url.find('?', network_start), url.size());
  const std::string network = url.substr(network_start, options_start - network_start);
  const size_t colon = network.find(':');
  UdpmUrl parts;
  parts.address = network.substr(0, colon);
  if (parts.address.empty()) parts.address = std::string(kLcmDefaultAddress);
  parts.port = colon == std::string::npos ? kLcmDefaultPort : parsePort(url, network.substr(colon + 1));
  if (options_start < url.size()) parts.options = url.substr(options_start + 1);
  return parts;
}

std::string urlWithPortOffset(const std::string& url, int offset) {
  if (!isUdpmUrl(url)) return url;
  const UdpmUrl parts = parseUdpmUrl(url);
  if (parts.port + offset > 65535) {
    throw std::invalid_argument("--lcm-url '" + url + "': port " + std::to_string(parts.port) +
                                " leaves no room for the " + std::to_string(offset) +
                                " ports above it of the split bus layout");
  }
  return std::string(kUdpmScheme) + parts.address + ":" + std::to_string(parts.port + offset) +
         (parts.options.empty() ? "" : "?" + parts.options);
}

std::string channelUrl(BusLayout layout, const std::string& base_url, std::string_view channel) {
  if (layout == BusLayout::kSingle) return urlWithPortOffset(base_url, 0);
  return urlWithPortOffset(base_url, channel::splitPortOffset(channel::baseName(channel)));
}

std::vector<std::string> layoutUrls(BusLayout layout, const std::string& base_url) {
  std::vector<std::string> urls{urlWithPortOffset(base_url, 0)};
  if (layout == BusLayout::kSingle) return urls;
  std::vector<int> offsets;  // of the channels' @split_port, lowest first
  for (const ChannelInfo& entry : kChannels) {
    if (entry.split_port > 0) offsets.push_back(entry.split_port);
  }
  std::sort(offsets.begin(), offsets.end());
  offsets.erase(std::unique(offsets.begin(), offsets.end()), offsets.end());
  for (int offset : offsets) urls.push_back(urlWithPortOffset(base_url, offset));
  return urls;
}

}  // namespace sdlqr::bus
