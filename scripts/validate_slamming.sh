#!/usr/bin/env bash
# Primary slamming validation (issue 9; docs/validation.md §1): cases/cylinder_constant_speed.toml,
# a rigid cylinder at constant speed, against the 2D theories of src/io/reference_curves.
#  - resolutions D/dx = 20, 40, 80 (and 160 with MAX_DDX=160) at c0/V = 15;
#  - sound speeds c0/V = 10, 15, 20, 30 at the two finest resolutions run;
#  - post-processing (scripts/slamming_convergence.py, Python standard library only):
#    filtered Cs at s/D = 0.01 ... 0.3, impulse over s/D 0.02-0.25, observed order and
#    Roache's GCI, the peak as a range with its s/D, dx/s* and Mach number; a plot of Cs
#    against s/D with every reference (cs_vs_sD.png) and tables (*.csv, report.txt).
# Runs already completed in OUT are reused (delete OUT/<tag> to redo one), so an interrupted
# sweep can be resumed. Usage:
#   scripts/validate_slamming.sh [THREADS=2] [OUT=results/validation_slamming]
#   MAX_DDX=160 scripts/validate_slamming.sh ...     # include D/dx = 160 (hours on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-2}
out=${2:-results/validation_slamming}
max_ddx=${MAX_DDX:-80}
mkdir -p "$out"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target slamsph slamming_references -j2 >/dev/null
case_file=cases/cylinder_constant_speed.toml
V=2.33
D=0.2

run() {  # D/dx c0/V
  local ddx=$1 mach=$2 tag="d$1_c$2"
  if [[ -f "$out/$tag/summary.json" ]] && grep -q '"status": "completed"' "$out/$tag/summary.json"; then
    return
  fi
  local dx c0 cy
  dx=$(python3 -c "print($D / $ddx)")
  c0=$(python3 -c "print($mach * $V)")
  cy=$(python3 -c "print(0.7 + 3 * $D / $ddx)")  # lowest point 3 dx above the free surface
  te=$(python3 -c "print(3 * $D / $ddx / $V + 0.031)")  # contact time + 31 ms (s/D = 0.36)
  sed -e "s/^dx = 0.005 .*/dx = $dx/" -e "s/^sound_speed = .*/sound_speed = $c0/" -e "s/^end_time = .*/end_time = $te/" \
    -e "s/^centre = \[0.6, 0.715\].*/centre = [0.6, $cy]/" -e "s/^\[output\]/[output]\nvtk = false/" \
    "$case_file" > "$out/$tag.toml"
  echo "run $tag (dx = $dx m, c0 = $c0 m/s) ..."
  local t_start=$SECONDS
  ./build/slamsph run "$out/$tag.toml" --out "$out/$tag" --overwrite --threads "$threads" --quiet
  echo "  $tag: $((SECONDS - t_start)) s"
}

run 20 15
run 40 15
run 80 15
for m in 10 20 30; do run 40 "$m"; done
for m in 10 20 30; do run 80 "$m"; done
if [[ $max_ddx -ge 160 ]]; then
  run 160 15
  for m in 10 20 30; do run 160 "$m"; done
fi

./build/slamming_references > "$out/references.csv"
python3 scripts/slamming_convergence.py "$out" "$V" "$D"
