// sdlqr-bridge: forwards between the split bus layout and a single LCM URL, for tools that
// listen or publish on one URL only (lcm-spy, lcm-logplayer). Each message is forwarded as is,
// once, its signature too (signed bus: the channel keeps its name, so it still verifies; the
// bridge never signs what it forwards); the bridge's own HEARTBEAT goes on the bus it listens to.

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "sdlqr/bus/bus_layout.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/config/cli.hpp"

using namespace sdlqr;

namespace {

constexpr int kQueueCapacity = 4096;  // LCM-side queue per URL; forwarding empties it at once

bool isPortOfLayout(const bus::Node& bus, const std::string& base_url, const std::string& url) {
  const std::vector<std::string> urls = bus::layoutUrls(bus.busLayout(), base_url);
  return std::find(urls.begin(), urls.end(), bus::urlWithPortOffset(url, 0)) != urls.end();
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-bridge", [&] {
    ProcessOptions options;
    std::string other_url;
    std::vector<std::string> positional;
    ArgParser parser("sdlqr-bridge",
                     "merge: every channel heard on every port of the bus (--lcm-url, --bus-layout) is\n"
                     "       republished on --to, so lcm-spy or a recorder on that one URL sees them all\n"
                     "       (./sdlqr spy runs this while lcm-spy runs).\n"
                     "split: every channel heard on the --lcm-url port itself that the split layout puts on\n"
                     "       a port of its own (IMU, MOTOR_CMD, ...) is republished there, so a log played\n"
                     "       with `lcm-logplayer LOG` (everything on one URL) drives processes on a split bus.");
    addProcessOptions(parser, &options);
    parser.addOption("--to", &other_url, "URL",
                     "merge: where to republish (default: the --lcm-url port + 10; never a port of the bus)");
    bool print_url = false;
    parser.addFlag("--print-url", &print_url, "merge: print the URL it would republish on and exit");
    parser.allowPositional(&positional, "merge|split");
    parser.setEpilog("exit codes: 0 stopped by SIGINT/SIGTERM, 1 runtime failure, 2 bad option");
    parser.parseOrExit(argc, argv);
    if (positional.size() != 1 || (positional[0] != "merge" && positional[0] != "split")) {
      throw std::invalid_argument("expected one mode, merge or split (see --help)");
    }
    const bool merge = positional[0] == "merge";
    const std::string base_url = bus::urlWithPortOffset(bus::resolveLcmUrl(options.lcm_url), 0);
    if (!bus::isUdpmUrl(base_url)) throw std::invalid_argument("--lcm-url: the bridge needs a udpm:// URL");

    if (merge) {
      if (other_url.empty()) other_url = bus::urlWithPortOffset(base_url, bus::kMonitorPortOffset);
      if (print_url) {
        std::cout << other_url << "\n";
        return 0;
      }
      bus::Node bus("sdlqr-bridge", options);
      // Republishing onto a port the bridge listens on would forward every message forever.
      if (isPortOfLayout(bus, base_url, other_url)) {
        throw std::invalid_argument("--to '" + other_url + "': a port of the bus being merged");
      }
      ProcessOptions target_options = options;
      target_options.lcm_url = other_url;
      target_options.bus_layout = "single";
      bus::Node target("sdlqr-bridge", target_options);
      bus.subscribeRaw(".*", [&](const std::string& channel, const void* data, uint32_t size, int64_t) {
        target.forwardEncoded(channel, data, static_cast<int>(size));
      }, kQueueCapacity);
      std::cerr << "sdlqr-bridge: merging " << bus.receiveUrls().size() << " ports of " << base_url << " onto "
                << other_url << "\n";
      bus.setState(bus::ProcessState::kRunning);
      while (bus.spin(100)) {
      }
      bus.shutdown();
      return 0;
    }

    if (!other_url.empty()) throw std::invalid_argument("--to: only for merge (split publishes on the layout's ports)");
    // Listens on the base port alone; publishes only on the other ports, so nothing loops.
    ProcessOptions listen_options = options;
    listen_options.bus_layout = "single";
    bus::Node listener("sdlqr-bridge", listen_options);
    ProcessOptions split_options = options;
    split_options.bus_layout = "split";
    bus::Node split_bus("sdlqr-bridge", split_options);
    listener.subscribeRaw(".*", [&](const std::string& channel, const void* data, uint32_t size, int64_t) {
      if (channel::splitPortOffset(channel::baseName(channel)) == 0) return;
      split_bus.forwardEncoded(channel, data, static_cast<int>(size));
    }, kQueueCapacity);
    std::cerr << "sdlqr-bridge: splitting the high-rate channels heard on " << base_url << " onto their ports\n";
    listener.setState(bus::ProcessState::kRunning);
    while (listener.spin(100)) {
    }
    listener.shutdown();
    return 0;
  });
}
