#!/usr/bin/env bash
# Baseline-vs-new ratios (issue 13 item 6): runs the same benchmarks with a baseline build
# and a new build ALTERNATELY (base, new, base, new, ...) so that a change in machine load
# hits both, and prints per benchmark the median of REPEAT runs of each and their ratio.
#   bench/ratio.sh BASE_BUILD NEW_BUILD [REPEAT=3] [FILTER='BM_RingSubsteps']
# BASE_BUILD / NEW_BUILD: CMake build folders with bench/bench_solid (e.g. a build of the
# landed main in /tmp/base/build and this worktree's build). Reports real time, CPU time and
# items per second (solid particle-steps/s); on a shared machine compare the CPU column and
# prefer callgrind counts (RATIO_MODE=callgrind: instructions inside advance_body for each
# case 0-2 of the FILTER family (BM_RingSubsteps or BM_RingSubstepsJohnsonCook), 1 thread,
# one iteration each; deterministic, REPEAT ignored).
set -euo pipefail
base=$1
new=$2
repeat=${3:-3}
filter=${4:-BM_RingSubsteps}
mode=${RATIO_MODE:-time}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

if [[ $mode == callgrind ]]; then
  printf "%-45s %15s %15s %8s\n" benchmark "base Ir" "new Ir" "base/new"
  for c in 0 1 2; do
    name="$filter/case:$c/threads:1/"
    for b in base new; do
      dir=$base
      [[ $b == new ]] && dir=$new
      valgrind --tool=callgrind --callgrind-out-file="$tmp/$b.out" \
        --toggle-collect='slamsph::advance_body*' "$dir/bench/bench_solid" \
        --benchmark_filter="$name" --benchmark_min_time=0 >/dev/null 2>"$tmp/$b.err"
      grep -h "Collected" "$tmp/$b.err" | awk '{print $4}' >"$tmp/$b.ir"
    done
    printf "%-45s %15s %15s %8.3f\n" "$name" "$(cat "$tmp/base.ir")" "$(cat "$tmp/new.ir")" \
      "$(awk -v a="$(cat "$tmp/base.ir")" -v b="$(cat "$tmp/new.ir")" 'BEGIN {print a / b}')"
  done
  exit 0
fi

for ((r = 0; r < repeat; r++)); do
  for b in base new; do
    dir=$base
    [[ $b == new ]] && dir=$new
    "$dir/bench/bench_solid" --benchmark_filter="$filter" --benchmark_format=csv \
      2>/dev/null | grep '^"' >"$tmp/$b.$r.csv" || true
  done
done
# CSV columns: name,iterations,real_time,cpu_time,time_unit,bytes_per_second,items_per_second,...
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
printf "%-48s %10s %10s %10s %10s %12s %12s %8s\n" benchmark "base real" "new real" "base cpu" \
  "new cpu" "base items/s" "new items/s" "ratio"
for name in $(cut -d, -f1 "$tmp/new.0.csv" | tr -d '"'); do
  for b in base new; do
    for col in 3 4 7; do
      cat "$tmp"/$b.*.csv | grep "^\"$name\"," | cut -d, -f$col | median >"$tmp/$b.$col"
    done
  done
  printf "%-48s %10.3g %10.3g %10.3g %10.3g %12.4g %12.4g %8.3f\n" "$name" "$(cat "$tmp/base.3")" \
    "$(cat "$tmp/new.3")" "$(cat "$tmp/base.4")" "$(cat "$tmp/new.4")" "$(cat "$tmp/base.7")" \
    "$(cat "$tmp/new.7")" "$(awk -v a="$(cat "$tmp/new.7")" -v b="$(cat "$tmp/base.7")" \
      'BEGIN {print (b > 0) ? a / b : 0}')"
done
echo "median of $repeat alternating runs each; ratio = new/base items per second (real time)"
echo "load: $(uptime)"
