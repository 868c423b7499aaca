#pragma once
// One decoded LCM message as one CSV row and back, for every type of lcmtypes/: the fields come
// from the generated visit (sdlqr/lcmtypes/generated/lcm_fields.hpp), in the column order of
// the type's descriptor. A fixed-size array fills one cell per element, a variable-length array
// one cell holding a JSON array (csv.hpp); reading is the exact inverse and checks every array
// length against the length field read before it.

#include <algorithm>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "sdlqr/lcmtypes/fields.hpp"
#include "sdlqr/logger/csv.hpp"

namespace sdlqr::logger {

namespace csv_row {

inline void cell(CsvWriter& w, double value) { w.real(value); }
inline void cell(CsvWriter& w, float value) { w.real32(value); }
inline void cell(CsvWriter& w, const std::string& value) { w.text(value); }
// Integers, and LCM booleans (int8_t: any byte), printed as integers.
template <class T, class = std::enable_if_t<std::is_integral_v<T>>>
void cell(CsvWriter& w, T value) {
  w.integer(static_cast<int64_t>(value));
}

using Lengths = lcmtypes::ArrayLengths;

// Writes the fields of one message as cells, field by field.
class Writer {
 public:
  explicit Writer(CsvWriter& w) : w_(w) {}

  template <class T>
  void operator()(const lcmtypes::FieldDescriptor& field, const T& member) {
    if constexpr (lcmtypes::kIsVector<T>) {
      writeJson(field, 0, member);
    } else {
      writeCells(member);
      lengths_.note(field, member);
    }
  }

 private:
  template <class T>
  void writeCells(const T& value) {
    if constexpr (std::is_array_v<T>) {
      for (const auto& element : value) writeCells(element);
    } else {
      cell(w_, value);
    }
  }

  template <class T>
  void writeJson(const lcmtypes::FieldDescriptor& field, int depth, const std::vector<T>& array) {
    const int64_t length = lengths_.of(field, depth);
    const std::size_t n = length < 0 ? 0 : std::min(array.size(), static_cast<std::size_t>(length));
    w_.beginArray();
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (lcmtypes::kIsVector<T>) writeJson(field, depth + 1, array[i]);
      else cell(w_, array[i]);
    }
    w_.endArray();
  }

  CsvWriter& w_;
  Lengths lengths_;
};

// Reads the cells of one row into the fields of a message, field by field.
class Reader {
 public:
  Reader(const std::vector<std::string>& cells, std::string* error) : cells_(cells), error_(error) {}

  template <class T>
  void operator()(const lcmtypes::FieldDescriptor& field, T& member) {
    if (!ok_) return;
    if constexpr (lcmtypes::kIsVector<T>) {
      JsonDocument array;
      ok_ = readJsonCell(cells_, column_++, array, error_) && readJson(field, 0, array, member);
    } else {
      ok_ = readCells(member);
      lengths_.note(field, member);
    }
  }
  bool ok() const { return ok_; }

 private:
  template <class T>
  bool readCells(T& value) {
    if constexpr (std::is_array_v<T>) {
      for (auto& element : value) {
        if (!readCells(element)) return false;
      }
      return true;
    } else {
      return readCell(cells_, column_++, value, error_);
    }
  }

  template <class T>
  bool readJson(const lcmtypes::FieldDescriptor& field, int depth, const JsonDocument& array, std::vector<T>& out) {
    if (!checkArray(array, static_cast<int>(lengths_.of(field, depth)), field.name, error_)) return false;
    out.resize(array.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      if constexpr (lcmtypes::kIsVector<T>) {
        if (!readJson(field, depth + 1, array[i], out[i])) return false;
      } else {
        if (!readJsonElement(array[i], out[i], field.name, error_)) return false;
      }
    }
    return true;
  }

  const std::vector<std::string>& cells_;
  std::string* error_;
  std::size_t column_ = 0;
  bool ok_ = true;
  Lengths lengths_;
};

}  // namespace csv_row

template <class LcmType>
void writeCsvRow(CsvWriter& w, const LcmType& message) {
  csv_row::Writer writer(w);
  lcmtypes::visitLcmFields(writer, message);
  w.endRow();
}

// False with *error set when a cell does not hold its field (wrong count, number, array length).
template <class LcmType>
bool readCsvRow(const std::vector<std::string>& cells, LcmType& message, std::string* error) {
  if (!checkCellCount(cells, lcmtypes::LcmFields<LcmType>::type.num_columns, error)) return false;
  csv_row::Reader reader(cells, error);
  lcmtypes::visitLcmFields(reader, message);
  return reader.ok();
}

}  // namespace sdlqr::logger
