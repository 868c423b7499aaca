#pragma once
// The plain C++ structs that the .lcm files describe, resolved from their annotations (see
// schema.hpp): member types, initial values, enums, row groups. Every emitter of plain code
// (structs, conversions, field visits) reads this one model, so they cannot disagree.

#include <string>
#include <vector>

#include "sdlqr/lcmgen/schema.hpp"

namespace sdlqr::lcmgen {

// Fixed-size Eigen types of common/math/types.hpp a double array may map to.
struct EigenType {
  std::string name;  // "Vec3"
  int elements = 0;
  int cols = 1;      // > 1: a matrix filled row-major from the flat array
  std::string init;  // initial value
};

// How one LCM array or scalar becomes a plain member (or a row member).
struct Shape {
  enum class Kind { kScalar, kBool, kEnum, kEigen, kArray, kVector };
  Kind kind = Kind::kScalar;
  std::string cpp_type;  // e.g. "double", "Vec3", "std::array<int32_t, 3>"
  std::string init;      // initial value, "" for none
  std::string lcm_scalar;  // the lcm-gen C++ scalar type, for casts back
  int size = 0;          // kArray: length; kEigen: elements
  int eigen_cols = 1;    // kEigen
  std::vector<Shape> inner;  // kArray, kVector: the element's shape (one entry)
};

struct PlainMember {
  std::string name;
  std::string comment;  // "[m] world frame, z up"
  bool wall_time = false;
  // A member that mirrors one LCM field (nullptr for a row group).
  const LcmField* field = nullptr;
  Shape shape;
  // A row group: std::vector<row_type> filled from the arrays sized by `length_field`.
  std::string row_type;
  const LcmField* length_field = nullptr;
};

struct PlainConstant {
  std::string name;  // kWeights
  std::string type;
  std::string value;
  std::string comment;
};

struct PlainEnum {
  std::string name;
  std::string underlying;
  std::vector<PlainConstant> values;  // in declaration order
  std::string defined_in;             // "gains_t.status STATUS_*": where its constants are
};

// The bus channel a message type travels on (one type per channel), from the .lcm file's
// `@channel NAME [Id]` and `@split_port N`.
struct PlainChannel {
  std::string name;    // "STATE_EST"; empty: the type has no channel of its own
  std::string id;      // "StateEstimate": channel::kStateEstimate, Stream::kStateEstimate
  int split_port = 0;  // port offset in the split bus layout; 0: the base port
};

struct PlainStruct {
  std::string name;
  std::string comment;
  const LcmStruct* lcm = nullptr;  // nullptr for a row struct
  std::vector<std::string> methods;
  std::vector<PlainConstant> constants;
  std::vector<PlainMember> members;
  PlainChannel channel;
};

struct PlainModel {
  std::string package;  // one package for all files
  std::vector<PlainEnum> enums;
  std::vector<PlainStruct> rows;     // row structs, e.g. TrajectorySample
  std::vector<PlainStruct> structs;  // one per LcmStruct, in the same order
};

// Resolves the annotations of every type; LcmSchemaError "file:line: ..." on a bad one.
// `types` must outlive the model (members point into it).
PlainModel buildPlainModel(const std::vector<LcmStruct>& types);

// "VIO_TIMEOUT" -> "kVioTimeout".
std::string constantName(const std::string& upper_snake);

}  // namespace sdlqr::lcmgen
