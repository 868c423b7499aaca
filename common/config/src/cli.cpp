#include "sdlqr/config/cli.hpp"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "sdlqr/config/config.hpp"

namespace sdlqr {

namespace {

// "usage: program [options] METAVAR", then the description, the options and the epilog; the
// positional words are named by the usage line alone.
class Formatter final : public CLI::Formatter {
 public:
  explicit Formatter(std::string positional) : positional_(std::move(positional)) { column_width(26); }
  std::string make_usage(const CLI::App* app, std::string name) const override {
    (void)app;
    return "usage: " + name + " [options]" + (positional_.empty() ? "" : " " + positional_) + "\n";
  }
  std::string make_positionals(const CLI::App*) const override { return {}; }
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override {
    const std::string footer = make_footer(app);
    return make_usage(app, name) + "\n" + make_description(app) + make_groups(app, mode) +
           (footer.empty() ? "" : "\n" + footer);
  }

 private:
  std::string positional_;
};

// The caller's help texts may carry the indentation of the old formatter after each line break.
std::string unindented(const std::string& help) {
  std::string out;
  for (size_t i = 0; i < help.size(); ++i) {
    out.push_back(help[i]);
    if (help[i] == '\n') {
      while (i + 1 < help.size() && help[i + 1] == ' ') ++i;
    }
  }
  return out;
}

// A number's text into *value; the error ("<name>: expected ...") or empty.
std::string parseNumber(const std::string& name, const std::string& v, double* value) {
  char* end = nullptr;
  errno = 0;
  *value = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || errno != 0 || !std::isfinite(*value)) {
    return name + ": expected a finite number, got '" + v + "'";
  }
  return {};
}

std::string parseInteger(const std::string& name, const std::string& v, long long min, long long max,
                         long long* value) {
  char* end = nullptr;
  errno = 0;
  *value = std::strtoll(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || errno != 0 || *value < min || *value > max) {
    return name + ": expected an integer, got '" + v + "'";
  }
  return {};
}

std::string parseNumber(const std::string& name, const std::string& v, long long* value) {
  return parseInteger(name, v, LLONG_MIN, LLONG_MAX, value);
}

std::string parseNumber(const std::string& name, const std::string& v, int* value) {
  long long wide = 0;
  const std::string error = parseInteger(name, v, INT_MIN, INT_MAX, &wide);
  *value = static_cast<int>(wide);
  return error;
}

// A number option: parsed, then refused outside `allowed`; *out set only to a value accepted.
template <class T>
CLI::Option* addNumber(CLI::App& app, const std::string& name, T* out, const std::string& metavar,
                       const std::string& help, const Range& allowed) {
  const bool bounded = allowed.hasLow() || allowed.hasHigh();
  const std::string shown_help = unindented(help) + (bounded ? "; " + allowed.rule("") : "");
  return app.add_option_function<std::string>(name, [name, out, allowed](const std::string& v) {
        T value{};
        std::string error = parseNumber(name, v, &value);
        if (error.empty() && !allowed.contains(static_cast<double>(value))) {
          error = name + ": " + allowed.rule("") + ", got '" + v + "'";
        }
        if (!error.empty()) throw CLI::ValidationError(error);
        *out = value;
      }, shown_help)->type_name(metavar);
}

}  // namespace

ArgParser::ArgParser(std::string program, std::string summary)
    : program_(std::move(program)), app_(std::make_unique<CLI::App>(std::move(summary), program_)) {
  app_->option_defaults()->group("options")->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app_->set_help_flag("-h,--help", "show this help and exit")->group("options");
  app_->formatter(std::make_shared<Formatter>(""));
}

ArgParser::~ArgParser() = default;

void ArgParser::addFlag(const std::string& name, bool* out, const std::string& help) {
  app_->add_flag(name, *out, unindented(help));
}

void ArgParser::addOption(const std::string& name, std::string* out, const std::string& metavar,
                          const std::string& help, Presence presence) {
  app_->add_option(name, *out, unindented(help))->type_name(metavar)->required(presence == Presence::kRequired);
}

void ArgParser::addOption(const std::string& name, double* out, const std::string& metavar, const std::string& help,
                          const Range& allowed, Presence presence) {
  addNumber(*app_, name, out, metavar, help, allowed)->required(presence == Presence::kRequired);
}

void ArgParser::addOption(const std::string& name, long long* out, const std::string& metavar,
                          const std::string& help, const Range& allowed) {
  addNumber(*app_, name, out, metavar, help, allowed);
}

void ArgParser::addOption(const std::string& name, int* out, const std::string& metavar, const std::string& help,
                          const Range& allowed) {
  addNumber(*app_, name, out, metavar, help, allowed);
}

void ArgParser::setEpilog(const std::string& epilog) { app_->footer(epilog); }

void ArgParser::allowPositional(std::vector<std::string>* out, const std::string& metavar) {
  app_->add_option("words", *out)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app_->formatter(std::make_shared<Formatter>(metavar));
}

std::string ArgParser::usage() const { return app_->help(); }

std::string ArgParser::parse(int argc, const char* const* argv, bool* help_requested) const {
  *help_requested = false;
  try {
    app_->parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    *help_requested = true;
  } catch (const CLI::ExtrasError& e) {
    return std::string(e.what()) + " (see --help)";
  } catch (const CLI::ParseError& e) {
    return e.what();
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
  addLcmUrlOption(parser, &options->lcm_url);
  parser.addOption("--vehicle", &options->vehicle, "PREFIX", "channel prefix, e.g. QUAD1 gives QUAD1/IMU");
  parser.addFlag("--print-config", &options->print_config,
                 "print the sections of the vehicle file this program reads, with the values it\n"
                 "                          would run with (defaults and --config), as YAML, and exit");
  addBusLayoutOption(parser, options);
}

void addLcmUrlOption(ArgParser& parser, std::string* lcm_url) {
  parser.addOption("--lcm-url", lcm_url, "URL", "LCM provider (default: $LCM_DEFAULT_URL or udpm://239.255.76.67:7667?ttl=0)");
}

void addBusLayoutOption(ArgParser& parser, ProcessOptions* options) {
  parser.addOption("--bus-layout", &options->bus_layout, "single|split",
                   "split (default): high-rate channels on ports of their own above the --lcm-url port;\n"
                   "single: every channel on the --lcm-url port (docs/architecture.md §2)");
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
