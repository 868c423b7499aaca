#pragma once
// Counts every heap allocation of the test binary that links this (global operator new is
// replaced in allocation_counter.cpp), so a test can show that a hot path allocates nothing.
// Counts under AddressSanitizer too: the binary's own operator new wins over the sanitizer
// runtime's, and the blocks it takes from malloc are still ASan's, checked as any other (only
// new/delete mismatches go unreported in such a binary).

namespace sdlqr::testing {

// Allocations made by the whole binary since it started.
long allocationCount();

// Allocations made between construction and count().
class AllocationCounter {
 public:
  AllocationCounter() : start_(allocationCount()) {}
  long count() const { return allocationCount() - start_; }

 private:
  long start_;
};

}  // namespace sdlqr::testing
