// Speed of Monte Carlo batches (tools/offline/batch): whole hover_jumps flights (52 s: the 1 kHz
// simulation and bodyrate loop, the 250 Hz estimator, the 100 Hz controller, the 10 Hz gain
// solves, the mission and the analysis of the flight) on the in-process closed loop.
//
//   BM_Flight          one flight on one thread, step by step
//   BM_Batch/jobs      a batch of flights of bench/hover_jumps_1000.yaml on `jobs` threads
//
// Counters: sim_s_per_wall_s (flights x simulated seconds per wall second) and, for the batch,
// s_per_1000_flights (the wall time 1,000 such flights would take at this rate; target <= 90 s on
// the 2-core machine). Run on a quiet machine: flock /work/coord/flight.lock ./sdlqr bench batch

#include <benchmark/benchmark.h>

#include <chrono>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "sdlqr/batch/heap.hpp"
#include "sdlqr/batch/runner.hpp"

namespace sdlqr::batch {
namespace {

const BatchContext& context() {
  static const BatchContext loaded = BatchContext::load(SDLQR_SOURCE_DIR "/bench/hover_jumps_1000.yaml");
  return loaded;
}

void BM_Flight(benchmark::State& state) {
  keepFreedHeapMemory();  // as runBatch does
  double simulated = 0.0;
  int flight = 0;
  logger::FlightLog spare;  // as a batch worker: each flight records into the last one's memory
  for (auto _ : state) {
    const FlightDraw draw = drawFlight(context().spec, context().config, context().scenario.sim, flight++);
    FlownFlight flown = fly(context(), worldOf(context(), draw), "sdlqr", false, std::move(spare));
    simulated += flown.world.scenario.duration;
    benchmark::DoNotOptimize(flown.report.checks.size());
    spare = std::move(flown.log);
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Flight)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();

void BM_Batch(benchmark::State& state) {
  const int jobs = static_cast<int>(state.range(0));
  const int flights = static_cast<int>(state.range(1));
  BatchContext batch = context();
  batch.spec.flights = flights;
  const std::string dir = "/tmp/sdlqr_bench_batch_" + std::to_string(::getpid());
  double simulated = 0.0, wall = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    if (std::system(("rm -rf '" + dir + "'").c_str()) != 0) state.SkipWithError("cannot clear the batch folder");
    state.ResumeTiming();
    RunOptions options;
    options.out_dir = dir;
    options.jobs = jobs;
    options.progress = false;
    const RunResult result = runBatch(batch, options);
    simulated += result.simulated_s;
    wall += result.wall_s;
  }
  if (std::system(("rm -rf '" + dir + "'").c_str()) != 0) state.SkipWithError("cannot clear the batch folder");
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  state.counters["s_per_1000_flights"] = wall / static_cast<double>(state.iterations()) / flights * 1000.0;
}
BENCHMARK(BM_Batch)->Args({1, 16})->Args({2, 32})->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace sdlqr::batch

BENCHMARK_MAIN();
