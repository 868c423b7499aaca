#pragma once
// Field visits over the generated code (sdlqr/lcmtypes/generated/plain_fields.hpp and
// lcm_fields.hpp): one call per member, in declaration order, over one or more structs of the
// same type at once, so comparing, filling or printing any message needs no per-field code.
//
//   visitFields(v, a, b);     // v(PlainField{"position", "m", false}, a.position, b.position) ...
//   visitLcmFields(v, m);     // v(FieldDescriptor of "gyro", m.gyro) ...

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "sdlqr/lcmtypes/field_descriptor.hpp"

namespace sdlqr::lcmtypes {

// One member of a plain struct. Units are those of the .lcm field ("" for a row group).
struct PlainField {
  std::string_view name;
  std::string_view unit;
  bool wall_time = false;  // @wall_time: measured by the process, not a function of its inputs
};

template <class Plain>
struct PlainFields;  // generated for every plain struct
template <class Lcm>
struct LcmFields;  // generated for every lcm-gen class

template <class T>
struct TypeTag {
  using type = T;
};

template <class T>
inline constexpr bool kIsPlainStruct = false;  // true where PlainFields<T> is generated

// Variable-length arrays are std::vector on both sides (lcm-gen and plain).
template <class T>
inline constexpr bool kIsVector = false;
template <class T, class A>
inline constexpr bool kIsVector<std::vector<T, A>> = true;

// The integer fields of a message visited so far: the lengths of the variable-length arrays after
// them. A decoded lcm-gen message's arrays may hold more than their length (a decode into a reused
// message does not shrink them), so the length field, not the vector, says how many there are.
class ArrayLengths {
 public:
  template <class T>
  void note(const FieldDescriptor& field, const T& value) {
    if constexpr (std::is_integral_v<T>) values_.emplace_back(field.name, static_cast<int64_t>(value));
  }
  // Elements of `field` at array depth `depth`: the fixed size, the length field's value, or -1
  // when the length field has not been seen.
  int64_t of(const FieldDescriptor& field, int depth) const {
    const ArrayDimension& dim = field.dimensions[depth];
    if (dim.size > 0) return dim.size;
    for (const auto& [name, value] : values_) {
      if (name == dim.length_field) return value;
    }
    return -1;
  }

 private:
  std::vector<std::pair<std::string_view, int64_t>> values_;
};

template <class Visitor, class First, class... Rest>
void visitFields(Visitor&& v, First&& first, Rest&&... rest) {
  PlainFields<std::remove_cv_t<std::remove_reference_t<First>>>::visit(v, std::forward<First>(first),
                                                                        std::forward<Rest>(rest)...);
}

template <class Visitor, class First, class... Rest>
void visitLcmFields(Visitor&& v, First&& first, Rest&&... rest) {
  LcmFields<std::remove_cv_t<std::remove_reference_t<First>>>::visit(v, std::forward<First>(first),
                                                                      std::forward<Rest>(rest)...);
}

// Rows of a plain vector filled from arrays sized by `count`: the count, never more than an
// array holds (a decoded message always has them equal).
inline std::size_t rowCount(int64_t count, std::initializer_list<std::size_t> array_sizes) {
  std::size_t n = count > 0 ? static_cast<std::size_t>(count) : 0;
  for (std::size_t size : array_sizes) n = std::min(n, size);
  return n;
}
template <class... Sizes>
std::size_t rowCount(int64_t count, Sizes... array_sizes) {
  return rowCount(count, {static_cast<std::size_t>(array_sizes)...});
}

}  // namespace sdlqr::lcmtypes
