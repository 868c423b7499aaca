#pragma once
// Test helpers over the generated field walk (sdlqr/lcmtypes/leaves.hpp): fill every number and
// text of a plain struct with a distinct non-default value, list the leaves that differ
// between two structs (doubles by their bits), encode an lcm-gen message.

#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "sdlqr/lcmtypes/leaves.hpp"

namespace sdlqr::lcmtypes::test {

// Every leaf gets a value no generated default has (defaults are 0, -1, 1, true/false, the
// first enumerator); every vector gets three elements.
struct Filler {
  int filled = 0;

  template <class T>
  void leaf(const LeafName&, T& value) {
    ++filled;
    if constexpr (std::is_same_v<T, bool>) {
      value = !value;
    } else if constexpr (std::is_floating_point_v<T>) {
      value = static_cast<T>(0.25 + filled);  // exact in float and double
    } else if constexpr (std::is_same_v<T, std::string>) {
      value = "text " + std::to_string(filled);
    } else if constexpr (std::is_enum_v<T>) {
      value = static_cast<T>(static_cast<std::underlying_type_t<T>>(10 + filled % 100));
    } else if constexpr (sizeof(T) < 4) {
      value = static_cast<T>(10 + filled % 100);
    } else {
      value = static_cast<T>(1000 + filled);
    }
  }
  template <class Vector>
  std::size_t rows(const LeafName&, Vector& vector) {
    vector.resize(3);
    return vector.size();
  }
};

// Resizes every vector as Filler does and leaves the values alone (defaults to compare with).
struct Sizer {
  template <class T>
  void leaf(const LeafName&, T&) {}
  template <class Vector>
  std::size_t rows(const LeafName&, Vector& vector) {
    vector.resize(3);
    return vector.size();
  }
};

struct Differences {
  std::vector<std::string> names;  // "position[2]", "samples.size()", ...
  int leaves = 0;                  // leaves compared

  template <class T>
  void leaf(const LeafName& name, const T& a, const T& b) {
    ++leaves;
    bool same = false;
    if constexpr (std::is_floating_point_v<T>) same = std::memcmp(&a, &b, sizeof a) == 0;
    else same = a == b;
    if (!same) names.push_back(name.text());
  }
  template <class Vector>
  std::size_t rows(const LeafName& name, const Vector& a, const Vector& b) {
    if (a.size() != b.size()) names.push_back(name.path + ".size()");
    return std::min(a.size(), b.size());
  }
};

template <class T>
Differences differences(const T& a, const T& b) {
  Differences d;
  visitLeaves(d, a, b);
  return d;
}

template <class Lcm>
std::vector<uint8_t> encode(const Lcm& message) {
  std::vector<uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  if (message.encode(bytes.data(), 0, static_cast<int>(bytes.size())) != static_cast<int>(bytes.size())) {
    throw std::runtime_error("encode failed");
  }
  return bytes;
}

template <class Lcm>
Lcm decode(const std::vector<uint8_t>& bytes) {
  Lcm message{};
  if (message.decode(bytes.data(), 0, static_cast<int>(bytes.size())) != static_cast<int>(bytes.size())) {
    throw std::runtime_error("decode failed");
  }
  return message;
}

}  // namespace sdlqr::lcmtypes::test
