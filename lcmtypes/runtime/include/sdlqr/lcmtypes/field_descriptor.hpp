#pragma once
// What the generated descriptors (sdlqr/lcmtypes/generated/descriptors.hpp, built from
// lcmtypes/*.lcm) say about each message type: its fields, their units and its CSV columns.

#include <cstddef>
#include <string_view>

namespace sdlqr::lcmtypes {

struct ArrayDimension {
  int size = 0;                   // fixed length, 0 when variable
  std::string_view length_field;  // variable length: name of the field holding the count
};

struct FieldDescriptor {
  std::string_view name;
  std::string_view type;  // LCM primitive type name
  std::string_view unit;  // as written in the .lcm comment, e.g. "rad/s" or "m, -, m/s"
  int num_dimensions = 0;
  ArrayDimension dimensions[2] = {};
};

struct TypeDescriptor {
  std::string_view name;  // e.g. "imu_t"
  const FieldDescriptor* fields = nullptr;
  std::size_t num_fields = 0;
  const std::string_view* columns = nullptr;  // CSV header cells, in row order
  std::size_t num_columns = 0;
};

}  // namespace sdlqr::lcmtypes
