#include "sdlqr/batch/heap.hpp"

#include <malloc.h>

namespace sdlqr::batch {

void keepFreedHeapMemory() {
#if defined(__GLIBC__)
  constexpr int kLargestFromHeap = 32 << 20;  // glibc's largest mmap threshold on 64-bit
  constexpr int kNeverTrim = 1 << 30;
  mallopt(M_MMAP_THRESHOLD, kLargestFromHeap);
  mallopt(M_TRIM_THRESHOLD, kNeverTrim);
#endif
}

}  // namespace sdlqr::batch
