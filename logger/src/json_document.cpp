#include "sdlqr/logger/json_document.hpp"

namespace sdlqr::logger {

void writeJsonDocument(std::ostream& out, const JsonDocument& document) {
  out << document.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace) << '\n';
}

JsonDocument toJson(const Distribution& d) {
  return {{"count", d.count}, {"mean", d.mean}, {"min", d.min}, {"median", d.median}, {"p99", d.p99}, {"max", d.max}};
}

}  // namespace sdlqr::logger
