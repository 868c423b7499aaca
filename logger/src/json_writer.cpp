#include "sdlqr/logger/json_writer.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>

namespace sdlqr::logger {

namespace {

void writeEscaped(std::ostream& out, std::string_view text) {
  out << '"';
  for (char c : text) {
    switch (c) {
      case '"': out << "\\\""; break;
      case '\\': out << "\\\\"; break;
      case '\n': out << "\\n"; break;
      case '\r': out << "\\r"; break;
      case '\t': out << "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out << escape;
        } else {
          out << c;
        }
    }
  }
  out << '"';
}

}  // namespace

void JsonWriter::newline() {
  out_ << '\n';
  for (size_t i = 0; i < first_in_scope_.size(); ++i) out_ << "  ";
}

void JsonWriter::beforeValue() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!first_in_scope_.empty()) {
    if (!first_in_scope_.back()) out_ << ',';
    first_in_scope_.back() = false;
    newline();
  }
}

void JsonWriter::beginObject() {
  beforeValue();
  out_ << '{';
  first_in_scope_.push_back(true);
}

void JsonWriter::endObject() {
  const bool empty = first_in_scope_.back();
  first_in_scope_.pop_back();
  if (!empty) newline();
  out_ << '}';
  if (first_in_scope_.empty()) out_ << '\n';
}

void JsonWriter::beginArray() {
  beforeValue();
  out_ << '[';
  first_in_scope_.push_back(true);
}

void JsonWriter::endArray() {
  const bool empty = first_in_scope_.back();
  first_in_scope_.pop_back();
  if (!empty) newline();
  out_ << ']';
  if (first_in_scope_.empty()) out_ << '\n';
}

void JsonWriter::key(std::string_view name) {
  beforeValue();
  writeEscaped(out_, name);
  out_ << ": ";
  after_key_ = true;
}

void JsonWriter::number(double value) {
  beforeValue();
  if (!std::isfinite(value)) {
    out_ << "null";
    return;
  }
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  out_ << buffer;
}

void JsonWriter::integer(int64_t value) {
  beforeValue();
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%" PRId64, value);
  out_ << buffer;
}

void JsonWriter::string(std::string_view value) {
  beforeValue();
  writeEscaped(out_, value);
}

void JsonWriter::boolean(bool value) {
  beforeValue();
  out_ << (value ? "true" : "false");
}

void JsonWriter::null() {
  beforeValue();
  out_ << "null";
}

}  // namespace sdlqr::logger
