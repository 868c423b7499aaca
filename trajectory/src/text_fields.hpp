#pragma once
// Internal to trajectory/src (waypoint_file.cpp, trajectory_csv.cpp): the blank-stripping both
// text formats apply to a field or a line before reading it.

#include <string>

namespace sdlqr::trajectory::detail {

// TEXT without leading and trailing blanks (space, tab, carriage return).
inline std::string trimBlanks(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

}  // namespace sdlqr::trajectory::detail
