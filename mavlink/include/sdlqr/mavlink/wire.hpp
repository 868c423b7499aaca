#pragma once
// Little-endian field access for the generated message structs (sdlqr/mavlink/messages.hpp):
// MAVLink payloads are little-endian whatever the host. Byte by byte, so alignment never matters.

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace sdlqr::mavlink::wire {

template <class T>
using Bits = std::conditional_t<sizeof(T) == 1, uint8_t,
             std::conditional_t<sizeof(T) == 2, uint16_t, std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>>;

template <class T>
void put(uint8_t* out, T value) {
  static_assert(std::is_arithmetic_v<T>, "a MAVLink field is a number or a char");
  Bits<T> bits;
  std::memcpy(&bits, &value, sizeof(T));
  for (size_t i = 0; i < sizeof(T); ++i) out[i] = static_cast<uint8_t>(bits >> (8 * i));
}

template <class T>
void get(const uint8_t* in, T& value) {
  static_assert(std::is_arithmetic_v<T>, "a MAVLink field is a number or a char");
  Bits<T> bits = 0;
  for (size_t i = 0; i < sizeof(T); ++i) bits = static_cast<Bits<T>>(bits | (static_cast<Bits<T>>(in[i]) << (8 * i)));
  std::memcpy(&value, &bits, sizeof(T));
}

template <class T, size_t N>
void put(uint8_t* out, const std::array<T, N>& values) {
  for (size_t i = 0; i < N; ++i) put(out + i * sizeof(T), values[i]);
}

template <class T, size_t N>
void get(const uint8_t* in, std::array<T, N>& values) {
  for (size_t i = 0; i < N; ++i) get(in + i * sizeof(T), values[i]);
}

}  // namespace sdlqr::mavlink::wire
