#!/usr/bin/env bash
# Mutation check (issue 9): applies each deliberate breakage of the physics to a copy of the
# source, builds it and runs the CI tests that guard the contact and the fluid; every
# breakage must make at least one test fail. Prints a table (and writes OUT/mutations.csv).
# Not part of CI (a few minutes per mutation on 2 cores).
# Tests run per mutation (a documented subset of scripts/test.sh, in this order, stopping at
# the first failure): the test executables in $TESTS below — the slamming report and the
# absorbing zone, the unit tests of the fluid and the contact, the set-up warnings, the golden values, then the verification tests of the
# contact and the slamming (still water next: it is the slowest), and last the four- and
# eight-lane fluid loops against the scalar one (since session 14 the fluid mutations are made
# in each loop: on an AVX2 CPU the four-lane one runs, since session 15 the eight-lane one on an
# AVX-512F CPU, and a change to one loop alone breaks their bit identity; it comes last so that
# a physics test is named first when one catches it; since session 16 the same for the
# contact's fluid-side loop in lanes, test_coupling_contact_lanes), then (session 16) the
# solid law and the fused solid sub-step against the operator sequence, and the threads
# tests (the water's pass beside small bodies' sub-steps), and (session 17) the executor's
# tests (the learnt split of weighted loops), the step limit found in the integrator's last
# sweep and the diverging runs' messages (session 18: also the last sweep inside the pass).
# Session 19: the lists' distance test in lanes (test_core_cell_grid). Session 22: the
# rebuild's reorder through kept storage (test_core_field_registry) and the cost model's
# Eulerian path (test_app_cost_eulerian, predictions only).
# Only these and slamsph are rebuilt per mutation.
# Usage: scripts/mutation_check.sh [OUT=results/mutation_check] [NAME_FILTER=regex]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=${1:-results/mutation_check}
filter=${2:-.}
mkdir -p "$out"
out=$(cd "$out" && pwd)
work=$out/src_copy
TESTS=${TESTS:-"test_io_entry_series test_app_absorbing_zone test_fluid_riemann test_fluid_gsph_limiter test_fluid_momentum test_coupling_contact test_coupling_cavitation test_coupling_geometry test_coupling_golden test_app_setup_warnings test_app_impact_warning test_app_slamming_constant_speed test_app_substep_average test_app_contact_physics test_app_spacing_ratio test_app_cylinder_entry test_app_coupling test_app_still_water test_fluid_pair_band test_solid_material test_solid_substep test_app_threads test_coupling_contact_lanes test_core_parallel test_app_fused_sweeps test_app_divergence test_core_cell_grid test_core_field_registry test_app_cost_eulerian"}
rm -rf "$work"
git clone -q --local --no-hardlinks "$root" "$work"
# The working tree's uncommitted changes are part of what is checked.
(cd "$root" && git diff HEAD) | (cd "$work" && git apply --allow-empty 2>/dev/null || true)
git -C "$work" add -A >/dev/null && git -C "$work" -c user.name=m -c user.email=m commit -qm base --allow-empty
cmake -S "$work" -B "$work/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
# shellcheck disable=SC2086
cmake --build "$work/build" -j2 --target slamsph $TESTS >/dev/null

# name | file | exact text | replacement  (the text must occur: a stale mutation is an error)
python3 - "$work" > "$out/mutations.tsv" <<'PY'
import sys
M = [
 ("suction: p* clamped at 0 again", "src/coupling/contact_pair.h",
  "if (p_star < p_min) {", "if (p_star < 0.0) {"),
 ("cavitation: continuity ignores the limit", "src/coupling/contact_pair.h",
  "u_star = std::min(s.u, L.u + std::max(L.p - p_min, 0.0) / (L.rho * c0));", "(void)u_star;"),
 ("static term switch ignored", "src/fluid/gsph_fluid_rates.cpp",
  "prm.hydrostatic_correction ? prm.gravity : Vec2{}", "prm.gravity"),
 ("sub-step averaged solid state: last sub-step instead", "src/coupling/substep_average.cpp",
  "  if (!avg.valid) return;", "  return;"),
 ("impact-pressure set-up warning removed", "src/app/setup_warnings.cpp",
  "const double p_impact = cfg.fluid.density", "const double p_impact = 0.0 * cfg.fluid.density"),
 ("fluid pressure-diffusion term deleted", "src/fluid/gsph_fluid_rates.cpp",
  "(pi - p[j] - dp_static) * inv_c0", "0.0 * (pi - p[j] - dp_static) * inv_c0"),
 ("fluid limiter: full acoustic dissipation", "src/fluid/gsph_fluid_rates.cpp",
  "const double beta = std::min(omega * std::max(du, 0.0), c0);", "const double beta = c0 + 0.0 * omega * du;"),
 ("contact force sign flipped", "src/coupling/contact_pair.h",
  "out.force = (-2.0 * in.Vi * in.Vs * p_star * dwr) * dx +", "out.force = (2.0 * in.Vi * in.Vs * p_star * dwr) * dx +"),
 ("short-range contact barrier off", "src/coupling/contact_pair.h",
  "  if (p_barrier <= 0.0 || r >= r0) return Vec2{};", "  return Vec2{};"),
 ("ghost layers removed", "src/coupling/ghost_layers.cpp",
  "  if (X.empty()) return out;", "  return out;"),
 ("contact force halved", "src/coupling/contact_pair.h",
  "out.force = (-2.0 * in.Vi * in.Vs * p_star * dwr) * dx +", "out.force = (-1.0 * in.Vi * in.Vs * p_star * dwr) * dx +"),
 ("no Riemann dissipation in the contact", "src/coupling/contact_pair.h",
  "solve_riemann(L, R, c0, omega, dp_static);", "solve_riemann(L, R, c0, 0.0 * omega, dp_static);"),
 ("no (g - a) term in the virtual pressure", "src/coupling/virtual_pressure.cpp",
  "dot(gravity - c.a[s], sum_rrw)", "0.0 * dot(gravity - c.a[s], sum_rrw)"),
 ("contact static term sign flipped", "src/coupling/contact_pair.h",
  "const double dp_static = 0.5 * (in.rhoi + in.rhos) * dot(in.g_rel, dx);",
  "const double dp_static = -0.5 * (in.rhoi + in.rhos) * dot(in.g_rel, dx);"),
 ("fluid j-side continuity doubled", "src/fluid/gsph_fluid_rates.cpp",
  "drho[j] -= Vi * (us - uR) * dwr_r;", "drho[j] -= 2.0 * Vi * (us - uR) * dwr_r;"),
 ("four lanes: pressure-diffusion term deleted", "src/fluid/gsph_pair_band_avx2.cpp",
  "(pi - pj - dp_static) * d.inv_c0", "0.0 * (pi - pj - dp_static) * d.inv_c0"),
 ("four lanes: limiter full acoustic dissipation", "src/fluid/gsph_pair_band_avx2.cpp",
  "_mm256_min_pd(c0, d.omega * _mm256_max_pd(zero, du))", "c0 + 0.0 * du"),
 ("four lanes: j-side continuity doubled", "src/fluid/gsph_pair_band_avx2.cpp",
  "cj = _mm256_and_pd(use, Vi * (us - uR) * dwr_r);", "cj = _mm256_and_pd(use, 2.0 * Vi * (us - uR) * dwr_r);"),
 ("eight lanes: pressure-diffusion term deleted", "src/fluid/gsph_pair_band_avx512.cpp",
  "(pi - pj - dp_static) * d.inv_c0", "0.0 * (pi - pj - dp_static) * d.inv_c0"),
 ("eight lanes: limiter full acoustic dissipation", "src/fluid/gsph_pair_band_avx512.cpp",
  "_mm512_min_pd(splat(d.c0), d.omega * _mm512_max_pd(zero, du))", "splat(d.c0) + 0.0 * du"),
 ("eight lanes: j-side continuity doubled", "src/fluid/gsph_pair_band_avx512.cpp",
  "_mm512_store_pd(c.cj + e, Vi * (us - uR) * dwr_r);", "_mm512_store_pd(c.cj + e, 2.0 * Vi * (us - uR) * dwr_r);"),
 ("eight lanes: coincident partners packed", "src/fluid/gsph_pair_band_avx512.cpp",
  "r2, zero, _CMP_NEQ_UQ);", "r2, zero, _CMP_TRUE_UQ);"),
 ("contact lanes: short-range barrier dropped", "src/coupling/contact_pair_lanes_body.h",
  "    fx = fx + bx;", "    fx = fx + 0.0 * bx;"),
 ("contact lanes: continuity ignores the cavitation limit", "src/coupling/contact_pair_lanes_body.h",
  "u_star = cav ? u_lim : su;", "u_star = cav ? su + 0.0 * u_lim : su;"),
 ("contact eight lanes: dry partners packed", "src/coupling/contact_pair_lanes_body.h",
  "    acts &= wet;", "    (void)wet;"),
 ("contact static-term switch ignored", "src/coupling/contact_rates.cpp",
  "const Vec2 g_rel = prm.hydrostatic_correction ? prm.gravity - c.a[s] : Vec2{};",
  "const Vec2 g_rel = prm.gravity - c.a[s];"),
 ("reported contact pressure not limited at p_cav", "src/app/probes.cpp",
  "std::max(sys.contact.p[s], p_cav)", "std::max(sys.contact.p[s], -1e300 + 0.0 * p_cav)"),
 ("absorbing zone does nothing", "src/fluid/absorbing_zone.cpp",
  "  if (!z.active()) return;", "  return;"),
 ("absorbing zone damps the velocity only", "src/fluid/absorbing_zone.cpp",
  "f.rho[i] = rho_h + decay * (f.rho[i] - rho_h);", "(void)rho_h;"),
 ("entry report: Cs with the contact speed, not V(t)", "src/io/entry_series.cpp",
  "force[k] / (density * vk * vk * radius)", "force[k] / (density * s.speed_at_contact * s.speed_at_contact * radius)"),
 ("entry report: t0 = start of the run", "src/io/entry_series.cpp",
  "    s.t.push_back(tk - s.t0);", "    s.t.push_back(tk - t_body.front());"),
 ("beside: water pass kept across a rebuild", "src/app/fsi_stepper.cpp",
  "    fluid_pass_done = false;", "    (void)fluid_pass_done;"),
 # Session 16: the SVK law inlined in its header and the sub-step's pass-2 tail in two lanes.
 ("SVK: lambda tr E left out of S_yy", "src/solid/materials/st_venant_kirchhoff.h",
  "  S.yy += l;", "  S.yy += 0.0 * l;"),
 ("sub-step: viscous power at the half-step velocity", "src/solid/elastic_substep.cpp",
  "dot2(fav * vi)", "dot2(fav * vhi)"),
 # Session 17: the fixed walls' virtual state beside the sub-steps; the learnt loop splits.
 ("beside: fixed entries' virtual state kept across a rebuild", "src/app/fsi_stepper.cpp",
  "    if (fluid_pass_done && fixed_virtual_beside_) {", "    if (fixed_virtual_beside_) {"),
 ("learnt split: bounds do not move", "src/core/parallel.cpp",
  "bound[k] += std::clamp(0.5 * (even - bound[k])", "bound[k] += std::clamp(0.0 * (even - bound[k])"),
 # Session 17: the two-pass schedule's sums of the powers folded into pass 2, the chain
 # carried from thread to thread.
 ("sub-step: the powers' chain not carried to the next thread", "src/solid/elastic_substep.cpp",
  "rank == 0 ? SubstepPower{0.0, 0.0, 0.0, 0.0} : carry;", "SubstepPower{0.0, 0.0, 0.0, 0.0};"),
 ("sub-step: the last thread's last sums left out", "src/solid/elastic_substep.cpp",
  "for (int r = steps - s; r < t; ++r) {", "for (int r = steps - s; r + 1 < t; ++r) {"),
 # Session 18: the sub-step's pair loops in eight lanes (AVX-512F CPUs; elsewhere the scalar
 # loops run and these two are not caught).
 ("sub-step lanes: the first lane of every block masked out", "src/solid/substep_pair_lanes_avx512.cpp",
  "((1u << hi) - 1u) & ~((1u << lo) - 1u)", "((1u << hi) - 2u) & ~((1u << lo) - 1u)"),
 ("sub-step lanes: the reverse pair's κ ε read at the pair's own slot", "src/solid/substep_pair_lanes_avx512.cpp",
  "_mm512_mask_i32gather_pd(zero, m, rp, d.keps_x, 8)", "_mm512_loadu_pd(d.keps_x + p)"),
 # Session 19: where the lanes apply, Auto takes them before the wavefront at any size
 # (caught on AVX-512F CPUs only, by the barrier count of the two-pass schedule).
 ("sub-step: the wavefront taken before the lanes again", "src/solid/elastic_substep.cpp",
  "kLanes || (lanes_go && schedule != SubstepSchedule::Wavefront)",
  "kLanes || (false && lanes_go && schedule != SubstepSchedule::Wavefront)"),
 # Session 19: the SVK law of pass 1 in the lanes (caught on AVX-512F CPUs only).
 ("sub-step lanes: SVK's lambda tr E left out of S_yy", "src/solid/substep_law_lanes_avx512.cpp",
  "const __m512d Syy = _mm512_add_pd(_mm512_mul_pd(Eyy, two_mu), l);",
  "const __m512d Syy = _mm512_mul_pd(Eyy, two_mu);"),
 # Session 20: for_alternating's bands kept on the core of their sweep share.
 ("band shares: every thread starts at share 0", "src/core/band_shares.h",
  "const int own = rank % shares_;", "const int own = 0 * rank;"),
 ("band shares: a steal takes the front, not the back", "src/core/band_shares.h",
  "if (const std::size_t k = take((own + d) % shares_, false); k != count_) return k;",
  "if (const std::size_t k = take((own + d) % shares_, true); k != count_) return k;"),
 # Session 22: the rebuild's reorder through kept storage on two threads.
 ("reorder: no barrier between a field's copy and its gather", "src/core/field_registry.h",
  "team.barrier();", "(void)team;"),
 ("reorder: one half of the storage for every field", "src/core/field_registry.h",
  "(team.size() > 1 ? (field++ % 2) * half : 0)", "(team.size() > 1 ? (field++ % 1) * half : 0)"),
 # Session 20: the lanes' lagged sweep (caught on AVX-512F CPUs only).
 ("sub-step lagged sweep: pass 2 a chunk before its neighbours' pass 1", "src/solid/elastic_substep.cpp",
  "q - (q - b) % kSubstepLaneChunk + lag + kSubstepLaneChunk);",
  "q - (q - b) % kSubstepLaneChunk + lag + 2 * kSubstepLaneChunk);"),
 # Session 19: the lists' distance test in eight lanes (caught on AVX-512F CPUs only).
 ("lists' lanes: pairs exactly at the radius kept", "src/core/candidate_lanes_avx512.cpp",
  "_mm512_cmp_pd_mask(d2, lim, _CMP_LT_OQ)", "_mm512_cmp_pd_mask(d2, lim, _CMP_LE_OQ)"),
 ("lists' lanes: the candidate's index one too high", "src/core/candidate_lanes_avx512.cpp",
  "_mm512_set_epi32(0, 0, 0, 0, 0, 0, 0, 0, 7, 6, 5, 4, 3, 2, 1, 0)",
  "_mm512_set_epi32(0, 0, 0, 0, 0, 0, 0, 0, 8, 7, 6, 5, 4, 3, 2, 1)"),
 # Session 17: the step limit, the state check and the lists' displacement in the
 # integrator's sweeps (app/fsi_stepper.cpp last_sweep / drift_sweep).
 ("fused sweeps: step limit from v_half, not the new v", "src/app/fsi_stepper.cpp",
  "norm2(w.v[i]), norm2(w.a[i])", "norm2(w.v_half[i]), norm2(w.a[i])"),
 ("fused sweeps: state check dropped from the last sweep", "src/app/fsi_stepper.cpp",
  "bad_fluid(w.x[i], w.v[i], w.rho[i], d) ? 1.0 : 0.0", "0.0 * (bad_fluid(w.x[i], w.v[i], w.rho[i], d) ? 1.0 : 0.0)"),
 ("fused sweeps: the drift's displacement taken as zero", "src/app/fsi_stepper.cpp",
  "return std::array<double, 1>{norm2(x[i] - x0[i])};", "return std::array<double, 1>{0.0 * norm2(x[i] - x0[i])};"),
 # Session 18: the kick-drift-kick step's last sweep in the pass's band tasks, the contact's
 # terms to the water computed before the pass and added there (app/fsi_stepper.cpp step).
 ("kick in the pass: the contact's terms not added to a", "src/app/fsi_stepper.cpp",
  "w.a[i] += ca[i];", "w.a[i] += 0.0 * ca[i];"),
 # Session 22: the cost model's Eulerian path of failed particles (app/cost_model.cpp).
 ("cost model: the Eulerian path's terms left out", "src/app/cost_model.cpp",
  "    if (bc.switched > 0)", "    if (false && bc.switched > 0)"),
 ("cost model: the switch at the start not seen", "src/app/cost_model.cpp",
  "  if (body.eulerian.active) return body.eulerian.members.size();",
  "  return body.eulerian.active ? body.eulerian.members.size() : 0;"),
]
for name, f, a, b in M:
    print("\t".join([name, f, a, b]))
PY

printf "%-55s | %-8s | %s\n" "breakage" "result" "first failing test" | tee "$out/table.txt"
echo "breakage,result,first failing test,seconds" > "$out/mutations.csv"
all_caught=1
while IFS=$'\t' read -r name file text repl; do
  [[ "$name" =~ $filter ]] || continue
  git -C "$work" checkout -q -- .
  t0=$SECONDS
  if ! python3 - "$work/$file" "$text" "$repl" <<'PY'
import sys
p, a, b = sys.argv[1:]
try:
    s = open(p).read()
except FileNotFoundError:
    sys.exit(1)
if a not in s or a == b:
    sys.exit(1)
open(p, "w").write(s.replace(a, b, 1))
PY
  then
    printf "%-55s | %-8s | %s\n" "$name" "STALE" "mutation text not found in $file" | tee -a "$out/table.txt"
    echo "\"$name\",stale,,0" >> "$out/mutations.csv"
    all_caught=0
    continue
  fi
  # shellcheck disable=SC2086
  if ! cmake --build "$work/build" -j2 --target slamsph $TESTS >"$out/build.log" 2>&1; then
    result="caught"; first="(does not build)"
  else
    first=""
    for t in $TESTS; do
      if ! "$work/build/tests/$t" --gtest_brief=1 >"$out/test.log" 2>&1; then
        first="$t: $(grep -m1 -E '^\[  FAILED  \] [A-Za-z]' "$out/test.log" | sed -E 's/^\[  FAILED  \] ([^ ]+).*/\1/')"
        break
      fi
    done
    if [[ -n "$first" ]]; then result="caught"; else result="MISSED"; all_caught=0; fi
  fi
  printf "%-55s | %-8s | %s\n" "$name" "$result" "$first" | tee -a "$out/table.txt"
  echo "\"$name\",$result,$first,$((SECONDS - t0))" >> "$out/mutations.csv"
done < "$out/mutations.tsv"
git -C "$work" checkout -q -- .
[[ $all_caught -eq 1 ]] && echo "every breakage caught" || { echo "some breakage NOT caught"; exit 1; }
