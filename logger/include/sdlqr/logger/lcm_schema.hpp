#pragma once
// Reads the field list of an LCM struct (.lcm file) and emits the C++ headers that describe
// and print its fields, so the CSV export cannot drift from lcmtypes/*.lcm. Used at build time
// by tools/lcm_fields_gen.cpp; pure text in, text out.
//
// Conventions enforced (STYLE.md "comment unit and frame on every field"): every field carries
// a trailing comment starting with its unit in brackets, e.g. `double gyro[3]; // [rad/s] ...`.
// A field without one, a nested struct type or more than kMaxDimensions array dimensions is a
// LcmSchemaError naming file and line, so the build fails instead of exporting wrong columns.

#include <stdexcept>
#include <string>
#include <vector>

namespace sdlqr::logger {

class LcmSchemaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr int kMaxDimensions = 2;

struct LcmDimension {
  int size = 0;              // fixed length; 0 when length_field names it
  std::string length_field;  // variable length: the integer field holding the count
  bool variable() const { return !length_field.empty(); }
};

struct LcmField {
  std::string type;  // LCM primitive: int8_t int16_t int32_t int64_t float double string boolean byte
  std::string name;
  std::vector<LcmDimension> dimensions;
  std::string unit;  // text inside the leading [...] of the comment, e.g. "m, -, m/s"
  int line = 0;

  bool hasVariableDimension() const;
  int fixedElementCount() const;  // product of the fixed dimensions (1 for a scalar)
};

struct LcmStruct {
  std::string package;
  std::string name;  // e.g. "imu_t"
  std::string file;
  std::vector<LcmField> fields;

  // First fields `int64_t utime; int64_t seq;` as every sdlqr message has (DESIGN §2).
  bool hasUtimeAndSeq() const;
};

// Parses one .lcm file holding one struct. Constants are skipped.
LcmStruct parseLcmStruct(const std::string& text, const std::string& file_name);

// CSV header cells: one per scalar element of fixed arrays ("gyro[0] [rad/s]"); one per
// variable-length array ("t[num_samples] [s]", its cell holds a JSON array).
std::vector<std::string> csvColumns(const LcmStruct& type);

// Unit of every element of a fixed-size field. A list such as "m, -, m/s" on a 10-element
// field is spread over the state layout p(3) q(4) v(3), "rad/s, m/s^2" on 4 elements over the
// input layout omega(3) c(1) (common/types.hpp); any other unit applies to every element.
std::vector<std::string> elementUnits(const LcmField& field);

// Generated headers: descriptors only (no LCM includes), and CSV row writers/readers for the
// lcm-gen C++ classes. `source_note` names the inputs in the banner comment.
std::string emitDescriptorsHeader(const std::vector<LcmStruct>& types, const std::string& source_note);
std::string emitCsvRowsHeader(const std::vector<LcmStruct>& types, const std::string& source_note);

}  // namespace sdlqr::logger
