#!/usr/bin/env bash
# The paper's elastic fuselage studies (§4.2–4.4, issue 10; docs/studies.md §2) at the shipped
# resolution (2-layer skin at 1.5 mm, water 6 mm), every run to the case's 50 ms:
#   skin_cylinder, skin_stringer_I, skin_stringer_L                       (Figs. 7, 10–12)
#   skin_L_floor_column and skin_I_floor_column, floor 5 / 10 / 15 mm      (Figs. 13, 15–17, 19–23)
#   the same with 20 mm columns                                           (Figs. 18, 24)
# and the overlays the paper's comparisons need (Figs. 12, 14, 17, 25). Each run is a
# normal run folder under OUT; a run whose summary.json says "completed" is skipped, so the
# script resumes. OUT/studies.md tabulates every run: particles, fluid steps, solid sub-steps
# per fluid step, wall time, leaked particles, momentum error (summary.json
# "momentum_balance": the largest |R| of the water–body momentum balance, x or y, against its
# largest term; README "Momentum balance"), peak force and time, impulse, peak strain and
# where, keel deflection, ovalisation, column shortening, floor deflection, energy residual.
# Usage: scripts/validate_fuselage_studies.sh [THREADS=2] [OUT=results/fuselage_studies]
#   RUNS="name ..." runs only those (names as in the table: skin_cylinder, L_floor10, ...).
#   EXTRA="--set KEY=VALUE ..." is passed to every run (e.g. a shorter --end-time).
#   SLAMSPH=path runs that binary instead of building build/slamsph (a frozen copy, so that
#   rebuilding during the hours of a study does not mix two versions in one table).
# Cost (session 7, main 30d7de5): the skin 222 s on 2 threads of an idle machine; the sections
# with stringers 410–460 s and with floor and columns 500–970 s on one thread each, two runs at
# a time on 2 cores; all eleven runs about 1 h that way (THREADS=1, RUNS split in two).
set -euo pipefail
cd "$(dirname "$0")/.."
threads=${1:-2}
out=${2:-results/fuselage_studies}
mkdir -p "$out"
slamsph=${SLAMSPH:-./build/slamsph}
if [ -z "${SLAMSPH:-}" ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build --target slamsph -j"$(nproc)" >/dev/null
fi

floor='body[1].shape.floor.thickness'
cols='body[1].shape.columns.width'
# name | case | overrides
table="skin_cylinder|skin_cylinder|
stringer_I|skin_stringer_I|
stringer_L|skin_stringer_L|
L_floor10|skin_L_floor_column|
I_floor10|skin_I_floor_column|
L_floor5|skin_L_floor_column|--set $floor=0.005
L_floor15|skin_L_floor_column|--set $floor=0.015
L_columns20|skin_L_floor_column|--set $cols=0.02
I_floor5|skin_I_floor_column|--set $floor=0.005
I_floor15|skin_I_floor_column|--set $floor=0.015
I_columns20|skin_I_floor_column|--set $cols=0.02"
selected=${RUNS:-$(cut -d'|' -f1 <<<"$table" | tr '\n' ' ')}

status() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("status",""))' "$1" 2>/dev/null || true; }

while IFS='|' read -r name case overrides; do
  [[ " $selected " == *" $name "* ]] || continue
  dir="$out/$name"
  if [ "$(status "$dir/summary.json")" = "completed" ]; then
    echo "$name: completed, skipped"
    continue
  fi
  echo "$name: running cases/fuselage/$case.toml $overrides"
  # shellcheck disable=SC2086  # overrides and EXTRA are word lists on purpose
  "$slamsph" run "cases/fuselage/$case.toml" --out "$dir" --overwrite --threads "$threads" \
    --quiet $overrides ${EXTRA:-} || echo "$name: exit $?"
done <<<"$table"

# Overlays of the paper's comparisons (only of runs that exist).
overlay() {
  local name=$1
  shift
  local dirs=()
  for r in "$@"; do [ -f "$out/$r/summary.json" ] && dirs+=("$out/$r"); done
  [ ${#dirs[@]} -ge 2 ] && "$slamsph" plot "${dirs[@]}" --out "$out/$name" >/dev/null || true
}
overlay fig12_stringers skin_cylinder stringer_I stringer_L
overlay fig14_L_floor_column stringer_L L_floor10
overlay fig17_L_floor L_floor5 L_floor10 L_floor15 L_columns20
overlay fig20_I_floor_column stringer_I I_floor10
overlay fig23_I_floor I_floor5 I_floor10 I_floor15 I_columns20
overlay fig25_skin_pyy skin_cylinder stringer_I I_floor10

python3 scripts/fuselage_study_table.py "$out" >"$out/studies.md"
cat "$out/studies.md"
