// The exact stage allocates nothing over the ordinary exponent range: this binary counts
// every operator new and every GMP allocation while exactly coplanar and collinear inputs,
// which only the exact stage decides, go through orient3d and crossDiff2d.
#include <gmp.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>
#include <thread>

#include "exact_cases.hpp"

namespace {
thread_local unsigned long long tAllocations = 0;
}  // namespace

// every allocation of this binary counted, then served by malloc (GCC, inlining the
// replacements, takes free for a mismatch with the operator new it cannot see is malloc)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  ++tAllocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
#pragma GCC diagnostic pop

using namespace exact_cases;

namespace {

void* (*gmpAlloc)(std::size_t);
void* (*gmpRealloc)(void*, std::size_t, std::size_t);
void (*gmpFree)(void*, std::size_t);
void* countedAlloc(std::size_t n) {
  ++tAllocations;
  return gmpAlloc(n);
}
void* countedRealloc(void* p, std::size_t from, std::size_t to) {
  ++tAllocations;
  return gmpRealloc(p, from, to);
}

// the allocations made in this thread while it lives (operator new and GMP's)
class AllocationCount {
 public:
  AllocationCount() : start_(tAllocations) {
    mp_get_memory_functions(&gmpAlloc, &gmpRealloc, &gmpFree);
    mp_set_memory_functions(countedAlloc, countedRealloc, gmpFree);
  }
  ~AllocationCount() { mp_set_memory_functions(gmpAlloc, gmpRealloc, gmpFree); }
  AllocationCount(const AllocationCount&) = delete;
  AllocationCount& operator=(const AllocationCount&) = delete;
  unsigned long long count() const { return tAllocations - start_; }

 private:
  unsigned long long start_;
};

}  // namespace

TEST(ExactStage, OrdinaryRangeAllocatesNothing) {
  // exactly coplanar and collinear cases, which only the exact stage can decide
  Rng r(105);
  const auto planes =
      make(2000, [&] { return r.below(2) ? latticePlane(r, -10) : columnPlane(r, -20, 20); });
  const auto lines =
      make(2000, [&] { return r.below(2) ? latticeLine(r, -10) : diagonalLine(r, -20, 20); });
  const ExactStageCounts before = exactStageCounts();
  int nonZero = 0;
  unsigned long long allocations = 0;
  {
    const AllocationCount count;
    for (const Orient& o : planes) nonZero += orient3d(o.a, o.b, o.c, o.d) != 0;
    for (const Cross& c : lines) nonZero += crossDiff2d(c.p0, c.p1, c.q0, c.q1) != 0;
    allocations = count.count();
  }
  EXPECT_EQ(nonZero, 0);
  EXPECT_EQ(allocations, 0u);
  // the filter decides none of them (bar a lattice case of zero permanent, unlikely): the
  // lattice cases go to the narrow integers, the full mantissas mostly to the expansions
  const ExactStageCounts counts = countsSince(before);
  EXPECT_EQ(counts.multiprecision, 0u);
  EXPECT_GT(counts.narrowIntegers, (planes.size() + lines.size()) / 3);
  EXPECT_GT(counts.expansions, (planes.size() + lines.size()) / 3);
}

TEST(ExactStage, ExtremeExponentsAllocateAndTheCountSeesIt) {
  // the counter is live: 2^700 and 2^-700 in one call take the multiprecision path, whose
  // integers of some 1400 bits allocate with either backend. The stage keeps its integers
  // per thread (predicates.cpp), so the call is a fresh thread's first: its integers grow.
  Rng r(106);
  Orient o = scaled(latticePlane(r, 0), 700);
  o.d.z = 0x1p-700;
  unsigned long long allocations = 0, multiprecision = 0;
  int sign = 0;
  std::thread([&] {
    const ExactStageCounts before = exactStageCounts();
    const AllocationCount count;
    sign = orient3d(o.a, o.b, o.c, o.d);
    allocations = count.count();
    multiprecision = countsSince(before).multiprecision;
  }).join();
  EXPECT_EQ(sign, refOrient3d(o.a, o.b, o.c, o.d));
  EXPECT_GT(allocations, 0u);
  EXPECT_EQ(multiprecision, 1u);
}
