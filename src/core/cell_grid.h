// Cell-linked list (spec §1): points binned into square cells no smaller than the search
// radius, so a search visits the 3x3 block of cells around a query. Binning is a serial
// counting sort, hence deterministic; queries are read-only and thread-safe.
#pragma once
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.h"

namespace slamsph {

class CellGrid {
 public:
  // Bins `pts` into cells of size `cell` covering their bounding box.
  void build(std::span<const Vec2> pts, double cell);

  // Calls f(b, e) for each run [b, e) of cell_order() that holds candidates of p: one run
  // per row of the 3x3 block (the cells of a row are contiguous in cell_order()).
  template <class F>
  void for_each_candidate_run(Vec2 p, F&& f) const {
    if (sorted_.empty()) return;
    // A point more than one cell outside the grid has no candidates.
    const double fx = (p.x - lo_.x) * inv_cell_, fy = (p.y - lo_.y) * inv_cell_;
    if (!(fx >= -1.0 && fx < nx_ + 1.0 && fy >= -1.0 && fy < ny_ + 1.0)) return;
    const int cx = cell_x(p.x), cy = cell_y(p.y);
    for (int jy = cy - 1; jy <= cy + 1; ++jy) {
      if (jy < 0 || jy >= ny_) continue;
      const int x0 = cx > 0 ? cx - 1 : 0;
      const int x1 = cx + 1 < nx_ ? cx + 1 : nx_ - 1;
      if (x0 > x1) continue;
      f(start_[static_cast<std::size_t>(jy) * nx_ + x0],
        start_[static_cast<std::size_t>(jy) * nx_ + x1 + 1]);
    }
  }
  // Calls f(j) for every binned point j in the 3x3 cells around p (a superset of the
  // points within `cell` of p). Points just outside the grid use the border cells.
  template <class F>
  void for_each_candidate(Vec2 p, F&& f) const {
    for_each_candidate_run(p, [&](std::uint32_t b, std::uint32_t e) {
      for (std::uint32_t k = b; k < e; ++k) f(sorted_[k]);
    });
  }

  // For point i of the binned set itself, when the set is in cell order (cell_order() is the
  // identity): calls f(j) for every candidate of for_each_candidate(p_i) with j > i, in the
  // same order. In cell order the row below holds only smaller indices and the own row only
  // [i + 1, end of the cell to the right) of them, so about half the cells are visited.
  // The _run form calls f(b, e) for the two runs of cell_order() that hold them.
  template <class F>
  void for_each_later_candidate_run(std::uint32_t i, Vec2 p, F&& f) const {
    const int cx = cell_x(p.x), cy = cell_y(p.y);
    const int x0 = cx > 0 ? cx - 1 : 0;
    const int x1 = cx + 1 < nx_ ? cx + 1 : nx_ - 1;
    const std::size_t row = static_cast<std::size_t>(cy) * nx_;
    f(i + 1, std::max(i + 1, start_[row + x1 + 1]));
    if (cy + 1 >= ny_) return;
    const std::size_t up = row + nx_;
    f(start_[up + x0], start_[up + x1 + 1]);
  }
  template <class F>
  void for_each_later_candidate(std::uint32_t i, Vec2 p, F&& f) const {
    for_each_later_candidate_run(i, p, [&](std::uint32_t b, std::uint32_t e) {
      for (std::uint32_t k = b; k < e; ++k) f(sorted_[k]);
    });
  }

  // After the binned points were permuted by cell_order() (point k is now the k-th in cell
  // order, at the same position): the grid of the permuted points, as build() would bin them
  // (same bounds and cells; the counting sort is stable, so each cell lists its points in
  // ascending order, here consecutive), without binning them again.
  void renumber_in_cell_order();

  // Point indices in cell order (row-major by y, then x): a locality-friendly ordering.
  const std::vector<std::uint32_t>& cell_order() const { return sorted_; }
  // Offsets into cell_order() where each row of cells (constant y index) begins; ny + 1
  // entries. Rows come in ascending y, cells within a row in ascending x.
  std::vector<std::uint32_t> row_offsets() const;
  double cell_size() const { return cell_; }

 private:
  int cell_x(double x) const {
    const int c = static_cast<int>((x - lo_.x) * inv_cell_);
    return c < 0 ? 0 : (c >= nx_ ? nx_ - 1 : c);
  }
  int cell_y(double y) const {
    const int c = static_cast<int>((y - lo_.y) * inv_cell_);
    return c < 0 ? 0 : (c >= ny_ ? ny_ - 1 : c);
  }

  Vec2 lo_;
  double cell_ = 1.0, inv_cell_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> start_;   // nx*ny + 1 offsets into sorted_
  std::vector<std::uint32_t> sorted_;  // point indices grouped by cell
};

// Compressed neighbour lists: neighbours of query i are index[start[i] .. start[i+1]).
struct NeighbourList {
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> index;
  // Workspace of the builders (cell_grid.cpp csr_lists), kept to reuse its memory: each
  // query's candidates, then the offsets of its part of it. Not part of the list.
  std::vector<std::uint32_t> scratch, scratch_start;
  std::size_t size() const { return start.empty() ? 0 : start.size() - 1; }
  std::size_t count(std::size_t i) const { return start[i + 1] - start[i]; }
};

class Executor;

// For every query point, the grid points strictly closer than `radius` (radius <= cell
// size). With `skip_self`, query i does not list point i (queries and points the same
// set). Neighbours appear in cell order (the serial binning's order), so the list is
// independent of the thread count.
void build_neighbour_list(std::span<const Vec2> queries, std::span<const Vec2> pts,
                          const CellGrid& grid, double radius, bool skip_self, const Executor& exec,
                          NeighbourList& out);

// Sorts every list ascending (for algorithms that search the lists, e.g. pair reversal).
void sort_each_list(NeighbourList& list, const Executor& exec);

// Each pair once, for symmetric pair loops: half[i] holds the neighbours j > i within
// `radius`. Particles are cut into bands of consecutive indices (band_start, one more entry
// than bands) such that for every pair the partner j lies in the band of i or the next one,
// which lets Executor::for_alternating run the bands in parallel without write conflicts.
// When the points are in the grid's cell order (cell_order() is the identity, as after
// permuting by it) each band is one row of cells, because a neighbour within one cell size
// is at most one row up; otherwise there is a single band.
struct BandedPairs {
  NeighbourList half;
  std::vector<std::uint32_t> band_start;
  std::size_t bands() const { return band_start.empty() ? 0 : band_start.size() - 1; }
};

// radius <= grid.cell_size() is required for more than one band.
void build_banded_pairs(std::span<const Vec2> pts, const CellGrid& grid, double radius,
                        const Executor& exec, BandedPairs& out);

}  // namespace slamsph
