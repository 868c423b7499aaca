#pragma once
// The byte-level stage of every received message, shared by the bus (Node) and by tools that
// read bytes from a log (the replay): the bytes must hold exactly one complete encoding of the
// type (the allocation-free walk generated from lcmtypes/, so a forged array length cannot allocate),
// then decode. A failure is a rejection like any other: kBadSize or kDecode.
// A message of a signed bus (signature_layout.hpp) is the encoding and a trailer of kSignatureSize
// bytes: it decodes too (its trailer ignored, as LCM's own decoders do), so a signed log reads
// like any.
// Checking the signature is the Node's, on arrival, before this (a reader of a log has no key).

#include <cstdint>
#include <utility>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/signature_layout.hpp"
#include "sdlqr/health/reject_reason.hpp"

namespace sdlqr::bus {

// The bytes hold exactly one complete encoding of T (walked without allocating); defined for
// every type of lcmtypes/ in wire_fits.cpp.
template <class T>
bool encodingFits(const uint8_t* data, int64_t size);

// Decodes in place (fixed-size types never allocate).
template <class T>
RejectReason decode(const void* data, uint32_t size, T& out) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  if (!encodingFits<T>(bytes, size)) {
    if (size < kSignatureSize || !encodingFits<T>(bytes, size - kSignatureSize)) return RejectReason::kBadSize;
    size -= kSignatureSize;
  }
  if (out.decode(data, 0, static_cast<int>(size)) < 0) return RejectReason::kDecode;
  return RejectReason::kNone;
}

// The generated LCM type of a plain message type.
template <class Msg>
using LcmOf = decltype(toLcm(std::declval<const Msg&>()));

}  // namespace sdlqr::bus
