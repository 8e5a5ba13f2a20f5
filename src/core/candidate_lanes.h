// The neighbour lists' distance test in eight AVX-512F lanes (core/cell_grid.cpp,
// build_banded_pairs in cell order): of the points pts[b..e) — a run of candidates, which in
// cell order are consecutive indices — those within sqrt(r2) of q, written to dst in index
// order, as the scalar test `norm2(q - pts[j]) < r2` one candidate at a time writes them. Each
// lane computes (q.x - x)², (q.y - y)² and their sum as the scalar code does, with no fused
// multiply-add (-ffp-contract=off): the same comparisons, so the same lists
// (CellGrid.BandedPairsLanesEqualTheScalarTest, tests/unit/test_core_cell_grid.cpp). The test
// was 12 % of the 3 200-particle peer dam break on one thread (perf, docs/validation.md §6,
// session 19). core/candidate_lanes_avx512.cpp is the only file built with -mavx512f for it;
// chosen at run time.
#pragma once
#include <cstdint>

#include "core/vec.h"

namespace slamsph {

bool candidate_lanes_avx512_available();

// The points j in [b, e) with (q.x - pts[j].x)² + (q.y - pts[j].y)² < r2, appended at dst in
// ascending j; returns the end of what it wrote. dst may hold only as many entries as it
// writes plus what stays of [b, e) after each group of eight (it never writes past
// dst + (e - b)). Where the CPU lacks AVX-512F it writes nothing and returns dst: the caller
// must then test the candidates itself (candidate_lanes_avx512_available()).
std::uint32_t* candidates_within_avx512(const Vec2* pts, std::uint32_t b, std::uint32_t e, Vec2 q,
                                        double r2, std::uint32_t* dst);

}  // namespace slamsph
