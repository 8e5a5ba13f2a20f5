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
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/parallel.h"
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
// elastic-only fields of a rigid body) are left alone. Each field is copied into `scratch` and
// gathered back, in one parallel region for sets of at least Executor::kMinParallelCheap
// particles (a plain copy and gather: below that the barriers cost more than the split
// saves); `scratch` keeps its capacity between calls, so a reorder allocates nothing once it
// has grown (bench_kernels BM_FluidReorder, session 22: 320 000 particles on 2 threads 1.4-1.6x
// faster than a fresh copy of each field gathered on one thread; on 1 thread within 3 %). Two
// halves of `scratch` alternate between fields, so that one barrier per field separates its copy
// from its gather: a thread copies field j+1 into the other half while another still gathers field
// j. The values are moved, never computed: the result is that of the serial loop bit for bit, on
// any thread count.
template <class Set, class Index>
void permute_fields(Set& set, const std::vector<Index>& perm, std::vector<std::byte>& scratch,
                    const Executor& exec) {
  const std::size_t n = perm.size();
  std::size_t widest = 0;
  Set::visit_fields(set, [&](const FieldSpec&, auto& f) {
    using T = typename std::decay_t<decltype(f)>::value_type;
    static_assert(std::is_trivially_copyable_v<T>);
    if (f.size() == n) widest = std::max(widest, sizeof(T));
  });
  // Each half starts on a 64-byte boundary (the buffer itself is new[]-aligned to 16 bytes,
  // enough for every element type above).
  const std::size_t half = (n * widest + 63) / 64 * 64;
  if (scratch.size() < 2 * half) scratch.resize(2 * half);
  exec.run_team(exec.threads_for(n, Executor::kMinParallelCheap), [&](const Team& team) {
    const auto [b, e] = team.share(n);
    int field = 0;
    Set::visit_fields(set, [&](const FieldSpec&, auto& f) {
      using T = typename std::decay_t<decltype(f)>::value_type;
      if (f.size() != n) return;
      // A team of one reuses the first half (the footprint of one field, warm in the cache).
      std::byte* copy = scratch.data() + (team.size() > 1 ? (field++ % 2) * half : 0);
      if (e > b) std::memcpy(copy + b * sizeof(T), f.data() + b, (e - b) * sizeof(T));
      team.barrier();
      const T* old = std::launder(reinterpret_cast<const T*>(copy));
      for (std::size_t k = b; k < e; ++k) f[k] = old[perm[k]];
    });
  });
}

// The same on the calling thread, with a scratch buffer of its own (tests, benchmarks).
template <class Set, class Index>
void permute_fields(Set& set, const std::vector<Index>& perm) {
  std::vector<std::byte> scratch;
  permute_fields(set, perm, scratch, Executor(1));
}

}  // namespace slamsph
