#!/usr/bin/env bash
# Whole-case throughput (issue 13 item 6): wall seconds per simulated millisecond of the
# fuselage cases, and from each run's phase split (summary.json "time_split_s",
# src/app/phase_times.h) the solid throughput (elastic particle-sub-steps per second of the
# solid phase) and the water's (water particle-steps per second of the water phases), for 1
# and 2 threads, medians of REPEAT runs. With a BASE binary the two binaries run
# alternately (base, new, base, new, ...) so that a change in machine load hits both, and
# the ratios base/new of the medians are printed.
#   bench/case_throughput.sh NEW_SLAMSPH [BASE_SLAMSPH] [REPEAT=3] [END_TIME=0.001]
# CASES (environment): the case files, default cases/fuselage/skin_cylinder.toml and
# cases/fuselage/skin_L_floor_column.toml; THREADS: default "1 2". Time 2 threads only
# on an idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
new=$1
base=${2:-}
repeat=${3:-3}
end=${4:-0.001}
cases=${CASES:-"cases/fuselage/skin_cylinder.toml cases/fuselage/skin_L_floor_column.toml"}
threads=${THREADS:-"1 2"}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# One run; prints "wall_per_ms solid_rate water_rate" (rates in M per second).
one() {
  local bin=$1 case=$2 th=$3
  "$bin" run "$case" --end-time "$end" --threads "$th" --out "$tmp/run" --overwrite -q \
    --set output.vtk=false --set "output.snapshots=[$end]" >/dev/null 2>&1 || true
  /usr/bin/python3 - "$tmp/run/summary.json" "$end" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
end = float(sys.argv[2])
t = s["time_split_s"]
n = s["fluid_steps"]
water = s["particles"]["fluid"]
elastic = sum(v for k, v in s["particles"].items() if k not in ("fluid", "tank"))
# Sub-steps of the (one) elastic body: the run's count.
solid = elastic * s["solid_substeps"] / t["solid_substeps"] / 1e6 if t["solid_substeps"] else 0
wt = t["fluid_rates"] + t["fluid_integration"] + t["neighbour_lists"] + t["contact"]
print(f'{s["wall_seconds"] / (1e3 * end):.4g} {solid:.4g} {water * n / wt / 1e6:.4g}')
EOF
}

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

printf "%-42s %-7s %-6s %14s %14s %14s\n" case threads build "wall s/sim ms" "solid M/s" "water M/s"
for case in $cases; do
  for th in $threads; do
    : >"$tmp/new.txt"
    : >"$tmp/base.txt"
    for ((r = 0; r < repeat; r++)); do
      [[ -n $base ]] && one "$base" "$case" "$th" >>"$tmp/base.txt"
      one "$new" "$case" "$th" >>"$tmp/new.txt"
    done
    for b in base new; do
      [[ $b == base && -z $base ]] && continue
      w=$(awk '{print $1}' "$tmp/$b.txt" | median)
      s=$(awk '{print $2}' "$tmp/$b.txt" | median)
      f=$(awk '{print $3}' "$tmp/$b.txt" | median)
      printf "%-42s %-7s %-6s %14s %14s %14s\n" "$case" "$th" "$b" "$w" "$s" "$f"
      eval "${b}_w=$w ${b}_s=$s"
    done
    if [[ -n $base ]]; then
      awk -v bw="$base_w" -v nw="$new_w" -v bs="$base_s" -v ns="$new_s" \
        'BEGIN {printf "%-42s %-7s ratio  wall base/new %.3f, solid new/base %.3f\n", "", "", bw / nw, ns / bs}'
    fi
  done
done
