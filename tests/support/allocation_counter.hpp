#pragma once
// Counts every heap allocation of the test binary that links this (global operator new is
// replaced in allocation_counter.cpp), so a test can show that a hot path allocates nothing.
// Counts under AddressSanitizer too: the binary's own operator new wins over the sanitizer
// runtime's, and the blocks it takes from malloc are still ASan's, checked as any other (only
// new/delete mismatches go unreported in such a binary).

#include <vector>

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

// Allocations counted while one vector is made and freed: at least 2 (the vector and its
// elements) when the counting operator new is the one in use, which gives a test's zero its meaning.
inline long allocationsOfOneVector() {
  const AllocationCounter counter;
  std::vector<int>* volatile escaped = new std::vector<int>(100);  // volatile: new/delete not elided
  delete escaped;
  return counter.count();
}

}  // namespace sdlqr::testing
