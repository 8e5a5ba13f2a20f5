#include "solid/symmetric_pairs.h"

#include <algorithm>

namespace slamsph {

void symmetric_union(const NeighbourList& sets, NeighbourList& pairs,
                     std::vector<std::uint32_t>& reverse, std::vector<std::uint8_t>& in_own_set) {
  const std::size_t n = sets.size();
  std::vector<std::vector<std::uint32_t>> adj(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = sets.start[i]; k < sets.start[i + 1]; ++k) {
      const std::uint32_t j = sets.index[k];
      adj[i].push_back(j);
      adj[j].push_back(static_cast<std::uint32_t>(i));
    }
  pairs.start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::sort(adj[i].begin(), adj[i].end());
    adj[i].erase(std::unique(adj[i].begin(), adj[i].end()), adj[i].end());
    pairs.start[i + 1] = pairs.start[i] + adj[i].size();
  }
  pairs.index.clear();
  pairs.index.reserve(pairs.start[n]);
  for (std::size_t i = 0; i < n; ++i)
    pairs.index.insert(pairs.index.end(), adj[i].begin(), adj[i].end());

  reverse.assign(pairs.index.size(), 0);
  in_own_set.assign(pairs.index.size(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto s_begin = sets.index.begin() + sets.start[i];
    const auto s_end = sets.index.begin() + sets.start[i + 1];
    for (std::uint32_t k = pairs.start[i]; k < pairs.start[i + 1]; ++k) {
      const std::uint32_t j = pairs.index[k];
      const auto b = pairs.index.begin() + pairs.start[j];
      const auto e = pairs.index.begin() + pairs.start[j + 1];
      reverse[k] = static_cast<std::uint32_t>(std::lower_bound(b, e, i) - pairs.index.begin());
      in_own_set[k] = std::find(s_begin, s_end, j) != s_end ? 1 : 0;
    }
  }
}

}  // namespace slamsph
