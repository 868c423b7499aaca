#pragma once
// Channel names, one type per channel, with the optional vehicle prefix. Each channel is declared
// with its type in lcmtypes/*.lcm (@channel NAME, @split_port N); sdlqr/lcmtypes/generated/
// channels.hpp (in the build folder) holds channel::k<Name>, the Stream of each channel, the table
// kChannels and channelOf<Msg>(). Below: what is done with the names.

#include <string>
#include <string_view>

#include "sdlqr/lcmtypes/generated/channels.hpp"

namespace sdlqr::channel {

// Bus layout. With one multicast port for everything every process's socket receives every
// message of the stack (~2,700 a second) and LCM drops those it did not subscribe to in user
// space; worse, the sender's sendmsg enqueues each datagram on every socket bound to the port and
// wakes every receive thread. The split layout gives each high-rate channel a port of its own,
// counted from the --lcm-url port: a socket then hears only the channels of its port. (Distinct
// groups on one port would not separate them: Linux delivers a datagram to every socket bound
// to the port whose host joined its group, IP_MULTICAST_ALL.) Every other channel stays on the
// base port. Channels one subscriber needs in their send order share a port (IMU and VIO_POSE: the
// estimator's inputs, from one publisher); across ports a process handles messages in the order
// its receive threads hand them over. bench/README.md has the measurements.
// A channel's @split_port in its .lcm file says which port it takes (kChannels[].split_port).
//
// Port offset of a channel (base name, without vehicle prefix) in the split layout; 0 (the
// base port) for every channel without a port of its own, including names that are not ours.
constexpr int splitPortOffset(std::string_view base) {
  for (const ChannelInfo& entry : kChannels) {
    if (entry.name == base) return entry.split_port;
  }
  return 0;
}

// "QUAD1/IMU" -> "IMU": the part after the last '/' (a vehicle name may itself hold '/').
constexpr std::string_view baseName(std::string_view channel) {
  const size_t slash = channel.rfind('/');
  return slash == std::string_view::npos ? channel : channel.substr(slash + 1);
}

// "IMU" with vehicle "QUAD1" becomes "QUAD1/IMU"; an empty vehicle leaves the name as is.
inline std::string name(std::string_view vehicle, std::string_view channel) {
  std::string out;
  if (!vehicle.empty()) {
    out.append(vehicle);
    out.push_back('/');
  }
  out.append(channel);
  return out;
}

}  // namespace sdlqr::channel
