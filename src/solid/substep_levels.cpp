#include "solid/substep_levels.h"

#include <algorithm>

namespace slamsph {
namespace {

// Breadth-first search over the pairs from `seed` through the particles whose mark is not
// `stamp`, marking them with it and appending them to `queue` in visiting order, level[i] =
// base + distance. Returns the last particle reached (one of the farthest).
std::uint32_t bfs(const NeighbourList& pairs, std::uint32_t seed, std::uint8_t stamp,
                  std::vector<std::uint8_t>& mark, std::vector<std::uint32_t>& level,
                  std::uint32_t base, std::vector<std::uint32_t>& queue) {
  const std::size_t q0 = queue.size();
  queue.push_back(seed);
  mark[seed] = stamp;
  level[seed] = base;
  for (std::size_t h = q0; h < queue.size(); ++h) {
    const std::uint32_t i = queue[h];
    for (std::uint32_t k = pairs.start[i]; k < pairs.start[i + 1]; ++k) {
      const std::uint32_t j = pairs.index[k];
      if (mark[j] == stamp) continue;
      mark[j] = stamp;
      level[j] = level[i] + 1;
      queue.push_back(j);
    }
  }
  return queue.back();
}

}  // namespace

void update_substep_levels(const NeighbourList& pairs, std::size_t min_level, SubstepLevels& lv) {
  const std::size_t n = pairs.size();
  if (!lv.start.empty() && lv.key_start == pairs.start && lv.key_index == pairs.index) return;
  lv.key_start = pairs.start;
  lv.key_index = pairs.index;
  // Two searches per connected part: from its first particle (the last particle reached is a
  // pseudo-peripheral one), then from that particle, whose distances are the levels; the
  // parts' levels follow one another.
  std::vector<std::uint8_t> mark(n, 0);
  std::vector<std::uint32_t> level(n, 0), queue;
  queue.reserve(n);
  std::uint32_t levels = 0;
  for (std::uint32_t seed = 0; seed < n; ++seed) {
    if (mark[seed] != 0) continue;
    const std::size_t q0 = queue.size();
    const std::uint32_t far = bfs(pairs, seed, 1, mark, level, 0, queue);
    queue.resize(q0);
    levels = level[bfs(pairs, far, 2, mark, level, levels, queue)] + 1;
  }
  // Consecutive levels merged while smaller than min_level particles.
  std::vector<std::uint32_t> count(levels, 0);
  for (std::size_t i = 0; i < n; ++i) ++count[level[i]];
  std::vector<std::uint32_t> merged(levels, 0);
  std::uint32_t m = 0, size = 0;
  for (std::uint32_t l = 0; l < levels; ++l) {
    if (size >= min_level) {
      ++m;
      size = 0;
    }
    merged[l] = m;
    size += count[l];
  }
  const std::size_t total = levels == 0 ? 0 : m + 1;
  lv.start.assign(total + 1, 0);
  lv.work.assign(total + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    level[i] = merged[level[i]];
    ++lv.start[level[i] + 1];
    lv.work[level[i] + 1] += 1.0 + (pairs.start[i + 1] - pairs.start[i]);
  }
  lv.widest = 0;
  for (std::size_t l = 0; l < total; ++l) {
    lv.widest = std::max<std::size_t>(lv.widest, lv.start[l + 1]);
    lv.start[l + 1] += lv.start[l];
    lv.work[l + 1] += lv.work[l];
  }
  // Each level in index order (a counting sort by level).
  lv.order.resize(n);
  std::vector<std::uint32_t> next(lv.start.begin(), lv.start.end() - 1);
  lv.slot.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    lv.slot[i] = next[level[i]]++;
    lv.order[lv.slot[i]] = i;
  }
  lv.ok = true;
  for (std::uint32_t i = 0; i < n && lv.ok; ++i)
    for (std::uint32_t k = pairs.start[i]; k < pairs.start[i + 1]; ++k) {
      const std::uint32_t a = level[i], b = level[pairs.index[k]];
      if (a > b + 1 || b > a + 1) lv.ok = false;
    }
}

}  // namespace slamsph
