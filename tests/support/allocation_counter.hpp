#pragma once
// Counts every heap allocation of the test binary that links this (global operator new is
// replaced in allocation_counter.cpp), so a test can show that a hot path allocates nothing.

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
