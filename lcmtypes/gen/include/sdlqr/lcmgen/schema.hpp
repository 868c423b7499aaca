#pragma once
// What one .lcm file says: its struct's fields (type, name, array dimensions, unit), its
// constants, and the @ annotations of its comments that shape the plain C++ struct.
// Pure text in, data out; the build-time generator (gen_main.cpp) reads lcmtypes/*.lcm with it.
//
// Conventions enforced (every field carries a trailing comment starting with its unit in
// brackets, e.g. `double gyro[3]; // [rad/s] ...`). A field without one, a nested struct type or
// more than kMaxDimensions array dimensions is an LcmSchemaError naming file and line, so the
// build fails instead of generating wrong code.
//
// Annotations live in comments, so they never change the LCM fingerprint:
//   before `struct`:  @plain Name                  name of the plain struct (required)
//                     @method <C++ declaration>    a member defined by hand (common/messages)
//                     @channel NAME [Id]           the bus channel of the type (one type per
//                                                  channel); Id names channel::kId and
//                                                  Stream::kId (default: the type's name, CamelCase)
//                     @split_port N                its port offset in the split bus layout
//   after a field:    @as Type                     plain member type (Vec3, Quat, bool, ...)
//                     @enum Name PREFIX_           enum class from the constants PREFIX_*
//                     @enum Name                   ... defined by another .lcm file
//                     @flags PREFIX_               the constants PREFIX_* as static members
//                     @default VALUE               initial value (a literal or a constant name)
//                     @rows member RowType         (on a length field) its arrays as one
//                                                  std::vector<RowType> member
//                     @row name                    member name inside the row (default: field)
//                     @wall_time                   a measured duration, not a function of the
//                                                  inputs: comparisons leave it out

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace sdlqr::lcmgen {

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

// `@name arguments` of one comment, in order; the arguments are the text up to the next `@`.
using Annotations = std::multimap<std::string, std::string>;

struct LcmField {
  std::string type;  // LCM primitive: int8_t int16_t int32_t int64_t float double string boolean byte
  std::string name;
  std::vector<LcmDimension> dimensions;
  std::string unit;     // text inside the leading [...] of the comment, e.g. "m, -, m/s"
  std::string comment;  // the whole trailing comment without its annotations
  Annotations annotations;
  int line = 0;

  bool hasVariableDimension() const;
  int fixedElementCount() const;  // product of the fixed dimensions (1 for a scalar)
  // The annotation's arguments, or "" when absent.
  std::string annotation(const std::string& name) const;
  bool has(const std::string& name) const { return annotations.count(name) > 0; }
};

struct LcmConst {
  std::string type;
  std::string name;
  std::string value;  // as written
  std::string comment;
  int line = 0;
};

struct LcmStruct {
  std::string package;
  std::string name;  // e.g. "imu_t"
  std::string file;
  std::string comment;  // the comment lines before `struct`, without annotations
  Annotations annotations;
  std::vector<LcmField> fields;
  std::vector<LcmConst> constants;

  // First fields `int64_t utime; int64_t seq;` as every sdlqr message has.
  bool hasUtimeAndSeq() const;
  const LcmField* field(const std::string& name) const;
};

// Parses one .lcm file holding one struct.
LcmStruct parseLcmStruct(const std::string& text, const std::string& file_name);

// CSV header cells: one per scalar element of fixed arrays ("gyro[0] [rad/s]"); one per
// variable-length array ("t[num_samples] [s]", its cell holds a JSON array).
std::vector<std::string> csvColumns(const LcmStruct& type);

// Unit of every element of a fixed-size field. A list such as "m, -, m/s" on a 10-element
// field is spread over the state layout p(3) q(4) v(3), "rad/s, m/s^2" on 4 elements over the
// input layout omega(3) c(1) (common/math/types.hpp); any other unit applies to every element.
std::vector<std::string> elementUnits(const LcmField& field);

}  // namespace sdlqr::lcmgen
