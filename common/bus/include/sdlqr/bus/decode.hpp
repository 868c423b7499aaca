#pragma once
// The byte-level stage of every received message, shared by the bus (Node) and by tools that
// read bytes from a log (the replay): the bytes must hold exactly one complete encoding of the
// type (the allocation-free walk generated from lcmtypes/, so a forged array length cannot allocate),
// then decode. A failure is a rejection like any other: kBadSize or kDecode.

#include <cstdint>
#include <utility>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/health/reject_reason.hpp"

namespace sdlqr::bus {

// The bytes hold exactly one complete encoding of T (walked without allocating); defined for
// every type of lcmtypes/ in wire_fits.cpp.
template <class T>
bool encodingFits(const uint8_t* data, int64_t size);

// Decodes in place (fixed-size types never allocate).
template <class T>
RejectReason decode(const void* data, uint32_t size, T& out) {
  if (!encodingFits<T>(static_cast<const uint8_t*>(data), size)) return RejectReason::kBadSize;
  if (out.decode(data, 0, static_cast<int>(size)) < 0) return RejectReason::kDecode;
  return RejectReason::kNone;
}

// The generated LCM type of a plain message type.
template <class Msg>
using LcmOf = decltype(toLcm(std::declval<const Msg&>()));

}  // namespace sdlqr::bus
