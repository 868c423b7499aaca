#include "sdlqr/config/cli.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "sdlqr/config/config.hpp"

namespace sdlqr {

ArgParser::ArgParser(std::string program, std::string summary)
    : program_(std::move(program)), summary_(std::move(summary)) {
  entries_.push_back({"--help", "", "show this help and exit", nullptr});
}

void ArgParser::addFlag(const std::string& name, bool* out, const std::string& help) {
  entries_.push_back({name, "", help, [out](const std::string&) {
                        *out = true;
                        return std::string();
                      }});
}

void ArgParser::addOption(const std::string& name, std::string* out, const std::string& metavar,
                          const std::string& help) {
  entries_.push_back({name, metavar, help, [out](const std::string& v) {
                        *out = v;
                        return std::string();
                      }});
}

void ArgParser::addOption(const std::string& name, double* out, const std::string& metavar, const std::string& help) {
  entries_.push_back({name, metavar, help, [out, name](const std::string& v) {
                        char* end = nullptr;
                        errno = 0;
                        const double value = std::strtod(v.c_str(), &end);
                        if (v.empty() || *end != '\0' || errno != 0 || !std::isfinite(value)) {
                          return name + ": expected a finite number, got '" + v + "'";
                        }
                        *out = value;
                        return std::string();
                      }});
}

void ArgParser::addOption(const std::string& name, long long* out, const std::string& metavar,
                          const std::string& help) {
  entries_.push_back({name, metavar, help, [out, name](const std::string& v) {
                        char* end = nullptr;
                        errno = 0;
                        const long long value = std::strtoll(v.c_str(), &end, 10);
                        if (v.empty() || *end != '\0' || errno != 0) {
                          return name + ": expected an integer, got '" + v + "'";
                        }
                        *out = value;
                        return std::string();
                      }});
}

void ArgParser::addOption(const std::string& name, int* out, const std::string& metavar, const std::string& help) {
  entries_.push_back({name, metavar, help, [out, name](const std::string& v) {
                        char* end = nullptr;
                        errno = 0;
                        const long value = std::strtol(v.c_str(), &end, 10);
                        if (v.empty() || *end != '\0' || errno != 0 || value < -2147483647L || value > 2147483647L) {
                          return name + ": expected an integer, got '" + v + "'";
                        }
                        *out = static_cast<int>(value);
                        return std::string();
                      }});
}

std::string ArgParser::usage() const {
  std::ostringstream out;
  out << "usage: " << program_ << " [options]";
  if (positional_) out << " " << positional_metavar_;
  out << "\n\n" << summary_ << "\n\noptions:\n";
  for (const Entry& e : entries_) {
    std::string left = "  " + e.name + (e.metavar.empty() ? "" : " " + e.metavar);
    if (left.size() < 26) left.resize(26, ' ');
    else left += "\n" + std::string(26, ' ');
    out << left << e.help << "\n";
  }
  if (!epilog_.empty()) out << "\n" << epilog_ << "\n";
  return out.str();
}

std::string ArgParser::parse(int argc, const char* const* argv, bool* help_requested) const {
  *help_requested = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      *help_requested = true;
      return {};
    }
    if (arg.rfind("--", 0) != 0 || arg == "--") {
      if (positional_ && arg != "--") {
        positional_->push_back(arg);
        continue;
      }
      return "unexpected argument '" + arg + "' (see --help)";
    }
    std::string value;
    bool has_inline_value = false;
    const auto eq = arg.find('=');
    if (eq != std::string::npos) {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      has_inline_value = true;
    }
    const Entry* entry = nullptr;
    for (const Entry& e : entries_) {
      if (e.name == arg) entry = &e;
    }
    if (!entry || !entry->set) return "unknown option '" + arg + "' (see --help)";
    if (entry->metavar.empty()) {
      if (has_inline_value) return arg + " takes no value";
    } else if (!has_inline_value) {
      if (i + 1 >= argc) return arg + " needs a value " + entry->metavar;
      value = argv[++i];
    }
    const std::string error = entry->set(value);
    if (!error.empty()) return error;
  }
  return {};
}

void ArgParser::parseOrExit(int argc, const char* const* argv) const {
  bool help = false;
  const std::string error = parse(argc, argv, &help);
  if (help) {
    std::cout << usage();
    std::exit(0);
  }
  if (!error.empty()) {
    std::cerr << program_ << ": " << error << "\n";
    std::exit(2);
  }
}

void addProcessOptions(ArgParser& parser, ProcessOptions* options) {
  parser.addOption("--config", &options->config_path, "FILE", "vehicle configuration (YAML); defaults built in");
  parser.addOption("--lcm-url", &options->lcm_url, "URL",
                   "LCM provider (default: $LCM_DEFAULT_URL or udpm://239.255.76.67:7667?ttl=0)");
  parser.addOption("--vehicle", &options->vehicle, "PREFIX", "channel prefix, e.g. QUAD1 gives QUAD1/IMU");
  parser.addFlag("--print-config", &options->print_config,
                 "print the sections of the vehicle file this program reads, with the values it\n"
                 "                          would run with (defaults and --config), as YAML, and exit");
  addBusLayoutOption(parser, options);
}

void addBusLayoutOption(ArgParser& parser, ProcessOptions* options) {
  parser.addOption("--bus-layout", &options->bus_layout, "single|split",
                   "split (default): high-rate channels on ports of their own above the --lcm-url port;\n"
                   "single: every channel on the --lcm-url port (README, Bus layout)");
}

int runMain(const std::string& program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const ConfigError& e) {
    std::cerr << program << ": config error: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": fatal: " << e.what() << "\n";
    return 1;
  }
}

ProcessOptions parseProcessCommandLine(int argc, const char* const* argv, const std::string& program,
                                       const std::string& description) {
  ProcessOptions options;
  ArgParser parser(program, description);
  addProcessOptions(parser, &options);
  parser.setEpilog("exit codes: 0 stopped by SIGINT/SIGTERM, 1 runtime failure, 2 bad option or configuration");
  parser.parseOrExit(argc, argv);
  return options;
}

}  // namespace sdlqr
