#!/usr/bin/env bash
# Fails if any C++ source differs from its clang-format output (.clang-format at the root).
set -euo pipefail
cd "$(dirname "$0")/.."
bad=0
while IFS= read -r f; do
  if ! diff -q <(clang-format "$f") "$f" >/dev/null; then
    echo "needs clang-format: $f"
    bad=1
  fi
done < <(git ls-files '*.h' '*.cpp')
[ $bad -eq 0 ] && echo "format ok"
exit $bad
