#include "sdlqr/config/yaml_writer.hpp"

#include <cctype>

#include "sdlqr/config/range.hpp"

namespace sdlqr {

std::string yamlNumber(double value) {
  std::string text = shortestNumber(value);
  const auto e = text.find('e');
  if (e == std::string::npos) {
    const bool word = text.find_first_of("ni") != std::string::npos;  // nan, inf: never printed by valid values
    if (!word && text.find('.') == std::string::npos) text += ".0";
    return text;
  }
  // "1e-12" -> "1.0e-12", "2e-05" -> "2.0e-5": YAML 1.1 floats need the point and the sign.
  std::string mantissa = text.substr(0, e);
  if (mantissa.find('.') == std::string::npos) mantissa += ".0";
  const char sign = text[e + 1];
  std::string digits = text.substr(e + 2);
  while (digits.size() > 1 && digits[0] == '0') digits.erase(0, 1);
  return mantissa + "e" + sign + digits;
}

void YamlWriter::comment(const std::string& text) { out_ << std::string(2 * depth_, ' ') << "# " << text << "\n"; }

void YamlWriter::open(const std::string& key, const std::string& comment) {
  line(key + ":", comment);
  ++depth_;
}

void YamlWriter::value(const std::string& key, const std::string& text, const std::string& comment,
                       bool commented_out) {
  line((commented_out ? "# " : "") + key + ": " + text, comment);
}

void YamlWriter::line(const std::string& body, const std::string& comment) {
  std::string text = std::string(2 * depth_, ' ') + body;
  if (!comment.empty()) {
    const size_t column = static_cast<size_t>(kCommentColumn);
    text += text.size() + 2 <= column ? std::string(column - text.size(), ' ') : std::string(2, ' ');
    text += "# " + comment;
  }
  out_ << text << "\n";
}

}  // namespace sdlqr
