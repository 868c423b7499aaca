#pragma once
// Every number and text of one or more plain structs of the same type, walked together and
// named as the .lcm field they come from: "position" index 2, "K" index 13 (row-major, as on
// the wire), "thrust" index -1, "samples[3].x" index 7. Built on the generated field visits,
// so a new field is walked with no edit here.
//
//   struct Visitor {
//     // Values are the members themselves: double, an integer, bool, an enum or std::string.
//     template <class... T> void leaf(const LeafName& name, T&... values);
//     // A std::vector member: how many elements to walk (e.g. the smallest size, after
//     // noting a difference; or a size set by the visitor).
//     template <class... V> std::size_t rows(const LeafName& name, V&... vectors);
//   };
//   visitLeaves(visitor, recorded, replayed);

#include <Eigen/Core>
#include <array>
#include <string>
#include <type_traits>
#include <vector>

#include "sdlqr/lcmtypes/fields.hpp"

namespace sdlqr::lcmtypes {

struct LeafName {
  const std::string& path;  // "position", "samples[3].x"
  int index;                // element of an array, -1 for a scalar
  const PlainField& field;  // the member it belongs to

  std::string text() const { return index < 0 ? path : path + "[" + std::to_string(index) + "]"; }
};

namespace detail {

template <class T>
inline constexpr bool kIsArray = false;
template <class T, std::size_t N>
inline constexpr bool kIsArray<std::array<T, N>> = true;
template <class T>
inline constexpr bool kIsEigen = std::is_base_of_v<Eigen::DenseBase<T>, T>;
template <class T>
inline constexpr bool kIsLeaf = !kIsVector<T> && !kIsArray<T> && !kIsEigen<T> && !kIsPlainStruct<T>;

template <class Visitor, class... S>
void walkStruct(Visitor& v, const std::string& prefix, S&... s);

// One member (or element) at `path`: a leaf, or an array, Eigen matrix or vector of them.
template <class Visitor, class First, class... Rest>
void walk(Visitor& v, const std::string& path, const PlainField& field, First& first, Rest&... rest) {
  using T = std::remove_const_t<First>;
  if constexpr (kIsEigen<T>) {
    for (Eigen::Index r = 0; r < first.rows(); ++r) {
      for (Eigen::Index c = 0; c < first.cols(); ++c) {
        v.leaf(LeafName{path, static_cast<int>(r * first.cols() + c), field}, first(r, c), rest(r, c)...);
      }
    }
  } else if constexpr (kIsArray<T> || kIsVector<T>) {
    std::size_t n = first.size();
    if constexpr (kIsVector<T>) n = v.rows(LeafName{path, -1, field}, first, rest...);
    using Element = typename T::value_type;
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (kIsLeaf<Element>) {
        v.leaf(LeafName{path, static_cast<int>(i), field}, first[i], rest[i]...);
      } else {
        const std::string element = path + "[" + std::to_string(i) + "]";
        if constexpr (kIsPlainStruct<Element>) walkStruct(v, element + ".", first[i], rest[i]...);
        else walk(v, element, field, first[i], rest[i]...);
      }
    }
  } else if constexpr (kIsPlainStruct<T>) {
    walkStruct(v, path + ".", first, rest...);
  } else {
    v.leaf(LeafName{path, -1, field}, first, rest...);
  }
}

template <class Visitor, class... S>
void walkStruct(Visitor& v, const std::string& prefix, S&... s) {
  visitFields([&](const PlainField& f, auto&... members) { walk(v, prefix + std::string(f.name), f, members...); },
              s...);
}

}  // namespace detail

template <class Visitor, class... S>
void visitLeaves(Visitor&& v, S&... s) {
  detail::walkStruct(v, std::string(), s...);
}

}  // namespace sdlqr::lcmtypes
