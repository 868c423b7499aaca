#pragma once
// A deployment file (config/deploy/*.yaml): which emulated host runs which process of the stack
// table (config/stack.procs), each host's address on the private segment, the LCM URL every
// process uses across hosts, whether the bus is signed, and an optional delay on what one host
// receives. scripts/deploy
// builds the hosts from the description this prints; parsing and validation live here only.

#include <string>
#include <vector>

namespace sdlqr::deploy {

struct Host {
  std::string name;        // also names its veth (h-<name>), so at most kMaxHostName characters
  std::string address;     // IPv4 on the segment, unique
  std::vector<std::string> processes;  // names of config/stack.procs rows
  double receive_delay_ms = 0.0;       // every message this host's processes receive waits this long
};

struct Deployment {
  std::string name;
  std::string lcm_url;     // udpm with ttl >= 1 as soon as there is more than one host
  int prefix_length = 24;  // of the segment the host addresses share
  std::string monitor;     // host of the launcher's own bus tools (calibration, heartbeat wait)
  // A signed bus (docs/hosts-and-signing.md, Signed bus): key `signing`, by default on across hosts, off on one.
  bool signing = true;
  // The stack table this deployment places (key `procs`, relative to the deployment file); empty:
  // the launcher's, config/stack.procs. Its rows may name a host's address as {address:HOST}.
  std::string procs;
  // A MAVLink link signed with a key generated for the run (key `mavlink_signing`; docs/px4.md).
  bool mavlink_signing = false;
  std::vector<Host> hosts;

  const Host* hostOf(const std::string& process) const;
};

inline constexpr size_t kMaxHostName = 12;  // "h-" + name fits Linux's 15-character interface names

// Loads and checks a deployment against the process names of the stack table: every process on
// exactly one host, no unknown process, unique host names and addresses, all in one subnet.
// Throws ConfigError naming the key.
Deployment loadDeployment(const std::string& path, const std::vector<std::string>& stack_processes);

// The stack table a deployment file names (key `procs`, resolved against the file's folder), or
// empty when it names none. Throws ConfigError as loadDeployment.
std::string deploymentProcs(const std::string& path);

// The process names of a stack table (the first word of every row that is not a comment).
std::vector<std::string> stackProcessNames(const std::string& procs_path);

// One `key=value` line per field (procs and mavlink_signing only when set) and one
// `host=NAME ADDRESS DELAY_MS PROCESS...` line per host, for scripts/deploy.
std::string describe(const Deployment& deployment);

}  // namespace sdlqr::deploy
