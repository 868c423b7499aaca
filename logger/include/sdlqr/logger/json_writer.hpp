#pragma once
// Streams indented JSON with members in the order they are written (stable key order).
// Non-finite numbers become null, which keeps the document valid JSON.

#include <cstdint>
#include <ostream>
#include <string_view>
#include <vector>

namespace sdlqr::logger {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  void beginObject();
  void endObject();
  void beginArray();
  void endArray();
  void key(std::string_view name);
  void number(double value);
  void integer(int64_t value);
  void string(std::string_view value);
  void boolean(bool value);
  void null();

  // key + value in one call.
  void member(std::string_view name, double value) {
    key(name);
    number(value);
  }
  void memberInt(std::string_view name, int64_t value) {
    key(name);
    integer(value);
  }
  void member(std::string_view name, std::string_view value) {
    key(name);
    string(value);
  }
  void memberBool(std::string_view name, bool value) {
    key(name);
    boolean(value);
  }

 private:
  void beforeValue();
  void newline();

  std::ostream& out_;
  std::vector<bool> first_in_scope_;  // one entry per open object/array
  bool after_key_ = false;
};

}  // namespace sdlqr::logger
