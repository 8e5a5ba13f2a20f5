#include "solid/stress_update.h"

#include <array>

#include "core/parallel.h"

namespace slamsph {
namespace {

template <class Law>
void update_with(const Law& law, SolidBody& body, std::span<const Mat2> F_old, double dt,
                 const Executor& exec) {
  exec.for_each(body.size(), [&](std::size_t i) {
    body.P[i] = commit_stress_at(law, body.history, F_old[i], body.F[i], dt, i);
  });
}

// The committed history of particle i, gathered (laws read at most a few fields).
template <std::size_t N>
std::array<double, N> history_of(const SolidBody& body, std::size_t i) {
  std::array<double, N> h{};
  for (std::size_t k = 0; k < N; ++k) h[k] = body.history.values[k][i];
  return h;
}

}  // namespace

void update_stress(SolidBody& body, std::span<const Mat2> F_old, double dt, const Executor& exec) {
  body.P.resize(body.size());
  std::visit([&](const auto& law) { update_with(law, body, F_old, dt, exec); }, body.material.law);
  ++body.history.updates;
}

double strain_energy_density(const SolidBody& body, std::size_t i) {
  return std::visit(
      [&](const auto& law) {
        const auto h = history_of<std::decay_t<decltype(law)>::kHistory.size()>(body, i);
        return law.energy_density(body.F[i], h);
      },
      body.material.law);
}

double cauchy_zz(const SolidBody& body, std::size_t i) {
  return std::visit(
      [&](const auto& law) {
        const auto h = history_of<std::decay_t<decltype(law)>::kHistory.size()>(body, i);
        return law.cauchy_zz(body.F[i], h);
      },
      body.material.law);
}

}  // namespace slamsph
