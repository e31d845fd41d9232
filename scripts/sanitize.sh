#!/usr/bin/env bash
# Builds roughgas with AddressSanitizer and UndefinedBehaviorSanitizer (gcc; CMakePresets.json
# "sanitize", build dir build-sanitize/) and runs the unit tests there (ctest -L unit). Any
# sanitizer report fails the test it occurs in (-fno-sanitize-recover, halt_on_error).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/apt_install.sh" --base
cd "$root"
[ -f build-sanitize/CMakeCache.txt ] || cmake --preset sanitize >/dev/null
"$root/scripts/cmake_build.sh" sanitize "$root/build-sanitize/build.log" --preset sanitize
ctest --preset sanitize "$@"
