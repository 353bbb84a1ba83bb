// convexloc — huge-page buffers for Table<T> (see table.hpp).
#include "convexloc/table.hpp"

#include <cstdlib>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace convexloc::detail {

void* allocateHuge(std::size_t bytes) {
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
  // advice only: where the kernel declines, the buffer keeps small pages
  madvise(p, rounded, MADV_HUGEPAGE);
#endif
  return p;
}

void freeHuge(void* p) noexcept { std::free(p); }

}  // namespace convexloc::detail
