#include "sdlqr/px4/px4_cli.hpp"

#include <chrono>
#include <cstdlib>
#include <stdexcept>

#include "sdlqr/bus/bus_key.hpp"

namespace sdlqr::px4 {

namespace {

// The options of every process on a MAVLink link: the process's own (bus, vehicle, config), then the link's.
void addProcessAndLinkOptions(ArgParser& parser, ProcessOptions* process, LinkOptions* o, const char* url_help) {
  addProcessOptions(parser, process);
  parser.addOption("--mavlink", &o->mavlink_url, "URL", url_help);
  parser.addOption("--mavlink-key", &o->key_path, "FILE",
                   "sign every frame and accept only frames signed with this key (64 hex digits, mode 0600; "
                   "default: $SDLQR_MAVLINK_KEY, else an unsigned link)");
  parser.addOption("--link-id", &o->link_id, "N", "MAVLink signing link id (default 0)", Range::closed(0, 255));
}

// Parses the command line of a process on a MAVLink link (their exit codes are the same).
void parseLinkCommandLine(ArgParser& parser, int argc, const char* const* argv) {
  parser.setEpilog("Exit codes: 0 stopped (SIGINT/SIGTERM), 2 bad option, configuration or key, 1 runtime error.");
  parser.parseOrExit(argc, argv);
}

}  // namespace

BridgeCommandLine parseBridgeCommandLine(int argc, const char* const* argv) {
  BridgeCommandLine o;
  o.link.mavlink_url = "udp://:14540";
  ArgParser parser("sdlqr-px4",
                   "The stack as a PX4 companion computer (docs/px4.md): MAVLink 2 to PX4 in offboard mode.\n"
                   "In: RATE_CMD, COMMAND.  Out: STATE_EST, SIM_CLOCK (the vehicle's clock), IMU, HEARTBEAT;\n"
                   "to PX4 SET_ATTITUDE_TARGET (body rates, normalized thrust), commands, our HEARTBEAT.");
  addProcessAndLinkOptions(parser, &o.process, &o.link,
                           "udp://[HOST]:PORT (listen; default udp://:14540, PX4's offboard port), "
                           "udpout://HOST:PORT[:BIND] or serial:DEVICE:BAUD (e.g. serial:/dev/ttyACM0:921600)");
  parser.addFlag("--bench", &o.bench,
                 "props-off bench test: print the odometry read and the setpoints RATE_CMD would send, twice a "
                 "second; never arm, ask a mode or send a setpoint");
  std::string clock = "vehicle";
  parser.addOption("--clock", &clock, "vehicle|start",
                   "the stack's clock: PX4's boot time (vehicle, default; the emulated PX4's is the simulation "
                   "time) or counted from the whole second before the first estimate (start: a real PX4, whose "
                   "uptime would make a scenario's events all due at once)");
  parser.addOption("--identify-hover", &o.identify_log, "LOG",
                   "fit px4.thrust.hover_throttle to the hover of a flight log (docs/px4.md) and exit");
  parseLinkCommandLine(parser, argc, argv);
  if (clock != "vehicle" && clock != "start") throw std::invalid_argument("--clock: expected vehicle or start, got '" + clock + "'");
  o.clock_from_start = clock == "start";
  return o;
}

EmulatorCommandLine parseEmulatorCommandLine(int argc, const char* const* argv) {
  EmulatorCommandLine o;
  o.link.mavlink_url = "udpout://127.0.0.1:14540:14580";
  ArgParser parser("sdlqr-px4-emulator",
                   "An autopilot to fly against without PX4 (docs/px4.md): the simulator, the estimator and the\n"
                   "bodyrate loop behind a MAVLink 2 endpoint that behaves as PX4 documents for offboard mode.\n"
                   "In: DISTURBANCE.  Out: SIM_TRUTH, MOTOR_CMD (for the log), HEARTBEAT; MAVLink as PX4's\n"
                   "onboard link. Owns the simulation clock.");
  addProcessAndLinkOptions(parser, &o.process, &o.link,
                           "where the companion listens: udpout://HOST:PORT[:BIND] (default "
                           "udpout://127.0.0.1:14540:14580, as PX4 SITL), udp://[HOST]:PORT or serial:DEVICE:BAUD");
  parser.addOption("--scenario", &o.scenario_path, "FILE", "scenario whose `sim:` key changes the simulated world");
  parser.addOption("--seed", &o.seed, "N", "noise seed (default: sim.seed of the config)", Range::atLeast(0));
  parser.addOption("--rate", &o.rate, "FACTOR", "simulated seconds per wall second (default 1)", Range::openClosed(0, 1000));
  parseLinkCommandLine(parser, argc, argv);
  return o;
}

std::optional<mavlink::SigningKey> loadLinkKey(const LinkOptions& options) {
  std::string path = options.key_path;
  if (path.empty()) {
    const char* variable = std::getenv(kMavlinkKeyVariable);
    if (variable != nullptr) path = variable;
  }
  if (path.empty()) return std::nullopt;
  try {
    const bus::BusKey bus_key = bus::loadBusKey(path);  // the bus key's file rules
    mavlink::SigningKey key;
    key.bytes = bus_key.bytes;
    return key;
  } catch (const std::invalid_argument& e) {
    const std::string text = e.what();  // "bus key FILE: reason"
    throw std::invalid_argument("MAVLink key" + text.substr(text.find(' ', 4)));
  }
}

uint64_t wallSigningTime() {
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  return mavlink::signingTime(std::chrono::duration_cast<std::chrono::microseconds>(since_epoch).count());
}

}  // namespace sdlqr::px4
