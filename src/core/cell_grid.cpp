#include "core/cell_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/candidate_lanes.h"
#include "core/parallel.h"

namespace slamsph {

void CellGrid::build(std::span<const Vec2> pts, double cell) {
  cell_ = cell;
  inv_cell_ = 1.0 / cell;
  sorted_.assign(pts.size(), 0);
  if (pts.empty()) {
    nx_ = ny_ = 0;
    start_.assign(1, 0);
    return;
  }
  Vec2 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec2 hi{-lo.x, -lo.y};
  for (const Vec2& p : pts) {
    lo.x = std::min(lo.x, p.x);
    lo.y = std::min(lo.y, p.y);
    hi.x = std::max(hi.x, p.x);
    hi.y = std::max(hi.y, p.y);
  }
  lo_ = lo;
  nx_ = static_cast<int>((hi.x - lo.x) * inv_cell_) + 1;
  ny_ = static_cast<int>((hi.y - lo.y) * inv_cell_) + 1;
  const std::size_t ncell = static_cast<std::size_t>(nx_) * ny_;
  start_.assign(ncell + 1, 0);
  std::vector<std::uint32_t> cell_of(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const std::uint32_t c = static_cast<std::uint32_t>(cell_y(pts[i].y)) * nx_ + cell_x(pts[i].x);
    cell_of[i] = c;
    ++start_[c + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) start_[c + 1] += start_[c];
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < pts.size(); ++i) sorted_[fill[cell_of[i]]++] = i;
}

void CellGrid::renumber_in_cell_order() {
  for (std::size_t k = 0; k < sorted_.size(); ++k) sorted_[k] = static_cast<std::uint32_t>(k);
}

namespace {

// CSR lists over n queries: runs(i, run) calls run(b, e) for each run of candidates of query i
// (their number bounds its list), visit(i, dst) writes every neighbour j of query i at dst in
// list order (`*dst++ = j`; dst may hold as many entries as the query has candidates). The
// candidates are tested once: each query fills its part of a scratch array as long as its
// candidates, then the lists are packed (the tests done once instead of counting first and
// filling after, docs/validation.md §6 Session 14).
template <class Runs, class Visit>
void csr_lists(std::size_t n, Runs runs, Visit visit, const Executor& exec, NeighbourList& out) {
  std::vector<std::uint32_t>& part = out.scratch_start;
  part.assign(n + 1, 0);
  out.start.assign(n + 1, 0);
  exec.for_each(n, [&](std::size_t i) {
    std::uint32_t c = 0;
    runs(i, [&c](std::uint32_t b, std::uint32_t e) { c += e > b ? e - b : 0; });
    part[i + 1] = c;
  });
  for (std::size_t i = 0; i < n; ++i) part[i + 1] += part[i];
  if (out.scratch.size() < part[n]) out.scratch.resize(part[n]);
  // Split by candidates (the tests' cost), not by queries: a fluid query next to a wall has
  // contact candidates, one far from it none (the fluid–contact lists).
  exec.for_each_weighted(n, part.data(), [&](std::size_t i) {
    std::uint32_t* dst = out.scratch.data() + part[i];
    visit(i, dst);
    out.start[i + 1] = static_cast<std::uint32_t>(dst - (out.scratch.data() + part[i]));
  });
  for (std::size_t i = 0; i < n; ++i) out.start[i + 1] += out.start[i];
  out.index.resize(out.start[n]);
  // Split by list lengths, as above (the fluid–contact lists are empty away from the walls).
  exec.for_each_weighted(n, out.start.data(), [&](std::size_t i) {
    std::copy_n(out.scratch.data() + part[i], out.start[i + 1] - out.start[i],
                out.index.data() + out.start[i]);
  });
}

// The points j within `radius` of each query i for which accept(i, j) holds.
template <class Accept>
void build_lists(std::span<const Vec2> queries, std::span<const Vec2> pts, const CellGrid& grid,
                 double radius, Accept accept, const Executor& exec, NeighbourList& out) {
  const double r2 = radius * radius;
  csr_lists(
      queries.size(),
      [&](std::size_t i, auto&& run) { grid.for_each_candidate_run(queries[i], run); },
      [&](std::size_t i, std::uint32_t*& dst) {
        const Vec2 q = queries[i];
        grid.for_each_candidate(q, [&](std::uint32_t j) {
          if (accept(i, j) && norm2(q - pts[j]) < r2) *dst++ = j;
        });
      },
      exec, out);
}

}  // namespace

void build_neighbour_list(std::span<const Vec2> queries, std::span<const Vec2> pts,
                          const CellGrid& grid, double radius, bool skip_self, const Executor& exec,
                          NeighbourList& out) {
  build_lists(
      queries, pts, grid, radius,
      [skip_self](std::size_t i, std::uint32_t j) { return !(skip_self && j == i); }, exec, out);
}

std::vector<std::uint32_t> CellGrid::row_offsets() const {
  std::vector<std::uint32_t> rows(static_cast<std::size_t>(ny_) + 1, 0);
  for (int jy = 0; jy <= ny_; ++jy) rows[jy] = start_[static_cast<std::size_t>(jy) * nx_];
  return rows;
}

void build_banded_pairs(std::span<const Vec2> pts, const CellGrid& grid, double radius,
                        const Executor& exec, BandedPairs& out) {
  const std::size_t n = pts.size();
  const std::vector<std::uint32_t>& order = grid.cell_order();
  bool in_cell_order = order.size() == n && radius <= grid.cell_size();
  for (std::size_t i = 0; in_cell_order && i < n; ++i) in_cell_order = order[i] == i;
  if (in_cell_order) {
    // The same lists, in the same order, from the cells that can hold a later point
    // (CellGrid::for_each_later_candidate): half the candidates of the 3x3 search.
    // In cell order a run of candidates is a run of consecutive points: tested eight at a time
    // where the CPU has AVX-512F (core/candidate_lanes.h; the same lists).
    const double r2 = radius * radius;
    const bool lanes = candidate_lanes_avx512_available();
    csr_lists(
        n,
        [&](std::size_t i, auto&& run) {
          grid.for_each_later_candidate_run(static_cast<std::uint32_t>(i), pts[i], run);
        },
        [&](std::size_t i, std::uint32_t*& dst) {
          const Vec2 q = pts[i];
          if (lanes) {
            grid.for_each_later_candidate_run(
                static_cast<std::uint32_t>(i), q, [&](std::uint32_t b, std::uint32_t e) {
                  if (e > b) dst = candidates_within_avx512(pts.data(), b, e, q, r2, dst);
                });
            return;
          }
          grid.for_each_later_candidate(static_cast<std::uint32_t>(i), q, [&](std::uint32_t j) {
            if (norm2(q - pts[j]) < r2) *dst++ = j;
          });
        },
        exec, out.half);
  } else {
    build_lists(
        pts, pts, grid, radius, [](std::size_t i, std::uint32_t j) { return j > i; }, exec,
        out.half);
  }
  out.band_start.clear();
  if (in_cell_order) {
    // One band per non-empty row of cells (row_offsets() starts at 0 and ends at n). Empty
    // rows hold no partners, so dropping them keeps every partner in the same or next band.
    for (std::uint32_t r : grid.row_offsets())
      if (out.band_start.empty() || r > out.band_start.back()) out.band_start.push_back(r);
  } else {
    out.band_start = {0, static_cast<std::uint32_t>(n)};
  }
}

void sort_each_list(NeighbourList& list, const Executor& exec) {
  exec.for_each(list.size(), [&](std::size_t i) {
    std::sort(list.index.begin() + list.start[i], list.index.begin() + list.start[i + 1]);
  });
}

}  // namespace slamsph
