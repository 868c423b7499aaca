#pragma once
// A batch process keeps the heap memory its flights free. Each flight allocates and frees the
// same few megabytes (the analysis' temporaries, the closed loop's reservations); by default glibc
// gives large blocks back to the kernel (mmap above 128 KiB, trimming the heap's top above
// 128 KiB) and the next flight page-faults them in again: ~160 faults per hover_jumps flight,
// each dear under a hypervisor (BM_Flight ~4 % of its CPU). Flights are unchanged: only where
// their memory comes from.

namespace sdlqr::batch {

// Process-wide (mallopt): blocks up to 32 MiB from the heap, never trimmed. Idempotent.
void keepFreedHeapMemory();

}  // namespace sdlqr::batch
