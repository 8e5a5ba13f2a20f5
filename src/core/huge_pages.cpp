#include "core/huge_pages.h"

#if defined(__linux__)
#include <sys/mman.h>

#include <cstdint>
#endif

namespace slamsph {
namespace {

constexpr std::size_t kHugePage = 2 * 1024 * 1024;

std::size_t rounded(std::size_t bytes) {
  return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

}  // namespace

void* huge_page_allocate(std::size_t bytes) {
#if defined(__linux__)
  if (bytes >= kHugePageMinBytes) {
    // Map one huge page more than needed, unmap the parts before the first 2 MiB boundary
    // and after the rounded size, then ask for huge pages before the first touch (a
    // touched range would wait for the kernel's background collapse).
    const std::size_t size = rounded(bytes);
    void* m =
        mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (m == MAP_FAILED) throw std::bad_alloc();
    const auto a = reinterpret_cast<std::uintptr_t>(m);
    const std::uintptr_t p = (a + kHugePage - 1) / kHugePage * kHugePage;
    if (p > a) munmap(m, p - a);
    if (a + kHugePage > p) munmap(reinterpret_cast<void*>(p + size), a + kHugePage - p);
    madvise(reinterpret_cast<void*>(p), size, MADV_HUGEPAGE);  // a hint: may be refused
    return reinterpret_cast<void*>(p);
  }
#endif
  return ::operator new(bytes);
}

void huge_page_free(void* p, std::size_t bytes) noexcept {
  if (p == nullptr) return;
#if defined(__linux__)
  if (bytes >= kHugePageMinBytes) {
    munmap(p, rounded(bytes));
    return;
  }
#endif
  ::operator delete(p);
}

}  // namespace slamsph
