#!/usr/bin/env bash
# Whole-run throughput: fluid particle-steps per second (fluid particles x fluid steps /
# wall seconds, no output) on bench/dam_break_peer.toml at dx = 0.025 m (3200 particles)
# and dx = 0.0025 m (320k), for 1 and 2 threads; median of REPEAT runs each. The case has
# SPHinXsys' sound speed (c0 = 62.64 m/s); a fixed step count, so its end_time does not matter.
# Usage: bench/throughput.sh [REPEAT=3]
set -euo pipefail
cd "$(dirname "$0")/.."
repeat=${1:-3}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target slamsph -j"$(nproc)" >/dev/null
printf "%-10s %-8s %-12s %s\n" "dx [m]" threads particles "M particle-steps/s (median of $repeat)"
for spec in "0.025 4000" "0.0025 400"; do
  set -- $spec
  for th in 1 2; do
    rates=()
    for ((r = 0; r < repeat; r++)); do
      line=$(./build/slamsph run bench/dam_break_peer.toml --dx "$1" --threads "$th" --max-steps "$2" \
        --no-output 2>&1 | grep "particle-steps/s")
      rates+=("$(echo "$line" | sed -E 's/.*\(([0-9.e+]+) particle-steps.*/\1/')")
      n=$(echo "$line" | sed -E 's/.*fluid particles: ([0-9]+).*/\1/')
    done
    med=$(printf "%s\n" "${rates[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
    printf "%-10s %-8s %-12s %s\n" "$1" "$th" "$n" "$(awk -v m="$med" 'BEGIN {printf "%.3f", m / 1e6}')"
  done
done
