// Speed of the state-dependent LQR gain (TARGET on the 2-core development machine: median <= 10 us,
// p99 <= 25 us per full solve at dt = 0.01; zero heap allocations, see common_alloc_tests).
// Every benchmark cycles through the fixture states so that no single easy case dominates.
// Figures and how to read them: bench/README.md.
//
//   bench_gains [--kernel_isa=baseline|avx2|avx512] [Google Benchmark flags]
//
// --kernel_isa lowers the kernels' instruction set (kernel_isa.hpp) to time the other code paths.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "gains_states.hpp"
#include "sdlqr/math/discretize.hpp"
#include "sdlqr/math/kernel_isa.hpp"
#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/riccati.hpp"

namespace sdlqr::bench {
namespace {

const std::vector<GainsCase>& cases() {
  static const std::vector<GainsCase> loaded = [] {
    std::vector<GainsCase> all = loadGainsCases();
    for (GainsCase& c : all) c.dt = 0.01;  // the benchmarked problem is the 100 Hz one
    return all;
  }();
  return loaded;
}

struct Prepared {
  TangentBasis E;
  TangentSystem tangent;
  DiscreteSystem<kTangentDim, kInputDim> discrete;
  DareSolution<kTangentDim, kInputDim> dare;
};

const std::vector<Prepared>& prepared() {
  static const std::vector<Prepared> all = [] {
    std::vector<Prepared> out;
    const LqrParams params;
    for (const GainsCase& c : cases()) {
      Prepared p;
      State x = c.x;
      orientation(x).normalize();
      p.E = tangentBasis(orientation(x));
      p.tangent = projectToTangent(linearize(x, c.u), p.E, params.q_diag);
      p.discrete = discretizeZoh<kTangentDim, kInputDim>(p.tangent.A, p.tangent.B, c.dt);
      p.dare = solveDareDoubling<kTangentDim, kInputDim>(p.discrete.A, p.discrete.B, p.tangent.Q,
                                                         params.r_diag.asDiagonal(), params.tolerance, 64);
      out.push_back(p);
    }
    return out;
  }();
  return all;
}

void BM_SolveLqrTangent(benchmark::State& state) {
  const LqrParams params;
  size_t i = 0;
  int failures = 0;
  for (auto _ : state) {
    const GainsCase& c = cases()[i++ % cases().size()];
    const LqrResult result = solveLqr(c.x, c.u, params);
    failures += result.status != SolveStatus::kOk;
    benchmark::DoNotOptimize(result.K.data());
  }
  state.counters["failures"] = failures;
}
BENCHMARK(BM_SolveLqrTangent)->Unit(benchmark::kMicrosecond);

// Times every solve on its own: the distribution (median, p99, max) the 10 Hz solver sees.
void BM_SolveLqrTangentLatency(benchmark::State& state) {
  const LqrParams params;
  std::vector<double> samples;
  samples.reserve(1 << 20);
  size_t i = 0;
  for (auto _ : state) {
    const GainsCase& c = cases()[i++ % cases().size()];
    const auto start = std::chrono::steady_clock::now();
    const LqrResult result = solveLqr(c.x, c.u, params);
    const auto stop = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(result.K.data());
    if (samples.size() < samples.capacity()) samples.push_back(std::chrono::duration<double, std::micro>(stop - start).count());
  }
  std::sort(samples.begin(), samples.end());
  const auto quantile = [&](double q) { return samples[static_cast<size_t>(q * (samples.size() - 1))]; };
  state.counters["median_us"] = quantile(0.5);
  state.counters["p99_us"] = quantile(0.99);
  state.counters["max_us"] = samples.back();
}
BENCHMARK(BM_SolveLqrTangentLatency)->Unit(benchmark::kMicrosecond)->MinTime(2.0);

// The duty cycle of sdlqr-gains, which solves once per 100 ms instead of back to back: before every
// timed solve the thread sleeps range(0) ms and, when range(1) is 1, writes one byte per cache
// line of a 64 MiB buffer (larger than L3), as the other processes of the stack do meanwhile.
// Reports the distribution of the solve alone (the sleep and the eviction are not timed).
void BM_SolveLqrTangentDutyCycle(benchmark::State& state) {
  const LqrParams params;
  const auto sleep = std::chrono::milliseconds(state.range(0));
  const bool evict = state.range(1) != 0;
  static std::vector<unsigned char> buffer(64u << 20);
  std::vector<double> samples;
  samples.reserve(static_cast<size_t>(state.max_iterations));
  size_t i = 0;
  for (auto _ : state) {
    const GainsCase& c = cases()[i++ % cases().size()];
    if (sleep.count() > 0) std::this_thread::sleep_for(sleep);
    if (evict) {
      for (size_t j = 0; j < buffer.size(); j += 64) buffer[j] = static_cast<unsigned char>(buffer[j] + 1);
      benchmark::ClobberMemory();
    }
    const auto start = std::chrono::steady_clock::now();
    const LqrResult result = solveLqr(c.x, c.u, params);
    const auto stop = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(result.K.data());
    const double seconds = std::chrono::duration<double>(stop - start).count();
    state.SetIterationTime(seconds);
    samples.push_back(seconds * 1e6);
  }
  std::sort(samples.begin(), samples.end());
  const auto quantile = [&](double q) { return samples[static_cast<size_t>(q * (samples.size() - 1))]; };
  state.counters["median_us"] = quantile(0.5);
  state.counters["p99_us"] = quantile(0.99);
  state.counters["max_us"] = samples.back();
}
BENCHMARK(BM_SolveLqrTangentDutyCycle)
    ->ArgNames({"sleep_ms", "evict"})
    ->Args({100, 0})
    ->Args({0, 1})
    ->Args({100, 1})
    ->Iterations(200)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);

void BM_Linearize(benchmark::State& state) {
  size_t i = 0;
  for (auto _ : state) {
    const GainsCase& c = cases()[i++ % cases().size()];
    const Linearization lin = linearize(c.x, c.u);
    benchmark::DoNotOptimize(lin.A.data());
  }
}
BENCHMARK(BM_Linearize);

void BM_ProjectToTangent(benchmark::State& state) {
  const LqrParams params;
  size_t i = 0;
  for (auto _ : state) {
    const GainsCase& c = cases()[i++ % cases().size()];
    const TangentBasis E = tangentBasis(orientation(c.x));
    const TangentSystem system = projectToTangent(linearize(c.x, c.u), E, params.q_diag);
    benchmark::DoNotOptimize(system.A.data());
  }
}
BENCHMARK(BM_ProjectToTangent);

void BM_ExpmZoh13(benchmark::State& state) {
  size_t i = 0;
  for (auto _ : state) {
    const Prepared& p = prepared()[i++ % prepared().size()];
    const DiscreteSystem<kTangentDim, kInputDim> d = discretizeZoh<kTangentDim, kInputDim>(p.tangent.A, p.tangent.B, 0.01);
    benchmark::DoNotOptimize(d.A.data());
  }
}
BENCHMARK(BM_ExpmZoh13);

void BM_Sda(benchmark::State& state) {
  const LqrParams params;
  const InputWeight R = params.r_diag.asDiagonal();
  size_t i = 0;
  int doublings = 0;
  for (auto _ : state) {
    const Prepared& p = prepared()[i++ % prepared().size()];
    const DareSolution<kTangentDim, kInputDim> s =
        solveDareDoubling<kTangentDim, kInputDim>(p.discrete.A, p.discrete.B, p.tangent.Q, R, params.tolerance, 64);
    doublings += s.doublings;
    benchmark::DoNotOptimize(s.X.data());
  }
  state.counters["doublings"] = benchmark::Counter(doublings, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_Sda)->Unit(benchmark::kMicrosecond);

void BM_GainStabilityResidual(benchmark::State& state) {
  const LqrParams params;
  const InputWeight R = params.r_diag.asDiagonal();
  size_t i = 0;
  for (auto _ : state) {
    const Prepared& p = prepared()[i++ % prepared().size()];
    const CertifiedGain<kTangentDim, kInputDim> gain =
        certifiedRiccatiGain<kTangentDim, kInputDim>(p.discrete.A, p.discrete.B, p.tangent.Q, R, p.dare.X);
    benchmark::DoNotOptimize(gain.K.data());
  }
}
BENCHMARK(BM_GainStabilityResidual);

void BM_SolveLqrIterative(benchmark::State& state) {
  LqrParams params;
  params.method = LqrMethod::kIterative;
  size_t i = 0;
  int iterations = 0;
  for (auto _ : state) {
    const GainsCase& c = cases()[i++ % cases().size()];
    const LqrResult result = solveLqr(c.x, c.u, params);
    iterations += result.iterations;
    benchmark::DoNotOptimize(result.K.data());
  }
  state.counters["iterations"] = benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_SolveLqrIterative)->Unit(benchmark::kMillisecond)->Iterations(46);

}  // namespace
}  // namespace sdlqr::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const std::string prefix = "--kernel_isa=";
    if (arg.compare(0, prefix.size(), prefix) != 0) {
      argv[kept++] = argv[i];
      continue;
    }
    const std::string name = arg.substr(prefix.size());
    sdlqr::KernelIsa isa;
    if (name == "baseline") {
      isa = sdlqr::KernelIsa::kBaseline;
    } else if (name == "avx2") {
      isa = sdlqr::KernelIsa::kAvx2Fma;
    } else if (name == "avx512") {
      isa = sdlqr::KernelIsa::kAvx512;
    } else {
      std::fprintf(stderr, "bench_gains: --kernel_isa must be baseline, avx2 or avx512\n");
      return 2;
    }
    if (sdlqr::setKernelIsa(isa) != isa) {
      std::fprintf(stderr, "bench_gains: this CPU does not support %s\n", name.c_str());
      return 2;
    }
  }
  argc = kept;
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::AddCustomContext("kernel_isa", sdlqr::toString(sdlqr::activeKernelIsa()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
