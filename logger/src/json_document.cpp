#include "sdlqr/logger/json_document.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace sdlqr::logger {

namespace {

// nlohmann-json reads standard JSON only: a bare NaN, Infinity or -Infinity becomes a marked
// string before parsing and the number again after (a document's own string would look marked only
// by starting with the escaped control character \u0001, which nothing we write holds).
constexpr std::string_view kMark = "\x01non-finite:";
constexpr std::string_view kNonFinite[] = {"-Infinity", "Infinity", "NaN"};

std::string markNonFinite(std::string_view text) {
  std::string out;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < text.size()) out += text[++i];
      else if (c == '"') in_string = false;
      continue;
    }
    in_string = c == '"';
    const auto token = std::find_if(std::begin(kNonFinite), std::end(kNonFinite),
                                    [&](std::string_view t) { return text.substr(i, t.size()) == t; });
    if (token == std::end(kNonFinite)) {
      out += c;
      continue;
    }
    out += "\"\\u0001non-finite:" + std::string(*token) + "\"";
    i += token->size() - 1;
  }
  return out;
}

void restoreNonFinite(JsonDocument& value) {
  if (value.is_structured()) {
    for (JsonDocument& element : value) restoreNonFinite(element);
    return;
  }
  if (!value.is_string()) return;
  const std::string& text = value.get_ref<const std::string&>();
  if (text.rfind(kMark, 0) != 0) return;
  const std::string_view token = std::string_view(text).substr(kMark.size());
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  value = token == "NaN" ? std::numeric_limits<double>::quiet_NaN() : token == "Infinity" ? kInfinity : -kInfinity;
}

}  // namespace

bool parseJson(std::string_view text, JsonDocument* out, std::string* error) {
  try {
    *out = JsonDocument::parse(markNonFinite(text));
  } catch (const JsonDocument::parse_error& e) {
    *error = "invalid JSON near byte " + std::to_string(e.byte) + ": " + e.what();
    return false;
  }
  restoreNonFinite(*out);
  return true;
}

std::string numberText(const JsonDocument& number) {
  if (number.is_number_integer()) return number.dump();
  const double value = number.get<double>();
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "Infinity" : "-Infinity";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

void writeJsonDocument(std::ostream& out, const JsonDocument& document) {
  out << document.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace) << '\n';
}

JsonDocument toJson(const Distribution& d) {
  return {{"count", d.count}, {"mean", d.mean}, {"min", d.min}, {"median", d.median}, {"p99", d.p99}, {"max", d.max}};
}

}  // namespace sdlqr::logger
