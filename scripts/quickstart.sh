#!/usr/bin/env bash
# Command 1 of the README: build slamsph and run the paper's validation case (elastic
# cylinder water entry, paper §4.1), then plot the slamming force against theory. Installs
# only what building and running need; the test tools come with scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSLAMSPH_TESTS=OFF -DSLAMSPH_BENCH=OFF >/dev/null
cmake --build build --target slamsph -j"$(nproc)"
case_file=${1:-cases/elastic_cylinder_entry.toml}
name=$(basename "$case_file" .toml)
./build/slamsph run "$case_file" --out "results/$name" --overwrite
echo "Plots: results/$name/*.png, ParaView: results/$name/fields.pvd"
