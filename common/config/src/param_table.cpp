#include "sdlqr/config/param_table.hpp"

namespace sdlqr::detail {

std::string paramComment(const std::string& unit, const std::string& help) {
  return "[" + (unit.empty() ? std::string("-") : unit) + "] " + help;
}

std::string choiceList(const std::vector<std::string>& words) {
  std::string text;
  for (size_t i = 0; i < words.size(); ++i) {
    if (i > 0) text += i + 1 == words.size() ? " or " : ", ";
    text += words[i];
  }
  return text;
}

}  // namespace sdlqr::detail
