#include "sdlqr/deploy/deployment.hpp"

#include <arpa/inet.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "sdlqr/config/config.hpp"

namespace sdlqr::deploy {
namespace {

uint32_t parseAddress(const std::string& key, const std::string& text) {
  in_addr address{};
  if (inet_pton(AF_INET, text.c_str(), &address) != 1) throw ConfigError(key, "expected an IPv4 address, got '" + text + "'");
  return ntohl(address.s_addr);
}

void checkHostName(const std::string& key, const std::string& name) {
  const bool valid = !name.empty() && name.size() <= kMaxHostName &&
                     std::all_of(name.begin(), name.end(), [](char c) {
                       return std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c));
                     });
  if (!valid) {
    throw ConfigError(key, "host names are 1-" + std::to_string(kMaxHostName) + " lower-case letters or digits, got '" +
                               name + "'");
  }
}

// The ttl of a udpm URL (LCM's default 0 keeps every datagram on the sending host).
int urlTtl(const std::string& url) {
  const size_t at = url.find("ttl=");
  if (at == std::string::npos) return 0;
  return std::atoi(url.c_str() + at + 4);
}

Host readHost(const ConfigReader& reader, const std::string& name, const YAML::Node& node) {
  Host host;
  host.name = name;
  checkHostName(reader.keyPath(name), name);
  ConfigReader h(node, reader.keyPath(name));
  h.allowOnly({"address", "processes", "receive_delay_ms"});
  if (!h.has("address")) throw ConfigError(h.keyPath("address"), "missing");
  h.read("address", host.address);
  h.read("receive_delay_ms", host.receive_delay_ms);
  if (!(host.receive_delay_ms >= 0.0 && host.receive_delay_ms <= 1000.0)) {
    throw ConfigError(h.keyPath("receive_delay_ms"), "must be in [0, 1000]");
  }
  const YAML::Node processes = node["processes"];
  if (!processes || !processes.IsSequence() || processes.size() == 0) {
    throw ConfigError(h.keyPath("processes"), "expected a non-empty list of process names");
  }
  for (const YAML::Node& p : processes) {
    if (!p.IsScalar()) throw ConfigError(h.keyPath("processes"), "expected process names");
    host.processes.push_back(p.as<std::string>());
  }
  return host;
}

void checkAddresses(const Deployment& d) {
  std::set<uint32_t> seen;
  const uint32_t mask = d.prefix_length == 0 ? 0u : ~0u << (32 - d.prefix_length);
  uint32_t network = 0;
  for (size_t i = 0; i < d.hosts.size(); ++i) {
    const std::string key = "hosts." + d.hosts[i].name + ".address";
    const uint32_t a = parseAddress(key, d.hosts[i].address);
    if ((a & ~mask) == 0 || (a & ~mask) == ~mask) throw ConfigError(key, "is the network or broadcast address of its subnet");
    if (i == 0) network = a & mask;
    if ((a & mask) != network) throw ConfigError(key, "not in the subnet of the first host (/" + std::to_string(d.prefix_length) + ")");
    if (!seen.insert(a).second) throw ConfigError(key, "used by another host");
  }
}

void checkProcesses(const Deployment& d, const std::vector<std::string>& stack_processes) {
  std::map<std::string, std::string> host_of;
  for (const Host& host : d.hosts) {
    for (const std::string& p : host.processes) {
      const std::string key = "hosts." + host.name + ".processes";
      if (std::find(stack_processes.begin(), stack_processes.end(), p) == stack_processes.end()) {
        throw ConfigError(key, "'" + p + "' is not a process of the stack table");
      }
      if (!host_of.emplace(p, host.name).second) throw ConfigError(key, "'" + p + "' is already on host " + host_of[p]);
    }
  }
  for (const std::string& p : stack_processes) {
    if (!host_of.count(p)) throw ConfigError("hosts", "process '" + p + "' is on no host");
  }
}

}  // namespace

const Host* Deployment::hostOf(const std::string& process) const {
  for (const Host& host : hosts) {
    if (std::find(host.processes.begin(), host.processes.end(), process) != host.processes.end()) return &host;
  }
  return nullptr;
}

Deployment loadDeployment(const std::string& path, const std::vector<std::string>& stack_processes) {
  const YAML::Node root = loadYamlFile(path);
  ConfigReader reader(root, "");
  reader.allowOnly({"name", "description", "lcm_url", "prefix_length", "monitor", "signing", "hosts", "procs",
                    "mavlink_signing"});
  Deployment d;
  d.procs = deploymentProcs(path);
  reader.read("mavlink_signing", d.mavlink_signing);
  reader.read("name", d.name);
  if (d.name.empty()) throw ConfigError("name", "missing");
  reader.read("lcm_url", d.lcm_url);
  if (d.lcm_url.rfind("udpm://", 0) != 0) throw ConfigError("lcm_url", "expected a udpm:// URL, got '" + d.lcm_url + "'");
  reader.read("prefix_length", d.prefix_length);
  if (d.prefix_length < 8 || d.prefix_length > 30) throw ConfigError("prefix_length", "must be in [8, 30]");
  const YAML::Node hosts = root["hosts"];
  if (!hosts || !hosts.IsMap() || hosts.size() == 0) throw ConfigError("hosts", "expected a mapping of host names");
  ConfigReader hosts_reader(hosts, "hosts");
  for (const auto& entry : hosts) d.hosts.push_back(readHost(hosts_reader, entry.first.as<std::string>(), entry.second));
  if (d.hosts.size() > 1 && urlTtl(d.lcm_url) < 1) {
    throw ConfigError("lcm_url", "needs ttl=1 or more to reach other hosts, got '" + d.lcm_url + "'");
  }
  reader.read("monitor", d.monitor);
  if (d.monitor.empty()) d.monitor = d.hosts.front().name;
  if (std::none_of(d.hosts.begin(), d.hosts.end(), [&](const Host& h) { return h.name == d.monitor; })) {
    throw ConfigError("monitor", "no host '" + d.monitor + "'");
  }
  d.signing = d.hosts.size() > 1;
  reader.read("signing", d.signing);
  checkAddresses(d);
  checkProcesses(d, stack_processes);
  return d;
}

std::string deploymentProcs(const std::string& path) {
  ConfigReader reader(loadYamlFile(path), "");
  std::string procs;
  reader.read("procs", procs);
  if (procs.empty() || procs[0] == '/') return procs;
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? procs : path.substr(0, slash + 1) + procs;
}

std::vector<std::string> stackProcessNames(const std::string& procs_path) {
  std::ifstream in(procs_path);
  if (!in) throw ConfigError(procs_path, "cannot open file");
  std::vector<std::string> names;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first;
    if (words >> first && first[0] != '#') names.push_back(first);
  }
  return names;
}

std::string describe(const Deployment& d) {
  std::ostringstream out;
  out << "name=" << d.name << "\nlcm_url=" << d.lcm_url << "\nprefix_length=" << d.prefix_length
      << "\nmonitor=" << d.monitor << "\nsigning=" << (d.signing ? "on" : "off") << "\n";
  if (!d.procs.empty()) out << "procs=" << d.procs << "\n";
  if (d.mavlink_signing) out << "mavlink_signing=on\n";
  for (const Host& host : d.hosts) {
    out << "host=" << host.name << " " << host.address << " " << host.receive_delay_ms;
    for (const std::string& p : host.processes) out << " " << p;
    out << "\n";
  }
  return out.str();
}

}  // namespace sdlqr::deploy
