#pragma once
// CSV as the export writes it (RFC 4180): comma separated, '\n' line ends, a cell quoted with
// '"' (inner quotes doubled) when it is a string field or contains ',', '"', CR or LF.
// Numbers round-trip exactly: doubles "%.17g", floats "%.9g", integers in decimal; non-finite
// doubles print as nan, inf, -inf. A variable-length array fills one cell with a JSON array
// (nested for 2-D), where non-finite numbers are NaN, Infinity, -Infinity (as Python's json
// reads them) and strings are JSON strings.
//
// The read side (readCsvRecord, readCell, ...) is the exact inverse; the generated readCsvRow
// functions use it, and the tests check the export by reading it back.

#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "sdlqr/tables/json_document.hpp"

namespace sdlqr::tables {

class CsvWriter {
 public:
  explicit CsvWriter(std::ostream& out) : out_(out) {}

  // A header cell: quoted only when it has to be.
  void name(std::string_view text);
  void integer(int64_t value);
  void real(double value);
  void real32(float value);
  void text(std::string_view value);  // always quoted (a JSON string inside an array)
  // Opens / closes a JSON array; the outermost one becomes a single cell.
  void beginArray();
  void endArray();
  void endRow();
  int64_t rows() const { return rows_; }

 private:
  void startValue();
  // A real with `digits` significant digits (enough to read back the same double or float).
  void realWithDigits(double value, int digits);
  // A number's text: a cell, or an element of the array being written.
  void appendNumber(const char* text);
  void appendCell(std::string_view cell, bool force_quotes);

  std::ostream& out_;
  std::string row_;
  std::string json_;     // outermost array being built
  int depth_ = 0;        // JSON array nesting
  bool first_cell_ = true;
  bool first_item_ = true;
  int64_t rows_ = 0;
};

// Reads one record (a quoted cell may span lines). Returns false at end of input; sets *error
// and returns false on an unterminated quote.
bool readCsvRecord(std::istream& in, std::vector<std::string>* cells, std::string* error);

// Header cell "position[0] [m]" -> "position[0]" and "m".
std::string columnName(std::string_view header_cell);
std::string columnUnit(std::string_view header_cell);

// ---- helpers of the generated readCsvRow functions ---------------------------------------
bool checkCellCount(const std::vector<std::string>& cells, std::size_t expected, std::string* error);
bool parseValue(std::string_view text, int8_t& out);
bool parseValue(std::string_view text, uint8_t& out);
bool parseValue(std::string_view text, int16_t& out);
bool parseValue(std::string_view text, int32_t& out);
bool parseValue(std::string_view text, int64_t& out);
bool parseValue(std::string_view text, float& out);
bool parseValue(std::string_view text, double& out);
bool parseValue(std::string_view text, std::string& out);

template <class T>
bool readCell(const std::vector<std::string>& cells, std::size_t column, T& out, std::string* error) {
  if (column < cells.size() && parseValue(cells[column], out)) return true;
  *error = "column " + std::to_string(column + 1) + ": cannot read '" + (column < cells.size() ? cells[column] : "") + "'";
  return false;
}

bool readJsonCell(const std::vector<std::string>& cells, std::size_t column, JsonDocument& out, std::string* error);
bool checkArray(const JsonDocument& value, int expected_size, std::string_view field, std::string* error);

// An element of a cell's array: a string for a string field; for a number field a number, read as
// its cell would be (an integer field takes only an integer).
template <class T>
bool readJsonElement(const JsonDocument& value, T& out, std::string_view field, std::string* error) {
  bool ok = false;
  if constexpr (std::is_same_v<T, std::string>) {
    ok = value.is_string() && parseValue(value.get_ref<const std::string&>(), out);
  } else {
    const bool kind_ok = std::is_floating_point_v<T> ? value.is_number() : value.is_number_integer();
    ok = kind_ok && parseValue(numberText(value), out);
  }
  if (!ok) *error = std::string(field) + ": bad array element '" + value.dump() + "'";
  return ok;
}

template <class T>
void ensureSize(std::vector<T>& container, std::size_t size) {
  container.resize(size);
}
template <class T, std::size_t N>
void ensureSize(T (&)[N], std::size_t) {}

}  // namespace sdlqr::tables
