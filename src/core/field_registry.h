// Named per-particle fields (issue 8, item 1). A particle set (FluidParticles,
// ContactParticles, SolidBody) declares each of its fields exactly once, in one
// `visit_fields(self, f)` function that calls f(FieldSpec, std::vector<T>&) per field.
// Everything that must treat all fields alike loops over that declaration: resize,
// permutation (fluid reordering), VTK output and checkpoints. The fields stay plain
// contiguous std::vector members, so the pair loops index them directly, with no
// indirection.
//
// Element types the generic loops understand: double, Vec2 (2 components), Mat2 (4,
// row-major xx, xy, yx, yy), std::int64_t, std::uint32_t, std::uint8_t and int.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/vec.h"

namespace slamsph {

struct FieldSpec {
  std::string_view name;    // unique in its set: VTK array name and checkpoint key
  std::string_view unit;    // SI unit text ("m/s", "-")
  bool persistent = false;  // state a continuation needs: goes into checkpoints
  bool vtk = false;         // written to the VTK output
};

// Number of doubles an element becomes in VTK output.
template <class T>
constexpr int field_components() {
  if constexpr (std::is_same_v<T, Vec2>)
    return 2;
  else if constexpr (std::is_same_v<T, Mat2>)
    return 4;
  else
    return 1;
}

// The element's components appended to `out` (VTK).
template <class T>
void append_components(const T& v, std::vector<double>& out) {
  if constexpr (std::is_same_v<T, Vec2>) {
    out.push_back(v.x);
    out.push_back(v.y);
  } else if constexpr (std::is_same_v<T, Mat2>) {
    out.insert(out.end(), {v.xx, v.xy, v.yx, v.yy});
  } else {
    out.push_back(static_cast<double>(v));
  }
}

template <class T>
std::vector<double> field_as_doubles(const std::vector<T>& f) {
  std::vector<double> out;
  out.reserve(f.size() * field_components<T>());
  for (const T& v : f) append_components(v, out);
  return out;
}

// Resizes every field of `set` to n particles.
template <class Set>
void resize_fields(Set& set, std::size_t n) {
  Set::visit_fields(set, [&](const FieldSpec&, auto& f) { f.resize(n); });
}

// Reorders every field of `set`: new[k] = old[perm[k]]. Fields of another length (empty
// elastic-only fields of a rigid body) are left alone.
template <class Set, class Index>
void permute_fields(Set& set, const std::vector<Index>& perm) {
  Set::visit_fields(set, [&](const FieldSpec&, auto& f) {
    if (f.size() != perm.size()) return;
    auto old = f;
    for (std::size_t k = 0; k < perm.size(); ++k) f[k] = old[perm[k]];
  });
}

}  // namespace slamsph
