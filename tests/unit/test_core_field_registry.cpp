// Named field registry (src/core/field_registry.h): every member of the fluid and contact
// sets is declared once (a member left out of visit_fields fails the size check), names
// are unique, and resize/permute reach every field.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "coupling/contact_particles.h"
#include "fluid/fluid_particles.h"
#include "solid/solid_body.h"

using namespace slamsph;

namespace {

template <class Set>
std::size_t count_fields(Set& s, std::set<std::string>& names) {
  std::size_t n = 0;
  Set::visit_fields(s, [&](const FieldSpec& spec, auto&) {
    ++n;
    EXPECT_TRUE(names.insert(std::string(spec.name)).second) << "duplicate " << spec.name;
    EXPECT_FALSE(spec.unit.empty()) << spec.name;
  });
  return n;
}

}  // namespace

TEST(FieldRegistry, FluidAndContactSetsDeclareEveryMemberOnce) {
  FluidParticles f;
  ContactParticles c;
  std::set<std::string> fn, cn;
  // Both sets hold only std::vector fields: a member missing from visit_fields changes
  // the count.
  EXPECT_EQ(count_fields(f, fn) * sizeof(std::vector<double>), sizeof(FluidParticles));
  EXPECT_EQ(count_fields(c, cn) * sizeof(std::vector<double>), sizeof(ContactParticles));
  SolidBody b;
  std::set<std::string> bn;
  EXPECT_GT(count_fields(b, bn), 10u);
}

TEST(FieldRegistry, ResizeAndPermuteReachEveryField) {
  FluidParticles f;
  f.resize(3);
  FluidParticles::visit_fields(f, [](const FieldSpec& spec, auto& v) {
    EXPECT_EQ(v.size(), 3u) << spec.name;
    using T = typename std::decay_t<decltype(v)>::value_type;
    for (std::size_t i = 0; i < v.size(); ++i) {
      std::vector<double> d;
      append_components(v[i], d);
      // Element i gets value i + 1 in its first component.
      if constexpr (std::is_same_v<T, Vec2>)
        v[i] = Vec2{double(i + 1), 0.0};
      else if constexpr (std::is_same_v<T, Mat2>)
        v[i] = Mat2{double(i + 1), 0.0, 0.0, 0.0};
      else
        v[i] = static_cast<T>(i + 1);
    }
  });
  f.permute(std::vector<std::uint32_t>{2, 0, 1});
  FluidParticles::visit_fields(f, [](const FieldSpec& spec, const auto& v) {
    const std::vector<double> d = field_as_doubles(v);
    const std::size_t k = d.size() / 3;  // components per element
    EXPECT_EQ(d[0], 3.0) << spec.name;
    EXPECT_EQ(d[k], 1.0) << spec.name;
    EXPECT_EQ(d[2 * k], 2.0) << spec.name;
  });
}

// The reorder of the neighbour rebuild (InteractionLists::update): a set above
// Executor::kMinParallelCheap on two threads, through a scratch buffer kept between calls
// and alternating halves (one barrier per field), gives every field exactly the serial
// gather new[k] = old[perm[k]], twice in a row with the same buffer.
TEST(FieldRegistry, ParallelPermuteThroughKeptScratchIsTheGather) {
  const std::size_t n = 3 * Executor::kMinParallelCheap + 7;
  FluidParticles f;
  f.resize(n);
  // Distinct values per field and element (field j, element i: 1000 j + i / n).
  int field = 0;
  FluidParticles::visit_fields(f, [&](const FieldSpec&, auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    ++field;
    for (std::size_t i = 0; i < n; ++i) {
      const double s = 1000.0 * field + double(i) / double(n);
      if constexpr (std::is_same_v<T, Vec2>)
        v[i] = Vec2{s, -s};
      else if constexpr (std::is_same_v<T, double>)
        v[i] = s;
      else
        v[i] = static_cast<T>(i * 7 + static_cast<std::size_t>(field));
    }
  });
  // A permutation that sends every element across the two threads' shares.
  std::vector<std::uint32_t> perm(n);
  for (std::size_t k = 0; k < n; ++k) perm[k] = static_cast<std::uint32_t>((k * 7919) % n);
  ASSERT_EQ(std::set<std::uint32_t>(perm.begin(), perm.end()).size(), n);
  FluidParticles expect = f;
  std::vector<std::byte> scratch;
  const Executor two(2);
  for (int round = 0; round < 2; ++round) {
    FluidParticles::visit_fields(expect, [&](const FieldSpec&, auto& v) {
      auto old = v;
      for (std::size_t k = 0; k < n; ++k) v[k] = old[perm[k]];
    });
    f.permute(perm, scratch, two);
    std::vector<std::vector<double>> got, want;
    FluidParticles::visit_fields(
        f, [&](const FieldSpec&, const auto& v) { got.push_back(field_as_doubles(v)); });
    FluidParticles::visit_fields(
        expect, [&](const FieldSpec&, const auto& v) { want.push_back(field_as_doubles(v)); });
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t j = 0; j < got.size(); ++j)
      EXPECT_TRUE(got[j] == want[j]) << "field " << j << ", round " << round;
  }
}
