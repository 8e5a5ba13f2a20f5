// Storage backed by 2 MiB transparent huge pages for the large scratch arrays of the hot
// loops (the elastic sub-step's workspace, solid/substep_workspace.h). On the x86-64
// virtual machines these were measured on, a 4 KiB page's translation misses the TLB once
// the arrays outgrow it (the 60 000-particle ring streams ~50 MB per sub-step over ~13 000
// pages), and each miss is a nested page walk; with 2 MiB pages the walks are gone (docs/
// validation.md §6 "Solid sub-step", session 20). The system's default ("madvise") backs
// only memory that asks for it. Nothing but where the bytes live changes: the same values,
// the same bits.
#pragma once
#include <cstddef>
#include <new>
#include <vector>

namespace slamsph {

// Allocations of at least this many bytes are placed on 2 MiB boundaries, rounded up to a
// multiple of 2 MiB and marked for huge pages (Linux madvise MADV_HUGEPAGE); smaller ones,
// and every one elsewhere, come from operator new.
inline constexpr std::size_t kHugePageMinBytes = 256 * 1024;

void* huge_page_allocate(std::size_t bytes);
void huge_page_free(void* p, std::size_t bytes) noexcept;

template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) { return static_cast<T*>(huge_page_allocate(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) noexcept { huge_page_free(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace slamsph
