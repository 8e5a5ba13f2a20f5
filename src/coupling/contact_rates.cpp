#include "coupling/contact_rates.h"

#include "coupling/contact_pair.h"
#include "coupling/contact_pair_lanes.h"

namespace slamsph {

namespace {

// Vi = m_i / rho_i, the fluid particle's volume (a gather over one fluid particle's
// partners divides once, not once per pair: the same value).
ContactPairInput pair_input(const FluidParticles& f, std::size_t i, double Vi,
                            const ContactParticles& c, std::size_t s, const ContactParams& prm) {
  const Vec2 g_rel = prm.hydrostatic_correction ? prm.gravity - c.a[s] : Vec2{};
  return {f.x[i], f.v[i],        f.rho[i], f.p[i], Vi,          c.x[s],
          c.v[s], c.v_noslip[s], c.rho[s], c.p[s], c.volume[s], g_rel};
}

constexpr std::uint32_t kPairUnitsToFluid = 8;

// The scalar loop over one fluid particle's listed contact partners; the lane loops
// (coupling/contact_pair_lanes.h) are tested against it bit for bit.
template <bool kViscous>
void to_fluid_one(FluidParticles& f, const ContactParticles& c, const NeighbourList& fc,
                  const Kernel& kernel, const ContactParams& prm, bool momentum, bool continuity,
                  ContactPairForces* keep, std::size_t i) {
  const std::uint32_t b = fc.start[i], e = fc.start[i + 1];
  if (b == e) return;
  Vec2 force;
  double drho = 0.0;
  const double Vi = f.m[i] / f.rho[i];
  for (std::uint32_t k = b; k < e; ++k) {
    const std::uint32_t s = fc.index[k];
    if (!c.wetted[s] || !c.faces(s, f.x[i])) continue;
    const ContactPairResult r =
        contact_pair<kViscous>(pair_input(f, i, Vi, c, s, prm), kernel, prm.c0, prm.omega,
                               prm.viscosity, prm.cavitation_pressure, prm.barrier_pressure);
    if (!r.active) continue;
    const Vec2 total = r.force + r.force_viscous;
    force += total;
    drho += r.drho_term;
    if (keep) {
      keep->total[k] = total;
      keep->viscous[k] = r.force_viscous;
      keep->acted[k] = 1;
    }
  }
  if (momentum) f.a[i] += force / f.m[i];
  if (continuity) f.drho[i] += 2.0 * f.rho[i] * drho;
}

template <bool kViscous>
void to_fluid(FluidParticles& f, const ContactParticles& c, const NeighbourList& fc,
              const Kernel& kernel, const ContactParams& prm, const Executor& exec, RatePass pass,
              ContactPairForces* keep, PairLoop loop) {
  const bool momentum = pass != RatePass::Continuity;
  const bool continuity = pass != RatePass::Momentum;
  if (!momentum) keep = nullptr;
  if (keep) {
    keep->total.resize(fc.index.size());
    keep->viscous.resize(fc.index.size());
    keep->acted.assign(fc.index.size(), 0);
  }
  // The lane loops for the Wendland kernel where the CPU has them: the same sums and kept
  // forces, bit for bit (docs/validation.md §6, Throughput, Session 16).
  const bool wendland = kernel.type() == KernelType::WendlandC2;
  const bool eight = wendland && (loop == PairLoop::Auto || loop == PairLoop::EightLanes) &&
                     contact_lanes_avx512_available();
  const bool four = wendland && !eight && (loop == PairLoop::Auto || loop == PairLoop::FourLanes) &&
                    contact_lanes_avx2_available();
  const ContactLaneData d{f.x.data(),
                          f.v.data(),
                          f.rho.data(),
                          f.p.data(),
                          f.m.data(),
                          f.a.data(),
                          f.drho.data(),
                          c.x.data(),
                          c.v.data(),
                          c.v_noslip.data(),
                          c.a.data(),
                          c.rho.data(),
                          c.p.data(),
                          c.volume.data(),
                          c.wetted.data(),
                          c.ghost.data(),
                          c.anchor.data(),
                          c.normal.data(),
                          fc.start.data(),
                          fc.index.data(),
                          keep ? keep->total.data() : nullptr,
                          keep ? keep->viscous.data() : nullptr,
                          keep ? keep->acted.data() : nullptr,
                          kernel.inv_h(),
                          kernel.wendland_dw_over_r_factor(),
                          kernel.support() * kernel.support(),
                          kMorrisEta2 * kernel.h() * kernel.h(),
                          prm.c0,
                          prm.omega,
                          prm.viscosity,
                          prm.cavitation_pressure,
                          prm.barrier_pressure,
                          prm.gravity,
                          prm.hydrostatic_correction,
                          kViscous,
                          momentum,
                          continuity};
  const auto scalar = [&](std::size_t i) {
    to_fluid_one<kViscous>(f, c, fc, kernel, prm, momentum, continuity, keep, i);
  };
  const auto lanes = [&d, eight](std::size_t b, std::size_t e) -> std::size_t {
    return eight ? contact_to_fluid_avx512(d, static_cast<std::uint32_t>(b),
                                           static_cast<std::uint32_t>(e))
                 : contact_to_fluid_avx2(d, static_cast<std::uint32_t>(b),
                                         static_cast<std::uint32_t>(e));
  };
  // Split by pairs: the fluid in contact is a few rows of cells next to the walls, which
  // equal shares of the (cell-ordered) fluid would give to one thread. A listed pair (a
  // Riemann solution, or a skipped dry or back-facing pair) costs about 8 items without pairs
  // (perf of the 3 200-particle dam break on 2 threads: with 1 the first thread took 2.5x the
  // second's time, with 8 within 3-13 % in two runs; docs/validation.md §6, Threads, Session 15).
  exec.for_ranges_weighted(
      f.size(), fc.start.data(),
      [&](std::size_t b, std::size_t e) {
        if (!eight && !four) {
          for (std::size_t i = b; i < e; ++i) scalar(i);
          return;
        }
        // A particle with more listed partners than a lane chunk holds (none in the shipped
        // cases) goes through the scalar loop; the lanes return at it.
        while (b < e) {
          b = lanes(b, e);
          if (b < e) scalar(b++);
        }
      },
      kPairUnitsToFluid);
}

template <bool kViscous>
void reaction(ContactParticles& c, const FluidParticles& f, const NeighbourList& cf,
              const Kernel& kernel, const ContactParams& prm, const Executor& exec,
              const ContactPairForces* kept, const std::vector<std::uint32_t>* cf_in_fc) {
  const bool reuse = kept && cf_in_fc && cf_in_fc->size() == cf.index.size();
  // Split by pairs: the wetted contact particles are one stretch of each body's surface.
  exec.for_each_weighted(c.size(), cf.start.data(), [&](std::size_t s) {
    Vec2 force, visc;
    if (c.wetted[s]) {
      for (std::uint32_t k = cf.start[s]; k < cf.start[s + 1]; ++k) {
        const std::uint32_t i = cf.index[k];
        if (reuse && (*cf_in_fc)[k] < kept->acted.size()) {
          // The pair as add_contact_to_fluid evaluated it (it skipped the same pairs: not
          // wetted, not facing, outside the support).
          const std::uint32_t q = (*cf_in_fc)[k];
          if (!kept->acted[q]) continue;
          force -= kept->total[q];
          visc -= kept->viscous[q];
          continue;
        }
        if (!c.faces(s, f.x[i])) continue;
        const ContactPairResult r = contact_pair<kViscous>(
            pair_input(f, i, f.m[i] / f.rho[i], c, s, prm), kernel, prm.c0, prm.omega,
            prm.viscosity, prm.cavitation_pressure, prm.barrier_pressure);
        if (!r.active) continue;
        force -= r.force + r.force_viscous;
        visc -= r.force_viscous;
      }
    }
    c.force[s] = force;
    c.force_viscous[s] = visc;
  });
}

}  // namespace

void add_contact_to_fluid(FluidParticles& f, const ContactParticles& c, const NeighbourList& fc,
                          const Kernel& kernel, const ContactParams& prm, const Executor& exec,
                          RatePass pass, ContactPairForces* keep, PairLoop loop) {
  if (prm.viscosity > 0.0)
    to_fluid<true>(f, c, fc, kernel, prm, exec, pass, keep, loop);
  else
    to_fluid<false>(f, c, fc, kernel, prm, exec, pass, keep, loop);
}

void compute_contact_reaction(ContactParticles& c, const FluidParticles& f, const NeighbourList& cf,
                              const Kernel& kernel, const ContactParams& prm, const Executor& exec,
                              const ContactPairForces* kept,
                              const std::vector<std::uint32_t>* cf_in_fc) {
  if (prm.viscosity > 0.0)
    reaction<true>(c, f, cf, kernel, prm, exec, kept, cf_in_fc);
  else
    reaction<false>(c, f, cf, kernel, prm, exec, kept, cf_in_fc);
}

}  // namespace slamsph
