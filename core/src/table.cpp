// convexloc — huge-page buffers for Table<T> (see table.hpp).
#include "convexloc/table.hpp"

#include <cstdlib>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace convexloc::detail {

void* allocateHuge(std::size_t bytes) {
  // whole small pages from a huge-page boundary; only the whole huge pages inside the
  // buffer get the advice, so the tail never takes a huge page the table does not fill
  // (memory stays what the locator reports)
  constexpr std::size_t kPage = 4096;
  void* p = std::aligned_alloc(kHugePage, (bytes + kPage - 1) / kPage * kPage);
  if (!p) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
  // advice only: where the kernel declines, the buffer keeps small pages
  madvise(p, bytes / kHugePage * kHugePage, MADV_HUGEPAGE);
#endif
  return p;
}

void freeHuge(void* p) noexcept { std::free(p); }

}  // namespace convexloc::detail
