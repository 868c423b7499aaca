#include "sdlqr/tables/csv.hpp"

#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace sdlqr::tables {

namespace {

bool needsQuotes(std::string_view cell) { return cell.find_first_of(",\"\r\n") != std::string_view::npos; }

void appendQuoted(std::string& out, std::string_view text) {
  out.push_back('"');
  for (char c : text) {
    if (c == '"') out.push_back('"');
    out.push_back(c);
  }
  out.push_back('"');
}

void appendJsonString(std::string& out, std::string_view text) {
  out.push_back('"');
  for (char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += escape;
        } else {
          out.push_back(c);
        }
    }
  }
  out.push_back('"');
}

// `text` NUL-terminated in `buffer` for the C parsers; false when it is empty or longer than
// `longest` (no number of the type is) or than the buffer holds.
template <std::size_t N>
bool terminated(std::string_view text, std::size_t longest, char (&buffer)[N]) {
  if (text.empty() || text.size() > longest || text.size() >= N) return false;
  text.copy(buffer, text.size());
  buffer[text.size()] = '\0';
  return true;
}

template <class Int>
bool parseInteger(std::string_view text, Int& out) {
  char buffer[32];
  if (!terminated(text, 24, buffer)) return false;
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(buffer, &end, 10);
  if (*end != '\0' || errno != 0) return false;
  if (value < static_cast<long long>(std::numeric_limits<Int>::min()) ||
      value > static_cast<long long>(std::numeric_limits<Int>::max())) {
    return false;
  }
  out = static_cast<Int>(value);
  return true;
}

}  // namespace

void CsvWriter::appendCell(std::string_view cell, bool force_quotes) {
  if (!first_cell_) row_.push_back(',');
  first_cell_ = false;
  if (force_quotes || needsQuotes(cell)) appendQuoted(row_, cell);
  else row_.append(cell);
}

void CsvWriter::startValue() {
  if (depth_ > 0) {
    if (!first_item_) json_.push_back(',');
    first_item_ = false;
  }
}

void CsvWriter::name(std::string_view text) { appendCell(text, false); }

void CsvWriter::integer(int64_t value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%" PRId64, value);
  appendNumber(buffer);
}

void CsvWriter::real(double value) { realWithDigits(value, 17); }

void CsvWriter::real32(float value) { realWithDigits(static_cast<double>(value), 9); }

void CsvWriter::realWithDigits(double value, int digits) {
  char buffer[40];
  if (depth_ > 0 && !std::isfinite(value)) {
    std::snprintf(buffer, sizeof buffer, "%s", std::isnan(value) ? "NaN" : (value > 0 ? "Infinity" : "-Infinity"));
  } else {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  }
  appendNumber(buffer);
}

void CsvWriter::appendNumber(const char* text) {
  startValue();
  if (depth_ > 0) json_ += text;
  else appendCell(text, false);
}

void CsvWriter::text(std::string_view value) {
  startValue();
  if (depth_ > 0) appendJsonString(json_, value);
  else appendCell(value, true);
}

void CsvWriter::beginArray() {
  startValue();
  if (depth_ == 0) json_.clear();
  json_.push_back('[');
  ++depth_;
  first_item_ = true;
}

void CsvWriter::endArray() {
  json_.push_back(']');
  --depth_;
  first_item_ = false;
  if (depth_ == 0) appendCell(json_, false);
}

void CsvWriter::endRow() {
  row_.push_back('\n');
  out_.write(row_.data(), static_cast<std::streamsize>(row_.size()));
  row_.clear();
  first_cell_ = true;
  ++rows_;
}

bool readCsvRecord(std::istream& in, std::vector<std::string>* cells, std::string* error) {
  cells->clear();
  int c = in.get();
  if (c == std::char_traits<char>::eof()) return false;
  std::string cell;
  bool quoted = false;
  bool cell_was_quoted = false;  // a quoted cell keeps a trailing CR: it is data
  while (true) {
    if (quoted) {
      if (c == std::char_traits<char>::eof()) {
        *error = "unterminated quoted cell";
        return false;
      }
      if (c == '"') {
        if (in.peek() == '"') {
          in.get();
          cell.push_back('"');
        } else {
          quoted = false;
        }
      } else {
        cell.push_back(static_cast<char>(c));
      }
    } else if (c == '"') {
      quoted = true;
      cell_was_quoted = true;
    } else if (c == ',') {
      cells->push_back(std::move(cell));
      cell.clear();
      cell_was_quoted = false;
    } else if (c == '\n' || c == std::char_traits<char>::eof()) {
      if (!cell_was_quoted && !cell.empty() && cell.back() == '\r') cell.pop_back();
      cells->push_back(std::move(cell));
      return true;
    } else {
      cell.push_back(static_cast<char>(c));
    }
    c = in.get();
  }
}

std::string columnName(std::string_view header_cell) {
  const size_t bracket = header_cell.rfind(" [");
  return std::string(bracket == std::string_view::npos ? header_cell : header_cell.substr(0, bracket));
}

std::string columnUnit(std::string_view header_cell) {
  const size_t bracket = header_cell.rfind(" [");
  if (bracket == std::string_view::npos || header_cell.back() != ']') return {};
  return std::string(header_cell.substr(bracket + 2, header_cell.size() - bracket - 3));
}

bool checkCellCount(const std::vector<std::string>& cells, std::size_t expected, std::string* error) {
  if (cells.size() == expected) return true;
  *error = "expected " + std::to_string(expected) + " cells, got " + std::to_string(cells.size());
  return false;
}

bool parseValue(std::string_view text, int8_t& out) { return parseInteger(text, out); }
bool parseValue(std::string_view text, uint8_t& out) { return parseInteger(text, out); }
bool parseValue(std::string_view text, int16_t& out) { return parseInteger(text, out); }
bool parseValue(std::string_view text, int32_t& out) { return parseInteger(text, out); }
bool parseValue(std::string_view text, int64_t& out) { return parseInteger(text, out); }

bool parseValue(std::string_view text, double& out) {
  char buffer[48];
  if (!terminated(text, 40, buffer)) return false;
  char* end = nullptr;
  out = std::strtod(buffer, &end);  // subnormals set ERANGE yet are exact: not an error here
  return *end == '\0';
}

bool parseValue(std::string_view text, float& out) {
  char buffer[48];
  if (!terminated(text, 40, buffer)) return false;
  char* end = nullptr;
  out = std::strtof(buffer, &end);
  return *end == '\0';
}

bool parseValue(std::string_view text, std::string& out) {
  out.assign(text);
  return true;
}

bool readJsonCell(const std::vector<std::string>& cells, std::size_t column, JsonDocument& out, std::string* error) {
  if (column >= cells.size()) {
    *error = "missing column " + std::to_string(column + 1);
    return false;
  }
  std::string json_error;
  if (!parseJson(cells[column], &out, &json_error)) {
    *error = "column " + std::to_string(column + 1) + ": " + json_error;
    return false;
  }
  return true;
}

bool checkArray(const JsonDocument& value, int expected_size, std::string_view field, std::string* error) {
  if (value.is_array() && expected_size >= 0 && value.size() == static_cast<size_t>(expected_size)) return true;
  *error = std::string(field) + ": expected an array of " + std::to_string(expected_size) + " elements";
  return false;
}

}  // namespace sdlqr::tables
