#!/usr/bin/env bash
# Builds roughgas with AddressSanitizer and UndefinedBehaviorSanitizer (gcc; CMakePresets.json
# "sanitize", build dir build-sanitize/) and runs the unit tests there (ctest -L unit). Any
# sanitizer report fails the test it occurs in (-fno-sanitize-recover, halt_on_error).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/apt_install.sh" --base
cd "$root"
log="$root/build-sanitize/build.log"
[ -f build-sanitize/CMakeCache.txt ] || cmake --preset sanitize >/dev/null
if ! cmake --build --preset sanitize >"$log" 2>&1; then
  grep -E -A5 "error|Error" "$log" | head -60 >&2
  echo "sanitize: build failed (full log: $log)" >&2
  exit 1
fi
ctest --preset sanitize "$@"
