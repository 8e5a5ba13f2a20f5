#include "solid/eulerian_failed_interaction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/parallel.h"
#include "solid/artificial_viscosity.h"
#include "solid/deformation_gradient.h"
#include "solid/hourglass_control.h"

namespace slamsph {
namespace {

// A topology in which no particle has pairs (every particle switched).
SolidTopology empty_topology(const SolidBody& body) {
  SolidTopology t;
  const std::size_t n = body.size();
  t.pairs.start.assign(n + 1, 0);
  t.fpm_sets.start.assign(n + 1, 0);
  t.B.assign(n, Mat2{});
  t.part = body.part.empty() ? std::vector<std::uint32_t>(n, 0) : body.part;
  t.h = body.topology.h;
  return t;
}

Kernel pair_kernel(const SolidBody& body, std::size_t i, std::size_t j) {
  const double h = 0.5 * (body.topology.h[i] + body.topology.h[j]);
  return h == body.kernel.h() ? body.kernel : Kernel(body.kernel.type(), h);
}

}  // namespace

const std::vector<double>* failed_flags(const SolidBody& body) {
  for (std::size_t k = 0; k < body.history.fields.size(); ++k)
    if (body.history.fields[k].name == "failed") return &body.history.values[k];
  return nullptr;
}

bool update_eulerian_switch(SolidBody& body, const Executor& exec) {
  EulerianState& e = body.eulerian;
  if (!body.eulerian_switch) return false;
  const std::vector<double>* flags = failed_flags(body);
  if (flags == nullptr) return false;
  const std::vector<double>& failed = *flags;
  const std::size_t n = body.size();
  std::size_t count = 0;
  for (double f : failed) count += f > 0.5 ? 1 : 0;
  if (count == e.failed_count) return e.active;  // `failed` is sticky: same count, same set
  if (!e.active) e.reference_pairs = body.topology.pairs;  // still the full reference build
  e.failed_count = count;
  // The hourglass springs' potential is a function of the topology: the rebuild removes the
  // springs of the switched particles and re-measures the remaining ones against the new,
  // one-sided F_kin. No force does that work, so the energy balance books the jump as
  // released by the switch (SolidBody::switch_released; docs/model.md §3).
  // A resumed run's rebuild at restore (F_rebase_failed already == count) books nothing: the
  // checkpointed switch_released has it.
  const double alpha = body.F_rebase_failed != count ? body.material.hourglass : 0.0;
  const double hg_before = alpha != 0.0 ? hourglass_energy(body, body.topology, alpha, exec) : 0.0;
  const NeighbourList& ref = e.reference_pairs;

  e.switched.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!(failed[i] > 0.5)) continue;
    e.switched[i] = 1;
    for (std::uint32_t k = ref.start[i]; k < ref.start[i + 1]; ++k) e.switched[ref.index[k]] = 1;
  }
  const TopologySpec spec{body.scheme, body.dx, body.kernel, body.part, true, body.spacing};
  for (;;) {
    std::vector<std::uint32_t> intact;
    for (std::size_t i = 0; i < n; ++i)
      if (!e.switched[i]) intact.push_back(static_cast<std::uint32_t>(i));
    if (intact.empty()) {
      body.topology = empty_topology(body);
      break;
    }
    try {
      body.topology = build_solid_topology(body.X, body.V0, spec, exec, intact);
      break;
    } catch (const std::invalid_argument&) {
      // Some intact particle next to the switched ones has no usable gradient set: switch
      // the intact particles that touch the switched set (reference pairs) and retry.
      std::vector<std::uint8_t> grow = e.switched;
      for (std::size_t i = 0; i < n; ++i) {
        if (!e.switched[i]) continue;
        for (std::uint32_t k = ref.start[i]; k < ref.start[i + 1]; ++k) grow[ref.index[k]] = 1;
      }
      e.switched = std::move(grow);
    }
  }
  // Continuity of F across the rebuild. The intact particles next to the switched set have
  // lost reference neighbours, and their kinematic F_kin from the remaining (one-sided) set
  // differs from the F they carry: by 0.02–0.14, once 2.1, in cases/johnson_cook_bar.toml,
  // against elastic strains of ~0.005. Taken as a strain increment, that jump is stress and
  // energy that no force did work for. F = F_kin C with C = F_kin⁻¹ F at the rebuild keeps
  // F where it is and moves it by the kinematic deformation since the rebuild (exact for an
  // affine motion, objective under rotation: x → Rx gives F → RF). A particle whose
  // one-sided F_kin is singular keeps C (its F jumps). A resumed run rebuilds the topology
  // but keeps the checkpointed C (F_rebase_failed).
  if (body.F_rebase_failed != count) {
    for (std::size_t i = 0; i < n; ++i) {
      if (e.switched[i]) {
        body.F_rebase[i] = Mat2::identity();
        continue;
      }
      const Mat2 Fk = reference_gradient(body.topology, body.x, i);
      if (det(Fk) > 1e-6) body.F_rebase[i] = inverse(Fk) * body.F[i];
    }
    body.F_rebase_failed = count;
  }
  e.members.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (e.switched[i]) e.members.push_back(static_cast<std::uint32_t>(i));
  e.active = !e.members.empty();
  if (alpha != 0.0)
    body.switch_released += hg_before - hourglass_energy(body, body.topology, alpha, exec);
  return e.active;
}

void build_eulerian_pairs(SolidBody& body, std::span<const Vec2> x) {
  EulerianState& e = body.eulerian;
  const std::size_t n = body.size();
  double hmax = 0.0;
  for (double h : body.topology.h) hmax = std::max(hmax, h);
  const double radius = 2.0 * hmax;
  e.member_x.resize(e.members.size());
  for (std::size_t k = 0; k < e.members.size(); ++k) e.member_x[k] = x[e.members[k]];
  e.grid.build(e.member_x, radius);
  const Executor serial(1);
  // Every particle's switched neighbours (indices into members), in the grid's cell order.
  build_neighbour_list(x, e.member_x, e.grid, radius, false, serial, e.to_members);
  // Counts: i lists its switched neighbours; a switched s also lists its intact neighbours.
  NeighbourList& p = e.pairs;
  p.start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = e.to_members.start[i]; k < e.to_members.start[i + 1]; ++k) {
      const std::uint32_t s = e.members[e.to_members.index[k]];
      if (s == i) continue;
      ++p.start[i + 1];
      if (!e.switched[i]) ++p.start[s + 1];
    }
  for (std::size_t i = 0; i < n; ++i) p.start[i + 1] += p.start[i];
  p.index.resize(p.start[n]);
  std::vector<std::uint32_t> fill(p.start.begin(), p.start.end() - 1);
  // First every particle's own switched neighbours, then (intact i ascending) the intact
  // neighbours of the switched ones: a fixed order, so the sums do not depend on threads.
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = e.to_members.start[i]; k < e.to_members.start[i + 1]; ++k) {
      const std::uint32_t s = e.members[e.to_members.index[k]];
      if (s != i) p.index[fill[i]++] = s;
    }
  for (std::size_t i = 0; i < n; ++i) {
    if (e.switched[i]) continue;
    for (std::uint32_t k = e.to_members.start[i]; k < e.to_members.start[i + 1]; ++k) {
      const std::uint32_t s = e.members[e.to_members.index[k]];
      p.index[fill[s]++] = static_cast<std::uint32_t>(i);
    }
  }
}

namespace {

// L_i = Σ_j (v_j − v_i) ⊗ g_ij with g_ij = K_i grad_ij, grad_ij = V0_j ∇_iW_ij, and the
// correction K_i = M_i⁻ᵀ, M_i = Σ_j (x_j − x_i) ⊗ grad_ij (so that Σ_j (x_j − x_i) ⊗ g_ij = 1:
// L exact for a linear velocity field); K = 1 where det M <= 0.1 (an almost isolated particle).
void velocity_gradient(const SolidBody& body, std::span<const Vec2> x, std::span<const Vec2> v,
                       std::size_t i, Mat2& L, Mat2& K) {
  const NeighbourList& p = body.eulerian.pairs;
  Mat2 G, M;
  const Vec2 xi = x[i], vi = v[i];
  for (std::uint32_t k = p.start[i]; k < p.start[i + 1]; ++k) {
    const std::uint32_t j = p.index[k];
    const Vec2 xij = xi - x[j];
    const double r = norm(xij);
    if (r == 0.0) continue;
    const Vec2 grad = (body.V0[j] * pair_kernel(body, i, j).dw_over_r(r)) * xij;
    G += outer(v[j] - vi, grad);
    M += outer(x[j] - xi, grad);
  }
  const bool corrected = det(M) > 0.1;
  const Mat2 Minv = corrected ? inverse(M) : Mat2::identity();
  L = G * Minv;
  K = transpose(Minv);
}

}  // namespace

void eulerian_motion(const SolidBody& body, std::span<const Vec2> x, std::span<const Vec2> v,
                     double h, std::size_t i, Mat2& F_new, Mat2& Fdot, Mat2& K) {
  Mat2 L;
  velocity_gradient(body, x, v, i, L, K);
  const Mat2 I = Mat2::identity();
  const Mat2& F_old = body.F[i];
  F_new = inverse(I - (0.5 * h) * L) * ((I + (0.5 * h) * L) * F_old);
  Fdot = L * (0.5 * (F_old + F_new));
}

Mat2 eulerian_stress_map(const SolidBody& body, std::size_t i, const Mat2& K) {
  // Kirchhoff stress τ = P Fᵀ (= J σ), symmetrised: the law's P Fᵀ is symmetric up to
  // round-off, and the exact symmetry is what makes the torque of i's forces vanish.
  const Mat2 t = body.P[i] * transpose(body.F[i]);
  const Mat2 tau = 0.5 * (t + transpose(t));
  return body.V0[i] * (tau * K);
}

void eulerian_force_on(const SolidBody& body, std::span<const Vec2> x, std::span<const Vec2> v,
                       std::span<const Mat2> A, std::size_t i, Vec2& fs, Vec2& fv, double& heat) {
  const NeighbourList& p = body.eulerian.pairs;
  fs = Vec2{};
  fv = Vec2{};
  if (p.start[i] == p.start[i + 1]) return;
  const SolidMaterial& mat = body.material;
  const bool viscous = !(mat.av_alpha == 0.0 && mat.av_beta == 0.0);
  const double rho_i = body.rho0[i] / det(body.F[i]);
  const Mat2& Ai = A[i];
  const double V0i = body.V0[i];
  for (std::uint32_t k = p.start[i]; k < p.start[i + 1]; ++k) {
    const std::uint32_t j = p.index[k];
    const Vec2 xij = x[i] - x[j];
    const double r = norm(xij);
    if (r == 0.0) continue;
    const Kernel W = pair_kernel(body, i, j);
    const double dwr = W.dw_over_r(r);
    if (dwr == 0.0) continue;
    // i's stress through i's gradient, j's through j's (header): the sum of the two maps is
    // commutative, so the pair force on j is the exact negative of this one.
    fs += (dwr * (body.V0[j] * Ai + V0i * A[j])) * xij;
    if (viscous) {
      const Vec2 vij = v[i] - v[j];
      const double rho_mean = 0.5 * (rho_i + body.rho0[j] / det(body.F[j]));
      const double pi =
          monaghan_pi(vij, xij, W.h(), 1.0 / rho_mean, mat.sound_speed, mat.av_alpha, mat.av_beta);
      if (pi == 0.0) continue;
      const Vec2 f = (-body.m[i] * body.m[j] * pi * dwr) * xij;
      fv += f;
      heat += -0.5 * dot(f, vij);
    }
  }
}

void add_eulerian_forces(SolidBody& body, std::span<const Vec2> v, const Executor& exec,
                         std::span<Vec2> f_stress, std::span<Vec2> f_av, std::span<double> heat) {
  if (!body.eulerian.active) return;
  build_eulerian_pairs(body, body.x);
  std::vector<Mat2>& A = body.eulerian.stress_map;
  A.assign(body.size(), Mat2{});
  const SolidBody& b = body;
  exec.for_each(b.eulerian.members.size(), [&](std::size_t k) {
    const std::size_t i = b.eulerian.members[k];
    Mat2 L, K;
    velocity_gradient(b, b.x, v, i, L, K);
    A[i] = eulerian_stress_map(b, i, K);
  });
  exec.for_each(body.size(), [&](std::size_t i) {
    Vec2 fs, fv;
    double q = 0.0;
    eulerian_force_on(b, b.x, v, A, i, fs, fv, q);
    f_stress[i] += fs;
    f_av[i] += fv;
    heat[i] += q;
  });
}

}  // namespace slamsph
