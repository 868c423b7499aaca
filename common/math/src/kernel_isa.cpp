#include "sdlqr/math/kernel_isa.hpp"

#include <atomic>

namespace sdlqr {

namespace {

KernelIsa detect() {
#if defined(__x86_64__) || defined(__i386__)
  // __builtin_cpu_supports also checks that the OS saves the wider registers (XCR0).
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("fma")) {
    return KernelIsa::kAvx512;
  }
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return KernelIsa::kAvx2Fma;
#endif
  return KernelIsa::kBaseline;
}

std::atomic<int>& active() {
  static std::atomic<int> isa{static_cast<int>(bestKernelIsa())};
  return isa;
}

}  // namespace

KernelIsa bestKernelIsa() {
  static const KernelIsa best = detect();
  return best;
}

KernelIsa activeKernelIsa() { return static_cast<KernelIsa>(active().load(std::memory_order_relaxed)); }

KernelIsa setKernelIsa(KernelIsa isa) {
  const KernelIsa chosen = static_cast<int>(isa) < static_cast<int>(bestKernelIsa()) ? isa : bestKernelIsa();
  active().store(static_cast<int>(chosen), std::memory_order_relaxed);
  return chosen;
}

const char* toString(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::kAvx512: return "avx512";
    case KernelIsa::kAvx2Fma: return "avx2";
    default: return "baseline";
  }
}

}  // namespace sdlqr
