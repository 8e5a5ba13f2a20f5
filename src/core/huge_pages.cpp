#include "core/huge_pages.h"

#if defined(__linux__)
#include <sys/mman.h>

#include <atomic>
#include <cstdint>
#endif

namespace slamsph {
namespace {

constexpr std::size_t kHugePage = 2 * 1024 * 1024;

std::size_t rounded(std::size_t bytes) {
  return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

// Where the k-th array starts after its 2 MiB boundary: arrays that all started on one would
// put element i of every array in the same cache set (the sub-step streams ~25 of them at
// once, more than the L1's 12 and the L2's 16 ways), so the starts are spread over 64 KiB
// (the L2's set span) in steps of 4 KiB + 64 B, which also moves them across the L1's sets.
std::size_t stagger() {
  static std::atomic<std::size_t> count{0};
  return count.fetch_add(1, std::memory_order_relaxed) * 4160 % 65536 / 64 * 64;
}

}  // namespace

void* huge_page_allocate(std::size_t bytes) {
#if defined(__linux__)
  if (bytes >= kHugePageMinBytes) {
    // Map one huge page more than needed, unmap the parts before the first 2 MiB boundary
    // and after the rounded size, then ask for huge pages before the first touch (a
    // touched range would wait for the kernel's background collapse).
    const std::size_t skew = stagger();
    const std::size_t size = rounded(bytes + skew);
    void* m =
        mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (m == MAP_FAILED) throw std::bad_alloc();
    const auto a = reinterpret_cast<std::uintptr_t>(m);
    const std::uintptr_t p = (a + kHugePage - 1) / kHugePage * kHugePage;
    if (p > a) munmap(m, p - a);
    if (a + kHugePage > p) munmap(reinterpret_cast<void*>(p + size), a + kHugePage - p);
    madvise(reinterpret_cast<void*>(p), size, MADV_HUGEPAGE);  // a hint: may be refused
    return reinterpret_cast<void*>(p + skew);
  }
#endif
  return ::operator new(bytes);
}

void huge_page_free(void* p, std::size_t bytes) noexcept {
  if (p == nullptr) return;
#if defined(__linux__)
  if (bytes >= kHugePageMinBytes) {
    // The mapping starts at the 2 MiB boundary below p (the stagger is less than 2 MiB).
    const auto a = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t base = a / kHugePage * kHugePage;
    munmap(reinterpret_cast<void*>(base), rounded(bytes + (a - base)));
    return;
  }
#endif
  ::operator delete(p);
}

}  // namespace slamsph
