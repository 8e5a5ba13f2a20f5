#!/usr/bin/env bash
# Mutation check of the structural verification (issue 10 item 6, issue 9's suction test):
# applies each deliberate breakage to a copy of the source, rebuilds the three structural
# verification tests and runs every one of them (not only up to the first failure), so the
# table shows which test catches which breakage. Every breakage must fail at least one.
# Not part of CI (a few minutes per breakage on 2 cores).
# Usage: scripts/mutation_check_structures.sh [OUT=results/mutation_structures]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=${1:-results/mutation_structures}
mkdir -p "$out"
out=$(cd "$out" && pwd)
work=$out/src_copy
TESTS="test_app_ring_modes test_app_static_structures test_app_wet_ring"
rm -rf "$work"
git clone -q --local --no-hardlinks "$root" "$work"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$work" -B "$work/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
# shellcheck disable=SC2086
cmake --build "$work/build" -j2 --target $TESTS >/dev/null
# name | file | exact text | replacement (the text must occur: a stale mutation is an error)
M=(
  "none (unbroken)|README.md|slamsph|slamsph"
  "material 10 % too stiff (P x 1.1)|src/solid/materials/st_venant_kirchhoff.h|return svk_pk1(p_, F_new);|return 1.1 * svk_pk1(p_, F_new);"
  "hourglass force not applied|src/solid/body_dynamics.cpp|s.f_stress[i] + body.f_av[i] + body.f_hg[i]|s.f_stress[i] + body.f_av[i]"
  "suction: contact p* clamped at 0|src/coupling/contact_pair.h|if (p_star < p_min) {|if (p_star < 0.0) {"
)
echo "breakage | $(echo $TESTS | sed 's/ / | /g')" | tee "$out/table.txt"
all=1
for m in "${M[@]}"; do
  IFS='|' read -r name file text repl <<<"$m"
  git -C "$work" checkout -q -- .
  python3 - "$work/$file" "$text" "$repl" <<'PY' || { echo "$name | STALE" | tee -a "$out/table.txt"; all=0; continue; }
import sys
p, a, b = sys.argv[1:]
s = open(p).read()
if a not in s:
    sys.exit(1)
open(p, "w").write(s.replace(a, b, 1))
PY
  # shellcheck disable=SC2086
  cmake --build "$work/build" -j2 --target $TESTS >"$out/build.log" 2>&1
  row="$name"
  failed=0
  for t in $TESTS; do
    log="$out/$(echo "$name" | tr -c 'a-zA-Z0-9' '_')_$t.log"
    if "$work/build/tests/$t" >"$log" 2>&1; then
      row+=" | pass"
    else
      row+=" | FAIL ($(grep -E '^\[  FAILED  \] [A-Za-z]' "$log" | sed -E 's/^\[  FAILED  \] ([^ ]+).*/\1/' | sort -u | paste -sd' '))"
      failed=1
    fi
  done
  echo "$row" | tee -a "$out/table.txt"
  if [ "$name" != "none (unbroken)" ] && [ $failed -eq 0 ]; then all=0; fi
  if [ "$name" = "none (unbroken)" ] && [ $failed -eq 1 ]; then all=0; fi
done
git -C "$work" checkout -q -- .
[ $all -eq 1 ] && echo "every breakage caught" || { echo "some breakage NOT caught"; exit 1; }
