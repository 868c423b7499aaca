#pragma once
// The vector instruction set that the fixed-size solver kernels (the doubling loop, the ZOH
// exponential, the stability certificate) run on. The best one the CPU supports is chosen at the
// first use; tests and benchmarks may lower it to cover or compare the other code paths.

namespace sdlqr {

enum class KernelIsa {
  kBaseline = 0,  // x86-64 SSE2 (and every non-x86 target)
  kAvx2Fma = 1,   // AVX2 + FMA: 4-lane vectors
  kAvx512 = 2,    // AVX-512 F/VL/DQ: 8-lane vectors
};

// The best set this CPU (and its operating system) supports.
KernelIsa bestKernelIsa();

// The set the kernels use now: bestKernelIsa() unless lowered by setKernelIsa.
KernelIsa activeKernelIsa();

// Makes the kernels use min(isa, bestKernelIsa()) and returns it. For tests and benchmarks; not to
// be called while another thread is solving.
KernelIsa setKernelIsa(KernelIsa isa);

const char* toString(KernelIsa isa);

}  // namespace sdlqr
