#include "sdlqr/logger/log_naming.hpp"

#include <cctype>

namespace sdlqr::logger {

namespace {

bool isFileNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
}

}  // namespace

std::string invalidScenarioReason(const std::string& scenario) {
  if (scenario.empty()) return "scenario name is empty";
  if (scenario.size() > 100) return "scenario name is longer than 100 characters";
  if (scenario[0] == '.') return "scenario name must not start with '.'";
  for (char c : scenario) {
    if (!isFileNameChar(c)) return "scenario name '" + scenario + "': use letters, digits, '_', '-' or '.' only";
  }
  return {};
}

std::string scenarioLogPath(const std::string& dir, const std::string& scenario, const std::tm& local_time) {
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local_time);
  std::string path = dir.empty() ? std::string(".") : dir;
  if (path.back() != '/') path.push_back('/');
  return path + stamp + "-" + scenario + kLogExtension;
}

std::string channelCsvPath(const std::string& channel) {
  std::string path;
  std::string component;
  auto flush = [&]() {
    if (component.empty() || component == "." || component == "..") component = "_";
    if (!path.empty()) path.push_back('/');
    path += component;
    component.clear();
  };
  for (char c : channel) {
    if (c == '/') {
      flush();
    } else {
      component.push_back(isFileNameChar(c) ? c : '_');
    }
  }
  flush();
  return path + ".csv";
}

}  // namespace sdlqr::logger
