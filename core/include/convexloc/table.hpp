// convexloc — storage for a locator's large tables.
//
// Table<T> is a std::vector whose buffers of 2 MiB and more are aligned to 2 MiB, and whose
// whole 2 MiB pages are marked for transparent huge pages before they are first touched (Linux: madvise
// MADV_HUGEPAGE, which Debian's default THP setting honours). A query reads a random cell
// of a table of many megabytes; with 4 KiB pages nearly every such read also misses the
// TLB, which the batches' prefetching cannot hide. Smaller buffers come from the usual
// allocator.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <vector>

namespace convexloc {

namespace detail {
// buffers at least this large get huge pages
inline constexpr std::size_t kHugePage = std::size_t{1} << 21;
// a buffer of `bytes` starting on a huge-page boundary; throws std::bad_alloc
void* allocateHuge(std::size_t bytes);
void freeHuge(void* p) noexcept;

// the bytes a vector's buffer holds (what the locators' stats() count as their memory)
template <class T, class A>
std::size_t bytesOf(const std::vector<T, A>& v) noexcept {
  return v.capacity() * sizeof(T);
}
}  // namespace detail

template <class T>
struct TableAllocator {
  using value_type = T;
  TableAllocator() noexcept = default;
  template <class U>
  TableAllocator(const TableAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    if (n * sizeof(T) >= detail::kHugePage) return static_cast<T*>(detail::allocateHuge(n * sizeof(T)));
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) >= detail::kHugePage)
      detail::freeHuge(p);
    else
      std::allocator<T>().deallocate(p, n);
  }
  friend bool operator==(const TableAllocator&, const TableAllocator&) noexcept { return true; }
};

template <class T>
using Table = std::vector<T, TableAllocator<T>>;

}  // namespace convexloc
