// The PX4 bridge's own cost per message, without the operating system (bench/px4_latency measures
// the whole path through the process): writing and parsing an ODOMETRY frame, unsigned and signed,
// and the bridge's core from the frame's bytes to STATE_EST and from a RATE_CMD to the
// SET_ATTITUDE_TARGET frame written.

#include <benchmark/benchmark.h>

#include <optional>
#include <vector>

#include "sdlqr/mavlink/parser.hpp"
#include "sdlqr/messages/in_process_wiring.hpp"
#include "sdlqr/px4/bridge_core.hpp"

namespace {

using namespace sdlqr;


mavlink::Odometry odometry(int64_t utime) {
  mavlink::Odometry o;
  o.time_usec = static_cast<uint64_t>(utime);
  o.frame_id = o.child_frame_id = mavlink::mav_frame::kLocalNed;
  o.q = {1.0f, 0.0f, 0.0f, 0.0f};
  o.z = -1.0f;
  return o;
}

void BM_WriteOdometry(benchmark::State& state) {
  mavlink::FrameWriter writer(mavlink::Address{1, 1});
  if (state.range(0)) writer.enableSigning(mavlink::SigningKey{}, 0);
  uint8_t bytes[mavlink::kMaxFrameSize];
  uint64_t t = 1000;
  for (auto _ : state) benchmark::DoNotOptimize(writer.write(odometry(4000), ++t, bytes));
}
BENCHMARK(BM_WriteOdometry)->ArgName("signed")->Arg(0)->Arg(1);

void BM_ParseOdometry(benchmark::State& state) {
  const bool sign = state.range(0) != 0;
  mavlink::FrameWriter writer(mavlink::Address{1, 1});
  if (sign) writer.enableSigning(mavlink::SigningKey{}, 0);
  std::vector<std::vector<uint8_t>> frames(1 << 14);  // signed: each newer than the one before
  uint8_t bytes[mavlink::kMaxFrameSize];
  for (size_t k = 0; k < frames.size(); ++k) frames[k].assign(bytes, bytes + writer.write(odometry(4000), 1000 + k, bytes));
  std::optional<mavlink::Parser> parser;
  size_t i = frames.size();
  int64_t accepted = 0;
  for (auto _ : state) {
    if (i == frames.size()) {  // a fresh receiver for the frames again: they would be replays
      state.PauseTiming();
      parser.emplace();
      if (sign) parser->requireSigning(mavlink::SigningKey{});
      i = 0;
      state.ResumeTiming();
    }
    parser->feed(frames[i].data(), frames[i].size(), 1000, [&](const mavlink::Frame&) { ++accepted; });
    ++i;
  }
  state.counters["accepted"] = benchmark::Counter(static_cast<double>(accepted), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_ParseOdometry)->ArgName("signed")->Arg(0)->Arg(1);

// ODOMETRY bytes -> STATE_EST published, and RATE_CMD -> SET_ATTITUDE_TARGET written, in the core.
void BM_BridgeCore(benchmark::State& state) {
  px4::DiscardingSink sink;
  px4::MavlinkEndpoint endpoint({1, px4::kOnboardComputerComponent}, sink, [] { return uint64_t{0}; });
  px4::BridgeCore core(px4::BridgeParams(), 9.81, ValidationLimits(), endpoint);
  OutboxTo<NoObserver> bus{NoObserver{}};
  mavlink::FrameWriter autopilot(mavlink::Address{1, 1});
  uint8_t bytes[mavlink::kMaxFrameSize];
  mavlink::Heartbeat heartbeat;
  heartbeat.autopilot = mavlink::mav_autopilot::kPx4;
  core.onBytes(bytes, autopilot.write(heartbeat, 0, bytes), true, bus);
  int64_t utime = 1'000'000;
  RateCommand command;
  command.thrust = 9.81;
  for (auto _ : state) {
    utime += 4000;
    if (state.range(0) == 0) {
      core.onBytes(bytes, autopilot.write(odometry(utime), 0, bytes), true, bus);
    } else {
      state.PauseTiming();
      core.onBytes(bytes, autopilot.write(odometry(utime), 0, bytes), true, bus);
      command.utime = utime;
      ++command.seq;
      state.ResumeTiming();
      benchmark::DoNotOptimize(core.onRateCommand(command));
    }
  }
}
BENCHMARK(BM_BridgeCore)->ArgName("rate_cmd")->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
