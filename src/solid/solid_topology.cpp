#include "solid/solid_topology.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "core/parallel.h"
#include "solid/correction_matrix.h"
#include "solid/fpm_neighbour_selection.h"
#include "solid/fpm_weight.h"
#include "solid/symmetric_pairs.h"

namespace slamsph {
namespace {

void reverse_of_symmetric(const NeighbourList& pairs, std::vector<std::uint32_t>& reverse) {
  reverse.assign(pairs.index.size(), 0);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    for (std::uint32_t k = pairs.start[i]; k < pairs.start[i + 1]; ++k) {
      const std::uint32_t j = pairs.index[k];
      const auto b = pairs.index.begin() + pairs.start[j];
      const auto e = pairs.index.begin() + pairs.start[j + 1];
      reverse[k] = static_cast<std::uint32_t>(std::lower_bound(b, e, i) - pairs.index.begin());
    }
}

// h per particle and w0 per pair (symmetric smoothing length, see the header). Particles
// at the body's spacing use the body's kernel itself, so one-spacing bodies are unchanged.
void pair_lengths(std::span<const Vec2> X, std::span<const double> spacing,
                  const TopologySpec& spec, const Executor& exec, SolidTopology& t) {
  const std::size_t n = X.size();
  const double hb = spec.kernel.h();
  t.h.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    t.h[i] = spacing[i] == spec.dx ? hb : hb * spacing[i] / spec.dx;
  t.w0.resize(t.pairs.index.size());
  exec.for_each(n, [&](std::size_t i) {
    for (std::uint32_t k = t.pairs.start[i]; k < t.pairs.start[i + 1]; ++k) {
      const std::uint32_t j = t.pairs.index[k];
      const double r = norm(X[j] - X[i]);
      const double hij = 0.5 * (t.h[i] + t.h[j]);
      t.w0[k] = hij == hb ? spec.kernel.w(r) : Kernel(spec.kernel.type(), hij).w(r);
    }
  });
}

// The operators of one group of particles that may all pair with each other (indices
// local to X).
SolidTopology build_group(std::span<const Vec2> X, std::span<const double> V0,
                          std::span<const double> spacing, const TopologySpec& spec,
                          const Executor& exec) {
  SolidTopology t;
  const std::size_t n = X.size();
  std::vector<std::uint8_t> use;
  std::vector<Vec2> raw;
  if (spec.scheme == SolidScheme::TlSfpm) {
    select_fpm_sets(X, spacing, exec, t.fpm_sets);
    symmetric_union(t.fpm_sets, t.pairs, t.pair_reverse, use);
    raw.resize(t.pairs.index.size());
    exec.for_each(n, [&](std::size_t i) {
      for (std::uint32_t k = t.pairs.start[i]; k < t.pairs.start[i + 1]; ++k)
        raw[k] = fpm_reference_gradient(X[i], X[t.pairs.index[k]], spacing[i]);
    });
  } else {
    CellGrid grid;
    grid.build(X, spec.kernel.support());
    build_neighbour_list(X, X, grid, spec.kernel.support(), true, exec, t.pairs);
    sort_each_list(t.pairs, exec);  // reverse_of_symmetric searches sorted lists
    reverse_of_symmetric(t.pairs, t.pair_reverse);
    use.assign(t.pairs.index.size(), 1);
    raw.resize(t.pairs.index.size());
    exec.for_each(n, [&](std::size_t i) {
      for (std::uint32_t k = t.pairs.start[i]; k < t.pairs.start[i + 1]; ++k) {
        const Vec2 rij = X[i] - X[t.pairs.index[k]];
        raw[k] = spec.kernel.dw_over_r(norm(rij)) * rij;
      }
    });
  }
  compute_correction_matrices(X, V0, t.pairs, raw, use, exec, t.B);
  t.grad0.assign(t.pairs.index.size(), Vec2{});
  exec.for_each(n, [&](std::size_t i) {
    for (std::uint32_t k = t.pairs.start[i]; k < t.pairs.start[i + 1]; ++k)
      if (use[k]) t.grad0[k] = V0[t.pairs.index[k]] * (t.B[i] * raw[k]);
  });
  pair_lengths(X, spacing, spec, exec, t);
  return t;
}

// Appends list `l` of every particle (global index `global[li]` for local li) into `out`
// in global particle order; `owner[i]` / `local[i]` locate global particle i's group list.
void merge_lists(const std::vector<const NeighbourList*>& lists,
                 const std::vector<std::vector<std::uint32_t>>& global,
                 const std::vector<int>& owner, const std::vector<std::uint32_t>& local,
                 NeighbourList& out) {
  const std::size_t n = owner.size();
  out.start.assign(n + 1, 0);
  out.index.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (owner[i] >= 0) {
      const NeighbourList& l = *lists[owner[i]];
      const std::vector<std::uint32_t>& g = global[owner[i]];
      for (std::uint32_t k = l.start[local[i]]; k < l.start[local[i] + 1]; ++k)
        out.index.push_back(g[l.index[k]]);
    }
    out.start[i + 1] = static_cast<std::uint32_t>(out.index.size());
  }
}

}  // namespace

SolidTopology build_solid_topology(std::span<const Vec2> X, std::span<const double> V0,
                                   const TopologySpec& spec, const Executor& exec,
                                   std::span<const std::uint32_t> active) {
  const std::size_t n = X.size();
  if (!spec.part.empty() && spec.part.size() != n)
    throw std::invalid_argument("build_solid_topology: one part id per particle expected");
  auto part_of = [&](std::size_t i) { return spec.part.empty() ? 0u : spec.part[i]; };
  if (!spec.spacing.empty() && spec.spacing.size() != n)
    throw std::invalid_argument("build_solid_topology: one spacing per particle expected");
  const std::vector<double> spacing =
      spec.spacing.empty() ? std::vector<double>(n, spec.dx) : spec.spacing;
  if (spec.scheme == SolidScheme::TlSph)
    for (double d : spacing)
      if (d != spec.dx)
        throw std::invalid_argument(
            "build_solid_topology: the tlsph scheme needs one spacing per body (parts of "
            "different spacing need scheme = 'tl_sfpm')");

  // Groups of particles that may pair: the active particles, split by part unless bonded.
  std::map<std::uint32_t, std::vector<std::uint32_t>> groups;  // ordered: deterministic
  for (std::size_t a = 0; a < (active.empty() ? n : active.size()); ++a) {
    const std::uint32_t i = active.empty() ? static_cast<std::uint32_t>(a) : active[a];
    if (i >= n) throw std::invalid_argument("build_solid_topology: active index out of range");
    groups[spec.bond_parts ? 0u : part_of(i)].push_back(i);
  }

  if (groups.size() == 1 && groups.begin()->second.size() == n) {
    // Every particle in one group: no index mapping (the common case of one-part bodies).
    SolidTopology t = build_group(X, V0, spacing, spec, exec);
    t.part.resize(n);
    for (std::size_t i = 0; i < n; ++i) t.part[i] = part_of(i);
    for (const Vec2& g : t.grad0) t.max_gradient = std::max(t.max_gradient, norm(g));
    return t;
  }

  std::vector<SolidTopology> built;
  std::vector<std::vector<std::uint32_t>> global;
  std::vector<int> owner(n, -1);
  std::vector<std::uint32_t> local(n, 0);
  for (auto& [id, members] : groups) {
    std::sort(members.begin(), members.end());  // the local order follows the global one
    members.erase(std::unique(members.begin(), members.end()), members.end());
    std::vector<Vec2> Xg;
    std::vector<double> Vg, Dg;
    for (std::size_t li = 0; li < members.size(); ++li) {
      owner[members[li]] = static_cast<int>(built.size());
      local[members[li]] = static_cast<std::uint32_t>(li);
      Xg.push_back(X[members[li]]);
      Vg.push_back(V0[members[li]]);
      Dg.push_back(spacing[members[li]]);
    }
    built.push_back(build_group(Xg, Vg, Dg, spec, exec));
    global.push_back(members);
  }

  SolidTopology t;
  std::vector<const NeighbourList*> pair_lists, set_lists;
  for (const SolidTopology& g : built) {
    pair_lists.push_back(&g.pairs);
    set_lists.push_back(&g.fpm_sets);
  }
  merge_lists(pair_lists, global, owner, local, t.pairs);
  if (spec.scheme == SolidScheme::TlSfpm) merge_lists(set_lists, global, owner, local, t.fpm_sets);
  t.pair_reverse.assign(t.pairs.index.size(), 0);
  t.grad0.assign(t.pairs.index.size(), Vec2{});
  t.w0.assign(t.pairs.index.size(), 0.0);
  t.B.assign(n, Mat2{});
  t.part.resize(n);
  t.h.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    t.part[i] = part_of(i);
    t.h[i] = spacing[i] == spec.dx ? spec.kernel.h() : spec.kernel.h() * spacing[i] / spec.dx;
    if (owner[i] < 0) continue;
    const SolidTopology& g = built[owner[i]];
    const std::uint32_t li = local[i];
    t.B[i] = g.B[li];
    for (std::uint32_t lk = g.pairs.start[li], k = t.pairs.start[i]; lk < g.pairs.start[li + 1];
         ++lk, ++k) {
      t.grad0[k] = g.grad0[lk];
      t.w0[k] = g.w0[lk];
      // (j, i) sits at the same offset within j's list in the group and in the merge.
      const std::uint32_t lr = g.pair_reverse[lk];
      const std::uint32_t lj = g.pairs.index[lk];
      t.pair_reverse[k] = t.pairs.start[global[owner[i]][lj]] + (lr - g.pairs.start[lj]);
    }
  }
  for (const Vec2& g : t.grad0) t.max_gradient = std::max(t.max_gradient, norm(g));
  return t;
}

}  // namespace slamsph
