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
  // (posix_memalign: C's aligned_alloc wants the size to be a multiple of the alignment)
  constexpr std::size_t kPage = 4096;
  void* p = nullptr;
  if (posix_memalign(&p, kHugePage, (bytes + kPage - 1) / kPage * kPage) != 0) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
  // advice only: where the kernel declines, the buffer keeps small pages
  madvise(p, bytes / kHugePage * kHugePage, MADV_HUGEPAGE);
#endif
  return p;
}

void freeHuge(void* p) noexcept { std::free(p); }

}  // namespace convexloc::detail
