// Cost of the signed bus per message (common/bus signature.hpp): signing on publish, the
// subscriber's admission (MAC check and replay window) on arrival, and the bytes added, for the
// 1 kHz IMU, the 100 Hz RATE_CMD and the largest routine message, GAINS. Counters: payload bytes
// and the trailer's share of them.

#include <benchmark/benchmark.h>

#include <vector>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/signature.hpp"
#include "sdlqr/gains_t.hpp"
#include "sdlqr/imu_t.hpp"
#include "sdlqr/rate_cmd_t.hpp"

namespace {

using namespace sdlqr;
using namespace sdlqr::bus;

template <class LcmType>
std::vector<uint8_t> encoded() {
  const LcmType message{};
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()) + kSignatureSize);
  message.encode(bytes.data(), 0, message.getEncodedSize());
  return bytes;
}

std::vector<uint8_t> encodedGains() {
  const gains_t message = toLcm(GainSet{});
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()) + kSignatureSize);
  message.encode(bytes.data(), 0, message.getEncodedSize());
  return bytes;
}

BusKey benchKey() {
  BusKey key;
  for (size_t i = 0; i < key.bytes.size(); ++i) key.bytes[i] = static_cast<uint8_t>(i * 37 + 11);
  return key;
}

void counters(benchmark::State& state, size_t payload) {
  state.counters["payload_bytes"] = static_cast<double>(payload);
  state.counters["added_bytes"] = static_cast<double>(kSignatureSize);
  state.counters["added_percent"] = 100.0 * static_cast<double>(kSignatureSize) / static_cast<double>(payload);
}

// Publisher side: the trailer written into the publish buffer.
void sign(benchmark::State& state, std::vector<uint8_t> bytes, const char* channel) {
  const BusSigner signer(benchKey());
  const size_t payload = bytes.size() - kSignatureSize;
  uint64_t timestamp = 1;
  for (auto _ : state) {
    signer.sign(channel, bytes.data(), payload, SignatureTrailer{7, ++timestamp});
    benchmark::DoNotOptimize(bytes.data());
  }
  counters(state, payload);
}

// Subscriber side: MAC check and replay window of a fresh message each time, then sign again
// (timed apart with PauseTiming would cost more than the work; reported as sign + admit).
void signAndAdmit(benchmark::State& state, std::vector<uint8_t> bytes, const char* channel) {
  const BusSigner signer(benchKey());
  ReplayWindow window(~uint64_t{0} >> 17);
  const size_t payload = bytes.size() - kSignatureSize;
  uint64_t timestamp = 1;
  for (auto _ : state) {
    signer.sign(channel, bytes.data(), payload, SignatureTrailer{7, ++timestamp});
    const RejectReason reason = admitSigned(signer, window, channel, bytes.data(), bytes.size(), false, timestamp);
    if (reason != RejectReason::kNone) state.SkipWithError("a fresh signed message was rejected");
    benchmark::DoNotOptimize(reason);
  }
  counters(state, payload);
}

BENCHMARK_CAPTURE(sign, imu, encoded<imu_t>(), "QUAD/IMU");
BENCHMARK_CAPTURE(sign, rate_cmd, encoded<rate_cmd_t>(), "QUAD/RATE_CMD");
BENCHMARK_CAPTURE(sign, gains, encodedGains(), "QUAD/GAINS");
BENCHMARK_CAPTURE(signAndAdmit, imu, encoded<imu_t>(), "QUAD/IMU");
BENCHMARK_CAPTURE(signAndAdmit, rate_cmd, encoded<rate_cmd_t>(), "QUAD/RATE_CMD");
BENCHMARK_CAPTURE(signAndAdmit, gains, encodedGains(), "QUAD/GAINS");

}  // namespace

BENCHMARK_MAIN();
