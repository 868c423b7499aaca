#pragma once
// Command-line parsing shared by every executable: CLI11 (Debian libcli11-dev) behind one facade,
// so every --help has the same form (usage line, description, options, epilog), and bad input is
// one line "<program>: <what>" with exit code 2. Only cli.cpp includes CLI11.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sdlqr/config/range.hpp"

namespace CLI {
class App;
}

namespace sdlqr {

// Whether parsing fails when an option is not given.
enum class Presence { kOptional, kRequired };

class ArgParser {
 public:
  ArgParser(std::string program, std::string summary);
  ~ArgParser();
  ArgParser(const ArgParser&) = delete;
  ArgParser& operator=(const ArgParser&) = delete;

  // Help texts are wrapped by the caller with '\n'; the indentation of continuation lines is
  // the formatter's.
  void addFlag(const std::string& name, bool* out, const std::string& help);
  // A required option missing is "<name> is required".
  void addOption(const std::string& name, std::string* out, const std::string& metavar, const std::string& help,
                 Presence presence = Presence::kOptional);
  // Numbers: a finite double, an integer of the type; anything else is "<name>: expected ...". A
  // value given outside `allowed` is "<name>: must be in (0, 1000], got '5000'": the range is
  // declared with the option, and --help shows it. What is not given keeps its default.
  void addOption(const std::string& name, double* out, const std::string& metavar, const std::string& help,
                 const Range& allowed = Range::finite(), Presence presence = Presence::kOptional);
  void addOption(const std::string& name, int* out, const std::string& metavar, const std::string& help,
                 const Range& allowed = Range::finite());
  void addOption(const std::string& name, long long* out, const std::string& metavar, const std::string& help,
                 const Range& allowed = Range::finite());
  // Free-form trailing text for --help (examples, exit codes).
  void setEpilog(const std::string& epilog);
  // Remaining non-option words are collected here when set; otherwise they are an error.
  void allowPositional(std::vector<std::string>* out, const std::string& metavar);

  // Prints usage and exits 0 on --help; prints "<program>: <error>" and exits 2 on bad input.
  void parseOrExit(int argc, const char* const* argv) const;
  // As above without exiting: returns an error text (empty on success); sets *help_requested.
  std::string parse(int argc, const char* const* argv, bool* help_requested) const;
  std::string usage() const;
  const std::string& program() const { return program_; }

 private:
  std::string program_;
  std::unique_ptr<CLI::App> app_;
};

// Standard options of every flight process.
struct ProcessOptions {
  std::string config_path;    // vehicle YAML
  std::string lcm_url;        // empty: $LCM_DEFAULT_URL or LCM's default
  std::string vehicle;        // channel prefix
  std::string bus_layout = "split";  // "single" or "split" (sdlqr/bus/bus_layout.hpp)
  bool print_config = false;  // print the sections read (printProcessConfig) and exit 0
};
void addProcessOptions(ArgParser& parser, ProcessOptions* options);
// --lcm-url and --bus-layout alone, for the tools that take them without the rest of
// addProcessOptions.
void addLcmUrlOption(ArgParser& parser, std::string* lcm_url);
void addBusLayoutOption(ArgParser& parser, ProcessOptions* options);
// The command line of a flight process with no options of its own: --help (the description and
// the exit codes), the process options; exits on --help or a bad option.
ProcessOptions parseProcessCommandLine(int argc, const char* const* argv, const std::string& program,
                                       const std::string& description);

// Runs `body`, turning a ConfigError or std::invalid_argument into a one-line message and exit
// code 2, any other exception into a one-line message and exit code 1.
int runMain(const std::string& program, const std::function<int()>& body);

}  // namespace sdlqr
