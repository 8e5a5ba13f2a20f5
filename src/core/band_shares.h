// Which band a thread of Executor::for_alternating runs next: the indices [0, count) cut
// into one contiguous share per thread (Executor's share: count * r / t), each thread taking
// its own share from the front and then the others' remainders from their back.
//
// Why not one shared counter: the bands' costs differ, so they are handed out at run time,
// but a counter hands every other band to the other thread, while the sweeps between the
// passes give each thread a contiguous half of the particles. Every pass then read half its
// bands from the other core's cache, and every sweep wrote half its lines there. Taking the
// own share first keeps a band on the core whose sweep share holds it; taking the others'
// remainders from their back keeps the balance of one counter (docs/validation.md §6,
// Session 20). Which thread runs a band never changes a result (for_alternating's tasks of
// one parity write disjoint data).
#pragma once
#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace slamsph {

class BandShares {
 public:
  // Shares kept apart; more threads than this share them (rank % kMaxShares), which stays
  // correct: every claim is a compare-and-swap on its share's [front, back).
  static constexpr int kMaxShares = 64;

  BandShares(std::size_t count, int threads)
      : count_(count), shares_(std::clamp(threads, 1, kMaxShares)) {
    const std::size_t s = static_cast<std::size_t>(shares_);
    for (std::size_t r = 0; r < s; ++r)
      share_[r].range.store(pack(count * r / s, count * (r + 1) / s), std::memory_order_relaxed);
  }

  // The next index for thread `rank`, or count when none is left. Safe to call concurrently.
  std::size_t next(int rank) {
    const int own = rank % shares_;
    if (const std::size_t k = take(own, true); k != count_) return k;
    for (int d = 1; d < shares_; ++d)
      if (const std::size_t k = take((own + d) % shares_, false); k != count_) return k;
    return count_;
  }

 private:
  // [front, back) of a share in one word, so that a claim from either end is one CAS.
  static std::uint64_t pack(std::size_t front, std::size_t back) {
    return static_cast<std::uint64_t>(front) | (static_cast<std::uint64_t>(back) << 32);
  }
  std::size_t take(int s, bool from_front) {
    std::atomic<std::uint64_t>& a = share_[static_cast<std::size_t>(s)].range;
    std::uint64_t v = a.load(std::memory_order_relaxed);
    for (;;) {
      const std::size_t front = v & 0xffffffffu, back = v >> 32;
      if (front >= back) return count_;
      const std::uint64_t taken = from_front ? pack(front + 1, back) : pack(front, back - 1);
      // Relaxed: the region's barrier orders the bands' work; a claim needs atomicity only.
      if (a.compare_exchange_weak(v, taken, std::memory_order_relaxed))
        return from_front ? front : back - 1;
    }
  }

  struct alignas(64) Share {  // a cache line each: a thread's claims stay on its own line
    std::atomic<std::uint64_t> range{0};
  };
  std::size_t count_;
  int shares_;
  std::array<Share, kMaxShares> share_;
};

}  // namespace slamsph
