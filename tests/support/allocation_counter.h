// Counts every operator new of the program that includes this header (in one of its source files
// only: it replaces the global allocation functions), for the checks that a steady World frame
// allocates nothing (tests/unit/test_world_allocations.cpp, bench/bench_world.cpp).
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

namespace collide2d::testing {
inline std::atomic<long> allocation_count{0};
}  // namespace collide2d::testing

void* operator new(std::size_t size) {
  collide2d::testing::allocation_count.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// GCC sees the replaced operator new's malloc meet these frees where it inlines both, and warns of
// a mismatch that the replacement makes correct.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop
