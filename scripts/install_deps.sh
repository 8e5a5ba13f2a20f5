#!/usr/bin/env bash
# Installs the Debian packages slamsph needs, if any is missing. Each is chosen on purpose.
# To build and run (scripts/quickstart.sh):
#   g++ cmake make pkg-config  build toolchain
#   libtomlplusplus-dev        case files (TOML, with line numbers for error messages)
#   libcli11-dev               command line (header-only): per-command --help with defaults,
#                              options in any position, --opt=value
#   zlib1g-dev                 optional zlib compression of the VTK output
#   gnuplot-nox                PNG plots (force histories, surge front, ...)
# With --test, also what only the test command needs (scripts/test.sh):
#   libgtest-dev               tests
#   libbenchmark-dev           kernels' micro-benchmarks (bench/)
#   clang-format               the format check
#   python3-vtk9               VTK's own reader, to read the VTK output back (ParaView's reader)
#   calculix-ccx               independent finite-element reference (CalculiX) for the structural
#                              verifications; scripts/calculix/ generates its inputs (validation only)
set -euo pipefail
pkgs=(g++ cmake make pkg-config libtomlplusplus-dev libcli11-dev zlib1g-dev gnuplot-nox)
if [ "${1:-}" = "--test" ]; then
  pkgs+=(libgtest-dev libbenchmark-dev clang-format python3-vtk9 calculix-ccx)
fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing missing Debian packages: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
