// libFuzzer harness of what a subscriber does with received bytes (common/bus and the process
// handlers): the generated pre-decode size walk, then the lcm-gen decoder, the conversion to the
// plain struct, the validator and, for a K, the closed-loop check. Input: one selector byte (the
// bus type), then the bytes of the message. Beyond ASan/UBSan findings it checks one property:
// every message that decodes re-encodes to bytes the size walk accepts (the walk never drops a
// valid message).

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "message_types.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/lcmtypes/generated/wire_fits.hpp"

namespace {

using namespace sdlqr;

template <class Plain>
auto validateIfAny(const Plain& plain, int) -> decltype(validate(plain, ValidationLimits{})) {
  return validate(plain, ValidationLimits{});
}
template <class Plain>
RejectReason validateIfAny(const Plain&, long) {
  return RejectReason::kNone;  // types no process validates beyond decoding (IMU, VIO, ...)
}

void closedLoopIfGains(const GainSet& gains) { (void)validateClosedLoop(gains); }
template <class Plain>
void closedLoopIfGains(const Plain&) {}

template <class Lcm>
void receive(const uint8_t* data, int64_t size) {
  if (!lcmtypes::encodingFits(static_cast<const Lcm*>(nullptr), data, size)) return;  // reject.size
  Lcm message;
  if (message.decode(data, 0, static_cast<int>(size)) < 0) return;  // reject.decode
  const auto plain = bus::fromLcm(message);
  if (validateIfAny(plain, 0) == RejectReason::kNone) closedLoopIfGains(plain);

  std::vector<uint8_t> encoded(static_cast<size_t>(message.getEncodedSize()));
  if (message.encode(encoded.data(), 0, static_cast<int>(encoded.size())) < 0) std::abort();
  if (!lcmtypes::encodingFits(static_cast<const Lcm*>(nullptr), encoded.data(),
                              static_cast<int64_t>(encoded.size()))) {
    std::abort();  // the walk would drop a valid message
  }
}

template <size_t... I>
void dispatch(int selector, const uint8_t* data, int64_t size, std::index_sequence<I...>) {
  ((selector == static_cast<int>(I) ? receive<std::tuple_element_t<I, fuzz::BusTypes>>(data, size) : void()), ...);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  dispatch(data[0] % fuzz::kBusTypeCount, data + 1, static_cast<int64_t>(size - 1),
           std::make_index_sequence<fuzz::kBusTypeCount>{});
  return 0;
}
