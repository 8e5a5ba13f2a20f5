#!/usr/bin/env bash
# Installs the Debian packages slamsph needs, if any is missing. Each is chosen on purpose:
#   g++ cmake make pkg-config  build toolchain
#   libtomlplusplus-dev        case files (TOML, with line numbers for error messages)
#   libgtest-dev               tests
#   libbenchmark-dev           kernels' micro-benchmarks (bench/)
#   gnuplot-nox                PNG plots (force histories, surge front, ...)
#   clang-format               the format check in the test command
set -euo pipefail
pkgs=(g++ cmake make pkg-config libtomlplusplus-dev libgtest-dev libbenchmark-dev gnuplot-nox
      clang-format)
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
