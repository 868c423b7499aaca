#pragma once
// A minimal JSON reader for the cells that hold variable-length arrays in the CSV export and
// for tests reading metrics.json. Accepts NaN, Infinity and -Infinity as numbers (the CSV
// export writes non-finite values so, like Python's json module). Numbers keep their text so
// 64-bit integers are read back exactly.

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace sdlqr::logger {

struct JsonValue {
  enum class Kind { kNull, kBoolean, kNumber, kString, kArray, kObject };
  Kind kind = Kind::kNull;
  bool boolean = false;
  double number = 0.0;
  std::string text;  // string contents, or the number as written
  std::vector<JsonValue> items;
  std::vector<std::pair<std::string, JsonValue>> members;  // object members in document order

  bool isArray() const { return kind == Kind::kArray; }
  bool isNumber() const { return kind == Kind::kNumber; }
  bool isString() const { return kind == Kind::kString; }
  bool isObject() const { return kind == Kind::kObject; }
  // Object member by key, nullptr when absent or not an object.
  const JsonValue* find(std::string_view key) const;
};

// Parses a whole document; returns false and sets *error (with the byte offset) on bad input.
bool parseJson(std::string_view text, JsonValue* out, std::string* error);

}  // namespace sdlqr::logger
