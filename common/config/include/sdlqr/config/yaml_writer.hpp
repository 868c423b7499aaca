#pragma once
// Writes parameters as commented YAML, one key a line with its comment in a common column:
//   lqr:
//     dt: 0.01                          # [s] LQR discretization step
// The printed defaults (config/quad255.yaml) and every --print-config come from here.

#include <ostream>
#include <string>

namespace sdlqr {

class YamlWriter {
 public:
  explicit YamlWriter(std::ostream& out) : out_(out) {}

  void comment(const std::string& text);  // "# text" at the current indentation
  void blank() { out_ << "\n"; }
  // "key:" opening a mapping one level deeper, with an optional trailing comment.
  void open(const std::string& key, const std::string& comment = "");
  void close() { --depth_; }
  // "key: value  # comment"; `commented_out` prints the line as "# key: value" (a value that
  // follows from others unless given).
  void value(const std::string& key, const std::string& text, const std::string& comment, bool commented_out = false);

  // Column where trailing comments start, counted from the line start.
  static constexpr int kCommentColumn = 38;

 private:
  void line(const std::string& body, const std::string& comment);
  std::ostream& out_;
  int depth_ = 0;
};

// A double as the vehicle file spells it: shortest round-trip text, with a decimal point so YAML
// 1.1 readers see a float too ("2.0", "0.0005", "1.0e-12").
std::string yamlNumber(double value);

}  // namespace sdlqr
